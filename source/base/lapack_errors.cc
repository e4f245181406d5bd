#include <fuzzycontact/base/lapack_errors.h>

#include <deal.II/base/exceptions.h>

#include <atomic>
#include <cctype>
#include <cstddef>
#include <mutex>
#include <string>
#include <vector>

namespace FuzzyContact
{
  namespace LapackErrors
  {
    namespace
    {
      std::atomic<bool>        recorded{false};
      std::mutex               mutex;
      std::vector<std::string> errors;
    } // namespace


    // Called from xerbla_ (below), possibly from several threads.
    void
    record(const char *routine, const std::size_t length, const int argument)
    {
      // The name is a Fortran string: not terminated, padded with blanks.
      // OpenBLAS passes its length as a 32-bit int, so read at most a few
      // characters and stop at the first that cannot be part of a name.
      std::string name;
      for (std::size_t i = 0; routine != nullptr && i < length && i < 32; ++i)
        {
          const unsigned char c = routine[i];
          if (!std::isalnum(c) && c != '_')
            break;
          name += static_cast<char>(std::toupper(c));
        }
      const std::string message =
        "LAPACK routine " + (name.empty() ? std::string("(unnamed)") : name) +
        " was called with an illegal value of its argument " +
        std::to_string(argument);
      std::lock_guard<std::mutex> lock(mutex);
      if (errors.size() < 8)
        errors.push_back(message);
      recorded = true;
    }


    void
    install()
    {
      // Nothing to do at run time: referring to this file's object from
      // run_program() puts xerbla_ into every program.
    }


    bool
    pending()
    {
      return recorded;
    }


    std::string
    take()
    {
      std::lock_guard<std::mutex> lock(mutex);
      std::string                 text;
      for (const std::string &e : errors)
        text += (text.empty() ? "" : "; ") + e;
      errors.clear();
      recorded = false;
      return text;
    }


    void
    check(const std::string &context)
    {
      if (!pending())
        return;
      const std::string what = take();
      AssertThrow(false,
                  dealii::ExcMessage(
                    context + ": " + what +
                    " (usually a value that overflowed or is not a number: "
                    "check the magnitudes of the moduli, densities, loads "
                    "and shifts of the input)."));
    }
  } // namespace LapackErrors
} // namespace FuzzyContact


// The replacement of LAPACK's XERBLA: records instead of stopping the
// program. Fortran passes the length of the name as a hidden last argument.
extern "C" void
xerbla_(const char *routine, const int *info, std::size_t length)
{
  FuzzyContact::LapackErrors::record(routine,
                                     length,
                                     info != nullptr ? *info : 0);
}
