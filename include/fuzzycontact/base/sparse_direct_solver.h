// A sparse LU factorisation (UMFPACK) with plain back-substitutions.
//
// deal.II's SparseDirectUMFPACK runs UMFPACK's iterative refinement in every
// solve, which makes a back-substitution about ten times as expensive as
// the substitution itself (measured: 0.011 s against 0.0011 s for 20434
// DoFs) without improving the forward error, which is limited by the
// condition of K (about 1e-9 relative here). The contact solvers need
// thousands of back-substitutions (columns of the contact flexibility,
// attachment modes), so this class calls UMFPACK directly with refinement
// off; where a solution must be accurate beyond the condition limit, the
// caller refines it with an extended-precision residual
// (FullOrderContact).

#ifndef fuzzycontact_base_sparse_direct_solver_h
#define fuzzycontact_base_sparse_direct_solver_h

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  class SparseDirectSolver
  {
  public:
    SparseDirectSolver()                           = default;
    SparseDirectSolver(const SparseDirectSolver &) = delete;
    SparseDirectSolver &
    operator=(const SparseDirectSolver &) = delete;
    ~SparseDirectSolver();

    /**
     * LU factorisation of the square matrix @p A (symbolic and numeric).
     * Throws with UMFPACK's status if @p A is singular.
     */
    void
    factorize(const SparseMatrix<double> &A);

    /**
     * UMFPACK's symbolic analysis of a matrix (its fill-reducing ordering,
     * about half the cost of a factorisation) and the pattern it was made
     * for, to share with matrices of that pattern.
     */
    struct Analysis
    {
      std::shared_ptr<void> symbolic;
      std::vector<long>     row_starts, columns;
    };

    /**
     * The same, reusing @p analysis (from analysis() of another solver)
     * if @p A has its pattern; otherwise, or if it is null, as above.
     */
    void
    factorize(const SparseMatrix<double>            &A,
              const std::shared_ptr<const Analysis> &analysis);

    /** The symbolic analysis of the factorised matrix. */
    std::shared_ptr<const Analysis>
    analysis() const;

    /** Overwrites @p b by A^{-1} b. */
    void
    solve(Vector<double> &b) const;
    /** dst = A^{-1} src (the interface of an inverse operator). */
    void
    vmult(Vector<double> &dst, const Vector<double> &src) const;

    /** Size of the factorised matrix (0 before factorize()). */
    types::global_dof_index
    n() const;

  private:
    void
    clear();

    /** Copies A's rows into the compressed arrays UMFPACK reads. */
    void
    copy_rows(const SparseMatrix<double> &A);

    /** The numeric factorisation, from analysis_. */
    void
    factorize_numeric();

    // The rows of A in compressed form, handed to UMFPACK as the columns of
    // A^T (solves then use UMFPACK_At).
    std::vector<long>               row_starts, columns;
    std::vector<double>             values;
    std::shared_ptr<const Analysis> analysis_;
    void                           *numeric = nullptr;
    std::vector<double>             control;
  };
} // namespace FuzzyContact

#endif
