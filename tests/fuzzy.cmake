## Tests of the fuzzy machinery (fuzzy numbers, fuzzy parameters, interval
## methods). Included from tests/CMakeLists.txt.
fuzzycontact_gtest(fuzzy)
