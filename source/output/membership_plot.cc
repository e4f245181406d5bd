#include <fuzzycontact/output/gnuplot_picture.h>
#include <fuzzycontact/output/membership_plot.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace FuzzyContact
{
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
           << "set output " << gnuplot_quoted(basename + ".png") << "\n"
           << "set multiplot layout " << rows << "," << columns << " title "
           << gnuplot_quoted(title) << "\n"
           << "set yrange [0:1.05]\nset ylabel \"membership\"\n"
           << "set grid\nset key bottom center box opaque font \",9\"\n";
    for (unsigned int p = 0; p < panels.size(); ++p)
      {
        script << "set title " << gnuplot_quoted(panels[p].title) << "\n"
               << "set xlabel " << gnuplot_quoted(panels[p].unit) << "\n"
               << "plot ";
        for (unsigned int c = 0; c < panels[p].curves.size(); ++c)
          script << (c ? ", \\\n     " : "")
                 << gnuplot_quoted(basename + ".dat") << " index "
                 << blocks[p][c] << " with " << panels[p].curves[c].style
                 << " title " << gnuplot_quoted(panels[p].curves[c].label);
        script << "\n";
      }
    script << "unset multiplot\n";

    return add_gnuplot_picture(files,
                               basename,
                               data.str(),
                               script.str(),
                               message);
  }
} // namespace FuzzyContact
