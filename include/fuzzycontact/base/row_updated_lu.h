// A dense LU factorisation kept while rows of its matrix are replaced.
//
// The exact contact solver with friction solves, many times over, dense
// systems that differ from one another in a few rows (a node turned from
// sticking to slipping replaces its tangential equation). A new LU
// factorisation per change costs O(N^3); this class keeps the factors of a
// matrix A0 and solves with M, A0 whose rows R are replaced by those of
// another matrix A, by the Sherman-Morrison-Woodbury formula:
//
//   M = A0 + E_R D,   D = (A - A0)_R   (r x N, the changed rows),
//   M^{-1} v = y - Z C^{-1} D y,   y = A0^{-1} v,   Z = A0^{-1} E_R,
//   C = I + D Z   (r x r, the capacitance matrix).
//
// The columns A0^{-1} e_i are computed once per row i (one back-
// substitution each) and kept for as long as the factors are, so a row
// that changes again, or back, costs nothing more; a solve costs one back-
// substitution and O(r N). Where M is only close to the matrix to solve
// (the caller's other rows moved a little too), it is the preconditioner
// of an iterative solver. LAPACK's getrf/getrs factorise and solve; the
// condition of A0 is estimated once (LAPACK's estimator) and that of C
// checked, so a replacement that makes M singular is refused, not solved.

#ifndef fuzzycontact_base_row_updated_lu_h
#define fuzzycontact_base_row_updated_lu_h

#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  class RowUpdatedLU
  {
  public:
    /**
     * Factorises the N x N column-major matrix @p A (kept as A0; no row
     * replaced). False, and the object empty, if A is singular or its
     * reciprocal condition number (1-norm, LAPACK's estimate) is below
     * @p min_rcond.
     */
    bool
    factorise(const std::vector<double> &A,
              const unsigned int         N,
              const double               min_rcond);

    /**
     * Replaces the rows @p rows of A0 by those of @p A (N x N, column-
     * major; only those rows are read). An empty list goes back to A0.
     * False if the replaced matrix is numerically singular (a bound of
     * its reciprocal condition number, from A0's and the capacitance
     * matrix's, below factorise()'s @p min_rcond): then no row is
     * replaced.
     */
    bool
    replace_rows(const std::vector<double>       &A,
                 const std::vector<unsigned int> &rows);

    /** Back to A0: no row replaced (the kept columns stay). */
    void
    restore();

    /** dst = M^{-1} src, M the factorised matrix with the rows replaced. */
    void
    vmult(Vector<double> &dst, const Vector<double> &src) const;

    /** Forgets the factors. */
    void
    clear();
    bool
    empty() const;
    unsigned int
    size() const;
    /** The rows replaced now. */
    const std::vector<unsigned int> &
    replaced_rows() const;
    /** Back-substitutions made for the columns A0^{-1} e_i so far. */
    unsigned long
    n_cached_columns() const;
    /**
     * The estimate of A0's reciprocal condition number in the 1-norm
     * (LAPACK's estimator, dlacn2, with getrs's solves); 0 without factors.
     */
    double
    rcond() const;

  private:
    // What belongs to A0: A0, its 1-norm and reciprocal condition number,
    // the least one accepted for the matrix with rows replaced, its LU
    // factors, and A0^{-1} e_i for the rows asked so far (column position
    // per row, or -1). Copies of a RowUpdatedLU share it (a copy costs no
    // O(N^2) data, and the columns one of them computes serve all); a new
    // factorisation makes a new one.
    struct Factors
    {
      unsigned int                 N = 0;
      std::vector<double>          matrix;
      double                       norm = 0, rcond = 0, min_rcond = 0;
      std::vector<double>          lu;
      std::vector<types::blas_int> pivots;
      std::vector<int>             column_of_row;
      std::vector<double>          columns;
      unsigned long                n_columns = 0;
    };
    std::shared_ptr<Factors> f;
    // The rows replaced now: D (r x N, column-major), Z (N x r) and the LU
    // factors of C (r x r).
    std::vector<unsigned int>    rows;
    std::vector<double>          D, Z, C;
    std::vector<types::blas_int> C_pivots;
  };
} // namespace FuzzyContact

#endif
