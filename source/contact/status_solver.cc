#include <fuzzycontact/base/lapack_extras.h>
#include <fuzzycontact/contact/status_solver.h>
#include <fuzzycontact/contact/status_system.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_templates.h>
#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/solver_gmres.h>

#include "dense_status_system.h"
#include <algorithm>
#include <cmath>
#include <limits>

namespace FuzzyContact
{
  namespace
  {
    // A dense column-major matrix for GMRES.
    class DenseOperator
    {
    public:
      DenseOperator(const std::vector<double> &A, const unsigned int N)
          : A(A)
          , N(N)
      {
      }
      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        const types::blas_int n = N, one = 1;
        const double          alpha = 1, beta = 0;
        gemv("N",
             &n,
             &n,
             &alpha,
             A.data(),
             &n,
             src.data(),
             &one,
             &beta,
             dst.data(),
             &one);
      }

    private:
      const std::vector<double> &A;
      const unsigned int         N;
    };

    // The symmetric system P = [W_BB, G'_B; G'_B^T, 0] (G' = scale G) by
    // block elimination on the Cholesky factor: with Y = W_BB^{-1} G'_B and
    // the Schur complement S = G'_B^T Y, a = S^+ (Y^T u - v) and x =
    // W_BB^{-1} u - Y a. S is singular where the closed rows do not hold a
    // motion (the normal rows of a flat interface do not hold the sliding
    // along it): its pseudo-inverse leaves that amplitude at zero, the
    // minimum-norm answer of StatusSystem's dense path.
    class BlockPreconditioner
    {
    public:
      BlockPreconditioner(const ClosedSetFactor &factor,
                          const RigidMotions    *rigid,
                          const double           scale)
          : factor(factor)
      {
        const std::vector<unsigned int> &rows = factor.rows();
        const unsigned int               m    = rows.size();
        const unsigned int n_m = rigid == nullptr ? 0 : rigid->size();
        if (n_m == 0)
          return;
        const FullMatrix<double> &G = rigid->gaps;
        Y.reinit(n_m, m);
        Vector<double> y(m);
        for (unsigned int j = 0; j < n_m; ++j)
          {
            for (unsigned int c = 0; c < m; ++c)
              y[c] = scale * G(rows[c], j);
            factor.solve(y);
            for (unsigned int c = 0; c < m; ++c)
              Y(j, c) = y[c];
          }
        LAPACKFullMatrix<double> S(n_m, n_m);
        for (unsigned int i = 0; i < n_m; ++i)
          for (unsigned int j = 0; j < n_m; ++j)
            {
              double s = 0;
              for (unsigned int c = 0; c < m; ++c)
                s += scale * G(rows[c], i) * Y(j, c);
              S(i, j) = s;
            }
        S.compute_inverse_svd(1e-10);
        S_inverse.reinit(n_m, n_m);
        Vector<double> e(n_m), column(n_m);
        for (unsigned int j = 0; j < n_m; ++j)
          {
            e    = 0;
            e[j] = 1;
            S.vmult(column, e);
            for (unsigned int i = 0; i < n_m; ++i)
              S_inverse(i, j) = column[i];
          }
      }

      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        const unsigned int m = factor.size(), n_m = Y.m();
        Vector<double>     x(m);
        for (unsigned int c = 0; c < m; ++c)
          x[c] = src[c];
        if (n_m > 0)
          {
            Vector<double> r(n_m), a(n_m);
            for (unsigned int j = 0; j < n_m; ++j)
              {
                double s = 0;
                for (unsigned int c = 0; c < m; ++c)
                  s += Y(j, c) * src[c];
                r[j] = s - src[m + j];
              }
            S_inverse.vmult(a, r);
            factor.solve(x);
            for (unsigned int j = 0; j < n_m; ++j)
              {
                for (unsigned int c = 0; c < m; ++c)
                  x[c] -= Y(j, c) * a[j];
                dst[m + j] = a[j];
              }
          }
        else
          factor.solve(x);
        for (unsigned int c = 0; c < m; ++c)
          dst[c] = x[c];
      }

