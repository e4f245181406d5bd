#include <fuzzycontact/base/lapack_errors.h>
#include <fuzzycontact/output/output_files.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sys/syscall.h>
#include <unistd.h>

namespace FuzzyContact
{
  using namespace dealii;

  namespace
  {
    namespace fs = std::filesystem;

    void
    write_plain(const fs::path &target, const std::string &content)
    {
      if (target.has_parent_path())
        fs::create_directories(target.parent_path());
      std::ofstream out(target, std::ios::binary);
      AssertThrow(out.good(),
                  ExcMessage("Cannot write the file <" + target.string() +
                             ">."));
      out << content;
      out.flush();
      AssertThrow(out.good(),
                  ExcMessage("Writing <" + target.string() +
                             "> failed (is the disk full?)."));
    }


    // True if a process with this id still runs.
    bool
    process_alive(const long pid)
    {
      return pid > 0 &&
             (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
    }


    // The staging folders of runs that were killed before they could swap
    // their results in: ".<name>.new-<pid>" and ".<name>.old-<pid>" beside
    // the output folder whose process is gone.
    void
    remove_stale_staging(const fs::path &parent, const std::string &name)
    {
      std::error_code  error;
      const std::regex staging(
        "\\." +
        std::regex_replace(name,
                           std::regex(R"([.^$|()\[\]{}*+?\\])"),
                           R"(\$&)") +
        "\\.(new|old)-([0-9]+)");
      for (const auto &entry : fs::directory_iterator(parent, error))
        {
          std::smatch       m;
          const std::string file = entry.path().filename().string();
          if (std::regex_match(file, m, staging) &&
              !process_alive(std::stol(m[2].str())))
            fs::remove_all(entry.path(), error);
        }
    }


    // Swaps two paths atomically (Linux renameat2 with RENAME_EXCHANGE);
    // false if the file system cannot.
    bool
    exchange(const fs::path &a, const fs::path &b)
    {
#ifdef SYS_renameat2
      constexpr unsigned int rename_exchange = 2; // RENAME_EXCHANGE
      return ::syscall(SYS_renameat2,
                       AT_FDCWD,
                       a.c_str(),
                       AT_FDCWD,
                       b.c_str(),
                       rename_exchange) == 0;
#else
      (void)a;
      (void)b;
      return false;
#endif
    }


    // A text output that carries a NaN or an infinity (as C++ streams and
    // nlohmann::json print them) is a failed computation, never a result.
    // (In a JSON file queued as text, a null is a NaN that the dump turned
    // into null; OutputFiles::add_json checks the numbers instead.)
    bool
    has_non_finite(const std::string &name,
                   const std::string &content,
                   const bool         nulls_are_values)
    {
      const std::string extension = fs::path(name).extension().string();
      if (extension != ".json" && extension != ".txt" && extension != ".dat")
        return false;
      static const std::regex word(
        R"((^|[^A-Za-z0-9_])[-+]?(nan|inf|infinity)([^A-Za-z0-9_]|$))",
        std::regex::icase);
      static const std::regex null(R"([:\[,]\s*null\s*[,\]\}\n])");
      return std::regex_search(content, word) ||
             (extension == ".json" && !nulls_are_values &&
              std::regex_search(content, null));
    }

    bool
    has_non_finite_number(const nlohmann::json &j)
    {
      if (j.is_number_float())
        return !std::isfinite(j.get<double>());
      if (j.is_structured())
        for (const auto &element : j)
          if (has_non_finite_number(element))
            return true;
      return false;
    }
  } // namespace


  void
  write_file_atomically(const std::string &filename, const std::string &content)
  {
    const fs::path target(filename);
    if (target.has_parent_path())
      fs::create_directories(target.parent_path());
    const fs::path temporary =
      target.string() + ".tmp-" + std::to_string(::getpid());
    write_plain(temporary, content);
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error)
      {
        fs::remove(temporary, error);
        AssertThrow(false,
                    ExcMessage("Cannot move the result into <" + filename +
                               ">: " + error.message()));
      }
  }


  OutputFiles::OutputFiles(const std::string &directory)
      : directory_(directory)
  {
  }


  void
  OutputFiles::add(const std::string &filename, std::string content)
  {
    files_[filename] = std::move(content);
    json_non_finite_.erase(filename);
  }


  void
  OutputFiles::add_json(const std::string    &filename,
                        const nlohmann::json &content)
  {
    files_[filename]           = content.dump(2) + "\n";
    json_non_finite_[filename] = has_non_finite_number(content);
  }


  void
  OutputFiles::write_all() const
  {
    // Nothing is written after a LAPACK error or with a non-finite number.
    LapackErrors::check("Writing the results to <" + directory_ + ">");
    for (const auto &[name, content] : files_)
      {
        const auto json    = json_non_finite_.find(name);
        const bool is_json = json != json_non_finite_.end();
        AssertThrow(
          !(is_json && json->second) && !has_non_finite(name, content, is_json),
          ExcMessage("The results contain a value that is not a finite "
                     "number (NaN or infinity, in " +
                     name + "), so nothing was written to <" + directory_ +
                     ">: an input made the computation overflow. Check the "
                     "magnitudes of the loads, moduli, densities and "
                     "friction coefficients."));
      }

    fs::path target = fs::path(directory_).lexically_normal();
    if (target.filename().empty())
      target = target.parent_path();
    const fs::path parent =
      target.has_parent_path() ? target.parent_path() : fs::path(".");
    const std::string name = target.filename().string();
    fs::create_directories(parent);
    remove_stale_staging(parent, name);

    // Every file goes into a new folder beside the target, which is then
    // swapped in as a whole: a reader sees the old set or the new one.
    const std::string pid     = std::to_string(::getpid());
    const fs::path    staging = parent / ("." + name + ".new-" + pid);
    const fs::path    old     = parent / ("." + name + ".old-" + pid);
    std::error_code   error;
    fs::remove_all(staging, error);
    try
      {
        fs::create_directory(staging);
        for (const auto &[file, content] : files_)
          write_plain(staging / file, content);
      }
    catch (...)
      {
        fs::remove_all(staging, error);
        throw;
      }
    const auto status = fs::symlink_status(target, error);
    if (fs::exists(status))
      {
        AssertThrow(fs::is_directory(status),
                    ExcMessage("Cannot write the results to <" + directory_ +
                               ">: it exists and is not a folder."));
        if (!exchange(staging, target))
          {
            // Without an atomic exchange: move the old set aside first.
            fs::rename(target, old, error);
            AssertThrow(!error,
                        ExcMessage("Cannot replace the folder <" + directory_ +
                                   ">: " + error.message()));
            fs::rename(staging, target, error);
            if (error)
              fs::rename(old, target);
            AssertThrow(!error,
                        ExcMessage("Cannot move the results into <" +
                                   directory_ + ">: " + error.message()));
            fs::remove_all(old, error);
          }
        // After an exchange, the staging folder holds the old set.
        fs::remove_all(staging, error);
      }
    else
      {
        fs::rename(staging, target, error);
        if (error)
          fs::remove_all(staging);
        AssertThrow(!error,
                    ExcMessage("Cannot move the results into <" + directory_ +
                               ">: " + error.message()));
      }
  }


  const std::string &
  OutputFiles::directory() const
  {
    return directory_;
  }


} // namespace FuzzyContact
