// First-order Taylor series of the eigenpairs (Lee's first derivatives,
// computed once), without projection: the cheapest reanalysis, and the
// least accurate.

#ifndef fuzzycontact_reanalysis_first_order_taylor_h
#define fuzzycontact_reanalysis_first_order_taylor_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/eigen_derivatives.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * First-order Taylor series of eigenvalues and modes, without projection.
   * A cluster of close modes is expanded as a subspace: its eigenvalues are
   * those of the m x m pencil (Lambda0 + Phi^T Delta K Phi, I + Phi^T Delta M
   * Phi) and its modes (Phi + X_1) y (first-order degenerate perturbation).
   */
  class FirstOrderTaylor : public ReanalysisMethod
  {
  public:
    /** Lee's bordered systems are solved by @p method. */
    FirstOrderTaylor(
      const ParameterModel  &model,
      const ModalBasis      &nominal,
      const double           cluster_gap,
      const DerivativeSolver method = DerivativeSolver::deflated_cg);

    std::string
    name() const override;
    bool
    has_order() const override;
    ReanalysisResult
    reanalyse(const std::vector<double> &t,
              const unsigned int         order = 1) const override;

  private:
    struct Cluster
    {
      std::vector<unsigned int> modes;
      /** Single mode: d lambda / dt_k, d phi / dt_k (Lee). */
      EigenpairDerivatives derivatives;
      /** Cluster: X_{e_k} (intermediate normalisation), per parameter. */
      std::vector<std::vector<Vector<double>>> X;
      /** Cluster: Phi^T K_k Phi and Phi^T M_k Phi, per parameter. */
      std::vector<FullMatrix<double>> PhiKPhi, PhiMPhi;
    };

    const ParameterModel &model;
    const ModalBasis     &nominal;
    std::vector<Cluster>  clusters;
  };
} // namespace FuzzyContact

#endif
