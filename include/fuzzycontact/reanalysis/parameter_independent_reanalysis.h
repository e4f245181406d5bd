// The parameter-independent HPTP: one reduced basis for every parameter
// sample, so that a sample costs a small dense eigenproblem whose size does
// not depend on the mesh.
//
// Offline (once per component and parameter set):
//  1. the nominal modes are grouped into clusters of close eigenvalues;
//  2. for each cluster, Lee's bordered systems give all Taylor
//     coefficients phi_alpha, |alpha| <= n, with respect to every
//     parameter: the derivatives d^|alpha| phi / dt^alpha / alpha!, mixed
//     ones included (eigen_derivatives.h), by deflated CG on the Cholesky
//     factorisation of K0 (or one UMFPACK factorisation per mode);
//  3. T = [nominal modes | all terms of order 1 | ... | order n] is
//     M0-orthonormalised with rank truncation (reduced_basis.h), so that the
//     leading columns of T are the basis of every lower order;
//  4. every zone matrix is projected: T^T K_z T and T^T M_z T.
// The span of T contains the sample-dependent HPTP basis of order n for
// every direction t (its terms phi_i = sum_{|alpha| = i} t^alpha phi_alpha
// are combinations of the columns), so this variant is at least as accurate
// as HPTP of the same order, by the Rayleigh-Ritz minimax property.
//
// Online (per sample t): K_r(t) = sum_z E_z(t) T^T K_z T, M_r(t) = sum_z
// rho_z(t) T^T M_z T (exact, since K and M are affine in the zone
// materials), and the lowest eigenpairs of (K_r, M_r) by LAPACK (dsygvx).
// The reanalysed modes are phi_j = T Y(:, j), M(t)-normalised. Nothing of
// size n_dofs is touched unless the modes are expanded or the residuals on
// the full matrices are asked for.
//
// Order: Ritz values from nested bases decrease monotonically towards the
// exact eigenvalues, so |f^(n) - f^(n+1)| is a (lower) estimate of the error
// of order n. online_to_tolerance() and select_order() choose the lowest
// order whose estimate meets a tolerance, by the rule of order_selection.h
// (the one step-2 uses too); residuals() checks the pairs on the full
// matrices.

#ifndef fuzzycontact_reanalysis_parameter_independent_reanalysis_h
#define fuzzycontact_reanalysis_parameter_independent_reanalysis_h

