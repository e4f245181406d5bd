// The optimisation method, the paper's interval method: the bounds of each
// output at each level as the results of bound-constrained local
// optimisation over the level's box.
//
// For every output there are two chains, one for the lower bound
// (minimisation) and one for the upper (maximisation). A chain goes through
// the levels from the core (alpha = 1) down to the support (alpha = 0),
// each level started at the optimum of the level above. The local
// optimiser is Trilinos ROL's projected spectral gradient method
// (Barzilai-Borwein steps) by default, or its projected quasi-Newton
// (L-BFGS) line search, on the parameters normalised by their supports and
// the output scaled by its nominal value, with finite-difference
// sensitivities (central, one-sided at the ends of the box). Evaluations
// are cached, so the points several chains share are computed once.
//
// Before the local optimisation, a global stage evaluates a space-filling
// design over the level's box, its vertices and the optima of the level
// above (global_stage.h); the local optimisation starts from the best of
// them (from several when the best is not a vertex), so a lower level's
// interval contains the upper's. A bound with coordinates inside their
// intervals is refined by a pattern search, which a kink does not stop,
// and every bound is classified (vertex, boundary or interior, the
// parameters with a kink) with a measure of its convergence (the projected
// gradient, the change over the pattern search's last refinements).
//
// Cheap when the response is smooth and monotone; a non-monotone response
// is detected and answered at every level:
//  - an optimum inside a parameter's interval is compared with the two
//    ends of the interval (the other coordinates kept): an interior
//    optimum, or an interior stationary point that is no optimum, is
//    reported; an end that is better (or as good) is taken;
//  - the vertices of the box and the design points are compared with the
//    optimum;
//  - on either finding, a multi-start from every vertex and the centre of
//    the box keeps the best local optimum (unless the fallback is off);
//  - a sensitivity that changes sign between the levels' optima is
//    reported.
// Differences below the response tolerance (the model's accuracy) are no
// evidence of non-monotonicity.
//
// With several MPI ranks, every rank runs every chain (one per output and
// direction) on one evaluation cache shared by the ranks (interval_method.h):
// the points every chain needs (the vertices and the design of every
// level's box) are evaluated first, spread over the ranks, and so are the
// points of each finite-difference gradient and each poll of the pattern
// search; every other point is evaluated by one rank and sent to all. Each
// distinct point is thus evaluated once, as with one process, and the
// bounds are those of one process for a response that is a pure function
// of its parameters.
//
// It is one of the interval methods of interval_method.h (see there for
// the others and for where to add one).

#ifndef fuzzycontact_fuzzy_optimisation_method_h
#define fuzzycontact_fuzzy_optimisation_method_h

#include <fuzzycontact/fuzzy/interval_method.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * The settings of OptimisationMethod. The values here are the defaults of
   * the parameter file too (subsection Optimisation).
   */
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
     * Relative accuracy of the response (e.g. set by the tolerance of an
     * iterative solver inside it; the default suits the reduced contact
     * model of prm/step-4.prm, whose FL2C tolerance bounds the accuracy of
     * its outputs): differences below it between an optimum and a vertex,
     * or between an optimum and the ends of an interval, are not taken as
     * evidence of a non-monotone response. The finite-difference step must
     * be well above it. For a response exact to round-off (a closed form),
     * set it near 1e-12.
     */
    double response_tolerance = 1e-7;
    /** Multi-start on detected non-monotonicity. */
    bool fallback = true;
    /**
     * Points of the space-filling design (a scrambled Sobol sequence with
     * a fixed seed, global_stage.h) evaluated over each level's box before
     * the local optimisation: with global_points_auto (the key's "auto",
     * the default) 32 per free parameter rounded up to a power of two
     * (default_design_points()), else global_points (0: vertices and the
     * level above's optima only).
     */
    bool         global_points_auto = true;
    unsigned int global_points      = 0;
    /**
     * Seconds the design may take over all levels (0: no limit): where the
     * vertices' evaluations say it would take longer, it is cut to the
     * largest power of two of points per box that fits (the report says
     * so: the number then depends on the machine's speed).
     */
    double global_time_limit = 60;
    /**
     * Local optimisations per bound and level at most: from the best point
     * of the global stage and from the best points of other basins of the
     * design (nearest-better clustering confirmed by a hill-valley test,
     * global_stage.h), so that a bound is called converged only where the
     * searches from distinct basins agree.
     */
    unsigned int local_starts = 3;
    /**
     * The pattern search that refines a bound with interior coordinates
     * stops when its step falls below this fraction of the intervals'
     * widths.
     */
    double refinement_step = 1e-6;
    /**
     * Values of a parameter on each line scanned through a bound (evenly
     * spaced over the box, ends included; 0 or 1: no scans). A chain scans
     * along the parameters in which it has met a kink or an interior
     * optimum, at this level or one above: a kinked response (a largest
     * nodal value whose node changes, a stick-slip transition) has local
     * optima where the gradient and pattern searches stop, and a line
     * through the bound finds the better ones a box-filling design of a
     * few points per parameter misses.
     */
    unsigned int line_scan_points = 33;

    /** Declares the subsection Optimisation, with the values above. */
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  class OptimisationMethod : public IntervalMethod
  {
  public:
    explicit OptimisationMethod(const OptimisationSettings &settings = {});

    /** "optimisation". */
    std::string
    name() const override;

    /**
     * Bound-constrained optimisation per output, bound and level, from
     * alpha = 1 down to 0, each level started at the optimum of the one
     * above (see the top of this file).
     */
    FuzzyOutputBounds
    bounds(const std::vector<FuzzyNumber> &parameters,
           const std::vector<double>      &alpha,
           const Response                 &response,
           const std::vector<std::string> &output_names,
           const MPI_Comm                  comm) const override;

    const OptimisationSettings &
    settings() const;

  private:
    OptimisationSettings settings_;
  };
} // namespace FuzzyContact

#endif
