// The global stage and the refinement of the optimisation method
// (optimisation_method.h), for responses with kinks and interior optima:
//
//  - a space-filling design (a Latin hypercube with a fixed seed, the same
//    in normalised coordinates for every level) over each alpha-box, beside
//    the box's vertices and the best points of the level above (which lie
//    in this level's box: the alpha-cuts stay nested); the best of them
//    start the local optimisation;
//  - a pattern search (compass search over the coordinates and, for up to
//    four free parameters, their pairwise diagonals, the step halved until
//    it falls below a tolerance) that refines a bound where the local
//    optimum has interior coordinates: it needs no gradient, so a kink
//    does not stop it;
//  - the shape of the optimum: which parameters lie inside their interval,
//    in which of them the response has a kink, and the projected gradient.
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
     * @p n_points points of a Latin hypercube in [0, 1]^@p dimension: in
     * every coordinate each of the n strata [i/n, (i+1)/n) holds one point.
     * Deterministic for a @p seed (its own Mersenne twister and shuffle, so
     * the design does not depend on the standard library).
     */
    std::vector<VectorType>
    latin_hypercube(const unsigned int n_points,
                    const unsigned int dimension,
                    const unsigned int seed);

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

    /**
     * The points of the global stage in the box [@p lower, @p upper]: the
     * @p unit_design mapped into it (none if the box is a point), its
     * vertices (for fewer than 20 free parameters) and the @p seeds
     * (clipped into it), each evaluated once, best first.
     */
    std::vector<Candidate>
    global_stage(OutputObjective               &objective,
                 const std::vector<VectorType> &unit_design,
                 const std::vector<VectorType> &seeds,
                 const VectorType              &lower,
                 const VectorType              &upper);

    /**
     * The starts of the local optimisation: the best candidate and, if it
     * is not a vertex (the response is then not monotone over the box),
     * up to @p max_starts - 1 further candidates, each further than a
     * quarter of the box (in every coordinate's width, max-norm) from the
     * starts already chosen.
     */
    std::vector<VectorType>
    local_starts(const std::vector<Candidate> &candidates,
                 const VectorType             &lower,
                 const VectorType             &upper,
                 const unsigned int            max_starts);

    /** What a pattern search did. */
    struct PatternSearch
    {
      /** Improvement over the last three halvings of the step. */
      double last_change = 0;
      /** The final step, relative to the intervals' widths. */
      double final_step = 0;
    };

    /**
     * Pattern search from @p x (value @p value, both updated) in the box:
     * polls x +- s w_i e_i (w_i the width of coordinate i) and, for up to
     * four free coordinates, x +- s (w_i e_i +- w_j e_j), clipped into the
     * box; moves to the best poll that improves by more than @p noise,
     * else halves s; from @p initial_step until s < @p final_step.
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
