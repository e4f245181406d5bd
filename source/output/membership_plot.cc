#include <fuzzycontact/output/membership_plot.h>

#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unistd.h>

namespace FuzzyContact
{
  namespace
  {
    std::string
    quoted(const std::string &s)
    {
      std::string q = "\"";
      for (const char c : s)
        q += (c == '"' ? std::string("\\\"") : std::string(1, c));
      return q + "\"";
    }

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

  bool
  add_membership_plot(OutputFiles                        &files,
                      const std::string                  &basename,
                      const std::string                  &title,
                      const std::vector<MembershipPanel> &panels,
                      std::string                        &message)
  {
    // Data: one block per (panel, curve), separated by two blank lines so
    // that gnuplot's 'index' picks them.
    std::ostringstream data;
    data << std::setprecision(10);
    data << "# membership functions: value alpha (one block per panel and "
            "curve)\n";
    unsigned int                           block = 0;
    std::vector<std::vector<unsigned int>> blocks(panels.size());
    for (unsigned int p = 0; p < panels.size(); ++p)
      for (const MembershipCurve &curve : panels[p].curves)
        {
          data << "# " << panels[p].title << ": " << curve.label << "\n";
          const unsigned int n = curve.alpha.size();
          // (A level without a bound, NaN, is left out.)
          for (unsigned int l = 0; l < n; ++l)
            if (std::isfinite(curve.bounds[l].lower))
              data << curve.bounds[l].lower / panels[p].scale << " "
                   << curve.alpha[l] << "\n";
          for (unsigned int l = n; l-- > 0;)
            if (std::isfinite(curve.bounds[l].upper))
              data << curve.bounds[l].upper / panels[p].scale << " "
                   << curve.alpha[l] << "\n";
          data << "\n\n";
          blocks[p].push_back(block++);
        }

    const unsigned int columns = panels.size() > 1 ? 2 : 1;
    const unsigned int rows    = (panels.size() + columns - 1) / columns;
    // (noenhanced: labels as written, "F_n" without a subscript.)
    std::ostringstream script;
    script << "# gnuplot script: gnuplot " << basename << ".gp\n"
           << "set terminal pngcairo noenhanced size " << 640 * columns << ","
           << 480 * rows + 40 << " font \",11\"\n"
           << "set output " << quoted(basename + ".png") << "\n"
           << "set multiplot layout " << rows << "," << columns << " title "
           << quoted(title) << "\n"
           << "set yrange [0:1.05]\nset ylabel \"membership\"\n"
           << "set grid\nset key bottom center box opaque font \",9\"\n";
    for (unsigned int p = 0; p < panels.size(); ++p)
      {
        script << "set title " << quoted(panels[p].title) << "\n"
               << "set xlabel " << quoted(panels[p].unit) << "\n"
               << "plot ";
        for (unsigned int c = 0; c < panels[p].curves.size(); ++c)
          script << (c ? ", \\\n     " : "") << quoted(basename + ".dat")
                 << " index " << blocks[p][c] << " with "
                 << panels[p].curves[c].style << " title "
                 << quoted(panels[p].curves[c].label);
        script << "\n";
      }
    script << "unset multiplot\n";

    files.add(basename + ".dat", data.str());
    files.add(basename + ".gp", script.str());

    // Run gnuplot in a private folder and keep the picture in memory, so
    // that it is written with the other files, atomically.
    namespace fs = std::filesystem;
    remove_stale_plot_folders();
    static int     counter = 0;
    const fs::path folder  = fs::temp_directory_path() /
                            ("fuzzycontact-plot-" + std::to_string(::getpid()) +
                             "-" + std::to_string(counter++));
    fs::create_directories(folder);
    std::ofstream(folder / (basename + ".dat")) << data.str();
    std::ofstream(folder / (basename + ".gp")) << script.str();
    const std::string command = "cd " + quoted(folder.string()) +
                                " && gnuplot " + quoted(basename + ".gp") +
                                " > gnuplot.log 2>&1";
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
