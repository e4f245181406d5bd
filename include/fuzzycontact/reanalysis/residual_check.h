// The a-posteriori check of reanalysed eigenpairs on the full matrices
// K(t), M(t): what a reanalysis can say about its own error without an
// exact re-solve.

#ifndef fuzzycontact_reanalysis_residual_check_h
#define fuzzycontact_reanalysis_residual_check_h

#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * A-posteriori check of approximate eigenpairs (lambda, phi) of K(t),
   * M(t) on the full matrices, with the residual r = K(t) phi - lambda M(t)
   * phi measured in two norms:
   *
   *  - relative: ||r|| / ||K(t) phi|| (Euclidean, as in step-1). Its floor
   *    is eps * lambda_max / lambda, and it is dominated by the smallest
   *    high-frequency error of phi, so it says little about eigenvalues;
   *  - energy: eta = ||r||_{K0^-1} / ||phi||_{K(t)}, the residual in the
   *    dual of the energy norm (K0 is factorised once, as a preconditioner
   *    spectrally equivalent to K(t)). For a Ritz pair, eta bounds the
   *    relative eigenvalue error to first order, and eta^2 / (relative gap
   *    to the next eigenvalue) estimates it.
   */
  class ResidualCheck
  {
  public:
    /** Factorises K0 (UMFPACK). @p model must outlive the check. */
    explicit ResidualCheck(const ParameterModel &model);

    struct Residuals
    {
      std::vector<double> relative;
      std::vector<double> energy;
    };

    Residuals
    check(const std::vector<double>         &t,
          const std::vector<double>         &eigenvalues,
          const std::vector<Vector<double>> &modes) const;

  private:
    const ParameterModel &model;
    SparseDirectUMFPACK   K0_inverse;
  };
} // namespace FuzzyContact

#endif
