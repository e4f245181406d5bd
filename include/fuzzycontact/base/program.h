// The main() of a step program: one parameter file on the command line, and
// every failure turned into a one-line message naming the problem on stderr
// with a non-zero exit status.

#ifndef fuzzycontact_base_program_h
#define fuzzycontact_base_program_h

#include <functional>
#include <string>

namespace FuzzyContact
{
  /**
   * The main() of a step program: checks the command line (one parameter
   * file), runs @p run on it, and turns any exception into a message on
   * stderr naming the problem and exit status 1.
   */
  int
  run_program(int                                             argc,
              char                                          **argv,
              const std::string                              &program_name,
              const std::function<void(const std::string &)> &run);
} // namespace FuzzyContact

#endif
