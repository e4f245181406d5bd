#include <fuzzycontact/contact/closed_set_factor.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>

namespace FuzzyContact
{
  namespace
  {
    // A pivot below this fraction of the row's own flexibility W_rr makes
    // the row numerically dependent on the rows already factorised.
    constexpr double dependence = 1e-12;
  } // namespace


  const std::vector<unsigned int> &
  ClosedSetFactor::rows() const
  {
    return rows_;
  }


  unsigned int
  ClosedSetFactor::size() const
  {
    return rows_.size();
  }


  int
  ClosedSetFactor::position(const unsigned int r) const
  {
    return r < positions.size() ? positions[r] : -1;
  }


  unsigned long
  ClosedSetFactor::state() const
  {
    return state_;
  }


  void
  ClosedSetFactor::clear()
  {
    for (const unsigned int r : rows_)
      positions[r] = -1;
    rows_.clear();
    state_ = 0;
  }


  void
  ClosedSetFactor::reserve(const unsigned int n)
  {
    if (n <= capacity)
      return;
    const unsigned int  new_capacity = std::max(n, 2 * capacity + 16);
    std::vector<double> grown(std::size_t(new_capacity) * new_capacity);
    const unsigned int  m = rows_.size();
    for (unsigned int j = 0; j < m; ++j)
      std::copy(&data[std::size_t(j) * capacity + j],
                &data[std::size_t(j) * capacity + m],
                &grown[std::size_t(j) * new_capacity + j]);
    data.swap(grown);
    capacity = new_capacity;
  }


  bool
  ClosedSetFactor::reset(FlexibilityOperator             &W,
                         const std::vector<unsigned int> &rows)
  {
    clear();
    ++n_resets;
    state_ = W.state();
    if (positions.size() < W.size())
      positions.resize(W.size(), -1);
    const unsigned int m = rows.size();
    reserve(m);
    for (unsigned int j = 0; j < m; ++j)
      {
        const double *column = W.column(rows[j]);
        for (unsigned int i = j; i < m; ++i)
          L(i, j) = column[rows[i]];
      }
    if (m > 0)
      {
        const types::blas_int n = m, lda = capacity;
        types::blas_int       info = 0;
        potrf("L", &n, data.data(), &lda, &info);
        if (info != 0)
          return false;
        // The same test of dependence as insert() makes.
        for (unsigned int j = 0; j < m; ++j)
          if (L(j, j) * L(j, j) <= dependence * W.diagonal(rows[j]))
            return false;
      }
    rows_ = rows;
    for (unsigned int i = 0; i < m; ++i)
      positions[rows_[i]] = i;
    return true;
  }


  bool
  ClosedSetFactor::insert(FlexibilityOperator &W, const unsigned int r)
  {
    Assert(W.state() == state_ || rows_.empty(),
           ExcMessage("The factor is of another state of W."));
    Assert(position(r) < 0, ExcMessage("The row is in the factor already."));
    if (rows_.empty())
      state_ = W.state();
    if (positions.size() < W.size())
      positions.resize(W.size(), -1);
    const unsigned int m = rows_.size();
    reserve(m + 1);
    // The new row of L: l = L^{-1} W_Br, stored in row m.
    const double       *column = W.column(r);
    std::vector<double> l(m);
    for (unsigned int i = 0; i < m; ++i)
      l[i] = column[rows_[i]];
    if (m > 0)
      {
        const types::blas_int n = m, lda = capacity, one = 1;
        types::blas_int       info = 0;
        trtrs("L", "N", "N", &n, &one, data.data(), &lda, l.data(), &n, &info);
        Assert(info == 0, ExcInternalError());
      }
    const double w_rr = column[r];
    const double pivot =
      w_rr - std::inner_product(l.begin(), l.end(), l.begin(), 0.);
    if (!(pivot > dependence * w_rr))
      return false;
    for (unsigned int j = 0; j < m; ++j)
      L(m, j) = l[j];
    L(m, m) = std::sqrt(pivot);
    rows_.push_back(r);
    positions[r] = m;
    ++n_inserts;
    return true;
  }


  void
  ClosedSetFactor::erase(const unsigned int r)
  {
    const int q = position(r);
    Assert(q >= 0, ExcMessage("The row is not in the factor."));
    const unsigned int m = rows_.size();
    // x: the column below the removed diagonal entry, taken up by the
    // trailing block.
    std::vector<double> x(m - q - 1);
    for (unsigned int i = q + 1; i < m; ++i)
      x[i - q - 1] = L(i, q);
    // Row q out of the columns before it.
    for (unsigned int j = 0; j < static_cast<unsigned int>(q); ++j)
      std::memmove(&L(q, j), &L(q + 1, j), sizeof(double) * (m - q - 1));
    // Column q out: the later columns move left and up by one.
    for (unsigned int j = q; j + 1 < m; ++j)
      std::memmove(&L(j, j), &L(j + 1, j + 1), sizeof(double) * (m - j - 1));
    // L_22 L_22^T + x x^T (LINPACK's dchud, by rotations).
    for (unsigned int k = q; k + 1 < m; ++k)
      {
        double      &lkk = L(k, k);
        const double xk  = x[k - q];
        const double rho = std::hypot(lkk, xk);
        const double c = rho / lkk, s = xk / lkk;
        lkk = rho;
        for (unsigned int i = k + 1; i + 1 < m; ++i)
          {
            double &lik = L(i, k);
            lik         = (lik + s * x[i - q]) / c;
            x[i - q]    = c * x[i - q] - s * lik;
          }
      }
    positions[r] = -1;
    rows_.erase(rows_.begin() + q);
    for (unsigned int i = q; i + 1 < m; ++i)
      positions[rows_[i]] = i;
    ++n_erases;
  }


  void
  ClosedSetFactor::solve(Vector<double> &x) const
  {
    AssertDimension(x.size(), rows_.size());
    if (rows_.empty())
      return;
    const types::blas_int n = rows_.size(), lda = capacity, one = 1;
    types::blas_int       info = 0;
    trtrs("L", "N", "N", &n, &one, data.data(), &lda, x.data(), &n, &info);
    Assert(info == 0, ExcInternalError());
    trtrs("L", "T", "N", &n, &one, data.data(), &lda, x.data(), &n, &info);
    Assert(info == 0, ExcInternalError());
  }
} // namespace FuzzyContact
