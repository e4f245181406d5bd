// The chains of the optimisation method (optimisation_method.h): chain 2k
// bounds output k from below, chain 2k + 1 from above, at every level from
// the core down, each level started at the best points of the level above:
// the global stage (global_stage.h), local optimisations from the best
// points of distinct basins (local_optimisation.h), the pattern search
// where the optimum has interior coordinates or a projected gradient, and
// the checks for a non-monotone response, and the lines scanned through
// the bound along the parameters with kinks.

#ifndef fuzzycontact_fuzzy_optimisation_chain_h
#define fuzzycontact_fuzzy_optimisation_chain_h

#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/fuzzy/fuzzy_number.h>
#include <fuzzycontact/fuzzy/global_stage.h>
#include <fuzzycontact/fuzzy/interval_method.h>
#include <fuzzycontact/fuzzy/local_optimisation.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>

#include <cmath>
#include <string>
#include <vector>

namespace FuzzyContact
{
  namespace LocalOptimisation
  {
    // The result of one chain: one output, one direction, all levels.
    struct ChainResult
    {
      std::vector<double>              value;    // per level, unscaled
      std::vector<std::vector<double>> argument; // per level, all parameters
      std::vector<BoundQuality>        quality;  // per level
      std::vector<std::string>         notes;
    };

    // One chain: the lower (or upper) bound of one output at every level,
    // from the core down, each level started at the optimum of the level
    // above, with the checks for a non-monotone response.
    class Chain
    {
    public:
      Chain(EvaluationCache                &cache,
            const Normalisation            &normalisation,
            const std::vector<FuzzyNumber> &parameters,
            const OptimisationSettings     &settings,
            const unsigned int              output,
            const bool                      upper,
            const double                    nominal,
            const std::string              &output_name)
          : cache(cache)
          , normalisation(normalisation)
          , parameters(parameters)
          , settings(settings)
          , output(output)
          , sign(upper ? -1. : 1.)
          , scale(std::abs(nominal) > 0 ? std::abs(nominal) : 1.)
          , what(output_name + (upper ? " (upper bound)" : " (lower bound)"))
      {
      }

      // The levels in @p order (from the core down), starting at @p centre,
      // with the global stage's @p design (in the unit box); once more if a
      // kink met at some level went unscanned at the levels above it.
      ChainResult
      run(const std::vector<double>       &alpha,
          const std::vector<unsigned int> &order,
          const VectorType                &centre,
          const std::vector<VectorType>   &design,
          Progress                        *progress) const;

    private:
      // One level's search: the objective on the level's box [lo, hi], the
      // range of the global stage's values there, and the level's name
      // for the notes.
      struct Level
      {
        OutputObjective   &objective;
        const VectorType  &lo, &hi;
        const double       range;
        const std::string &name;
      };

      // The levels in @p order; @p rough: the free parameters in which a
      // kink or an interior optimum was met (lines through the bound are
      // scanned along them), at the start and as the levels find more.
      ChainResult
      levels(const std::vector<double>       &alpha,
             const std::vector<unsigned int> &order,
             const VectorType                &centre,
             const std::vector<VectorType>   &design,
             Progress                        *progress,
             std::vector<bool>               &rough) const;
      bool
      unscanned(const std::vector<double>       &alpha,
                const std::vector<unsigned int> &order,
                const std::vector<bool>         &rough,
                const ChainResult               &result) const;
      std::vector<LocalOptimum>
      local_stage(const Level &level, const Starts &starts) const;
      void
      compare_basins(const Level                     &level,
                     const std::vector<LocalOptimum> &optima,
                     const unsigned int               winner,
                     LocalOptimum                    &best,
                     BoundQuality                    &quality,
                     ChainResult                     &result) const;
      bool
      check_interval_ends(const Level              &level,
                          LocalOptimum             &best,
                          std::vector<std::string> &findings) const;
      void
      refine(const Level  &level,
             LocalOptimum &best,
             BoundQuality &quality) const;
      void
      scan_lines(const Level       &level,
                 LocalOptimum      &best,
                 BoundQuality      &quality,
                 std::vector<bool> &rough,
                 ChainResult       &result) const;
      std::string
      iteration_limit_note(const std::string  &level,
                           const BoundQuality &quality) const;
      std::string
      multi_start(const Level &level, LocalOptimum &best) const;
      std::string
      non_monotone(const Level                    &level,
                   LocalOptimum                   &best,
                   const std::vector<std::string> &findings,
                   const bool                      missed,
                   const unsigned int              n_starts,
                   const unsigned int              n_design) const;
      void
      check_sensitivity_signs(const std::vector<VectorType> &gradients,
                              ChainResult                   &result) const;

      EvaluationCache                &cache;
      const Normalisation            &normalisation;
      const std::vector<FuzzyNumber> &parameters;
      const OptimisationSettings     &settings;
      const unsigned int              output;
      const double                    sign;
      const double                    scale;
      const std::string               what;
    };
  } // namespace LocalOptimisation
} // namespace FuzzyContact

#endif
