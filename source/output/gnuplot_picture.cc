#include <fuzzycontact/output/gnuplot_picture.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace FuzzyContact
{
  namespace
  {
    // The plot folders of runs that were killed while gnuplot ran
    // ("fuzzycontact-plot-<pid>-<k>" whose process is gone).
    void
    remove_stale_plot_folders()
    {
      namespace fs = std::filesystem;
      std::error_code   error;
      const std::string prefix = "fuzzycontact-plot-";
      for (const auto &entry :
           fs::directory_iterator(fs::temp_directory_path(error), error))
        {
          const std::string name = entry.path().filename().string();
          if (name.rfind(prefix, 0) != 0)
            continue;
          const long pid = std::atol(name.c_str() + prefix.size());
          if (pid > 0 && ::kill(static_cast<pid_t>(pid), 0) != 0 &&
              errno == ESRCH)
            fs::remove_all(entry.path(), error);
        }
    }
  } // namespace


  std::string
  gnuplot_quoted(const std::string &s)
  {
    std::string q = "\"";
    for (const char c : s)
      q += (c == '"' ? std::string("\\\"") : std::string(1, c));
    return q + "\"";
  }


  bool
  add_gnuplot_picture(OutputFiles       &files,
                      const std::string &basename,
                      const std::string &data,
                      const std::string &script,
                      std::string       &message)
  {
    files.add(basename + ".dat", data);
    files.add(basename + ".gp", script);

    // Run gnuplot in a private folder and keep the picture in memory, so
    // that it is written with the other files, atomically.
    namespace fs = std::filesystem;
    remove_stale_plot_folders();
    static int     counter = 0;
    const fs::path folder  = fs::temp_directory_path() /
                            ("fuzzycontact-plot-" + std::to_string(::getpid()) +
                             "-" + std::to_string(counter++));
    fs::create_directories(folder);
    std::ofstream(folder / (basename + ".dat")) << data;
    std::ofstream(folder / (basename + ".gp")) << script;
    const std::string command =
      "cd " + gnuplot_quoted(folder.string()) + " && gnuplot " +
      gnuplot_quoted(basename + ".gp") + " > gnuplot.log 2>&1";
    const int  status = std::system(command.c_str());
    const auto png    = folder / (basename + ".png");
    bool       ok     = false;
    if (status == 0 && fs::exists(png) && fs::file_size(png) > 0)
      {
        std::ifstream      in(png, std::ios::binary);
        std::ostringstream bytes;
        bytes << in.rdbuf();
        files.add(basename + ".png", bytes.str());
        ok = true;
      }
    else
      {
        std::ifstream log(folder / "gnuplot.log");
        std::string   first_line;
        std::getline(log, first_line);
        message = "gnuplot did not draw " + basename +
                  ".png (is Debian's gnuplot-nox installed?)" +
                  (first_line.empty() ? "" : ": " + first_line);
      }
    std::error_code ignore;
    fs::remove_all(folder, ignore);
    return ok;
  }
} // namespace FuzzyContact
