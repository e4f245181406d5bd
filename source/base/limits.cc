#include <fuzzycontact/base/limits.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <system_error>
#include <unistd.h>

namespace FuzzyContact
{
  namespace Input
  {
    using namespace dealii;

    double
    in_range(const double       value,
             const double       lower,
             const double       upper,
             const std::string &what,
             const std::string &why)
    {
      // (The message is formed only when it is needed: a study checks its
      // values at every evaluation.)
      if (!(std::isfinite(value) && value >= lower && value <= upper))
        {
          std::ostringstream message;
          message << what << " must lie between " << lower << " and " << upper
                  << (why.empty() ? "" : " (" + why + ")") << ", got "
                  << std::setprecision(10) << value << ".";
          AssertThrow(false, ExcMessage(message.str()));
        }
      return value;
    }


    unsigned int
    integer_in_range(const long         value,
                     const long         lower,
                     const long         upper,
                     const std::string &what,
                     const std::string &why)
    {
      Assert(lower >= 0, ExcInternalError());
      AssertThrow(value >= lower && value <= upper,
                  ExcMessage(what + " must be an integer from " +
                             std::to_string(lower) + " to " +
                             std::to_string(upper) +
                             (why.empty() ? "" : " (" + why + ")") + ", got " +
                             std::to_string(value) + "."));
      return static_cast<unsigned int>(value);
    }


    void
    check_output_directory(const std::string &folder, const std::string &key)
    {
      namespace fs           = std::filesystem;
      const std::string name = Utilities::trim(folder);
      AssertThrow(!name.empty(),
                  ExcMessage(key + " must name a folder for the results, "
                                   "but it is empty."));
      std::error_code error;
      fs::path        target = fs::absolute(name, error).lexically_normal();
      if (target.filename().empty() && target.has_parent_path() &&
          target != target.root_path())
        target = target.parent_path(); // "results/" is the folder results
      const fs::path here = fs::current_path(error).lexically_normal();
      // The results replace the whole folder at the end of a run, so it
      // must be a folder of its own.
      const std::string t = target.string(), h = here.string();
      const bool        is_here_or_above =
        t == "/" || h == t || h.rfind(t + (t.back() == '/' ? "" : "/"), 0) == 0;
      AssertThrow(!is_here_or_above && target.filename() != "" &&
                    target.filename() != "." && target.filename() != "..",
                  ExcMessage(key + " <" + name +
                             "> is the current folder or one above it; the "
                             "results replace the whole folder at the end "
                             "of a run, so give a folder of their own (e.g. "
                             "'results')."));
      const auto status = fs::status(target, error);
      AssertThrow(!fs::exists(status) || fs::is_directory(status),
                  ExcMessage(key + " <" + name +
                             "> exists and is not a folder; give a folder "
                             "for the results."));
      // The results are written into a new folder beside the target and
      // swapped in: the nearest existing ancestor must accept a new folder.
      fs::path parent = target.parent_path();
      while (!parent.empty() && !fs::exists(parent, error))
        parent = parent.parent_path();
      // A real probe: permissions alone do not tell (root, read-only or
      // virtual file systems such as /proc).
      bool writable = false;
      if (!parent.empty() && fs::is_directory(parent, error))
        {
          const fs::path probe =
            parent / (".fuzzycontact-probe-" + std::to_string(::getpid()));
          writable = fs::create_directory(probe, error) && !error;
          fs::remove(probe, error);
        }
      AssertThrow(writable,
                  ExcMessage(key + " <" + name + ">: the folder <" +
                             parent.string() +
                             "> cannot receive the results (it is not a "
                             "writable folder); give another output "
                             "directory."));
    }
  } // namespace Input
} // namespace FuzzyContact
