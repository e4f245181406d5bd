// Progress lines for the long stages (the offline build on large meshes,
// the optimisation's global stage and bounds, the reference's sampling):
// what is done out of how much, the elapsed and
// the estimated remaining time, at most one line every few seconds, on
// standard error so that standard output stays the report.
//
// Whether lines are printed is the "verbosity" key of the step programs:
//   quiet      never;
//   auto       when standard error is a terminal (the default: a log file
//              or a pipe gets no progress lines);
//   progress   always.
// Only the first MPI rank prints.

#ifndef fuzzycontact_base_progress_h
#define fuzzycontact_base_progress_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <functional>
#include <string>

namespace FuzzyContact
{
  using namespace dealii;

  namespace ProgressLines
  {
    enum class Verbosity
    {
      quiet,
      automatic,
      progress
    };

    /** Declares "verbosity" (quiet | auto | progress) in the current section.
     */
    void
    declare_parameters(ParameterHandler &prm);

    /** Reads "verbosity" and sets the process-wide setting. */
    void
    parse_parameters(const ParameterHandler &prm);

    /** Sets the process-wide setting (the first MPI rank prints only). */
    void
    set_verbosity(const Verbosity verbosity);

    /** Whether this process prints progress lines. */
    bool
    enabled();

    /**
     * Says that stage @p what of the offline build is done (the @p done-th
     * of @p total), if the last line was printed more than the interval
     * ago; the elapsed time counts from the first stage of the process.
     */
    void
    stage(const std::string &what,
          const unsigned int done,
          const unsigned int total);

    /**
     * Says @p what of a stage whose length is not known beforehand (an
     * adaptive loop: "Krylov static correction of Plate: level 2, ..."),
     * under the same rule as stage(): "  ... <what>, 31 s elapsed".
     */
    void
    note(const std::string &what);

    /**
     * The text of a counting line: "<what>: 120/641 (18 %), 3.1 s elapsed,
     * about 14 s left" (no estimate when nothing or everything is done).
     */
    std::string
    line(const std::string &what,
         const unsigned int done,
         const unsigned int total,
         const double       elapsed,
         const std::string &detail = "");
  } // namespace ProgressLines

  /**
   * Counts the steps of one long loop and prints "<what>: 120/641 (19 %),
   * 3.1 s elapsed, about 13 s left" at most every @p interval seconds, and
   * a last line when all are done if any line was printed; @p detail, if
   * given, adds its text after the count ("..., 4210 evaluations, ...").
   */
  class Progress
  {
  public:
    Progress(const std::string                  &what,
             const unsigned int                  total,
             const double                        interval = 3.,
             const std::function<std::string()> &detail   = {});
    ~Progress();

    void
    advance(const unsigned int n = 1);

  private:
    void
    print() const;

    std::string                  what;
    std::function<std::string()> detail;
    unsigned int                 total;
    unsigned int                 done = 0;
    double                       interval;
    double                       last_line;
    bool                         printed = false;
    Timer                        timer;
  };
} // namespace FuzzyContact

#endif
