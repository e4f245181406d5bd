// A reduced basis T, orthonormal in the inner product of a mass matrix M
// (T^T M T = I), grown vector by vector with rank truncation, and the
// projections that reduced models need: T^T A T, T^T A Psi, C T, T^T f, and
// the expansion T y. Also the reduced generalised eigenproblem, solved by
// LAPACK.
//
// Orthonormalisation: classical Gram-Schmidt applied twice ("twice is
// enough", Giraud et al. 2005), in the M inner product, with M T kept so that
// no product with M is repeated. A candidate v is dropped when the M-norm of
// what is left of it after both passes is below
//
//     tolerance * max(||v||_M, reference)
//
// where reference is the size below which the candidate's content is
// negligible in absolute terms (1 for Taylor coefficients of M-normalised
// modes with respect to relative parameter changes). The basis keeps the
// order in which vectors were added, so the leading columns of T span the
// vectors added first: bases of increasing order are nested.

#ifndef fuzzycontact_reanalysis_reduced_basis_h
#define fuzzycontact_reanalysis_reduced_basis_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  class ReducedBasis
  {
  public:
    /**
     * An empty basis, orthonormal in the inner product of @p mass (which
     * must be symmetric positive semi-definite and outlive the basis).
     */
    ReducedBasis(const SparseMatrix<double> &mass, const double tolerance);

    /**
     * Orthonormalises @p v against the basis and appends it, unless it is
     * numerically dependent (see above); returns whether it was kept.
     */
    bool
    add(const Vector<double> &v, const double reference = 1.);

    /** Number of columns of T. */
    unsigned int
    size() const;
    /** Number of candidates dropped as dependent so far. */
    unsigned int
    n_dropped() const;
    double
    tolerance() const;

    /** The columns of T. */
    const std::vector<Vector<double>> &
    vectors() const;
    const Vector<double> &
    operator[](const unsigned int i) const;

    /** T^T A T, using the first @p n_columns columns (all by default). */
    FullMatrix<double>
    project(const SparseMatrix<double> &A,
            const unsigned int n_columns = numbers::invalid_unsigned_int) const;

    /** T^T A Psi. */
    FullMatrix<double>
    project(const SparseMatrix<double>        &A,
            const std::vector<Vector<double>> &Psi) const;

    /** T^T f. */
    Vector<double>
    project(const Vector<double> &f) const;

    /** C T for a (possibly rectangular) sparse C with n_dofs columns. */
    FullMatrix<double>
    apply(const SparseMatrix<double> &C) const;

    /** T y, for y of length <= size() (the leading columns). */
    Vector<double>
    expand(const Vector<double> &y) const;

    /** The columns T Y(:, j) for a coefficient matrix Y. */
    std::vector<Vector<double>>
    expand(const FullMatrix<double> &Y) const;

    /** max |T^T M T - I|, for checks. */
    double
    orthonormality_error() const;

  private:
    const SparseMatrix<double> *mass;
    double                      tolerance_;
    unsigned int                n_dropped_ = 0;
    std::vector<Vector<double>> T, MT;
  };


  /**
   * The lowest eigenpairs of a reduced symmetric-definite pencil.
   */
  struct ReducedEigenpairs
  {
    /** Ascending. */
    std::vector<double> eigenvalues;
    /** Column j: the B-normalised eigenvector (y^T B y = 1). */
    FullMatrix<double> vectors;
  };

  /**
   * The @p n_wanted lowest eigenpairs of A y = lambda B y, with A
   * symmetric and B symmetric positive definite (LAPACK dsygvx, selected by
   * index). Only the leading @p size x @p size blocks are used (all if
   * size is invalid_unsigned_int). Throws a message if B is not positive
   * definite.
   */
  ReducedEigenpairs
  solve_reduced_eigenproblem(
    const FullMatrix<double> &A,
    const FullMatrix<double> &B,
    const unsigned int        n_wanted,
    const unsigned int        size = numbers::invalid_unsigned_int);
} // namespace FuzzyContact

#endif
