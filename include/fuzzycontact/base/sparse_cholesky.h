// A sparse Cholesky factorisation of a symmetric positive definite matrix
// (CHOLMOD, supernodal), with chosen DoFs ordered last.
//
// With a fill-reducing ordering constrained (CAMD) to put the DoFs B last,
//
//   P A P^T = L L^T,  L = [L_II 0; L_BI L_BB],
//
// the trailing block gives A^{-1} restricted to B without a single solve:
// L^{-1} is lower triangular, so the trailing block of A^{-1} = P^T L^{-T}
// L^{-1} P is (L_BB L_BB^T)^{-1}, the inverse of the Schur complement
// S = A_BB - A_BI A_II^{-1} A_IB = L_BB L_BB^T. A component's contact
// flexibility, its load responses at the contact and the displacements it
// reports all live on such a set B (reduction/reduced_model.h).
//
// Solves are plain forward and backward substitutions (no iterative
// refinement): the backward error of a Cholesky factorisation is at the
// round-off level, so refinement would not improve the forward error, which
// the condition of A limits.

#ifndef fuzzycontact_base_sparse_cholesky_h
#define fuzzycontact_base_sparse_cholesky_h

#include <fuzzycontact/base/stiffness_solver.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/types.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  class SparseCholesky : public StiffnessSolver
  {
  public:
    SparseCholesky();
    SparseCholesky(const SparseCholesky &) = delete;
    SparseCholesky &
    operator=(const SparseCholesky &) = delete;
    ~SparseCholesky() override;

    /**
     * Factorises the symmetric positive definite matrix @p A (only its
     * lower triangle is read), with the DoFs @p last ordered last (in an
     * order of CHOLMOD's choice, see trailing_dofs()). @p what names the
     * matrix in messages ("<what> is not positive definite"): a matrix that
     * is not positive definite (a
     * component whose rigid-body motions are not all suppressed) is refused
     * with the pivot that failed.
     */
    void
    factorize(const SparseMatrix<double>                 &A,
              const std::vector<types::global_dof_index> &last = {},
              const std::string                          &what = "The matrix");

    /** Size of the factorised matrix (0 before factorize()). */
    types::global_dof_index
    n() const override;

    /** Overwrites @p b by A^{-1} b. */
    void
    solve(Vector<double> &b) const override;
    /** dst = A^{-1} src (the interface of an inverse operator). */
    void
    vmult(Vector<double> &dst, const Vector<double> &src) const;
    /**
     * Overwrites the @p n_columns vectors of length n() stored one after
     * the other from @p columns by A^{-1} times them, in calls of CHOLMOD
     * on up to 64 columns each (its supernodal substitutions then work on
     * blocks of columns: cheaper per column than one solve() each; its
     * workspace, kept between solves, is of that many vectors).
     */
    void
    solve(double *columns, const unsigned int n_columns) const;

    /**
     * The DoFs given as @p last to factorize(), in the order in which they
     * are the trailing rows of L.
     */
    const std::vector<types::global_dof_index> &
    trailing_dofs() const;

    /**
     * The trailing block L_BB of L (lower triangular), rows and columns in
     * the order of trailing_dofs().
     */
    FullMatrix<double>
    trailing_factor() const;

    /**
     * (A^{-1})_BB = (L_BB L_BB^T)^{-1}, rows and columns in the order of
     * trailing_dofs().
     */
    FullMatrix<double>
    trailing_inverse() const;

    /**
     * How many factorisations so far (in this process) reused the symbolic
     * analysis of an earlier one: a matrix with the pattern and the DoFs
     * ordered last of one of the last two factorised gets a copy of its
     * analysis (the same ordering and structure, hence the same factor
     * bit for bit) and pays the numeric factorisation only.
     */
    static unsigned long
    n_shared_analyses();

    /**
     * Factorisation f of @p factorisations, made on rank @p roots[f] of
     * @p comm, on every rank: the root's object, a copy of its factor on
     * the others (the same numbers, bit for bit, so that their solves give
     * the same results as the root's). The entries of @p factorisations
     * are read on their roots only. All factors travel at once (a rank
     * sends its own while it receives the others'). Collective.
     */
    static std::vector<std::shared_ptr<const SparseCholesky>>
    broadcast(
      const std::vector<std::shared_ptr<const SparseCholesky>> &factorisations,
      const std::vector<unsigned int>                          &roots,
      const MPI_Comm                                            comm);

    /** Entries of L, and the bytes CHOLMOD holds for the factorisation. */
    double
    n_factor_entries() const;
    /**
     * Floating-point operations of the numeric factorisation (CHOLMOD's
     * count from the symbolic analysis): with n_factor_entries(), what a
     * new factorisation costs against a solve (about 4 entries' worth).
     */
    double
    n_factor_flops() const;
    std::size_t
    memory_consumption() const;

  private:
    struct Data;
    std::unique_ptr<Data>                data;
    std::vector<types::global_dof_index> trailing;
  };
} // namespace FuzzyContact

#endif
