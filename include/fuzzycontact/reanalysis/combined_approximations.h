// Kirsch's Combined Approximations: the basis r_1 = K0^{-1} M(t) phi0,
// r_{i+1} = -K0^{-1} Delta K r_i (terms of the binomial series of
// K(t)^{-1}) for every mode, then Rayleigh-Ritz.

#ifndef fuzzycontact_reanalysis_combined_approximations_h
#define fuzzycontact_reanalysis_combined_approximations_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <deal.II/lac/sparse_direct.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * Kirsch's Combined Approximations. At order n the basis holds n + 1
   * terms r_1..r_{n+1} per mode (as many vectors as HPTP of order n); each
   * term is truncated relative to its own norm (the terms of the series
   * shrink geometrically).
   */
  class CombinedApproximations : public ReanalysisMethod
  {
  public:
    CombinedApproximations(const ParameterModel &model,
                           const ModalBasis     &nominal,
                           const double          truncation_tolerance);

    std::string
    name() const override;
    bool
    has_order() const override;
    ReanalysisResult
    reanalyse(const std::vector<double> &t,
              const unsigned int         order) const override;

  private:
    const ParameterModel &model;
    const ModalBasis     &nominal;
    double                truncation_tolerance;
    SparseDirectUMFPACK   K0_inverse;
  };
} // namespace FuzzyContact

#endif
