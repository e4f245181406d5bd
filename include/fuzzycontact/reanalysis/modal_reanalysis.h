// Modal reanalysis: the eigenpairs of K(t) phi = lambda M(t) phi for
// parameter changes t (see reanalysis_parameters.h), from the nominal modes,
// without a new eigensolution. This header holds what the methods share
// (settings, result, interface, Rayleigh-Ritz) and the methods that depend
// on the sample:
//
//  - ExactResolve: ARPACK on K(t), M(t), the reference;
//  - FirstOrderTaylor: lambda0 + grad(lambda).t, phi0 + grad(phi).t, no
//    projection (Lee's first derivatives, computed once);
//  - CombinedApproximations (Kirsch): the basis r_1 = K0^{-1} M(t) phi0,
//    r_{i+1} = -K0^{-1} Delta K r_i (terms of the binomial series of
//    K(t)^{-1}) for every mode, then Rayleigh-Ritz;
//  - HomotopyPerturbation (HPTP, Massa et al. 2011): the basis of the
//    nominal modes and their homotopy terms phi_i = (1/i!) d^i phi / d eps^i
//    along the sample's direction, i = 1..n, then Rayleigh-Ritz.
//
// The parameter-independent HPTP, whose online cost does not depend on the
// mesh, is in parameter_independent_reanalysis.h.
//
// The methods keep references to the ParameterModel and the nominal
// ModalBasis they are built with: both must outlive them.
//
// Close eigenvalues: the nominal modes are grouped into clusters whose
// eigenvalues lie within a relative "cluster gap" of each other, and each
// cluster is expanded as a subspace (eigen_derivatives.h). Every method
// returns its modes sorted by eigenvalue; mode_comparison.h matches them
// with the exact modes by MAC.

#ifndef fuzzycontact_reanalysis_modal_reanalysis_h
#define fuzzycontact_reanalysis_modal_reanalysis_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/eigen_derivatives.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/reanalysis/reduced_basis.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * Settings of a reanalysis (subsection "Reanalysis" of a parameter file).
   */
  struct ReanalysisSettings
  {
    /** Highest Taylor order n of HPTP (and basis size of CA), 1..3. */
    unsigned int max_order = 3;
    /**
     * The order is the lowest n whose estimated relative frequency error,
     * max_j |f_j^(n) - f_j^(n+1)| / f_j^(n+1), is at most this.
     */
    double order_tolerance = 1e-6;
    /**
     * Rank truncation of the basis (see reduced_basis.h): a dropped
     * direction of relative size delta changes Ritz values by O(delta^2),
     * so 1e-6 costs at most ~1e-12, below the round-off floor, while
     * smaller values admit round-off directions that grow with the mesh.
     */
    double truncation_tolerance = 1e-6;
    /**
     * Nominal modes whose eigenvalues differ by at most this relative gap
     * are expanded together as a cluster.
     */
    double cluster_gap = 1e-2;
    /** Compute the residuals of the reanalysed pairs on the full matrices. */
    bool residual_check = true;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };


  /** Eigenpairs returned by a reanalysis method. */
  struct ReanalysisResult
  {
    /** Ascending. */
    std::vector<double> eigenvalues;
    /** Full mode vectors (M(t)-normalised for the projection methods). */
    std::vector<Vector<double>> modes;
    /** Order used (0 for methods without one). */
    unsigned int order = 0;
    /** Columns of the reduced basis (0 for methods without one). */
    unsigned int basis_size = 0;

    std::vector<double>
    frequencies() const;
  };


  /** The interface every method offers, for comparisons. */
  class ReanalysisMethod
  {
  public:
    virtual ~ReanalysisMethod() = default;

    /** Short name: "exact", "taylor", "ca", "hptp", "hptp-pi". */
    virtual std::string
    name() const = 0;

    /** Whether reanalyse() uses its order argument. */
    virtual bool
    has_order() const = 0;

    /**
     * The reanalysed eigenpairs at the relative parameter changes @p t
     * (one per parameter of the model), at @p order where the method has
     * one.
     */
    virtual ReanalysisResult
    reanalyse(const std::vector<double> &t, const unsigned int order) const = 0;
  };


  /**
   * The clusters of nominal modes that a reanalysis expands together: modes
   * whose eigenvalues differ by at most max(@p cluster_gap,
   * minimum_cluster_gap), relative (singletons included).
   */
  std::vector<std::vector<unsigned int>>
  reanalysis_clusters(const ModalBasis &nominal, const double cluster_gap);

  /**
   * How many leading modes of @p nominal to reanalyse so that the lowest
   * @p n_wanted are included together with every mode of their clusters.
   * Throws a message naming the modes if the cluster of mode n_wanted
   * reaches the highest mode of @p nominal: its partners may lie above, so
   * more nominal modes must be computed (one more than wanted is the
   * minimum for this check).
   */
  unsigned int
  modes_with_complete_clusters(const ModalBasis  &nominal,
                               const unsigned int n_wanted,
                               const double       cluster_gap);

  /** The first @p n modes of @p basis. */
  ModalBasis
  leading_modes(const ModalBasis &basis, const unsigned int n);


  /**
   * Rayleigh-Ritz: the @p n_modes lowest eigenpairs of (T^T K T, T^T M T),
   * expanded to full vectors (M-normalised).
   */
  ReanalysisResult
  rayleigh_ritz(const SparseMatrix<double> &K,
                const SparseMatrix<double> &M,
                const ReducedBasis         &T,
                const unsigned int          n_modes);


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


  /** The reference: a new ARPACK solve on K(t), M(t). */
  class ExactResolve : public ReanalysisMethod
  {
  public:
    ExactResolve(const ParameterModel  &model,
                 const ModalParameters &modal_parameters);

    std::string
    name() const override;
    bool
    has_order() const override;
    ReanalysisResult
    reanalyse(const std::vector<double> &t,
              const unsigned int         order = 0) const override;

    /** The exact modes as a ModalBasis (with residuals). */
    ModalBasis
    solve(const std::vector<double> &t) const;

  private:
    const ParameterModel &model;
    ModalParameters       modal_parameters;
  };


  /**
   * First-order Taylor series of eigenvalues and modes, without projection.
   * A cluster of close modes is expanded as a subspace: its eigenvalues are
   * those of the m x m pencil (Lambda0 + Phi^T Delta K Phi, I + Phi^T Delta M
   * Phi) and its modes (Phi + X_1) y (first-order degenerate perturbation).
   */
  class FirstOrderTaylor : public ReanalysisMethod
  {
  public:
    FirstOrderTaylor(const ParameterModel &model,
                     const ModalBasis     &nominal,
                     const double          cluster_gap);

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


  /**
   * HPTP with a basis built for each sample: nominal modes and their
   * homotopy terms along the direction t (Lee's bordered systems, factorised
   * once per mode in the constructor).
   */
  class HomotopyPerturbation : public ReanalysisMethod
  {
  public:
    HomotopyPerturbation(const ParameterModel &model,
                         const ModalBasis     &nominal,
                         const double          truncation_tolerance,
                         const double          cluster_gap);

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
