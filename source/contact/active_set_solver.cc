#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>

// LAPACK's condition estimate of an LU factorisation (not wrapped by
// deal.II).
extern "C" void
dgecon_(const char                    *norm,
        const dealii::types::blas_int *n,
        const double                  *a,
        const dealii::types::blas_int *lda,
        const double                  *anorm,
        double                        *rcond,
        double                        *work,
        dealii::types::blas_int       *iwork,
        dealii::types::blas_int       *info);

namespace FuzzyContact
{
  void
  ActiveSetParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact contact solver");
    prm.declare_entry("tolerance",
                      "1e-10",
                      Patterns::Double(),
                      "Relative complementarity residual at which the "
                      "primal-dual active set method stops.");
    prm.declare_entry("max iterations",
                      "200",
                      Patterns::Integer(),
                      "Active set iterations per load step before the "
                      "solver gives up with an error.");
    prm.leave_subsection();
  }

  void
  ActiveSetParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact contact solver");
    tolerance    = Input::positive(prm.get_double("tolerance"),
                                "Exact contact solver: tolerance");
    const long n = prm.get_integer("max iterations");
    AssertThrow(n >= 1,
                ExcMessage("Exact contact solver: max iterations must be at "
                           "least 1, got " +
                           std::to_string(n) + "."));
    max_iterations = n;
    prm.leave_subsection();
  }


  namespace
  {
    // Solves A x = b (A square, general) by LU with partial pivoting; if
    // LAPACK's condition estimate says A is numerically singular, by the
    // pseudo-inverse (least squares, minimum norm) instead.
    Vector<double>
    solve_dense(const FullMatrix<double> &A, const Vector<double> &b)
    {
      const types::blas_int n = A.m();
      Vector<double>        x(b);
      if (n == 0)
        return x;
      std::vector<double> lu(n * n);
      double              norm1 = 0;
      for (types::blas_int j = 0; j < n; ++j)
        {
          double column = 0;
          for (types::blas_int i = 0; i < n; ++i)
            {
              lu[i + j * n] = A(i, j);
              column += std::abs(A(i, j));
            }
          norm1 = std::max(norm1, column);
        }
      std::vector<types::blas_int> pivots(n);
      types::blas_int              info = 0;
      getrf(&n, &n, lu.data(), &n, pivots.data(), &info);
      Assert(info >= 0, ExcInternalError());
      double rcond = 0;
      if (info == 0)
        {
          std::vector<double>          work(4 * n);
          std::vector<types::blas_int> iwork(n);
          const char                   norm = '1';
          dgecon_(&norm,
                  &n,
                  lu.data(),
                  &n,
                  &norm1,
                  &rcond,
                  work.data(),
                  iwork.data(),
                  &info);
          Assert(info == 0, ExcInternalError());
        }
      if (rcond > 1e-13)
        {
          const char            trans = 'N';
          const types::blas_int one   = 1;
          getrs(&trans,
                &n,
                &one,
                lu.data(),
                &n,
                pivots.data(),
                x.data(),
                &n,
                &info);
          Assert(info == 0, ExcInternalError());
          return x;
        }
      LAPACKFullMatrix<double> pinv(n, n);
      pinv = A;
      pinv.compute_inverse_svd(1e-13);
      pinv.vmult(x, b);
      return x;
    }

    // A status with its slip direction, as one comparable key.
    std::vector<int>
    signature(const std::vector<ContactStatus> &status,
              const std::vector<int>           &sign)
    {
      std::vector<int> key(status.size());
      for (unsigned int k = 0; k < status.size(); ++k)
        key[k] =
          status[k] == ContactStatus::open
            ? 0
            : (status[k] == ContactStatus::stick ? 1 : 2 + (sign[k] > 0));
      return key;
    }

    // The linear system of a fixed status: unknowns p_n of the closed nodes,
    // then p_t of the sticking ones; equations g_n = 0 of the closed nodes,
    // then g_t = g_t,previous of the sticking ones.
    struct StatusSystem
    {
      std::vector<unsigned int> closed, sticking, rows, columns;
      FullMatrix<double>        A;

      StatusSystem(FlexibilityOperator              &W,
                   const std::vector<ContactStatus> &status,
                   const std::vector<int>           &sign,
                   const std::vector<double>        &mu)
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

        const unsigned int size = rows.size();
        A.reinit(size, size);
        for (unsigned int r = 0; r < size; ++r)
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
      }

      // The forces of a solution x of the system.
      Vector<double>
      forces(const Vector<double>             &x,
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
    };

    // g = g_free + W p, using only the columns where p is not zero.
    Vector<double>
    gaps_of(const FlexibilityOperator       &W,
            const Vector<double>            &g_free,
            const Vector<double>            &p,
            const std::vector<unsigned int> &columns)
    {
      Vector<double> g = g_free;
      for (const unsigned int j : columns)
        if (p[j] != 0)
          for (unsigned int i = 0; i < g.size(); ++i)
            g[i] += W(i, j) * p[j];
      return g;
    }

    // One load step of the method described in active_set_solver.h: the
    // statuses as they evolve, the iteration count over both phases, the
    // scaling of the complementarity functions, and the steps of the
    // method.
    class ActiveSetMethod
    {
    public:
      ActiveSetMethod(FlexibilityOperator       &W,
                      const LoadStep            &step,
                      const std::vector<double> &mu,
                      const ActiveSetParameters &parameters,
                      const std::string         &what)
          : W(W)
          , step(step)
          , mu(mu)
          , what(what)
          , n(mu.size())
          , tol(parameters.tolerance)
          , max_iterations(parameters.max_iterations)
          , cn(n, 0.)
          , ct(n, 0.)
          , c_n([this](const unsigned int k) {
            return diagonal_inverse(normal_row(k), cn, k);
          })
          , c_t([this](const unsigned int k) {
            return diagonal_inverse(tangential_row(k), ct, k);
          })
          , status(step.previous.status)
          , sign(step.previous.slip_sign)
      {
        if (status.size() != n)
          status.assign(n, ContactStatus::open);
        if (sign.size() != n)
          sign.assign(n, 0);
      }

      // Phase 1 unless warm started, then phase 2 until the residual is
      // at most the tolerance; throws otherwise.
      ContactState
      solve()
      {
        if (std::all_of(status.begin(),
                        status.end(),
                        [](const ContactStatus s) {
                          return s == ContactStatus::open;
                        }))
          frictionless_start();
        complete_statuses();

        // Phase 2: primal-dual active set iterations.
        ContactState               state;
        std::set<std::vector<int>> seen;
        seen.insert(signature(status, sign));
        bool   murty    = false;
        double residual = 0;
        while (true)
          {
            ++iterations;
            solve_with_statuses(state);

            // The stopping test: the relative complementarity residual.
            const std::vector<double> r =
              complementarity_residuals(state.p,
                                        state.g,
                                        step.g_previous,
                                        mu,
                                        c_n,
                                        c_t);
            const double scale = residual_scale(state.p, step.g_free, c_n);
            const double worst = *std::max_element(r.begin(), r.end());
            residual           = (worst == 0 ? 0. : worst / scale);
            state.iterations   = iterations;
            state.residual     = residual;
            if (residual <= tol)
              return converged(state);
            if (iterations >= max_iterations)
              break;

            std::vector<ContactStatus> new_status = status;
            std::vector<int>           new_sign   = sign;
            if (!predict_statuses(state, r, scale, murty, new_status, new_sign))
              {
                std::ostringstream message;
                message << what << ": the active set has settled after "
                        << iterations
                        << " iterations, but the complementarity residual is "
                        << residual << " > " << tol
                        << " (the active system is too ill-conditioned for "
                           "this tolerance).";
                AssertThrow(false, ExcMessage(message.str()));
              }
            // A cycle: from here on, one node per iteration (Murty's rule).
            if (seen.count(signature(new_status, new_sign)) > 0)
              {
                if (murty)
                  {
                    std::ostringstream message;
                    message << what << ": the active set cycles after "
                            << iterations
                            << " iterations, even under Murty's least-index "
                               "rule; complementarity residual "
                            << residual << ".";
                    AssertThrow(false, ExcMessage(message.str()));
                  }
                murty = true;
                seen.clear();
                murty_step(state, r, scale, new_status, new_sign);
              }
            seen.insert(signature(new_status, new_sign));
            status = new_status;
            sign   = new_sign;
          }

        std::ostringstream message;
        message << what
                << ": the active set method did not converge in max_iterations "
                   "= "
                << max_iterations << " iterations (load step " << step.step
                << "); complementarity residual " << residual << " > " << tol
                << ".";
        AssertThrow(false, ExcMessage(message.str()));
        return state;
      }

    private:
      double
      diagonal_inverse(const unsigned int   row,
                       std::vector<double> &cache,
                       const unsigned int   k)
      {
        if (cache[k] == 0)
          {
            const double d = W.diagonal(row);
            AssertThrow(d > 0 && std::isfinite(d),
                        ExcMessage(what +
                                   ": the contact flexibility of slave "
                                   "node " +
                                   std::to_string(k) +
                                   " is not positive; the node cannot move."));
            cache[k] = 1. / d;
          }
        return cache[k];
      }

      // Phase 1: the frictionless normal problem by Lawson and Hanson's
      // active set method. Its closed nodes stick (slip without friction).
      void
      frictionless_start()
      {
        std::vector<bool>         closed(n, false), blocked(n, false);
        std::vector<unsigned int> closed_list;
        Vector<double>            p(n);
        std::vector<double>       gn(n);
        const auto                update_gaps = [&]() {
          for (unsigned int k = 0; k < n; ++k)
            {
              gn[k] = step.g_free[normal_row(k)];
              for (const unsigned int j : closed_list)
                gn[k] += W(normal_row(k), normal_row(j)) * p[j];
            }
        };
        update_gaps();
        while (true)
          {
            // The most penetrating open node; stop if it penetrates less than
            // the tolerance allows.
            int    deepest = -1;
            double total   = 0;
            for (unsigned int k = 0; k < n; ++k)
              {
                total += p[k];
                if (!closed[k] && !blocked[k] && gn[k] < 0 &&
                    (deepest < 0 || gn[k] < gn[deepest]))
                  deepest = k;
              }
            if (deepest < 0 ||
                (total > 0 && -c_n(deepest) * gn[deepest] <= tol * total))
              break;
            ++iterations;
            if (iterations > max_iterations)
              {
                std::ostringstream message;
                message << what
                        << ": the frictionless start (Lawson-Hanson) did not "
                           "finish in max_iterations = "
                        << max_iterations << " iterations (load step "
                        << step.step
                        << "); the deepest open node still "
                           "penetrates by "
                        << -gn[deepest] << " m.";
                AssertThrow(false, ExcMessage(message.str()));
              }
            closed[deepest]               = true;
            const Vector<double> p_before = p;
            solve_on_closed_set(closed, p);
            closed_list.clear();
            for (unsigned int k = 0; k < n; ++k)
              if (closed[k])
                closed_list.push_back(k);
            update_gaps();
            // A node that could not stay closed is not tried again until the
            // closed set changes otherwise.
            if (!closed[deepest])
              {
                Vector<double> difference = p;
                difference -= p_before;
                if (difference.linfty_norm() == 0)
                  blocked[deepest] = true;
                else
                  std::fill(blocked.begin(), blocked.end(), false);
              }
            else
              std::fill(blocked.begin(), blocked.end(), false);
          }
        for (unsigned int k = 0; k < n; ++k)
          if (closed[k])
            {
              status[k] =
                mu[k] > 0 ? ContactStatus::stick : ContactStatus::slip;
              sign[k] = 1;
            }
      }

      // The inner loop of phase 1: solve on the closed set; step back to the
      // boundary while a force would become negative, and open the nodes
      // whose force reached zero.
      void
      solve_on_closed_set(std::vector<bool> &closed, Vector<double> &p)
      {
        std::vector<unsigned int> closed_list, columns;
        while (true)
          {
            closed_list.clear();
            columns.clear();
            for (unsigned int k = 0; k < n; ++k)
              if (closed[k])
                {
                  closed_list.push_back(k);
                  columns.push_back(normal_row(k));
                }
            W.prepare(columns);
            const unsigned int size = closed_list.size();
            FullMatrix<double> A(size, size);
            Vector<double>     b(size);
            for (unsigned int r = 0; r < size; ++r)
              {
                b[r] = -step.g_free[normal_row(closed_list[r])];
                for (unsigned int c = 0; c < size; ++c)
                  A(r, c) =
                    W(normal_row(closed_list[r]), normal_row(closed_list[c]));
              }
            const Vector<double> z     = solve_dense(A, b);
            double               alpha = 1;
            int                  limit = -1;
            for (unsigned int r = 0; r < size; ++r)
              if (z[r] <= 0)
                {
                  const unsigned int k        = closed_list[r];
                  const double       fraction = p[k] / (p[k] - z[r]);
                  if (fraction < alpha)
                    {
                      alpha = fraction;
                      limit = k;
                    }
                }
            for (unsigned int r = 0; r < size; ++r)
              {
                const unsigned int k = closed_list[r];
                p[k] += alpha * (z[r] - p[k]);
              }
            if (limit < 0)
              return;
            // The node that limited the step, and any other whose force
            // reached zero, open again.
            p[limit] = 0;
            for (unsigned int r = 0; r < size; ++r)
              if (p[closed_list[r]] <= 0)
                {
                  p[closed_list[r]]      = 0;
                  closed[closed_list[r]] = false;
                }
            closed[limit] = false;
          }
      }

      // Without friction a closed node slips; a slipping node needs a
      // direction.
      void
      complete_statuses()
      {
        for (unsigned int k = 0; k < n; ++k)
          {
            if (status[k] == ContactStatus::stick && mu[k] == 0)
              status[k] = ContactStatus::slip;
            if (status[k] == ContactStatus::slip && sign[k] == 0)
              sign[k] = 1;
          }
      }

      // The forces and gaps of the linear system of the current statuses.
      void
      solve_with_statuses(ContactState &state)
      {
        const StatusSystem system(W, status, sign, mu);
        Vector<double>     b(system.rows.size());
        for (unsigned int r = 0; r < b.size(); ++r)
          {
            const unsigned int i = system.rows[r];
            b[r] = (r < system.closed.size() ? 0. : step.g_previous[i]) -
                   step.g_free[i];
          }
        state.p = system.forces(solve_dense(system.A, b), status, sign, mu);
        state.g = gaps_of(W, step.g_free, state.p, system.columns);
      }

      // The status of node k that the complementarity functions predict.
      std::pair<ContactStatus, int>
      predict(const ContactState &state, const unsigned int k)
      {
        const double a =
          state.p[normal_row(k)] - c_n(k) * state.g[normal_row(k)];
        if (a <= 0)
          return std::make_pair(ContactStatus::open, 0);
        if (mu[k] == 0)
          return std::make_pair(ContactStatus::slip, 1);
        const double dgt =
          state.g[tangential_row(k)] - step.g_previous[tangential_row(k)];
        const double z = state.p[tangential_row(k)] - c_t(k) * dgt;
        if (std::abs(z) < mu[k] * a)
          return std::make_pair(ContactStatus::stick, 0);
        return std::make_pair(ContactStatus::slip, z >= 0 ? 1 : -1);
      }

      // New status of the nodes whose own residual r[k] is too large (only of
      // the first of them under Murty's rule); false if none changes.
      bool
      predict_statuses(const ContactState         &state,
                       const std::vector<double>  &r,
                       const double                scale,
                       const bool                  murty,
                       std::vector<ContactStatus> &new_status,
                       std::vector<int>           &new_sign)
      {
        bool changed = false;
        for (unsigned int k = 0; k < n && !(murty && changed); ++k)
          if (r[k] > tol * scale)
            {
              const auto [s, d] = predict(state, k);
              if (s != status[k] || (s == ContactStatus::slip && d != sign[k]))
                {
                  new_status[k] = s;
                  new_sign[k]   = d;
                  changed       = true;
                }
            }
        return changed;
      }

      // Murty's least-index rule: only the violated node of least index
      // changes.
      void
      murty_step(const ContactState         &state,
                 const std::vector<double>  &r,
                 const double                scale,
                 std::vector<ContactStatus> &new_status,
                 std::vector<int>           &new_sign)
      {
        new_status = status;
        new_sign   = sign;
        for (unsigned int k = 0; k < n; ++k)
          if (r[k] > tol * scale)
            {
              const auto [s, d] = predict(state, k);
              new_status[k]     = s;
              new_sign[k]       = d;
              break;
            }
      }

      ContactState
      converged(ContactState &state) const
      {
        state.status    = status;
        state.slip_sign = sign;
        for (unsigned int k = 0; k < n; ++k)
          if (status[k] != ContactStatus::slip)
            state.slip_sign[k] = 0;
        return state;
      }

      FlexibilityOperator       &W;
      const LoadStep            &step;
      const std::vector<double> &mu;
      const std::string         &what;
      const unsigned int         n;
      const double               tol;
      const unsigned int         max_iterations;

      // Scaling of the complementarity functions, from the diagonal of W;
      // computed (and the columns prepared) only for nodes that need it.
      std::vector<double>                       cn, ct;
      const std::function<double(unsigned int)> c_n, c_t;

      std::vector<ContactStatus> status;
      std::vector<int>           sign;
      unsigned int               iterations = 0;
    };

  } // namespace


  ActiveSetSolver::ActiveSetSolver(const ActiveSetParameters &parameters)
      : parameters_(parameters)
  {
  }

  const ActiveSetParameters &
  ActiveSetSolver::parameters() const
  {
    return parameters_;
  }


  ContactState
  ActiveSetSolver::solve(FlexibilityOperator       &W,
                         const LoadStep            &step,
                         const std::vector<double> &mu,
                         const std::string         &what) const
  {
    AssertDimension(W.size(), 2 * mu.size());
    AssertDimension(step.g_free.size(), 2 * mu.size());
    return ActiveSetMethod(W, step, mu, parameters_, what).solve();
  }


  Vector<double>
  ActiveSetSolver::correction(FlexibilityOperator       &W,
                              const ContactState        &state,
                              const std::vector<double> &mu,
                              const Vector<double>      &violation) const
  {
    const StatusSystem system(W, state.status, state.slip_sign, mu);
    Vector<double>     b(system.rows.size());
    for (unsigned int r = 0; r < b.size(); ++r)
      b[r] = -violation[system.rows[r]];
    return system.forces(solve_dense(system.A, b),
                         state.status,
                         state.slip_sign,
                         mu);
  }


  std::string
  ActiveSetSolver::name() const
  {
    return "reduced exact";
  }


  ContactState
  ActiveSetSolver::solve_step(const ContactProblem &problem,
                              const LoadStep       &step,
                              const std::string    &what) const
  {
    if (problem.flexibility != nullptr)
      return solve(*problem.flexibility, step, problem.mu, what);
    DenseFlexibility W(problem.W);
    return solve(W, step, problem.mu, what);
  }
} // namespace FuzzyContact
