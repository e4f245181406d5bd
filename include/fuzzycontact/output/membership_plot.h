// A picture of fuzzy results: one panel per output, the membership function
// of each method drawn from its alpha-cut bounds (lower ends rising on the
// left, upper ends falling on the right). Drawn by gnuplot (Debian's
// gnuplot-nox); the data and the script are written beside the PNG, so the
// figure can be redrawn or restyled.

#ifndef fuzzycontact_output_membership_plot_h
#define fuzzycontact_output_membership_plot_h

#include <fuzzycontact/fuzzy/fuzzy_number.h>
#include <fuzzycontact/output/output_files.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  struct MembershipCurve
  {
    std::string           label;
    std::vector<double>   alpha;
    std::vector<Interval> bounds;
    /** A gnuplot style, e.g. "lines lw 2" or "points pt 7 ps 0.6". */
    std::string style;
  };

  struct MembershipPanel
  {
    std::string title;
    std::string unit;
    /** Values are divided by this for plotting (e.g. 1e3 for kN). */
    double                       scale = 1;
    std::vector<MembershipCurve> curves;
  };

  /**
   * Queues <basename>.dat and <basename>.gp in @p files and, if gnuplot can
   * be run, <basename>.png. Returns false (and leaves the PNG out) if
   * gnuplot is not installed or fails; @p message then says why.
   */
  bool
  add_membership_plot(OutputFiles                        &files,
                      const std::string                  &basename,
                      const std::string                  &title,
                      const std::vector<MembershipPanel> &panels,
                      std::string                        &message);
} // namespace FuzzyContact

#endif