    private:
      const ClosedSetFactor &factor;
      FullMatrix<double>     Y; // row j: W_BB^{-1} G'_B e_j
      FullMatrix<double>     S_inverse;
    };

  } // namespace

  // The GMRES solves of one StatusSolver, on one SolverControl and one
  // deal.II SolverGMRES kept from solve to solve (making them costs as much
  // as a few GMRES steps on these small systems).
  struct StatusSolver::Krylov
  {
    SolverControl               control{gmres_max_steps, 0., false, false};
    SolverGMRES<Vector<double>> solver{
      control,
      SolverGMRES<Vector<double>>::AdditionalData(gmres_max_steps + 2, true)};

    // The system @p A of size N solved by its preconditioner @p P (exact
    // where P is A's inverse: then the residual, one product with A, says
    // so) or else by GMRES from there; false if GMRES does not reach the
    // tolerance in the steps allowed.
    template <class Preconditioner>
    bool
    solve(const std::vector<double> &A,
          const Preconditioner      &P,
          const Vector<double>      &b,
          Vector<double>            &x,
          StatusSolver::Counts      &counts)
    {
      const DenseOperator operator_A(A, b.size());
      const double tolerance = StatusSolver::gmres_tolerance * b.l2_norm();
      x.reinit(b.size());
      P.vmult(x, b);
      residual.reinit(b.size(), true);
      operator_A.vmult(residual, x);
      residual.sadd(-1., b);
      const double reduction = residual.l2_norm() / b.l2_norm();
      if (!(reduction > StatusSolver::gmres_tolerance))
        return true;
      // P far from A's inverse (a point far from the factorised one):
      // GMRES, which reduces the residual by about as much per step as P
      // did, or faster, would take more than twice the steps after which
      // the factors are made anew anyway; none.
      if (std::pow(reduction, 2 * StatusSolver::gmres_refresh_steps) >
          StatusSolver::gmres_tolerance)
        return false;
      control.set_tolerance(tolerance);
      ++counts.gmres;
      try
        {
          solver.solve(operator_A, x, b, P);
        }
      catch (const SolverControl::NoConvergence &)
        {
          counts.gmres_steps += control.last_step();
          return false;
        }
      counts.gmres_steps += control.last_step();
      return true;
    }
    Vector<double> residual;
  };

  StatusSolver::StatusSolver()                         = default;
  StatusSolver::~StatusSolver()                        = default;
  StatusSolver::StatusSolver(StatusSolver &&) noexcept = default;
  StatusSolver &
  StatusSolver::operator=(StatusSolver &&) noexcept = default;


  StatusSolver::Krylov &
  StatusSolver::krylov()
  {
    if (!krylov_)
      krylov_ = std::make_unique<Krylov>();
    return *krylov_;
  }


  std::vector<unsigned int>
  StatusSolver::Stamp::rows_differing_from(const Stamp &other) const
  {
    AssertDimension(key.size(), other.key.size());
    std::vector<unsigned int> rows;
    for (unsigned int i = 0; i + 1 < key.size(); ++i)
      if (key[i] != other.key[i])
        rows.push_back(2 * i + 1);
    return rows;
  }


  void
  StatusSolver::clear()
  {
    factor_.clear();
    lu = Stamp();
    factors.clear();
    matrix.clear();
    assembled = Stamp();
  }


  void
  StatusSolver::set_siblings(const std::vector<StatusSolver> *siblings)
  {
    this->siblings = siblings;
  }


  const StatusSolver::Counts &
  StatusSolver::counts() const
  {
    return counts_;
  }


  const ClosedSetFactor &
  StatusSolver::factor() const
  {
    return factor_;
  }


  bool
  StatusSolver::solve_symmetric(FlexibilityOperator             &W,
                                const std::vector<unsigned int> &B,
                                const RigidMotions              *rigid,
                                const double                     scale,
                                const Vector<double>            &b,
                                Vector<double>                  &x)
  {
    // The factor's rows, compared with B as sets.
    std::vector<unsigned int> out, in;
    std::vector<bool>         wanted(W.size(), false);
    for (const unsigned int r : B)
      {
        wanted[r] = true;
        if (factor_.position(r) < 0)
          in.push_back(r);
      }
    for (const unsigned int r : factor_.rows())
      if (!wanted[r])
        out.push_back(r);
    const bool stale       = factor_.size() > 0 && factor_.state() != W.state();
    const unsigned int n_m = rigid == nullptr ? 0 : rigid->size();

    // b in the factor's order, and x back in B's.
    const auto solve_on_factor = [&](const bool exact) {
      const unsigned int m = B.size(), N = m + n_m;
      Vector<double>     y(N), z(N);
      for (unsigned int c = 0; c < m; ++c)
        y[factor_.position(B[c])] = b[c];
      for (unsigned int j = m; j < N; ++j)
        y[j] = b[j];
      const BlockPreconditioner P(factor_, rigid, scale);
      if (exact)
        P.vmult(z, y);
      else
        {
          // The system at the current W, in the factor's order.
          const std::vector<unsigned int> &rows = factor_.rows();
          std::vector<double>              A(std::size_t(N) * N, 0.);
          for (unsigned int c = 0; c < m; ++c)
            {
              const double *w = W.column(rows[c]);
              for (unsigned int r = 0; r < m; ++r)
                A[std::size_t(c) * N + r] = w[rows[r]];
            }
          for (unsigned int j = 0; j < n_m; ++j)
            for (unsigned int c = 0; c < m; ++c)
              A[std::size_t(m + j) * N + c] = A[std::size_t(c) * N + m + j] =
                scale * rigid->gaps(rows[c], j);
          if (!krylov().solve(A, P, y, z, counts_))
            return false;
        }
      x.reinit(N);
      for (unsigned int c = 0; c < m; ++c)
        x[c] = z[factor_.position(B[c])];
      for (unsigned int j = m; j < N; ++j)
        x[j] = z[j];
      return true;
    };

    // The same rows at another W: the old factor preconditions GMRES.
    if (stale && in.empty() && out.empty() && solve_on_factor(false))
      return true;
    // Many rows to change, or another W: a new factorisation; else updates.
    if (stale || out.size() + in.size() > 8 + B.size() / 32)
      {
        if (!factor_.reset(W, B))
          return false;
      }
    else
      {
        // Rows out from the last one first (the cheapest updates).
        std::sort(out.begin(), out.end(), [this](const auto r, const auto s) {
          return factor_.position(r) > factor_.position(s);
        });
        for (const unsigned int r : out)
          factor_.erase(r);
        for (const unsigned int r : in)
          if (!factor_.insert(W, r))
            {
              if (!factor_.reset(W, B))
                return false;
              break;
            }
      }
    return solve_on_factor(true);
  }


  bool
  StatusSolver::solve_general(FlexibilityOperator              &W,
                              const Unknowns                   &unknowns,
                              const std::vector<ContactStatus> &status,
                              const std::vector<int>           &sign,
                              const std::vector<double>        &mu,
                              const RigidMotions               *rigid,
                              const double                      scale,
                              const Vector<double>             &b,
                              Vector<double>                   &x)
  {
    // What the system is: per closed node its tangential equation
    // (sticking, or mu s of slipping), and the scale.
    Stamp now{unknowns, {}, W.state()};
    for (const unsigned int k : unknowns.closed)
      now.key.push_back(status[k] == ContactStatus::stick
                          ? std::numeric_limits<double>::infinity()
                          : mu[k] * sign[k]);
    now.key.push_back(scale);
    const std::vector<double> &key = now.key;
    // Factors of another W: a sibling's of this W, if one is close enough,
    // instead (a far point: the first load step made them).
    if (siblings != nullptr &&
        !(!factors.empty() && lu.same_unknowns_and_W(now)))
      for (const StatusSolver &other : *siblings)
        if (&other != this && !other.factors.empty() &&
            other.lu.same_unknowns_and_W(now) &&
            other.lu.rows_differing_from(now).size() <=
              max_replaced_rows(unknowns.size()))
          {
            lu      = other.lu;
            factors = other.factors;
            ++counts_.adopted;
            break;
          }
    const bool kept   = !factors.empty() && unknowns == lu.unknowns;
    const bool same_W = !factors.empty() && lu.same_unknowns_and_W(now);
    if (same_W && key == lu.key)
      {
        factors.restore();
        factors.vmult(x, b);
        return true;
      }
    // The rows whose equation is not the factorised one: a node turned
    // from sticking to slipping, or back, or its slip reversed; at the same
    // W also a slipping node's other friction coefficient. The kept factors
    // take them by a row update (RowUpdatedLU), exactly; what else changed
    // (another W, friction coefficients at another W: every row a little)
    // is left to GMRES, preconditioned by the updated factors.
    // At the same W, rows whose friction coefficient changed are replaced
    // too, as long as they are few (a new friction coefficient at a
    // neighbouring point changes every slipping row: GMRES then).
    std::vector<unsigned int> changed, moved;
    if (kept)
      for (unsigned int i = 0; i + 1 < key.size(); ++i)
        {
          if (std::isinf(key[i]) != std::isinf(lu.key[i]) ||
              (key[i] < 0) != (lu.key[i] < 0))
            changed.push_back(2 * i + 1);
          else if (same_W && key[i] != lu.key[i])
            moved.push_back(2 * i + 1);
        }
    if (changed.size() + moved.size() <= max_replaced_rows(unknowns.size()))
      {
        changed.insert(changed.end(), moved.begin(), moved.end());
        std::sort(changed.begin(), changed.end());
      }
    // The system: at the same unknowns, W and scale as the one assembled
    // last, only the rows whose equation changed are made anew (most
    // iterations of the active-set method change a few nodes).
    std::vector<double> &A = matrix;
    const DenseSystem    system(W, unknowns, status, sign, mu, rigid, scale);
    if (!A.empty() && assembled.same_unknowns_and_W(now))
      system.regather(assembled.rows_differing_from(now), A);
    else
      system.gather(A);
    assembled = now;
    // If GMRES took more than a few steps, or too many rows changed, the
    // factors are made anew for this system (the next solve, at a
    // neighbouring point or the next iteration, is then close to them
    // again).
    const unsigned long steps_before = counts_.gmres_steps;
    const bool          answered =
      kept && changed.size() <= max_replaced_rows(unknowns.size()) &&
      factors.replace_rows(A, changed) &&
      krylov().solve(A, factors, b, x, counts_);
    counts_.row_updates += answered && !changed.empty();
    if (answered && counts_.gmres_steps - steps_before <= gmres_refresh_steps)
      return true;
    // A new factorisation, kept (none if LAPACK's condition estimate calls
    // the system singular).
    ++counts_.lu;
    if (!factors.factorise(A, unknowns.size(), 1e-13))
      return answered;
    lu = now;
    if (!answered)
      factors.vmult(x, b);
    return true;
  }


  void
  StatusSolver::solve(FlexibilityOperator              &W,
                      const std::vector<ContactStatus> &status,
                      const std::vector<int>           &sign,
                      const std::vector<double>        &mu,
                      const RigidMotions               *rigid,
                      const Vector<double>             &target,
                      const Vector<double>             &load,
                      Vector<double>                   &p,
                      Vector<double>                   &a)
  {
    ++counts_.solves;
    const unsigned int n   = status.size();
    const unsigned int n_m = rigid == nullptr ? 0 : rigid->size();
    AssertDimension(target.size(), 2 * n);
    // The closed nodes; the free motions scaled by the closed rows' mean
    // flexibility (StatusSystem's scale).
    Unknowns unknowns;
    unknowns.n_motions = n_m;
    double sum         = 0;
    bool   friction    = false;
    for (unsigned int k = 0; k < n; ++k)
      if (status[k] != ContactStatus::open)
        {
          unknowns.closed.push_back(k);
          sum += W.diagonal(normal_row(k));
          friction = friction || mu[k] > 0;
        }
    const unsigned int n_c   = unknowns.closed.size();
    const double       scale = n_c == 0 ? 1. : sum / n_c;

    bool solved = false;
    p.reinit(2 * n);
    a.reinit(n_m);
    if (n_c > 0 && !friction)
      {
        // Normal rows only: p_t = 0.
        std::vector<unsigned int> B;
        Vector<double>            b(n_c + n_m), x;
        for (unsigned int i = 0; i < n_c; ++i)
          {
            B.push_back(normal_row(unknowns.closed[i]));
            b[i] = target[B[i]];
          }
        for (unsigned int j = 0; j < n_m; ++j)
          b[n_c + j] = -scale * load[j];
        if ((solved = solve_symmetric(W, B, rigid, scale, b, x)))
          {
            for (unsigned int i = 0; i < n_c; ++i)
              p[B[i]] = x[i];
            for (unsigned int j = 0; j < n_m; ++j)
              a[j] = scale * x[n_c + j];
          }
      }
    else if (n_c > 0)
      {
        Vector<double> b(unknowns.size()), x;
        for (unsigned int i = 0; i < n_c; ++i)
          {
            const unsigned int k = unknowns.closed[i];
            b[2 * i]             = target[normal_row(k)];
            b[2 * i + 1] =
              status[k] == ContactStatus::stick ? target[tangential_row(k)] : 0;
          }
        for (unsigned int j = 0; j < n_m; ++j)
          b[2 * n_c + j] = -scale * load[j];
        if ((solved = solve_general(W,
                                    unknowns,
                                    status,
                                    sign,
                                    mu,
                                    rigid,
                                    scale,
                                    b,
                                    x)))
          {
            // A slipping node's friction force is mu s p_n, exactly (the
            // solve gives it to round-off: zero must stay zero without
            // friction).
            for (unsigned int i = 0; i < n_c; ++i)
              {
                const unsigned int k = unknowns.closed[i];
                p[normal_row(k)]     = x[2 * i];
                p[tangential_row(k)] = status[k] == ContactStatus::stick
                                         ? x[2 * i + 1]
                                         : mu[k] * sign[k] * x[2 * i];
              }
            for (unsigned int j = 0; j < n_m; ++j)
              a[j] = scale * x[2 * n_c + j];
          }
      }
    if (!solved)
      {
        // Numerically singular (or nothing closed): least squares.
        ++counts_.pseudo_inverse;
        const StatusSystem system(W, status, sign, mu, rigid);
        Vector<double>     rhs(system.rows.size());
        for (unsigned int r = 0; r < rhs.size(); ++r)
          rhs[r] = target[system.rows[r]];
        const Vector<double> y = system.solve(rhs, load);
        p                      = system.forces(y, status, sign, mu);
        a                      = system.amplitudes(y);
      }
  }
} // namespace FuzzyContact
