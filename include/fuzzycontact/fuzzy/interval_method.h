// Interval methods: the interval bounds of a model's outputs over the
// alpha-cuts of its fuzzy parameters, the core of a fuzzy propagation.
//
// At every alpha level the fuzzy parameters span a box (the product of their
// alpha-cuts), and each output's alpha-cut is [min S, max S] over that box.
// An IntervalMethod finds these intervals for all outputs and levels at
// once. Three are provided, one file each, with their own cost and risk:
//
//  - OptimisationMethod (optimisation_method.h): per output, a
//    bound-constrained local minimisation and maximisation (Trilinos ROL,
//    projected spectral gradient by default) started at the optimum of the
//    level above, with checks for non-monotone responses and a multi-start
//    fallback: the paper's method, cheap when the response is smooth;
//  - VertexMethod (vertex_method.h): the 2^n corners of each box, exact for
//    responses that are monotone in each parameter, wrong otherwise;
//  - ExtensionPrinciple (extension_principle.h): the reference, a tensor
//    grid of every box (corners included), nested over the levels.
//
// Methods spread their work over the ranks of an MPI communicator and give
// every rank the same bounds, which do not depend on the number of ranks
// provided the response is a pure function of its parameters (no state
// carried between evaluations).
//
// A response may have no solution at some points (a contact problem whose
// loads no friction forces can hold: no static equilibrium): it then
// returns no outputs (an empty vector). Every method leaves such points out
// and bounds the outputs over the part of each box where the response has
// a solution; FuzzyOutputBounds counts, per level, the points it evaluated
// in the box and those without a solution, and a level where it found none
// has no bounds (NaN, and no arguments).
//
// To add an interval method: derive from IntervalMethod and implement name()
// and bounds() in a header and source file of their own in fuzzy/; a method
// that evaluates a set of points fixed in advance derives from
// SamplingMethod (sampling_method.h) and gives only its points.

#ifndef fuzzycontact_fuzzy_interval_method_h
#define fuzzycontact_fuzzy_interval_method_h

#include <fuzzycontact/fuzzy/fuzzy_number.h>

