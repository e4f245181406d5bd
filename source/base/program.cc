#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/program.h>

#include <deal.II/base/exceptions.h>

#include <exception>
#include <iostream>

namespace FuzzyContact
{
  using namespace dealii;

  int
  run_program(int                                             argc,
              char                                          **argv,
              const std::string                              &program_name,
              const std::function<void(const std::string &)> &run)
  {
    if (argc != 2 || std::string(argv[1]) == "--help" ||
        std::string(argv[1]) == "-h")
      {
        std::cerr << "Usage: " << program_name << " <parameter file>\n"
                  << "  for instance: " << program_name << " prm/"
                  << program_name << ".prm" << std::endl;
        return (argc == 2) ? 0 : 2;
      }
    try
      {
        run(argv[1]);
      }
    catch (const ExceptionBase &e)
      {
        // Only the "additional information" of a deal.II exception is for the
        // user; the source location and stack trace are for developers.
        std::cerr << program_name << ": error: " << Input::message_of(e)
                  << std::endl;
        return 1;
      }
    catch (const std::exception &e)
      {
        std::cerr << program_name << ": error: " << e.what() << std::endl;
        return 1;
      }
    catch (...)
      {
        std::cerr << program_name << ": error: unknown exception" << std::endl;
        return 1;
      }
    return 0;
  }
} // namespace FuzzyContact
