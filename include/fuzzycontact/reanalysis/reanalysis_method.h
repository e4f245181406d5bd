// Modal reanalysis: the eigenpairs of K(t) phi = lambda M(t) phi for
// parameter changes t (see reanalysis_parameters.h), from the nominal modes,
// without a new eigensolution. This header holds what the methods share:
// their settings, their result, the interface ReanalysisMethod, the
// clusters of close nominal modes, and Rayleigh-Ritz. The methods have one
// file each:
//
//  - exact_resolve.h: ARPACK on K(t), M(t), the reference;
//  - first_order_taylor.h: lambda0 + grad(lambda).t, phi0 + grad(phi).t, no
//    projection (Lee's first derivatives, computed once);
//  - combined_approximations.h (Kirsch): the binomial-series basis of
//    K(t)^{-1} for every mode, then Rayleigh-Ritz;
//  - homotopy_perturbation.h (HPTP, Massa et al. 2011): the nominal modes
//    and their homotopy terms along the sample's direction, then
//    Rayleigh-Ritz;
//  - parameter_independent_reanalysis.h: the HPTP whose online cost does not
//    depend on the mesh.
//
// reanalysis_factory.h makes a method from its name, order_selection.h
// chooses the order a tolerance asks for, and residual_check.h checks
// reanalysed pairs on the full matrices.
//
// The methods keep references to the ParameterModel and the nominal
// ModalBasis they are built with: both must outlive them.
//
// Close eigenvalues: the nominal modes are grouped into clusters whose
// eigenvalues lie within a relative "cluster gap" of each other, and each
// cluster is expanded as a subspace (eigen_derivatives.h). Every method
// returns its modes sorted by eigenvalue; mode_comparison.h matches them
// with the exact modes by MAC.

#ifndef fuzzycontact_reanalysis_reanalysis_method_h
#define fuzzycontact_reanalysis_reanalysis_method_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/deflated_bordered_solver.h>
#include <fuzzycontact/reanalysis/reduced_basis.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

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
    /**
     * How Lee's bordered systems are solved: deflated CG on the Cholesky
     * factorisation of K0 (falling back to the direct path for a system it
     * does not solve), or one LU factorisation per mode.
     */
    DerivativeSolver derivative_solver = DerivativeSolver::deflated_cg;

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

} // namespace FuzzyContact

#endif
