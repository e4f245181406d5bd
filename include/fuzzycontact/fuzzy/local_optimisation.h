// The local problems of the optimisation method (optimisation_method.h):
// the lower or upper bound of one output over one level's box, as a
// bound-constrained minimisation in parameters normalised by their
// supports, solved by Trilinos ROL (projected spectral gradient by default,
// or projected quasi-Newton line search; see OptimisationSettings).
//
// ROL's headers are heavy: only local_optimisation.cc includes them.

#ifndef fuzzycontact_fuzzy_local_optimisation_h
#define fuzzycontact_fuzzy_local_optimisation_h

#include <fuzzycontact/fuzzy/fuzzy_number.h>
#include <fuzzycontact/fuzzy/interval_method.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>

#include <deal.II/lac/vector.h>

#include <utility>
#include <vector>

namespace FuzzyContact
{
  namespace LocalOptimisation
  {
    using VectorType = dealii::Vector<double>;

    /**
     * The uncertain parameters (those with a support of non-zero width) in
     * coordinates normalised by their support: x = (p - a) / (b - a).
     */
    class Normalisation
    {
    public:
      explicit Normalisation(const std::vector<FuzzyNumber> &parameters);

      unsigned int
      n_free() const;

      /**
       * All parameters at @p x (the others at the midpoint of their core).
       * The ends of a support are returned exactly, so that vertices
       * coincide with those of the vertex method and of the cache.
       */
      std::vector<double>
      parameters(const VectorType &x) const;

      /** Normalised coordinate of value @p p of free parameter @p i. */
      double
      coordinate(const unsigned int i, const double p) const;

      /** The box of a level in normalised coordinates. */
      std::pair<VectorType, VectorType>
      box(const std::vector<FuzzyNumber> &parameters, const double alpha) const;

      /** Indices of the free parameters among all. */
      std::vector<unsigned int> free;
      std::vector<Interval>     supports;
      std::vector<double>       fixed;
    };

    /**
     * sign * S_k(p(x)) / scale on the box [lower, upper], with central
     * finite-difference gradients (one-sided where a central step would
     * leave the box).
     */
    class OutputObjective
    {
    public:
      OutputObjective(EvaluationCache     &cache,
                      const Normalisation &normalisation,
                      const unsigned int   output,
                      const double         sign,
                      const double         scale,
                      const double         step,
                      const VectorType    &lower,
                      const VectorType    &upper);

      double
      at(const VectorType &x);

      /**
       * Evaluates the points @p xs ahead, together (spread over the ranks
       * of a shared cache, EvaluationCache::prefetch()).
       */
      void
      prefetch(const std::vector<VectorType> &xs);

      /** The finite-difference gradient (its points prefetched together). */
      void
      gradient_at(VectorType &grad, const VectorType &x0);

    private:
      EvaluationCache     &cache;
      const Normalisation &normalisation;
      const unsigned int   output;
      const double         sign;
      const double         scale;
      const double         step;
      const VectorType    &lower;
      const VectorType    &upper;
    };

    /** The result of one local minimisation. */
    struct LocalOptimum
    {
      VectorType x;
      /** Of the scaled, signed objective. */
      double     value;
      VectorType gradient;
      int        iterations;
      /** ROL's exit: false if it stopped at its iteration limit. */
      bool converged = true;
    };

    /**
     * Minimises @p objective on the box [@p lower, @p upper] by ROL with
     * @p settings from @p start (clipped into the box), and gives the
     * value and gradient at the optimum.
     */
    LocalOptimum
    minimise(OutputObjective            &objective,
             const VectorType           &start,
             const VectorType           &lower,
             const VectorType           &upper,
             const OptimisationSettings &settings);
  } // namespace LocalOptimisation
} // namespace FuzzyContact

#endif
