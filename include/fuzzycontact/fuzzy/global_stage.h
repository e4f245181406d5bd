// The global stage and the refinement of the optimisation method
// (optimisation_method.h), for responses with kinks and interior optima:
//
//  - a space-filling design over each alpha-box: a scrambled Sobol
//    sequence (Joe and Kuo's direction numbers, from Boost.Random, with
//    Matousek's random linear scrambling and a random digital shift, fixed
//    seed: the same design in normalised coordinates at every level, on
//    every platform and MPI rank), beside the box's vertices and the best
//    points of the level above (which lie in this level's box: the
//    alpha-cuts stay nested);
//  - the starts of the local searches: the best points of distinct basins
//    of the design, by nearest-better clustering (Preuss 2010: every point
//    is joined to its nearest better point, the joins much longer than the
//    average are cut, and each tree's root is the best point of a basin)
//    confirmed by a hill-valley test (Ursem 1999: a point on the segment
//    between two roots that is worse than both separates their basins);
//  - a pattern search (compass search over the coordinates and, for up to
//    four free parameters, their pairwise diagonals, plus an orthogonal
//    basis turned at every poll as in OrthoMADS, Abramson et al. 2009, so
//    that the polled directions become dense and a ridge of kinks is
//    followed) that refines a bound where the local optimum has interior
//    coordinates: it needs no gradient, so a kink does not stop it; it
//    halves its step down to the refinement step and on until three
//    halvings in a row improve nothing (converged) or a limit is met;
//  - the shape of the optimum: which parameters lie inside their interval,
//    in which of them the response has a kink, and the projected gradient.
//
// Points where the response has no solution (no outputs: a contact problem
// without static equilibrium) are worse than every point that has one:
// the design leaves them out (and counts them), the searches never move
// there, and the bounds are those over the part of the box with a
// solution.
//
// Everything works on the scaled, signed objective of OutputObjective
// (local_optimisation.h): smaller is better.

#ifndef fuzzycontact_fuzzy_global_stage_h
#define fuzzycontact_fuzzy_global_stage_h

#include <fuzzycontact/fuzzy/interval_method.h>
#include <fuzzycontact/fuzzy/local_optimisation.h>

#include <vector>

namespace FuzzyContact
{
  namespace LocalOptimisation
  {
    /**
     * @p n_points points of a scrambled Sobol sequence in (0, 1)^@p
     * dimension: the first n_points points of the Sobol sequence (index 0
     * first) with Joe and Kuo's direction numbers (Boost.Random's
     * sobol_engine, S. Joe and F. Y. Kuo, SIAM J. Sci. Comput. 30, 2008),
     * each coordinate's 32 bits scrambled by a random lower triangular
     * binary matrix with unit diagonal and a random digital shift
     * (Matousek 1998), drawn from a Mersenne twister with @p seed. For
     * n_points = 2^m the points form a (t, m, d)-net: in every coordinate
     * each of the n strata [i/n, (i+1)/n) holds one point, and in the first
     * two coordinates every box [i/2^a, (i+1)/2^a) x [j/2^b, (j+1)/2^b) with
     * a + b = m holds one. Deterministic, the same on every platform.
     */
    std::vector<VectorType>
    scrambled_sobol(const unsigned int n_points,
                    const unsigned int dimension,
                    const unsigned int seed);

    /**
     * The design's points per alpha-box for @p n_free free parameters when
     * the key says "auto": 32 per parameter, rounded up to a power of two
     * (a Sobol net): 32, 64, 128, 128, 256, ... It grows with the number of
     * parameters and costs little next to the local searches on a reduced
     * model (doc/fuzzy-study.md measures it).
     */
    unsigned int
    default_design_points(const unsigned int n_free);

    /** A point of the global stage and its objective value. */
    struct Candidate
    {
      VectorType x;
      double     value;
      bool       vertex;
    };

    /**
     * The points the global stage evaluates in the box [@p lower, @p upper]
     * whatever its seeds: its vertices (for fewer than 20 free parameters)
     * and the @p unit_design mapped into it (none if the box is a point),
     * in this order, as global_stage() evaluates them (clipped into the
     * box). They can be evaluated ahead (EvaluationCache::prefetch()).
     */
    std::vector<VectorType>
    fixed_points(const std::vector<VectorType> &unit_design,
                 const VectorType              &lower,
                 const VectorType              &upper);

    /** The points of a global stage, best first. */
    struct GlobalStage
    {
      /** The points with a solution, best first. */
      std::vector<Candidate> candidates;
      /** Distinct points evaluated, and those without a solution. */
      unsigned long n_points = 0, n_infeasible = 0;
    };

