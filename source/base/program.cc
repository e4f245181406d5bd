#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/lapack_errors.h>
#include <fuzzycontact/base/program.h>

#include <deal.II/base/exceptions.h>

#include <exception>
#include <iostream>
#include <new>

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
    LapackErrors::install();
    const std::string parameter_file = argv[1];
    std::string       message;
    try
      {
        run(parameter_file);
        // A LAPACK error that nothing checked: the run's numbers cannot be
        // trusted, even if they were written.
        LapackErrors::check("the computation");
        return 0;
      }
    catch (const ExceptionBase &e)
      {
        // Only the "additional information" of a deal.II exception is for the
        // user; the source location and stack trace are for developers.
        message = Input::message_of(e);
        if (message.empty() || message == "(none)")
          message = std::string("internal error without a message (") +
                    e.get_exc_name() +
                    "); please report it with the parameter files";
      }
    catch (const std::bad_alloc &)
      {
        message = "out of memory: the run needs more memory than this "
                  "machine has. Reduce 'mesh refinements' or the "
                  "'subdivisions' of the scene's components";
      }
    catch (const std::exception &e)
      {
        message = e.what();
        if (message.empty())
          message = "internal error without a message; please report it "
                    "with the parameter files";
      }
    catch (...)
      {
        message = "internal error of an unknown kind; please report it with "
                  "the parameter files";
      }
    if (LapackErrors::pending())
      message += " (before this, " + LapackErrors::take() + ")";
    // Every message names a parameter file: the one it is about if it says
    // so, else the one that configured the run.
    if (message.find(".prm") == std::string::npos &&
        message.find(parameter_file) == std::string::npos)
      message = parameter_file + ": " + message;
    std::cerr << program_name << ": error: " << message << std::endl;
    return 1;
  }
} // namespace FuzzyContact
