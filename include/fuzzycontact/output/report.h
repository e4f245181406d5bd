// What every program reports: text printed as it is produced and kept for
// report.txt, and the number formats of its tables. The step programs
// compute; the reporting modules of this folder turn their results into
// tables, JSON and plots through these.

#ifndef fuzzycontact_output_report_h
#define fuzzycontact_output_report_h

#include <functional>
#include <iostream>
#include <sstream>
#include <string>

namespace FuzzyContact
{
  /**
   * The text of a program's report: each piece is printed (on the screen,
   * by the first MPI rank only if @p active is false elsewhere) as soon as
   * it is said, and kept for report.txt.
   */
  class Report
  {
  public:
    explicit Report(std::ostream &out = std::cout, const bool active = true);

    /** Prints @p text and keeps it. */
    void
    say(const std::string &text);

    /** Everything said so far. */
    std::string
    text() const;

  private:
    std::ostream      &out;
    bool               active;
    std::ostringstream kept;
  };

  namespace Format
  {
    /** "1.5e-04" with @p digits after the point; "-" if not finite. */
    std::string
    scientific(const double value, const int digits = 1);

    /** "0.123" with @p digits after the point; "-" if not finite. */
    std::string
    fixed(const double value, const int digits);

    /** A relative value in percent with its sign, "+0.153%". */
    std::string
    percent(const double relative, const int digits = 3);
  } // namespace Format

  /**
   * |a - b| / |b|; 0 if both vanish, 1 (100 %) if only the reference @p b
   * does.
   */
  double
  relative_error(const double a, const double b);

  /**
   * Mean wall time of one call of @p f, which is run at least once and until
   * @p min_seconds have passed.
   */
  double
  time_per_call(const std::function<void()> &f,
                const double                 min_seconds = 0.05);
} // namespace FuzzyContact

#endif