    /**
     * The points of the global stage in the box [@p lower, @p upper]: the
     * @p unit_design mapped into it (none if the box is a point), its
     * vertices (for fewer than 20 free parameters) and the @p seeds
     * (clipped into it), each evaluated once, best first; those without a
     * solution are counted and left out.
     */
    GlobalStage
    global_stage(OutputObjective               &objective,
                 const std::vector<VectorType> &unit_design,
                 const std::vector<VectorType> &seeds,
                 const VectorType              &lower,
                 const VectorType              &upper);

    /**
     * The nearest-better clustering of @p candidates (best first) in the
     * box: every candidate but the best is joined to the nearest better one
     * (distances in units of the box's widths); joins longer than @p phi
     * times their mean are cut. Returns the roots (indices into
     * @p candidates, best first): the best point of each cluster.
     */
    std::vector<unsigned int>
    nearest_better_roots(const std::vector<Candidate> &candidates,
                         const VectorType             &lower,
                         const VectorType             &upper,
                         const double                  phi = 2.);

    /**
     * The hill-valley test: true if a point at 1/4, 1/2 or 3/4 of the
     * segment from @p a to @p b is worse than both by more than @p noise
     * (or has no solution): a hill separates their basins.
     */
    bool
    separated(OutputObjective &objective,
              const Candidate &a,
              const Candidate &b,
              const double     noise);

    /** The starts of the local searches of one bound at one level. */
    struct Starts
    {
      std::vector<Candidate> points;
      /** Roots of the nearest-better clustering (candidate basins). */
      unsigned int n_roots = 0;
      /**
       * Every root was tested (a start, or in the basin of one): the
       * starts cover every basin the design shows.
       */
      bool all_roots_tested = true;
    };

    /**
     * The starts of the local optimisation: the best candidate, then the
     * roots of the nearest-better clustering in their order, each taken if
     * the hill-valley test separates it from every start taken (a distinct
     * basin), up to @p max_starts; at most 2 @p max_starts + 2 roots are
     * tested. A design whose values differ by at most @p noise (the
     * response's accuracy) shows one basin: its best point is the only
     * start.
     */
    Starts
    basin_starts(OutputObjective              &objective,
                 const std::vector<Candidate> &candidates,
                 const VectorType             &lower,
                 const VectorType             &upper,
                 const unsigned int            max_starts,
                 const double                  noise);

    /** What a pattern search did. */
    struct PatternSearch
    {
      /** Improvement over the last three halvings of the step. */
      double last_change = 0;
      /** The final step, relative to the intervals' widths. */
      double final_step = 0;
      /**
       * True if it stopped because three halvings in a row below the
       * final step improved nothing, or below the final step a poll met
       * points without a solution (at_edge: the bound presses against the
       * edge of the part of the box with one), not at a limit.
       */
      bool converged = false;
      bool at_edge   = false;
      /** Points polled. */
      unsigned long n_polls = 0;
    };

    /**
     * Pattern search from @p x (value @p value, both updated) in the box:
     * polls x +- s w_i e_i (w_i the width of coordinate i), for up to
     * four free coordinates x +- s (w_i e_i +- w_j e_j), and x +- s W h_j
     * for the columns h_j of a Householder basis turned at every poll,
     * clipped into the box; moves to the best poll that improves by more
     * than @p noise and on along its direction, twice as far each time,
     * while that improves (MADS's speculative search), else halves s;
     * from @p initial_step until s < @p final_step and three halvings in a
     * row improved nothing or the last poll met points without a solution,
     * or s < final_step / 1024, or 10000 polls.
     */
    PatternSearch
    pattern_search(OutputObjective  &objective,
                   VectorType       &x,
                   double           &value,
                   const VectorType &lower,
                   const VectorType &upper,
                   const double      initial_step,
                   const double      final_step,
                   const double      noise);

    /**
     * Fills @p quality's interior parameters (of @p normalisation, strictly
     * inside their interval by more than @p interior_tolerance of its
     * width), kinks and projected gradient, for the optimum @p x (value
     * @p value, finite-difference gradient @p gradient) of @p objective;
     * @p range is the objective's range over the box (from the global
     * stage), @p noise its accuracy.
     */
    void
    shape_of_optimum(OutputObjective     &objective,
                     const Normalisation &normalisation,
                     const VectorType    &x,
                     const double         value,
                     const VectorType    &gradient,
                     const VectorType    &lower,
                     const VectorType    &upper,
                     const double         interior_tolerance,
                     const double         range,
                     const double         noise,
                     BoundQuality        &quality);
  } // namespace LocalOptimisation
} // namespace FuzzyContact

#endif
