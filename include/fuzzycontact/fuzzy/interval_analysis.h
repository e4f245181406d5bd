// Interval bounds of a model's outputs over the alpha-cuts of its fuzzy
// parameters: the core of a fuzzy propagation.
//
// At every alpha level the fuzzy parameters span a box (the product of their
// alpha-cuts), and each output's alpha-cut is [min S, max S] over that box.
// Three ways to find it are provided, each with its own cost and risk:
//
//  - optimisation_method(): for every output, a bound-constrained local
//    minimisation and maximisation (Trilinos ROL, projected quasi-Newton
//    line search) with finite-difference sensitivities, started at the
//    optimum of the previous (higher) alpha level: the paper's method. Cheap
//    when the response is smooth. Non-monotone responses (an optimum inside
//    the box, a sensitivity that changes sign, a vertex better than the
//    local optimum) are detected and answered by a multi-start from every
//    vertex of the box and its centre.
//  - vertex_method(): the 2^n corners of each box. Exact for responses that
//    are monotone in each parameter, wrong otherwise.
//  - extension_principle(): the reference. Every box is sampled on a
//    tensor grid (its corners included), and each level takes the extremes
//    over all samples inside its box, so the results are nested.
//
// The vertex and Extension Principle samples are spread over the ranks of an
// MPI communicator; the optimisation chains (one per output and direction)
// are too. Results are gathered on every rank and do not depend on the
// number of ranks, provided the response is a pure function of its
// parameters (no state carried between evaluations).

#ifndef fuzzycontact_fuzzy_interval_analysis_h
#define fuzzycontact_fuzzy_interval_analysis_h

#include <fuzzycontact/fuzzy/fuzzy_number.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /** A model: values of the parameters in, values of the outputs out. */
  using Response =
    std::function<std::vector<double>(const std::vector<double> &)>;

  /**
   * Remembers every evaluation of a response (keyed by the exact parameter
   * values), so that the corners and optima that several outputs and levels
   * share are computed once, and counts the evaluations really made.
   */
  class EvaluationCache
  {
  public:
    explicit EvaluationCache(const Response &response);

    const std::vector<double> &
    operator()(const std::vector<double> &parameters);

    /** Evaluations of the response (cache misses). */
    unsigned long
    n_evaluations() const;

  private:
    Response                                           response;
    std::map<std::vector<double>, std::vector<double>> values;
  };

  /** The alpha-cut box: one interval per parameter. */
  std::vector<Interval>
  alpha_box(const std::vector<FuzzyNumber> &parameters, const double alpha);

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
    /** What was detected (non-monotone responses) and done about it. */
    std::vector<std::string> notes;
  };

  /** 2^n corners of each box. */
  FuzzyOutputBounds
  vertex_method(const std::vector<FuzzyNumber> &parameters,
                const std::vector<double>      &alpha,
                const Response                 &response,
                const unsigned int              n_outputs,
                const MPI_Comm                  comm = MPI_COMM_SELF);

  /**
   * The Extension Principle by sampling: every level's box is sampled on a
   * grid of @p points_per_dimension equally spaced values per parameter
   * (both ends included, so the vertices are samples). The bounds of a level
   * are taken over every sample inside its box, its own and those of the
   * levels above it, so the results are nested.
   */
  FuzzyOutputBounds
  extension_principle(const std::vector<FuzzyNumber> &parameters,
                      const std::vector<double>      &alpha,
                      const Response                 &response,
                      const unsigned int              n_outputs,
                      const unsigned int              points_per_dimension,
                      const MPI_Comm                  comm = MPI_COMM_SELF);

  /** Number of samples extension_principle() would evaluate. */
  unsigned long
  extension_principle_size(const std::vector<FuzzyNumber> &parameters,
                           const std::vector<double>      &alpha,
                           const unsigned int points_per_dimension);

  struct OptimisationSettings
  {
    /**
     * ROL's algorithm for the bound-constrained problems: "spectral
     * gradient" (projected gradient with Barzilai-Borwein steps, the
     * default: the responses are nearly linear and badly scaled, and long
     * spectral steps reach the vertices in a few iterations) or
     * "quasi-newton" (projected L-BFGS line search).
     */
    std::string algorithm = "spectral gradient";
    /** ROL's tolerance on the projected gradient (scaled objective). */
    double gradient_tolerance = 1e-10;
    /** ROL's tolerance on the step (normalised parameters). */
    double step_tolerance = 1e-12;
    /** ROL iterations per bound and level. */
    unsigned int max_iterations = 50;
    /**
     * Finite-difference step for the sensitivities, relative to the width
     * of each parameter's support.
     */
    double finite_difference_step = 1e-4;
    /**
     * A coordinate of an optimum counts as interior if it lies further than
     * this (relative to its alpha-cut width) from both ends.
     */
    double interior_tolerance = 1e-6;
    /**
     * Relative accuracy of the response (e.g. the tolerance of an iterative
     * solver inside it): differences below it between an optimum and a
     * vertex, or between an optimum and the ends of an interval, are not
     * taken as evidence of a non-monotone response. The finite-difference
     * step must be well above it.
     */
    double response_tolerance = 1e-12;
    /** Multi-start on detected non-monotonicity. */
    bool fallback = true;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /**
   * Bound-constrained optimisation per output, bound and level, from alpha
   * = 1 down to 0, each level started at the optimum of the one above.
   * @p output_names label the notes.
   */
  FuzzyOutputBounds
  optimisation_method(const std::vector<FuzzyNumber> &parameters,
                      const std::vector<double>      &alpha,
                      const Response                 &response,
                      const std::vector<std::string> &output_names,
                      const OptimisationSettings     &settings,
                      const MPI_Comm                  comm = MPI_COMM_SELF);

  /**
   * Largest relative difference between two sets of bounds over all levels
   * and both ends, for one output: max |b - r| / max(|r|, floor).
   */
  double
  max_relative_difference(const std::vector<Interval> &bounds,
                          const std::vector<Interval> &reference,
                          const double                 floor = 0);
} // namespace FuzzyContact

#endif
