#include <fuzzycontact/reanalysis/reduced_basis.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  ReducedBasis::ReducedBasis(const SparseMatrix<double> &mass,
                             const double                tolerance)
      : mass(&mass)
      , tolerance_(tolerance)
  {
    AssertThrow(tolerance > 0 && tolerance < 1,
                ExcMessage("truncation tolerance must lie in (0, 1), got " +
                           std::to_string(tolerance) + "."));
  }


  bool
  ReducedBasis::add(const Vector<double> &v, const double reference)
  {
    Vector<double> w(v), Mw(v.size());
    mass->vmult(Mw, w);
    const double norm_before = std::sqrt(std::max(w * Mw, 0.));
    if (!std::isfinite(norm_before))
      AssertThrow(false,
                  ExcMessage("reduced basis: a candidate vector is not "
                             "finite."));

    // Two passes of classical Gram-Schmidt: c = T^T M w = (M T)^T w.
    for (unsigned int pass = 0; pass < 2; ++pass)
      {
        std::vector<double> c(T.size());
        for (unsigned int i = 0; i < T.size(); ++i)
          c[i] = MT[i] * w;
        for (unsigned int i = 0; i < T.size(); ++i)
          w.add(-c[i], T[i]);
      }
    mass->vmult(Mw, w);
    const double norm_after = std::sqrt(std::max(w * Mw, 0.));
    if (!(norm_after > tolerance_ * std::max(norm_before, reference)))
      {
        ++n_dropped_;
        return false;
      }
    w /= norm_after;
    Mw /= norm_after;
    T.push_back(std::move(w));
    MT.push_back(std::move(Mw));
    return true;
  }


  unsigned int
  ReducedBasis::size() const
  {
    return T.size();
  }


  unsigned int
  ReducedBasis::n_dropped() const
  {
    return n_dropped_;
  }


  double
  ReducedBasis::tolerance() const
  {
    return tolerance_;
  }


  const std::vector<Vector<double>> &
  ReducedBasis::vectors() const
  {
    return T;
  }


  const Vector<double> &
  ReducedBasis::operator[](const unsigned int i) const
  {
    AssertIndexRange(i, T.size());
    return T[i];
  }


  FullMatrix<double>
  ReducedBasis::project(const SparseMatrix<double> &A,
                        const unsigned int          n_columns) const
  {
    const unsigned int n = std::min<unsigned int>(n_columns, T.size());
    FullMatrix<double> result(n, n);
    Vector<double>     At(T.empty() ? 0 : T[0].size());
    for (unsigned int j = 0; j < n; ++j)
      {
        A.vmult(At, T[j]);
        for (unsigned int i = 0; i <= j; ++i)
          result(i, j) = T[i] * At;
      }
    // A is symmetric here (stiffness and mass matrices): mirror the
    // computed upper triangle, which halves the work.
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = j + 1; i < n; ++i)
        result(i, j) = result(j, i);
    return result;
  }


  FullMatrix<double>
  ReducedBasis::project(const SparseMatrix<double>        &A,
                        const std::vector<Vector<double>> &Psi) const
  {
    FullMatrix<double> result(T.size(), Psi.size());
    Vector<double>     APsi(A.m());
    for (unsigned int j = 0; j < Psi.size(); ++j)
      {
        A.vmult(APsi, Psi[j]);
        for (unsigned int i = 0; i < T.size(); ++i)
          result(i, j) = T[i] * APsi;
      }
    return result;
  }


  Vector<double>
  ReducedBasis::project(const Vector<double> &f) const
  {
    Vector<double> result(T.size());
    for (unsigned int i = 0; i < T.size(); ++i)
      result[i] = T[i] * f;
    return result;
  }


  FullMatrix<double>
  ReducedBasis::apply(const SparseMatrix<double> &C) const
  {
    FullMatrix<double> result(C.m(), T.size());
    Vector<double>     Ct(C.m());
    for (unsigned int j = 0; j < T.size(); ++j)
      {
        C.vmult(Ct, T[j]);
        for (unsigned int i = 0; i < C.m(); ++i)
          result(i, j) = Ct[i];
      }
    return result;
  }


  Vector<double>
  ReducedBasis::expand(const Vector<double> &y) const
  {
    AssertThrow(y.size() <= T.size(),
                ExcMessage("reduced basis: more coefficients than columns."));
    Vector<double> u(T.empty() ? 0 : T[0].size());
    for (unsigned int i = 0; i < y.size(); ++i)
      u.add(y[i], T[i]);
    return u;
  }


  std::vector<Vector<double>>
  ReducedBasis::expand(const FullMatrix<double> &Y) const
  {
    std::vector<Vector<double>> result;
    Vector<double>              y(Y.m());
    for (unsigned int j = 0; j < Y.n(); ++j)
      {
        for (unsigned int i = 0; i < Y.m(); ++i)
          y[i] = Y(i, j);
        result.push_back(expand(y));
      }
    return result;
  }


  double
  ReducedBasis::orthonormality_error() const
  {
    double error = 0;
    for (unsigned int i = 0; i < T.size(); ++i)
      for (unsigned int j = 0; j < T.size(); ++j)
        error = std::max(error, std::abs(T[i] * MT[j] - (i == j ? 1. : 0.)));
    return error;
  }


  ReducedEigenpairs
  solve_reduced_eigenproblem(const FullMatrix<double> &A,
                             const FullMatrix<double> &B,
                             const unsigned int        n_wanted,
                             const unsigned int        size)
  {
    const unsigned int n = std::min<unsigned int>(size, A.m());
    AssertThrow(n <= B.m() && n <= A.n() && n <= B.n(),
                ExcMessage("reduced eigenproblem: matrix sizes differ."));
    AssertThrow(n_wanted >= 1 && n_wanted <= n,
                ExcMessage("reduced eigenproblem: " + std::to_string(n_wanted) +
                           " eigenpairs wanted from a basis of " +
                           std::to_string(n) + " vectors."));
    // Column-major copies of the leading blocks (symmetric, so the layout
    // only matters for the upper triangle LAPACK reads).
    std::vector<double> a(n * n), b(n * n);
    for (unsigned int j = 0; j < n; ++j)
      for (unsigned int i = 0; i < n; ++i)
        {
          a[i + j * n] = A(i, j);
          b[i + j * n] = B(i, j);
        }
    const types::blas_int        itype = 1, N = n, il = 1, iu = n_wanted;
    const char                   jobz = 'V', range = 'I', uplo = 'U';
    const double                 vl = 0, vu = 0;
    const double                 abstol = 0; // LAPACK's default accuracy
    types::blas_int              found = 0, info = 0;
    std::vector<double>          w(n), z(n * n_wanted);
    const types::blas_int        lwork = std::max<types::blas_int>(1, 40 * n);
    std::vector<double>          work(lwork);
    std::vector<types::blas_int> iwork(5 * n), ifail(n);
    const types::blas_int        ldz = N;
    sygvx(&itype,
          &jobz,
          &range,
          &uplo,
          &N,
          a.data(),
          &N,
          b.data(),
          &N,
          &vl,
          &vu,
          &il,
          &iu,
          &abstol,
          &found,
          w.data(),
          z.data(),
          &ldz,
          work.data(),
          &lwork,
          iwork.data(),
          ifail.data(),
          &info);
    AssertThrow(!(info > 0 && info <= N),
                ExcMessage("reduced eigenproblem: LAPACK dsygvx failed with "
                           "info = " +
                           std::to_string(info) +
                           " (some eigenvectors did not converge)."));
    AssertThrow(info == 0,
                ExcMessage("reduced eigenproblem: the reduced mass matrix is "
                           "not positive definite (LAPACK dsygvx info = " +
                           std::to_string(info) +
                           "); the basis is numerically dependent."));
    AssertThrow(static_cast<unsigned int>(found) == n_wanted,
                ExcMessage("reduced eigenproblem: LAPACK returned " +
                           std::to_string(found) + " of " +
                           std::to_string(n_wanted) + " eigenpairs."));
    ReducedEigenpairs result;
    result.eigenvalues.assign(w.begin(), w.begin() + n_wanted);
    result.vectors.reinit(n, n_wanted);
    for (unsigned int j = 0; j < n_wanted; ++j)
      for (unsigned int i = 0; i < n; ++i)
        result.vectors(i, j) = z[i + j * n];
    return result;
  }
} // namespace FuzzyContact
