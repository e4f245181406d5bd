// Eigen-derivatives by Lee's algebraic method, and the higher Taylor
// coefficients of eigenpairs (or of clusters of close eigenpairs) that the
// homotopy perturbation reanalysis (HPTP) needs.
//
// For a simple nominal eigenpair (lambda_0, phi_0) of K0 phi = lambda M0 phi
// and the affine model K(t) = K0 + sum_k t_k K_k, M(t) = M0 + sum_k t_k M_k
// (see reanalysis_parameters.h), write the eigenpair as a Taylor series in
// the changes, phi(t) = sum_alpha t^alpha phi_alpha, lambda(t) = sum_alpha
// t^alpha lambda_alpha (multi-indices alpha). Matching powers of t in K phi
// = lambda M phi and in the normalisation phi^T M phi = 1 gives, for every
// |alpha| >= 1, one linear system with the same matrix (Lee and Jung 1997):
//
//   [ K0 - l0 M0   -M0 phi0 ] [ phi_alpha    ]   [ r_alpha ]
//   [ -phi0^T M0       0    ] [ lambda_alpha ] = [ c_alpha ]
//
//   r_alpha = - sum_k K_k phi_{alpha-e_k}
//             + sum_{beta+gamma=alpha; beta,gamma != 0} lambda_beta M0
//             phi_gamma
//             + sum_k sum_{beta+gamma=alpha-e_k} lambda_beta M_k phi_gamma
//   c_alpha = 1/2 [ sum_{beta+gamma=alpha; beta,gamma != 0} phi_beta^T M0
//   phi_gamma
//                   + sum_k sum_{beta+gamma=alpha-e_k} phi_beta^T M_k phi_gamma
//                   ]
//
// For alpha = e_k this is Lee's system for the first derivatives, r = -(K_k -
// l0 M_k) phi0, c = 1/2 phi0^T M_k phi0; second derivatives are
// d2/dt_k dt_l = (1 + delta_kl) phi_{e_k + e_l}. The bordered matrix is
// symmetric, indefinite and sparse (one extra dense row and column). Two
// ways of solving it (DerivativeSolver):
//  - deflated_cg (the default of the programs): conjugate gradients on the
//    M0-orthogonal complement of the computed nominal modes, preconditioned
//    by the Cholesky factorisation of K0 that the rest of the model shares,
//    the modal part in closed form (deflated_bordered_solver.h); a system
//    that CG does not solve falls back to the direct path;
//  - direct: the bordered matrix factorised once per mode by UMFPACK
//    (plain back-substitutions, no iterative refinement:
//    SparseDirectSolver; the modes' matrices share one symbolic analysis)
//    and reused for every parameter, every order and every direction.
//
// Close or repeated eigenvalues. The bordered matrix is singular when
// lambda_0 is repeated and ill-conditioned when it is close to another
// eigenvalue, and the Taylor series of an individual mode then converges
// only for tiny changes (the modes of a cluster rotate into each other). A
// cluster C of m close modes Phi = [phi_c] is therefore expanded as a
// subspace: X(t) = Phi + sum t^alpha X_alpha with Phi^T M0 X_alpha = 0, and
// K(t) X = M(t) X Lambda(t) with an m x m matrix Lambda(t) = sum t^alpha
// Lambda_alpha whose eigenvalues are the cluster's eigenvalues. Column j of
// X_alpha and of Lambda_alpha solve the bordered system with the whole
// cluster as border,
//
//   [ K0 - l_j M0   -M0 Phi ] [ x_alpha,j      ]   [ r_alpha,j ]
//   [ -Phi^T M0        0    ] [ Lambda_alpha e_j ] = [ 0         ],
//
//   R_alpha = - sum_k K_k X_{alpha-e_k}
//             + sum_{beta+gamma=alpha; beta,gamma != 0} M0 X_gamma Lambda_beta
//             + sum_k sum_{beta+gamma=alpha-e_k} M_k X_gamma Lambda_beta,
//
// which is nonsingular as long as no eigenvalue outside the cluster equals
// l_j. A simple mode is the case m = 1 (then with the "intermediate"
// normalisation phi0^T M0 phi_alpha = 0 instead of Lee's M-normalisation);
// both give the same nested subspaces span{phi_alpha : |alpha| <= n}.
//
// Directions. The coefficients may be taken with respect to the parameters
// themselves (the parameter-independent variant: all mixed derivatives), or
// with respect to q "directions" d_1..d_q, each a combination of the
// parameters (K_d = sum_k d_k K_k): with the single direction d = t of a
// sample, the coefficients are the homotopy terms phi_i = (1/i!) d^i phi /
// d eps^i of K0 + eps Delta K, Delta K = sum_k t_k K_k (Massa et al. 2011).

