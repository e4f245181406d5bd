// Helpers shared by the GoogleTest programs.

#ifndef fuzzycontact_tests_test_utilities_h
#define fuzzycontact_tests_test_utilities_h

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/exceptions.h>

#include <gtest/gtest.h>

#include <string>

namespace FuzzyContact
{
  namespace Testing
  {
    /** The repository's top folder (set by CMake). */
    inline const std::string source_dir = FUZZYCONTACT_SOURCE_DIR;

    /**
     * @p text with the first occurrence of @p from replaced by @p to (a bad
     * input made from a good one); a test failure if @p from is absent.
     */
    inline std::string
    replace(std::string text, const std::string &from, const std::string &to)
    {
      const auto pos = text.find(from);
      EXPECT_NE(pos, std::string::npos)
        << "test setup: <" << from << "> not found";
      if (pos != std::string::npos)
        text.replace(pos, from.size(), to);
      return text;
    }

    /** The fuzzy parameters of a step file's text, bound to @p scene. */
    inline FuzzyParameterSet
    fuzzy_parameters(const Scene &scene, const std::string &text)
    {
      FuzzyParameterSet set;
      Input::parse_in_passes(
        text,
        "test.prm",
        [&](dealii::ParameterHandler &prm) {
          set.declare_parameters(prm);
        },
        [&](dealii::ParameterHandler &prm) {
          return set.learn_names(prm);
        },
        [&](dealii::ParameterHandler &prm) {
          set.parse_parameters(prm, scene);
        });
      return set;
    }

    /** The user-facing message of the exception @p f throws ("" if none). */
    template <typename F>
    std::string
    error_of(const F &f)
    {
      try
        {
          f();
        }
      catch (const dealii::ExceptionBase &e)
        {
          return Input::message_of(e);
        }
      return "";
    }
  } // namespace Testing
} // namespace FuzzyContact

#endif