#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/eigen_derivatives.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/reanalysis/reduced_basis.h>
#include <fuzzycontact/reanalysis/residual_check.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/full_matrix.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /** The online answer of the parameter-independent reanalysis. */
  struct ReanalysedModes
  {
    /** Taylor order of the basis used. */
    unsigned int order = 0;
    /** Columns of T used (the leading ones). */
    unsigned int basis_size = 0;
    /** lambda_j = omega_j^2, ascending, one per nominal mode. */
    std::vector<double> eigenvalues;
    /** basis_size x n_modes: mode j is T Y(:, j), M(t)-normalised. */
    FullMatrix<double> Y;
    /**
     * When the order was chosen to a tolerance: the estimated relative
     * frequency error, max_j |f_j(order) - f_j(order + 1)| / f_j(order + 1)
     * (and eta^2 / 2 if residuals were checked); NaN if no estimate was
     * available (highest order without residual check).
     */
    double estimated_error = std::numeric_limits<double>::quiet_NaN();
    /** Whether estimated_error met the tolerance asked for. */
    bool tolerance_met = false;

    std::vector<double>
    frequencies() const;
  };


  class ParameterIndependentReanalysis : public ReanalysisMethod
  {
  public:
    ParameterIndependentReanalysis() = default;

    /**
     * Builds the basis and its projections (see above) for the parameters
     * named in @p parameter_names (e.g. "P1.root.E", "P1.rho"), Taylor
     * order @p order (1 to 3), rank truncation @p truncation_tolerance and
     * the clusters of @p nominal at relative gap @p cluster_gap. The
     * nominal state is the component's current zone materials; @p nominal
     * must be its modes there (copied). @p component must outlive this
     * object. Stages are timed in @p timer if given. Lee's bordered
     * systems are solved by @p method; deflated CG runs on
     * @p stiffness_factorisation, a Cholesky factorisation of the
     * component's stiffness at the nominal state (made here if null).
     */
    void
    offline(
      const Component                &component,
      const ModalBasis               &nominal,
      const std::vector<std::string> &parameter_names,
      const unsigned int              order,
      const double                    truncation_tolerance,
      const double                    cluster_gap = 1e-2,
      TimerOutput                    *timer       = nullptr,
      const DerivativeSolver          method = DerivativeSolver::deflated_cg,
      std::shared_ptr<const SparseCholesky> stiffness_factorisation = nullptr);

    /** What Lee's bordered systems cost in the last offline(). */
    struct DerivativeCost
    {
      DerivativeSolver method = DerivativeSolver::deflated_cg;
      /** Systems given to deflated CG, its steps, those it left. */
      unsigned int systems = 0, cg_iterations = 0, not_solved_by_cg = 0;
      /** Bordered matrices factorised (UMFPACK). */
      unsigned int factorisations = 0;
    };
    const DerivativeCost &
    derivative_cost() const;

    /** The reanalysed eigenpairs at relative changes @p t, at order(). */
    ReanalysedModes
    online(const std::vector<double> &t) const;
    /** Same at a given order (1 .. max_order()). */
    ReanalysedModes
    online(const std::vector<double> &t, const unsigned int order) const;
    /**
     * The lowest order whose estimated relative frequency error meets
     * @p tolerance (or max_order(), with tolerance_met = false). The
     * estimate of order n is its change to order n + 1 (mesh-independent
     * cost); with @p check_residuals also eta^2 / 2, eta the largest
     * energy-norm residual on the full matrices (see ResidualCheck), which
     * costs O(n_dofs) per order but also covers the highest order.
     */
    ReanalysedModes
    online_to_tolerance(const std::vector<double> &t,
                        const double               tolerance,
                        const bool check_residuals = false) const;

    /**
     * Sets order() to the lowest order that meets @p tolerance at every
     * sample (for instance the corners of a parameter box; see
     * online_to_tolerance()) and returns it; max_order() if none does.
     */
    unsigned int
    select_order(const std::vector<std::vector<double>> &samples,
                 const double                            tolerance,
                 const bool check_residuals = false);
    unsigned int
    order() const;
    void
    set_order(const unsigned int order);
    unsigned int
    max_order() const;

    /** The full basis T (M0-orthonormal columns). */
    const ReducedBasis &
    basis() const;
    /** Number of leading columns of T that make the basis of @p order. */
    unsigned int
    basis_size(const unsigned int order) const;
    const ParameterModel &
    model() const;
    const ModalBasis &
    nominal() const;
    /** The clusters of nominal modes expanded together. */
    const std::vector<std::vector<unsigned int>> &
    clusters() const;

    /** T^T K_z T and T^T M_z T (full basis). */
    const FullMatrix<double> &
    zone_stiffness_projection(const unsigned int zone) const;
    const FullMatrix<double> &
    zone_mass_projection(const unsigned int zone) const;
    /** T^T K(t) T and T^T M(t) T on the basis of @p order. */
    FullMatrix<double>
    reduced_stiffness(const std::vector<double> &t,
                      const unsigned int         order) const;
    FullMatrix<double>
    reduced_mass(const std::vector<double> &t, const unsigned int order) const;

    /** The full mode vectors T Y. */
    std::vector<Vector<double>>
    modes(const ReanalysedModes &modes) const;
    /**
     * Residuals of the reanalysed pairs on the full matrices (see
     * ResidualCheck: Euclidean and energy-norm). Costs a few sparse
     * products and one back-solve per mode; the first call factorises K0.
     */
    ResidualCheck::Residuals
    residuals(const std::vector<double> &t, const ReanalysedModes &modes) const;

    // ReanalysisMethod
    std::string
    name() const override;
    bool
    has_order() const override;
    ReanalysisResult
    reanalyse(const std::vector<double> &t,
              const unsigned int         order) const override;

  private:
    FullMatrix<double>
    combine(const std::vector<FullMatrix<double>> &zone_projections,
            const std::vector<double>             &zone_values,
            const unsigned int                     size) const;

    std::unique_ptr<ParameterModel>        model_;
    ModalBasis                             nominal_;
    std::vector<std::vector<unsigned int>> clusters_;
    std::unique_ptr<ReducedBasis>          basis_;
    std::vector<unsigned int>              basis_sizes_;
    std::vector<FullMatrix<double>>        zone_K_, zone_M_;
    unsigned int                           max_order_ = 0;
    DerivativeCost                         derivative_cost_;
    // Built on the first call of residuals() (not needed online).
    mutable std::unique_ptr<ResidualCheck> residual_check_;
    unsigned int                           order_ = 0;
  };
} // namespace FuzzyContact

#endif
