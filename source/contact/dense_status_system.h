// The dense system with friction of StatusSolver (status_solver.h) over
// the closed nodes' forces and the free motions, gathered from W's
// columns, with only the rows whose equation changed made anew. Not a
// public header: only status_solver.cc uses it.

#ifndef fuzzycontact_contact_dense_status_system_h
#define fuzzycontact_contact_dense_status_system_h

#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/contact/status_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace FuzzyContact
{
  // The system with friction of @p unknowns as a dense column-major N x N
  // matrix, from W's contiguous columns: per closed node k (unknowns
  // p_n, p_t at 2i, 2i + 1) its normal equation, a row of W, and its
  // tangential one, a row of W if it sticks, W_tt (p_t - mu s p_n) = 0 if
  // it slips; the free motions' columns and equilibrium rows scaled by
  // @p scale, as in StatusSystem.
  class DenseSystem
  {
  public:
    DenseSystem(FlexibilityOperator              &W,
                const StatusSolver::Unknowns     &unknowns,
                const std::vector<ContactStatus> &status,
                const std::vector<int>           &sign,
                const std::vector<double>        &mu,
                const RigidMotions               *rigid,
                const double                      scale)
        : W(W)
        , unknowns(unknowns)
        , closed(unknowns.closed)
        , status(status)
        , sign(sign)
        , mu(mu)
        , rigid(rigid)
        , scale(scale)
        , m(2 * closed.size())
        , N(unknowns.size())
    {
    }

    // The whole matrix.
    void
    gather(std::vector<double> &A) const
    {
      // Every entry is written once (no clearing first: the matrix is
      // assembled anew at every new W).
      A.resize(std::size_t(N) * N);
      // W's column of each unknown c < m, all of them at once: a part of
      // W that changes with the state (reduced_model_flexibility.h)
      // combines many missing columns as one matrix product, where one
      // column at a time would read its whole factor per column.
      std::vector<unsigned int> columns(m);
      for (unsigned int c = 0; c < m; ++c)
        columns[c] = row_of_W(c);
      W.prepare(columns);
      // Unknown c's row of W (W is symmetric: its column), or -1 where
      // the equation is not W's.
      std::vector<int> rows(m);
      for (unsigned int c = 0; c < m; ++c)
        rows[c] = c % 2 == 0 || status[closed[c / 2]] == ContactStatus::stick
                    ? int(columns[c])
                    : -1;
      for (unsigned int c = 0; c < m; ++c)
        {
          const double *w      = W.column(columns[c]);
          double       *column = &A[std::size_t(c) * N];
          for (unsigned int r = 0; r < m; ++r)
            column[r] = rows[r] >= 0 ? w[rows[r]] : 0.;
        }
      for (unsigned int r = 1; r < m; r += 2)
        if (rows[r] < 0)
          slip_row(r, A);
      if (unknowns.n_motions == 0)
        return;
      const FullMatrix<double> &G = rigid->gaps;
      for (unsigned int j = 0; j < unknowns.n_motions; ++j)
        {
          double *column = &A[std::size_t(m + j) * N];
          for (unsigned int r = 0; r < m; ++r)
            column[r] = rows[r] >= 0 ? scale * G(rows[r], j) : 0.;
          std::fill(column + m, column + N, 0.);
          for (unsigned int c = 0; c < m; ++c)
            A[std::size_t(c) * N + m + j] = scale * G(row_of_W(c), j);
        }
    }

    // The rows @p rows (the tangential equations 2i + 1 of closed nodes
    // whose status or friction coefficient changed) of a matrix @p A
    // that gather() assembled for the same unknowns, W and scale, made
    // anew for the statuses now. W is symmetric, so the row of W that a
    // sticking node's equation needs is its column: one column per row,
    // instead of all of them.
    void
    regather(const std::vector<unsigned int> &rows,
             std::vector<double>             &A) const
    {
      AssertDimension(A.size(), std::size_t(N) * N);
      for (const unsigned int r : rows)
        {
          Assert(r % 2 == 1 && r < m, ExcInternalError());
          if (status[closed[r / 2]] == ContactStatus::stick)
            {
              const double *w = W.column(row_of_W(r));
              for (unsigned int c = 0; c < m; ++c)
                A[std::size_t(c) * N + r] = w[row_of_W(c)];
              for (unsigned int j = 0; j < unknowns.n_motions; ++j)
                A[std::size_t(m + j) * N + r] =
                  scale * rigid->gaps(row_of_W(r), j);
            }
          else
            {
              for (unsigned int c = 0; c < N; ++c)
                A[std::size_t(c) * N + r] = 0;
              slip_row(r, A);
            }
        }
    }

  private:
    // The row of W of unknown c < m (p_n or p_t of a closed node).
    unsigned int
    row_of_W(const unsigned int c) const
    {
      return c % 2 == 0 ? normal_row(closed[c / 2])
                        : tangential_row(closed[c / 2]);
    }

    // A slipping node's tangential equation (row r = 2i + 1, zero
    // elsewhere): W_tt (p_t - mu s p_n) = 0.
    void
    slip_row(const unsigned int r, std::vector<double> &A) const
    {
      const unsigned int k = closed[r / 2];
      // (W_tt = 0 at a node held tangentially on both bodies, which has
      // no friction: its row is then p_t = 0, scaled by W_nn.)
      const double d                = W.diagonal(tangential_row(k)) != 0
                                        ? W.diagonal(tangential_row(k))
                                        : W.diagonal(normal_row(k));
      A[std::size_t(r) * N + r]     = d;
      A[std::size_t(r - 1) * N + r] = -d * mu[k] * sign[k];
    }

    FlexibilityOperator              &W;
    const StatusSolver::Unknowns     &unknowns;
    const std::vector<unsigned int>  &closed;
    const std::vector<ContactStatus> &status;
    const std::vector<int>           &sign;
    const std::vector<double>        &mu;
    const RigidMotions               *rigid;
    const double                      scale;
    const unsigned int                m, N;
  };
} // namespace FuzzyContact

#endif