#include <deal.II/base/mpi.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /**
   * A model: values of the parameters in, values of the outputs out; no
   * outputs (an empty vector) where it has no solution (see above).
   */
  using Response =
    std::function<std::vector<double>(const std::vector<double> &)>;

  /** Whether @p outputs of a Response are a solution (not empty). */
  inline bool
  has_solution(const std::vector<double> &outputs)
  {
    return !outputs.empty();
  }

  /**
   * Remembers every evaluation of a response (keyed by the exact parameter
   * values), so that the corners and optima that several outputs and levels
   * share are computed once, and counts the evaluations really made.
   *
   * Shared over the ranks of a communicator (with several ranks), it holds
   * the same values on every rank, and every distinct point is evaluated
   * once over all of them: every rank must then ask for the same points in
   * the same order (run the same deterministic algorithm), since each
   * evaluation is made by one rank and sent to the others. A point asked
   * for alone is evaluated by the ranks in turn (the others wait); the
   * points of prefetch() are spread over the ranks. A failed evaluation
   * throws its message on every rank.
   */
  class EvaluationCache
  {
  public:
    explicit EvaluationCache(const Response &response,
                             const MPI_Comm  comm = MPI_COMM_SELF);

    /** The response at @p parameters (collective when shared). */
    const std::vector<double> &
    operator()(const std::vector<double> &parameters);

    /**
     * Evaluates those of @p points that are not known yet, each once, dealt
     * round robin to the ranks (collective when shared).
     */
    void
    prefetch(const std::vector<std::vector<double>> &points);

    /** Distinct points known (the same on every rank when shared). */
    unsigned long
    n_evaluations() const;

    /**
     * Evaluations of the response made on this rank (n_evaluations() with
     * one rank; their sum over the ranks of a shared cache is
     * n_evaluations()).
     */
    unsigned long
    n_evaluated_here() const;

  private:
    Response                                           response;
    MPI_Comm                                           comm;
    unsigned int                                       n_ranks = 1, rank = 0;
    unsigned long                                      n_alone = 0;
    unsigned long                                      n_here  = 0;
    std::map<std::vector<double>, std::vector<double>> values;
  };

  /** The alpha-cut box: one interval per parameter. */
  std::vector<Interval>
  alpha_box(const std::vector<FuzzyNumber> &parameters, const double alpha);

  /**
   * How one bound (one output, level and side) of the optimisation method
   * was found and how converged it is (optimisation_method.h).
   */
  struct BoundQuality
  {
    /** "vertex", "boundary" (some coordinates inside) or "interior". */
    std::string where = "vertex";
    /** Parameters (indices among all) strictly inside their interval. */
    std::vector<unsigned int> interior;
    /**
     * Interior parameters in which the response has a kink at the bound:
     * its one-sided slopes differ by more than a hundredth of the output's
     * range over the box per interval width.
     */
    std::vector<unsigned int> kinks;
    /**
     * Norm of the projected finite-difference gradient at the bound, per
     * unit of the normalised parameters, relative to the output's range
     * over the box (zero: first-order optimal).
     */
    double projected_gradient = 0;
    /**
     * True if the pattern search refined the bound; then the change of the
     * bound over its last three halvings of the step (relative to the
     * output's range over the box) and its final step (relative to the
     * intervals' widths).
     */
    bool   refined     = false;
    double last_change = 0;
    double final_step  = 0;
    /** ROL stopped at its iteration limit from the start that won. */
    bool iteration_limit = false;
    /**
     * Interior parameters along which a neighbour of the bound has no
     * solution: the bound lies at the edge of the part of the box where
     * the response has one.
     */
    std::vector<unsigned int> edge;

    /** What was searched: points of the global stage (vertices, design,
     * the optima of the level above) with a solution, roots of their
     * nearest-better clustering, local searches started from distinct
     * basins, and how many of these reached the bound (to the agreement
     * tolerance: the larger of 10 response tolerances and 1e-6 of the
     * range). */
    unsigned long n_design = 0;
    unsigned int  n_roots  = 0;
    unsigned int  n_starts = 0;
    unsigned int  n_agree  = 0;
    /**
     * How far the best local optimum of another basin that did not reach
     * the bound lies from it, relative to the range (0 if all agreed).
     */
    double other_optimum = 0;
    /**
     * Every basin the design showed was searched (each root of its
     * clustering a start, or in the basin of one).
     */
    bool basins_searched = true;
    /** A point of the global stage was better than every local search. */
    bool design_better = false;
    /** The pattern search stopped converged (not at a limit). */
    bool search_converged = false;
    /**
     * Parameters (indices among all) along which lines through the bound
     * were scanned (OptimisationSettings::line_scan_points), and how much
     * better than the local searches' optimum the scans found the bound,
     * relative to the output's range over the box (0: no better point).
     */
    std::vector<unsigned int> scanned;
    double                    scan_gain = 0;
    /**
     * The bound is called converged only with evidence: first-order
     * optimal at a vertex (projected gradient 0), or refined by a pattern
     * search that stopped converged; no point of the global stage better
     * than the local searches; and, where the design showed several
     * basins, the searches from at least two of them reached the bound or
     * every basin it showed was searched (the bound is the best of their
     * optima).
     */
    bool converged = false;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &where &interior &kinks &projected_gradient &refined &last_change
        &final_step &iteration_limit &edge &n_design &n_roots &n_starts &n_agree
          &other_optimum &basins_searched &design_better &search_converged
            &scanned &scan_gain &converged;
    }
  };

  /**
   * Interval bounds of every output at every level, and where they are
   * attained.
   */
  struct FuzzyOutputBounds
  {
    std::vector<double> alpha;
    /** bounds[output][level] */
    std::vector<std::vector<Interval>> bounds;
    /** Parameters at which the lower and upper bounds are attained. */
    std::vector<std::vector<std::vector<double>>> argmin, argmax;
    /** Evaluations of the response, over all ranks. */
    unsigned long n_evaluations = 0;
    /** Wall time [s] (the longest over all ranks). */
    double wall_time = 0;
    /**
     * Wall time [s] spent inside the response, summed over the ranks that
     * evaluated it (bounds_on_ranks() measures it; 0 elsewhere): the
     * evaluations' own cost, without the method's work between them.
     */
    double evaluation_time = 0;
    /** What was detected (non-monotone responses) and done about it. */
    std::vector<std::string> notes;
    /**
     * How each bound was found: [output][level], lower and upper (the
     * optimisation method only; empty for the sampling methods).
     */
    std::vector<std::vector<BoundQuality>> lower_quality, upper_quality;
    /**
     * Per level: the distinct points the method evaluated in the level's
     * box (for the optimisation, those of its global stage) and how many
     * of them had no solution (left out of the bounds).
     */
    std::vector<unsigned long> n_points, n_infeasible;
    /**
     * The optimisation's design: points per alpha-box, and whether the
     * global time limit cut it (then the number depends on the machine).
     */
    unsigned int design_points = 0, design_wanted = 0;
    bool         design_cut = false;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &alpha &bounds &argmin &argmax &n_evaluations &wall_time
        &evaluation_time &notes &lower_quality &upper_quality &n_points
          &n_infeasible &design_points &design_wanted &design_cut;
    }
  };

  /**
   * Largest relative difference between two sets of bounds over all levels
   * and both ends, for one output: max |b - r| / max(|r|, floor), over the
   * bounds that both have (not NaN: a level without a point with a
   * solution).
   */
  double
  max_relative_difference(const std::vector<Interval> &bounds,
                          const std::vector<Interval> &reference,
                          const double                 floor = 0);

  class IntervalMethod;

  /**
   * @p method's bounds of @p response, computed on @p solving (a
   * communicator of those ranks of @p comm that can evaluate @p response,
   * for instance FuzzyContactModel::reduced_communicator(); MPI_COMM_NULL
   * on the others) and sent to every rank of @p comm. With
   * @p solving = @p comm, method.bounds() on @p comm. Collective on
   * @p comm. Also measures FuzzyOutputBounds::evaluation_time.
   */
  FuzzyOutputBounds
  bounds_on_ranks(const IntervalMethod           &method,
                  const std::vector<FuzzyNumber> &parameters,
                  const std::vector<double>      &alpha,
                  const Response                 &response,
                  const std::vector<std::string> &output_names,
                  const MPI_Comm                  comm,
                  const MPI_Comm                  solving);

  /** The interface of the interval methods (see the top of this file). */
  class IntervalMethod
  {
  public:
    virtual ~IntervalMethod() = default;

    /** The name of the method in reports. */
    virtual std::string
    name() const = 0;

    /**
     * The bounds of the outputs of @p response (one per entry of
     * @p output_names, which also label the notes) at the levels @p alpha
     * of the fuzzy @p parameters, computed on the ranks of @p comm and
     * returned on every rank.
     */
    virtual FuzzyOutputBounds
    bounds(const std::vector<FuzzyNumber> &parameters,
           const std::vector<double>      &alpha,
           const Response                 &response,
           const std::vector<std::string> &output_names,
           const MPI_Comm                  comm) const = 0;
  };
} // namespace FuzzyContact

#endif
