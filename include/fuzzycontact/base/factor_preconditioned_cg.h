// K x = b for a stiffness K that differs from the nominal one K0 by a zone
// modulus (K = K0 + sum_k t_k K_k), by deal.II's conjugate gradients
// preconditioned with the Cholesky factorisation of K0 that the study
// already holds: no new factorisation.
//
// For a zone modulus scaled by 1 + t, the preconditioned operator
// K0^{-1} K has its eigenvalues between 1 and 1 + t (K_k is the zone's
// share of K0, between 0 and K0), so the condition number is at most
// max(1 + t, 1 / (1 + t)): 3 for +-50 %, and every step reduces the error
// by (sqrt(3) - 1) / (sqrt(3) + 1) = 0.27 or better, whatever the mesh.
// Each step costs one back-substitution with the factor and a product
// with K. A solve stops when ||b - K x||_2 <= tolerance ||b||_2; without
// that in max_iterations steps it throws, naming the keys that set both.

#ifndef fuzzycontact_base_factor_preconditioned_cg_h
#define fuzzycontact_base_factor_preconditioned_cg_h

#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/base/stiffness_solver.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>

namespace FuzzyContact
{
  /** What the conjugate gradient solves of a study did. */
  struct IterativeSolveStatistics
  {
    unsigned long solves = 0, iterations = 0;
    /** The most steps one solve took. */
    unsigned int max_iterations = 0;
    /**
     * Changed stiffnesses solved by CG, and those factorised instead
     * (where an automatic choice found CG dearer).
     */
    unsigned long by_cg = 0, factorised = 0;
  };

  /**
   * The CG steps that reach the relative error @p tolerance for a
   * preconditioned operator whose eigenvalues lie in [@p lower, @p upper]
   * (the classical bound 2 ((sqrt(k) - 1) / (sqrt(k) + 1))^n, k = upper /
   * lower).
   */
  unsigned int
  cg_steps_bound(const double lower,
                 const double upper,
                 const double tolerance);

  class FactorPreconditionedCG : public StiffnessSolver
  {
  public:
    /**
     * Solves with @p matrix (copied; its sparsity pattern must outlive this
     * object), preconditioned by @p nominal (a factorisation of a nearby
     * symmetric positive definite matrix of the same size).
     * @p tolerance, @p max_iterations: see the top of this file;
     * @p keys names the keys that set them, for the message of a solve that
     * does not converge; @p what names the matrix. The solves are counted
     * in @p statistics if given.
     */
    FactorPreconditionedCG(
      const SparseMatrix<double>               &matrix,
      std::shared_ptr<const SparseCholesky>     nominal,
      const double                              tolerance,
      const unsigned int                        max_iterations,
      const std::string                        &keys,
      const std::string                        &what,
      std::shared_ptr<IterativeSolveStatistics> statistics = nullptr);

    types::global_dof_index
    n() const override;

    void
    solve(Vector<double> &b) const override;

  private:
    SparseMatrix<double>                      matrix;
    std::shared_ptr<const SparseCholesky>     nominal;
    double                                    tolerance;
    unsigned int                              max_iterations;
    std::string                               keys, what;
    std::shared_ptr<IterativeSolveStatistics> statistics;
  };
} // namespace FuzzyContact

#endif
