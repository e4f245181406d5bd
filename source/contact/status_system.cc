#include <fuzzycontact/base/row_updated_lu.h>
#include <fuzzycontact/contact/status_system.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  Vector<double>
  solve_dense(const FullMatrix<double> &A, const Vector<double> &b)
  {
    const types::blas_int n = A.m();
    Vector<double>        x(b);
    if (n == 0)
      return x;
    // LAPACK's LU where its condition estimate allows, else least squares.
    std::vector<double> columns(std::size_t(n) * n);
    for (types::blas_int j = 0; j < n; ++j)
      for (types::blas_int i = 0; i < n; ++i)
        columns[i + j * n] = A(i, j);
    RowUpdatedLU lu;
    if (lu.factorise(columns, n, 1e-13))
      {
        lu.vmult(x, b);
        return x;
      }
    LAPACKFullMatrix<double> pinv(n, n);
    pinv = A;
    pinv.compute_inverse_svd(1e-13);
    pinv.vmult(x, b);
    return x;
  }


  StatusSystem::StatusSystem(FlexibilityOperator              &W,
                             const std::vector<ContactStatus> &status,
                             const std::vector<int>           &sign,
                             const std::vector<double>        &mu,
                             const RigidMotions               *rigid)
      : n_motions(rigid == nullptr ? 0 : rigid->size())
  {
    for (unsigned int k = 0; k < status.size(); ++k)
      if (status[k] != ContactStatus::open)
        {
          closed.push_back(k);
          if (status[k] == ContactStatus::stick)
            sticking.push_back(k);
        }
    for (const unsigned int k : closed)
      {
        columns.push_back(normal_row(k));
        if (mu[k] > 0)
          columns.push_back(tangential_row(k));
      }
    W.prepare(columns);
    for (const unsigned int k : closed)
      rows.push_back(normal_row(k));
    for (const unsigned int k : sticking)
      rows.push_back(tangential_row(k));

    const unsigned int n_forces = rows.size(), size = n_forces + n_motions;
    A.reinit(size, size);
    for (unsigned int r = 0; r < n_forces; ++r)
      {
        const unsigned int i = rows[r];
        for (unsigned int c = 0; c < closed.size(); ++c)
          {
            const unsigned int k = closed[c];
            A(r, c)              = W(i, normal_row(k));
            if (status[k] == ContactStatus::slip && mu[k] > 0)
              A(r, c) += mu[k] * sign[k] * W(i, tangential_row(k));
          }
        for (unsigned int c = 0; c < sticking.size(); ++c)
          A(r, closed.size() + c) = W(i, tangential_row(sticking[c]));
      }
    if (n_motions == 0)
      return;

    // The free motions: G's rows in the gap equations, G^T in the
    // equilibrium ones, both scaled by the closed rows' mean flexibility.
    double sum = 0;
    for (const unsigned int k : closed)
      sum += W(normal_row(k), normal_row(k));
    scale                       = closed.empty() ? 1. : sum / closed.size();
    const FullMatrix<double> &G = rigid->gaps;
    for (unsigned int j = 0; j < n_motions; ++j)
      {
        for (unsigned int r = 0; r < n_forces; ++r)
          A(r, n_forces + j) = scale * G(rows[r], j);
        for (unsigned int c = 0; c < closed.size(); ++c)
          {
            const unsigned int k = closed[c];
            double             a = G(normal_row(k), j);
            if (status[k] == ContactStatus::slip && mu[k] > 0)
              a += mu[k] * sign[k] * G(tangential_row(k), j);
            A(n_forces + j, c) = scale * a;
          }
        for (unsigned int c = 0; c < sticking.size(); ++c)
          A(n_forces + j, closed.size() + c) =
            scale * G(tangential_row(sticking[c]), j);
      }
  }


  Vector<double>
  StatusSystem::solve(const Vector<double> &gap_rhs,
                      const Vector<double> &load) const
  {
    AssertDimension(gap_rhs.size(), rows.size());
    Vector<double> b(rows.size() + n_motions);
    for (unsigned int r = 0; r < rows.size(); ++r)
      b[r] = gap_rhs[r];
    for (unsigned int j = 0; j < n_motions; ++j)
      b[rows.size() + j] = -scale * load[j];
    return solve_dense(A, b);
  }


  Vector<double>
  StatusSystem::forces(const Vector<double>             &x,
                       const std::vector<ContactStatus> &status,
                       const std::vector<int>           &sign,
                       const std::vector<double>        &mu) const
  {
    Vector<double> p(2 * status.size());
    for (unsigned int c = 0; c < closed.size(); ++c)
      {
        const unsigned int k = closed[c];
        p[normal_row(k)]     = x[c];
        if (status[k] == ContactStatus::slip)
          p[tangential_row(k)] = mu[k] * sign[k] * x[c];
      }
    for (unsigned int c = 0; c < sticking.size(); ++c)
      p[tangential_row(sticking[c])] = x[closed.size() + c];
    return p;
  }


  Vector<double>
  StatusSystem::amplitudes(const Vector<double> &x) const
  {
    Vector<double> a(n_motions);
    for (unsigned int j = 0; j < n_motions; ++j)
      a[j] = scale * x[rows.size() + j];
    return a;
  }


  Vector<double>
  gaps_of(FlexibilityOperator             &W,
          const Vector<double>            &g_free,
          const Vector<double>            &p,
          const std::vector<unsigned int> &columns,
          const LoadStep                  *step,
          const Vector<double>            &a)
  {
    Vector<double> g = g_free;
    W.add_columns(columns, p, g);
    if (step != nullptr)
      add_rigid_gaps(*step, a, g);
    return g;
  }
} // namespace FuzzyContact