#ifndef fuzzycontact_reanalysis_eigen_derivatives_h
#define fuzzycontact_reanalysis_eigen_derivatives_h

#include <fuzzycontact/base/sparse_direct_solver.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/deflated_bordered_solver.h>
#include <fuzzycontact/reanalysis/multi_index_set.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * Taylor coefficients of one cluster of eigenpairs (a single mode is a
   * cluster of size 1) with respect to q directions.
   */
  struct EigenTaylorCoefficients
  {
    /** Indices of the cluster's modes in the nominal basis. */
    std::vector<unsigned int> modes;
    /**
     * True: Lee's normalisation phi(t)^T M(t) phi(t) = 1 (single modes
     * only); false: intermediate normalisation Phi^T M0 X_alpha = 0.
     */
    bool mass_normalised = false;
    /** The directions, one row of parameter coefficients each. */
    std::vector<std::vector<double>> directions;
    MultiIndexSet                    indices{0, 0};
    /** vectors[a][j]: column j of X_alpha for alpha = indices[a]. */
    std::vector<std::vector<Vector<double>>> vectors;
    /** eigenvalues[a]: the m x m matrix Lambda_alpha (1 x 1 for a mode). */
    std::vector<FullMatrix<double>> eigenvalues;
  };


  /**
   * First and second derivatives of a simple eigenpair with respect to the
   * relative changes t_k of the model's parameters (M-normalised modes).
   * Divide by P_k^0 (resp. P_k^0 P_l^0) for derivatives with respect to the
   * parameters themselves.
   */
  struct EigenpairDerivatives
  {
    unsigned int mode;
    /** d lambda / d t_k. */
    std::vector<double> eigenvalue;
    /** d phi / d t_k. */
    std::vector<Vector<double>> mode_shape;
    /** d2 lambda / d t_k d t_l (empty if only first order was asked). */
    FullMatrix<double> second_eigenvalue;
    /** d2 phi / d t_k d t_l, [k][l]. */
    std::vector<std::vector<Vector<double>>> second_mode_shape;
  };


  /**
   * Eigenvalues closer than this (relative) are numerically repeated: a
   * single mode among them has no derivative, and its bordered matrix is
   * singular to working precision. They are always expanded together,
   * whatever cluster gap is asked for.
   */
  constexpr double minimum_cluster_gap = 1e-6;


  /**
   * Lee's bordered systems for one cluster of nominal modes, and the Taylor
   * coefficients they give. Solved by deflated CG when a
   * DeflatedBorderedSolver is given, otherwise (and for any system CG does
   * not solve) by one UMFPACK factorisation per mode of the cluster, made
   * when first needed and reused for every right-hand side.
   */
  class EigenDerivatives
  {
  public:
    /**
     * @p cluster lists the indices (into @p nominal) of the modes expanded
     * together: one mode, or all the modes of a cluster of close
     * eigenvalues. Throws a message naming the modes if a nominal mode
     * outside the cluster lies within max(@p cluster_gap,
     * minimum_cluster_gap) (relative) of one inside it, since the expansion
     * of an incomplete cluster is not defined. @p model and @p nominal must
     * outlive this object. @p same_pattern: the analysis() of another
     * cluster's derivatives, whose bordered matrices have the pattern of
     * this one's if the clusters have one size (it is then shared, which
     * halves the cost of each factorisation; otherwise it is ignored).
     * @p deflated: the deflated CG solver of @p model and @p nominal
     * (shared by all the clusters); null: the direct path, every bordered
     * matrix factorised here.
     */
    EigenDerivatives(
      const ParameterModel                                      &model,
      const ModalBasis                                          &nominal,
      const std::vector<unsigned int>                           &cluster,
      const double                                               cluster_gap,
      const std::shared_ptr<const SparseDirectSolver::Analysis> &same_pattern =
        nullptr,
      std::shared_ptr<const DeflatedBorderedSolver> deflated = nullptr);
    ~EigenDerivatives();

    /**
     * The symbolic analysis of the bordered matrices' pattern, if one was
     * made (or given); null otherwise.
     */
    std::shared_ptr<const SparseDirectSolver::Analysis>
    analysis() const;

    const std::vector<unsigned int> &
    cluster() const;

    /** Bordered matrices factorised so far (the direct path). */
    unsigned int
    n_factorisations() const;

    /**
     * Taylor coefficients up to @p order in the given @p directions (each
     * a vector of n_parameters() coefficients). @p mass_normalise selects
     * Lee's M-normalisation and needs a single mode.
     */
    EigenTaylorCoefficients
    taylor_coefficients(const std::vector<std::vector<double>> &directions,
                        const unsigned int                      order,
                        const bool mass_normalise) const;

    /**
     * The same for several clusters of one nominal basis at once (their
     * systems of each multi-index solved together: one multi-column
     * back-substitution per CG step); @p mass_normalise per cluster.
     */
    static std::vector<EigenTaylorCoefficients>
    taylor_coefficients(const std::vector<const EigenDerivatives *> &clusters,
                        const std::vector<std::vector<double>>      &directions,
                        const unsigned int                           order,
                        const std::vector<bool> &mass_normalise);

    /**
     * Lee's derivatives of a simple mode up to order 1 or 2 with respect to
     * every parameter. Throws, naming the modes, for a cluster of more than
     * one mode: the derivatives of individual modes are not defined for
     * repeated eigenvalues (use taylor_coefficients() on the subspace).
     */
    EigenpairDerivatives
    derivatives(const unsigned int order) const;

    /**
     * The solution (x, mu) of the bordered system of cluster column @p j
     * for the right-hand side (r, c): (K0 - l_j M0) x - M0 Phi mu = r,
     * -Phi^T M0 x = c.
     */
    void
    solve(const unsigned int         j,
          const Vector<double>      &r,
          const std::vector<double> &c,
          Vector<double>            &x,
          std::vector<double>       &mu) const;

  private:
    /** Solves @p system (a column of this cluster) directly. */
    void
    solve_directly(BorderedSystem &system) const;
    /** The factorisation of column j's bordered matrix, made if needed. */
    const SparseDirectSolver &
    factorisation(const unsigned int j) const;

    const ParameterModel                                    &model;
    const ModalBasis                                        &nominal;
    std::vector<unsigned int>                                cluster_;
    std::shared_ptr<const DeflatedBorderedSolver>            deflated;
    std::vector<Vector<double>>                              M0_phi;
    std::vector<double>                                      border_scale;
    std::shared_ptr<const SparseDirectSolver::Analysis>      same_pattern;
    mutable std::unique_ptr<SparsityPattern>                 bordered_pattern;
    mutable std::vector<std::unique_ptr<SparseDirectSolver>> factorisations;
  };


  /**
   * Text naming modes for messages, e.g. "modes 8 and 9 (19342.7 and 19369
   * Hz)". Mode numbers are 1-based.
   */
  std::string
  describe_modes(const ModalBasis                &basis,
                 const std::vector<unsigned int> &modes);
} // namespace FuzzyContact

#endif
