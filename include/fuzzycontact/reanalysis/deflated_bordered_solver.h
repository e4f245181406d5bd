// Lee's bordered systems (eigen_derivatives.h) solved on the Cholesky
// factorisation of the nominal stiffness K0 instead of one LU factorisation
// of each bordered matrix.
//
// The system of column j of a cluster C of nominal modes Phi = V_C, with
// shift l = l_j and A = K0 - l M0,
//
//   A x - M0 Phi mu = r,   -Phi^T M0 x = c,
//
// is split along the k computed nominal modes V (M0-orthonormal) and their
// M0-orthogonal complement: x = V a + z, V^T M0 z = 0. The border fixes
// a_C = -c; the modes outside the cluster, F, and the complement are
// coupled only through the eigen-residuals of the computed modes, U =
// P^T K0 V with P = I - V V^T M0 (exactly zero for exact eigenpairs), and
// H = V^T A V (diagonal l_i - l for exact eigenpairs):
//
//   H_FF a_F + U_F^T z           = V_F^T w,       w = r - A V_C a_C,
//   U_F a_F + P^T A P z          = P^T w,
//   mu = H_CF a_F + H_CC a_C + U_C^T z - V_C^T r.
//
// Eliminating a_F (the modal, Nelson-like closed form; H_FF is small and
// nonsingular as long as no mode outside the cluster shares l) leaves, on
// the complement,
//
//   S z = (P^T A P - U_F H_FF^-1 U_F^T) z = P^T w - U_F H_FF^-1 V_F^T w,
//
// which is solved by preconditioned conjugate gradients with P K0^-1 P^T as
// preconditioner: each step is one back-substitution with the shared
// factorisation. On the complement, A is positive definite when l lies
// below the first eigenvalue that was not computed, l_{k+1}, and the
// preconditioned operator has the eigenvalues 1 - l / l_i, i > k (for exact
// eigenpairs), so CG needs few steps unless l_k is close to l_{k+1}.
// The answer is that of the bordered system itself (not of an
// approximation that assumes exact eigenpairs), to the CG tolerance.
//
// A system is reported as not solved when CG meets a direction of
// non-positive curvature (l is not below the complement's spectrum) or does
// not reach the tolerance within the iteration limit; EigenDerivatives then
// factorises that bordered matrix (the direct path).

#ifndef fuzzycontact_reanalysis_deflated_bordered_solver_h
#define fuzzycontact_reanalysis_deflated_bordered_solver_h

#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /** How Lee's bordered systems are solved (key 'derivative solver'). */
  enum class DerivativeSolver
  {
    /** CG on the complement of the nominal modes, K0's Cholesky factor. */
    deflated_cg,
    /** One UMFPACK LU factorisation of each bordered matrix. */
    direct
  };

  /** "deflated cg" or "direct". */
  std::string
  to_string(const DerivativeSolver method);


  /** One bordered system of Lee's recursion and its solution. */
  struct BorderedSystem
  {
    /** The nominal modes of the border (a cluster). */
    std::vector<unsigned int> cluster;
    /** The column: the shift is the eigenvalue of nominal mode cluster[j]. */
    unsigned int j = 0;
    /** Right-hand side (r, c), one entry of c per cluster mode. */
    Vector<double>      r;
    std::vector<double> c;
    /** Solution (x, mu), set if solved. */
    Vector<double>      x;
    std::vector<double> mu;
    bool                solved     = false;
    unsigned int        iterations = 0;
  };


  /** When deflated CG stops. */
  struct DeflatedSolverSettings
  {
    /**
     * CG stops when the preconditioned residual norm sqrt(g^T K0^-1 g)
     * has fallen by this factor.
     */
    double tolerance = 1e-10;
    /** A system that needs more steps is left to the direct path. */
    unsigned int max_iterations = 200;
  };


  class DeflatedBorderedSolver
  {
  public:
    struct Statistics
    {
      unsigned int systems = 0, iterations = 0, not_solved = 0;
    };

    /**
     * @p nominal: the computed nominal modes (all of them deflate, not only
     * the re-analysed ones), M0-normalised. @p stiffness_factorisation: a
     * Cholesky factorisation of model.nominal_stiffness(); made here if
     * null. @p model, @p nominal must outlive this object.
     */
    DeflatedBorderedSolver(
      const ParameterModel                 &model,
      const ModalBasis                     &nominal,
      std::shared_ptr<const SparseCholesky> stiffness_factorisation,
      const DeflatedSolverSettings &settings = DeflatedSolverSettings());

    /**
     * Solves @p systems, in lockstep: one multi-column back-substitution
     * per CG step for all the systems still running. Each system's
     * `solved` says whether it converged (see the header).
     */
    void
    solve(std::vector<BorderedSystem> &systems) const;

    /** Systems solved so far, CG steps, systems left unsolved. */
    Statistics
    statistics() const;

    const SparseCholesky &
    stiffness_factorisation() const;

  private:
    struct Shifted;
    /**
     * Q = (K0 - l_s M0) P for the first @p n_columns columns s (n x
     * n_columns, column-major), l_s = @p shifts[s].
     */
    void
    apply_shifted(const std::vector<double> &shifts,
                  const double              *P,
                  double                    *Q,
                  const unsigned int         n_columns) const;
    /**
     * On the first @p n_columns columns of Y: T = B^T Y, Y <- Y - A T, A
     * and B n x k column-major (the projections P and P^T).
     */
    void
    project(const std::vector<double> &A,
            const std::vector<double> &B,
            double                    *Y,
            const unsigned int         n_columns,
            std::vector<double>       &T) const;

    const ParameterModel                 &model;
    const ModalBasis                     &nominal;
    std::shared_ptr<const SparseCholesky> factorisation;
    DeflatedSolverSettings                settings;
    unsigned int                          n, k;
    // K0 and M0 (one pattern) in compressed rows, read in one pass.
    std::vector<std::size_t>  row_start;
    std::vector<unsigned int> column;
    std::vector<double>       K_value, M_value;
    // V, M0 V and U = P^T K0 V, n x k column-major; V^T K0 V, V^T M0 V.
    std::vector<double> V, MV, U;
    FullMatrix<double>  VKV, VMV;
    bool                orthonormal = false;
    mutable Statistics  statistics_;
  };
} // namespace FuzzyContact

#endif
