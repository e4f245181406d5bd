// The Extension Principle by sampling, the reference of the interval
// methods: every level's box is sampled on a tensor grid of
// points_per_dimension equally spaced values per parameter (both ends
// included, so the vertices are samples; one value for a parameter whose
// alpha-cut is a point). The bounds of a level are taken over every sample
// inside its box, its own and those of the levels above it, so the results
// are nested. The intervals lie inside the exact ones and close in on them
// as the grid is refined; the cost is about n_levels r^n evaluations.
//
// It is one of the interval methods of interval_method.h (see there for
// the others and for where to add one); the evaluation over MPI ranks is
// SamplingMethod's (sampling_method.h).

#ifndef fuzzycontact_fuzzy_extension_principle_h
#define fuzzycontact_fuzzy_extension_principle_h

#include <fuzzycontact/fuzzy/sampling_method.h>

#include <deal.II/base/parameter_handler.h>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * The keys of subsection "Extension principle" of a fuzzy study: the grid
   * of every box, and whether the exact model that evaluates it keeps its
   * factorisations where that is exact (false: every sample is an
   * independent analysis).
   */
  struct ExtensionPrincipleSettings
  {
    unsigned int points_per_dimension = 4;
    bool         reuse_factorisations = true;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Throws, naming the keys, if @p n_alpha levels of @p n_parameters
     * fuzzy parameters would need more than 1e5 exact solves.
     */
    void
    check_size(const unsigned int n_alpha,
               const unsigned int n_parameters) const;
  };


  class ExtensionPrinciple : public SamplingMethod
  {
  public:
    /**
     * Samples every box on a grid of @p points_per_dimension values per
     * parameter; throws unless it is at least 2 (the ends of every
     * interval).
     */
    explicit ExtensionPrinciple(const unsigned int points_per_dimension);

    /** "Extension Principle". */
    std::string
    name() const override;

    unsigned int
    points_per_dimension() const;

  protected:
    /** The grid of every level's box. */
    std::vector<std::vector<double>>
    points(const std::vector<FuzzyNumber> &parameters,
           const std::vector<double>      &alpha) const override;

  private:
    unsigned int points_per_dimension_;
  };

  /** Number of samples ExtensionPrinciple(points_per_dimension) evaluates. */
  unsigned long
  extension_principle_size(const std::vector<FuzzyNumber> &parameters,
                           const std::vector<double>      &alpha,
                           const unsigned int points_per_dimension);
} // namespace FuzzyContact

#endif
