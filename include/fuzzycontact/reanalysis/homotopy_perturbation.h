// HPTP (Massa et al. 2011) with a basis built for each sample: the nominal
// modes and their homotopy terms phi_i = (1/i!) d^i phi / d eps^i along the
// sample's direction, i = 1..n, then Rayleigh-Ritz. The variant whose
// basis serves every sample is in parameter_independent_reanalysis.h.

#ifndef fuzzycontact_reanalysis_homotopy_perturbation_h
#define fuzzycontact_reanalysis_homotopy_perturbation_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/eigen_derivatives.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * HPTP with a basis built for each sample: nominal modes and their
   * homotopy terms along the direction t (Lee's bordered systems, solved
   * by @p method: deflated CG on one Cholesky factorisation of K0, or one
   * LU factorisation per mode, both made in the constructor).
   */
  class HomotopyPerturbation : public ReanalysisMethod
  {
  public:
    HomotopyPerturbation(
      const ParameterModel  &model,
      const ModalBasis      &nominal,
      const double           truncation_tolerance,
      const double           cluster_gap,
      const DerivativeSolver method = DerivativeSolver::deflated_cg);

    std::string
    name() const override;
    bool
    has_order() const override;
    ReanalysisResult
    reanalyse(const std::vector<double> &t,
              const unsigned int         order) const override;

  private:
    const ParameterModel                          &model;
    const ModalBasis                              &nominal;
    double                                         truncation_tolerance;
    std::vector<std::unique_ptr<EigenDerivatives>> clusters;
  };
} // namespace FuzzyContact

#endif
