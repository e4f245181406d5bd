// What more friction says of a point whose contact solve failed.
//
// Where the friction cones hold the load only after the bodies slid beyond
// small sliding (a pin that would spin in its bore), the active set
// iterations often cycle instead of converging to that answer, at some
// friction coefficients and not at others nearby. More friction holds the
// bodies better (less friction, more slip), so an answer with more
// friction that already slides beyond small sliding says that the point's
// own does too, and one within small sliding says that no larger factor
// slides beyond it. A fuzzy study (fuzzy_contact_model.h) therefore solves
// a failed point again with its friction coefficients times the factors
// sliding_probe_factors(), and the first answer upwards is the verdict:
//  - beyond small sliding: the point slides (it counts as without static
//    equilibrium);
//  - within it: the point's failure lies below the friction that holds the
//    bodies within small sliding (it is left out, with a warning);
//  - none: the failure is the solver's (the study first probes again with
//    a more thorough solver).
//
// A probe that fails costs what the probe solver's iteration limits allow
// (30 ms each in a pin study, scene pin.prm), an answer far less (0.1-4
// ms), so probe_sliding() does not probe upwards: just above the point
// first (most points answer there, within), then at twice its friction,
// where the points that slide beyond mostly answer so (an answer beyond
// settles the verdict, since below it every answer slides beyond too; made
// upwards, 8-10 failed probes came first), then the others upwards, until
// the probes made so far fix the first answer upwards. The verdict is the
// same as probing upwards wherever the answers are monotone in the
// friction.

#ifndef fuzzycontact_study_sliding_probes_h
#define fuzzycontact_study_sliding_probes_h

#include <functional>
#include <vector>

namespace FuzzyContact
{
  /**
   * The friction factors of the probes, increasing: 1 + 2^-k for k =
   * n_fine - 1, ..., 0 (just above the point up to twice its friction),
   * then 4 and @p largest.
   */
  std::vector<double>
  sliding_probe_factors(const unsigned int n_fine  = 11,
                        const double       largest = 8);

  /** The verdict of the probes, and what it took. */
  struct SlidingVerdict
  {
    enum Kind
    {
      none,
      beyond,
      within_with_more
    } kind = none;
    /** within_with_more: the least factor that answered within small
     * sliding. */
    double factor = 1;
    /** Probes made, and of them those that failed. */
    unsigned int probes = 0, failed = 0;
  };

  /**
   * The first answer upwards over @p factors (increasing, with 2 among
   * them) of @p answer (factor -> -1: the answer slid beyond small
   * sliding, 1: within it, 0: the solve failed), the probes made in the
   * order above.
   */
  SlidingVerdict
  probe_sliding(const std::vector<double>        &factors,
                const std::function<int(double)> &answer);
} // namespace FuzzyContact

#endif
