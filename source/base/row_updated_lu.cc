#include <fuzzycontact/base/lapack_extras.h>
#include <fuzzycontact/base/row_updated_lu.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  namespace
  {
    // The 1-norm of the m x n column-major @p a (its largest column sum).
    double
    norm1(const double *a, const std::size_t m, const std::size_t n)
    {
      double norm = 0;
      for (std::size_t j = 0; j < n; ++j)
        {
          double column = 0;
          for (std::size_t i = 0; i < m; ++i)
            column += std::abs(a[j * m + i]);
          norm = std::max(norm, column);
        }
      return norm;
    }

    // LU factors of the n x n column-major @p a, whose 1-norm is @p norm,
    // in place, and LAPACK's estimate of its reciprocal condition number
    // (0 if it is singular).
    double
    factorise_in_place(std::vector<double>          &a,
                       const types::blas_int         n,
                       const double                  norm,
                       std::vector<types::blas_int> &pivots)
    {
      pivots.resize(n);
      types::blas_int info = 0;
      getrf(&n, &n, a.data(), &n, pivots.data(), &info);
      if (info != 0)
        return 0;
      if (n == 0)
        return 1; // (as dgecon)
      // 1 / (|A|_1 |A^{-1}|_1), |A^{-1}|_1 estimated as LAPACK's dgecon
      // does (the same estimator, dlacn2), but with the factors applied by
      // getrs: dgecon's triangular solves (dlatrs) guard against overflow
      // column by column and cost as much as a third of the factorisation
      // itself at a few hundred unknowns, where getrs is about ten times
      // cheaper. Overflow, possible only for a matrix that is singular to
      // working precision, gives a non-finite estimate: rcond 0.
      std::vector<double>          v(n), x(n);
      std::vector<types::blas_int> isgn(n);
      types::blas_int              kase = 0, isave[3] = {0, 0, 0};
      const types::blas_int        one          = 1;
      double                       inverse_norm = 0;
      while (true)
        {
          dlacn2_(&n,
                  v.data(),
                  x.data(),
                  isgn.data(),
                  &inverse_norm,
                  &kase,
                  isave);
          if (kase == 0)
            break;
          getrs(kase == 1 ? "N" : "T",
                &n,
                &one,
                a.data(),
                &n,
                pivots.data(),
                x.data(),
                &n,
                &info);
          if (info != 0)
            return 0.;
        }
      const double rcond = 1. / (inverse_norm * norm);
      return std::isfinite(rcond) && inverse_norm > 0 ? rcond : 0.;
    }
  } // namespace


  bool
  RowUpdatedLU::factorise(const std::vector<double> &A,
                          const unsigned int         size,
                          const double               min_rcond)
  {
    AssertDimension(A.size(), std::size_t(size) * size);
    clear();
    auto factors  = std::make_shared<Factors>();
    factors->lu   = A;
    factors->norm = norm1(A.data(), size, size);
    factors->rcond =
      factorise_in_place(factors->lu, size, factors->norm, factors->pivots);
    if (!(factors->rcond >= min_rcond) || size == 0)
      return false;
    factors->N         = size;
    factors->min_rcond = min_rcond;
    factors->matrix    = A;
    factors->column_of_row.assign(size, -1);
    f = std::move(factors);
    return true;
  }


  bool
  RowUpdatedLU::replace_rows(const std::vector<double>       &A,
                             const std::vector<unsigned int> &new_rows)
  {
    Assert(!empty(), ExcMessage("replace_rows() needs factors"));
    const unsigned int N = f->N;
    AssertDimension(A.size(), std::size_t(N) * N);
    restore();
    if (new_rows.empty())
      return true;
    const types::blas_int n = N, r = new_rows.size();

    // A0^{-1} e_i for the rows not asked before, in one back-substitution
    // of several right-hand sides.
    std::vector<unsigned int> missing;
    for (const unsigned int i : new_rows)
      {
        AssertIndexRange(i, N);
        if (f->column_of_row[i] < 0)
          missing.push_back(i);
      }
    if (!missing.empty())
      {
        std::vector<double>  &columns = f->columns;
        const types::blas_int k       = missing.size();
        const std::size_t     first   = columns.size();
        columns.resize(first + std::size_t(k) * N, 0.);
        for (types::blas_int j = 0; j < k; ++j)
          {
            columns[first + std::size_t(j) * N + missing[j]] = 1;
            f->column_of_row[missing[j]]                     = first / N + j;
          }
        types::blas_int info = 0;
        getrs("N",
              &n,
              &k,
              f->lu.data(),
              &n,
              f->pivots.data(),
              &columns[first],
              &n,
              &info);
        Assert(info == 0, ExcInternalError());
        f->n_columns += k;
      }

    // D = (A - A0)_R, Z = A0^{-1} E_R and C = I + D Z, factorised.
    D.resize(std::size_t(r) * N);
    Z.resize(std::size_t(N) * r);
    // (Column by column of A: the rows of one column lie together.)
    for (unsigned int c = 0; c < N; ++c)
      {
        const double *a  = &A[std::size_t(c) * N],
                     *a0 = &f->matrix[std::size_t(c) * N];
        double *d        = &D[std::size_t(c) * r];
        for (types::blas_int j = 0; j < r; ++j)
          d[j] = a[new_rows[j]] - a0[new_rows[j]];
      }
    for (types::blas_int j = 0; j < r; ++j)
      std::copy_n(&f->columns[std::size_t(f->column_of_row[new_rows[j]]) * N],
                  N,
                  &Z[std::size_t(j) * N]);
    C.assign(std::size_t(r) * r, 0.);
    const double alpha = 1, beta = 0;
    gemm("N",
         "N",
         &r,
         &r,
         &n,
         &alpha,
         D.data(),
         &r,
         Z.data(),
         &n,
         &beta,
         C.data(),
         &r);
    for (types::blas_int j = 0; j < r; ++j)
      C[std::size_t(j) * r + j] += 1;
    // M's condition, bounded by A0's and C's: with M^{-1} = (I - Z C^{-1}
    // D) A0^{-1}, 1 / rcond(M) <= (1 + |D| / |A0|) (1 + |Z| |C^{-1}| |D|)
    // / rcond(A0) in 1-norms, |C^{-1}| from C's condition estimate. A
    // replacement that makes M singular (C singular) is refused, as is one
    // that makes it too ill-conditioned to solve.
    const double norm_D = norm1(D.data(), r, N), norm_Z = norm1(Z.data(), N, r),
                 norm_C  = norm1(C.data(), r, r),
                 rcond_C = factorise_in_place(C, r, norm_C, C_pivots);
    if (!(rcond_C > 0) ||
        !(f->rcond / ((1 + norm_D / f->norm) *
                      (1 + norm_Z * norm_D / (rcond_C * norm_C))) >=
          f->min_rcond))
      return false;
    rows = new_rows;
    return true;
  }


  void
  RowUpdatedLU::vmult(Vector<double> &dst, const Vector<double> &src) const
  {
    Assert(!empty(), ExcMessage("vmult() needs factors"));
    AssertDimension(src.size(), f->N);
    dst                     = src;
    const types::blas_int n = f->N, one = 1;
    types::blas_int       info = 0;
    getrs("N",
          &n,
          &one,
          f->lu.data(),
          &n,
          f->pivots.data(),
          dst.data(),
          &n,
          &info);
    Assert(info == 0, ExcInternalError());
    if (rows.empty())
      return;
    // dst -= Z C^{-1} D dst.
    const types::blas_int r = rows.size();
    std::vector<double>   t(r);
    const double          alpha = 1, beta = 0, minus = -1;
    gemv("N",
         &r,
         &n,
         &alpha,
         D.data(),
         &r,
         dst.data(),
         &one,
         &beta,
         t.data(),
         &one);
    getrs("N", &r, &one, C.data(), &r, C_pivots.data(), t.data(), &r, &info);
    Assert(info == 0, ExcInternalError());
    gemv("N",
         &n,
         &r,
         &minus,
         Z.data(),
         &n,
         t.data(),
         &one,
         &alpha,
         dst.data(),
         &one);
  }


  void
  RowUpdatedLU::restore()
  {
    rows.clear();
  }


  void
  RowUpdatedLU::clear()
  {
    f.reset();
    rows.clear();
    D.clear();
    Z.clear();
    C.clear();
    C_pivots.clear();
  }


  bool
  RowUpdatedLU::empty() const
  {
    return f == nullptr;
  }


  unsigned int
  RowUpdatedLU::size() const
  {
    return f == nullptr ? 0 : f->N;
  }


  const std::vector<unsigned int> &
  RowUpdatedLU::replaced_rows() const
  {
    return rows;
  }


  unsigned long
  RowUpdatedLU::n_cached_columns() const
  {
    return f == nullptr ? 0 : f->n_columns;
  }


  double
  RowUpdatedLU::rcond() const
  {
    return f == nullptr ? 0 : f->rcond;
  }
} // namespace FuzzyContact
