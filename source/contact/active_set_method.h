// One load step of the exact contact solver (active_set_solver.h): the
// primal-dual active set method with its statuses, iteration count and
// complementarity scaling. Not a public header: only active_set_solver.cc,
// which decides from which start and under which rule a step is solved
// (its retries), uses it.

#ifndef fuzzycontact_contact_active_set_method_h
#define fuzzycontact_contact_active_set_method_h

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/contact_workspace.h>
#include <fuzzycontact/contact/static_equilibrium.h>
#include <fuzzycontact/contact/status_system.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <set>
#include <sstream>

namespace FuzzyContact
{
  // A status with its slip direction, as one comparable key.
  inline std::vector<int>
  signature(const std::vector<ContactStatus> &status,
            const std::vector<int>           &sign)
  {
    std::vector<int> key(status.size());
    for (unsigned int k = 0; k < status.size(); ++k)
      key[k] = status[k] == ContactStatus::open
                 ? 0
                 : (status[k] == ContactStatus::stick ? 1 : 2 + (sign[k] > 0));
    return key;
  }

  // One load step of the method described in active_set_solver.h: the
  // statuses as they evolve, the iteration count over both phases, the
  // scaling of the complementarity functions, and the steps of the
  // method.
  class ActiveSetMethod
  {
  public:
    // With @p stick_before_reversal (and bodies held by contact alone), a
    // slipping node whose slip would reverse sticks first (below).
    ActiveSetMethod(FlexibilityOperator       &W,
                    const LoadStep            &step,
                    const std::vector<double> &mu,
                    const ActiveSetParameters &parameters,
                    const std::string         &what,
                    const bool                 stick_before_reversal = true)
        : W(W)
        , step(step)
        , mu(mu)
        , what(what)
        , n(mu.size())
        , tol(parameters.tolerance)
        , max_iterations(parameters.max_iterations)
        , max_iterations_key(parameters.max_iterations_key)
        , cn(n, 0.)
        , ct(n, 0.)
        , c_n([this](const unsigned int k) {
          return diagonal_inverse(normal_row(k), cn, k);
        })
        , c_t([this](const unsigned int k) {
          return diagonal_inverse(tangential_row(k), ct, k);
        })
        , stick_before_reversal(stick_before_reversal)
        , status(step.start != nullptr ? step.start->status
                                       : step.previous.status)
        , sign(step.start != nullptr ? step.start->slip_sign
                                     : step.previous.slip_sign)
        , linear(step.workspace != nullptr ? step.workspace->linear(step.step)
                                           : own_linear)
    {
      if (status.size() != n)
        status.assign(n, ContactStatus::open);
      if (sign.size() != n)
        sign.assign(n, 0);
    }

    // Phase 1 unless warm started, then phase 2 until the residual is
    // at most the tolerance; throws otherwise. A load that no contact
    // forces within the friction cones balance is said to be so
    // (check_equilibrium()) when the iterations fail; a converged state
    // shows that they do (its residual holds both), so the test is not
    // made before every solve (it cost as much as the solve itself on
    // distributed contact).
    ContactState
    solve()
    {
      try
        {
          return iterate();
        }
      catch (const ExceptionBase &)
        {
          check_equilibrium(step, mu, what);
          throw;
        }
    }

  private:
    ContactState
    iterate()
    {
      if (std::all_of(status.begin(), status.end(), [](const ContactStatus s) {
            return s == ContactStatus::open;
          }))
        {
          // A body held by contact alone: the frictionless start from
          // normal forces that balance its load (it then keeps the
          // equilibrium); if friction must hold it, from every node
          // closed.
          Vector<double>            p0(2 * n);
          const std::vector<double> frictionless(n, 0.);
          if (step.n_motions() == 0 ||
              admissible_forces(step, frictionless, p0))
            frictionless_start(p0);
          else
            std::fill(status.begin(), status.end(), ContactStatus::stick);
        }
      complete_statuses();
      // The start's iterations have their own limit (frictionless_start).
      const unsigned int start_iterations = iterations;

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
          residual           = std::max(worst == 0 ? 0. : worst / scale,
                              equilibrium_residual(step, state.p, scale));
          state.iterations = iterations;
          state.residual   = residual;
          if (residual <= tol)
            {
              check_motions_determined(step, state.p, what, scale);
              return converged(state);
            }
          if (iterations - start_iterations >= max_iterations)
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
                      << (step.n_motions() > 0 &&
                              equilibrium_residual(step, state.p, scale) > tol
                            ? " (the contact forces of the closed nodes "
                              "cannot balance the load on the bodies held by "
                              "contact alone: their position is not "
                              "determined by this contact)."
                            : " (the active system is too ill-conditioned "
                              "for this tolerance).");
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
      message << what << ": the active set method did not converge in "
              << max_iterations << " iterations (key '" << max_iterations_key
              << "'; load step " << step.step << "); complementarity residual "
              << residual << " > " << tol << ".";
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
          // (A node held tangentially on both bodies has W_tt = 0 and no
          // friction: its dg_t vanishes, and any scaling of it will do.)
          const double d = row % 2 == 1 && W.diagonal(row) == 0 && mu[k] == 0
                             ? W.diagonal(row - 1)
                             : W.diagonal(row);
          AssertThrow(
            d > 0 && std::isfinite(d),
            ExcMessage(
              what + ": the " + (row % 2 == 0 ? "normal" : "tangential") +
              " contact flexibility of slave node " + std::to_string(k) +
              " is not positive; the node cannot move" +
              (row % 2 == 0
                 ? "."
                 : " along the face, and it has friction: a node whose "
                   "tangential motion is held on both bodies (the "
                   "contact interface gives such a node none) cannot "
                   "carry friction.")));
          cache[k] = 1. / d;
        }
      return cache[k];
    }

    // Phase 1: the frictionless normal problem by Lawson and Hanson's
    // active set method, from the normal forces of @p p0 (zero, or forces
    // that balance the load on the bodies held by contact alone, whose
    // equilibrium every step then keeps: the amplitudes of their free
    // motions are the multipliers of that constraint). Its closed nodes
    // stick (slip without friction).
    void
    frictionless_start(const Vector<double> &p0)
    {
      std::vector<bool>         closed(n, false), blocked(n, false);
      std::vector<unsigned int> closed_list;
      Vector<double>            p(n), a(step.n_motions());
      std::vector<double>       gn(n);
      for (unsigned int k = 0; k < n; ++k)
        if (p0[normal_row(k)] > 0)
          {
            p[k]      = p0[normal_row(k)];
            closed[k] = true;
            closed_list.push_back(k);
          }
      if (!closed_list.empty())
        solve_on_closed_set(closed, p, a);
      const auto update_gaps = [&]() {
        closed_list.clear();
        for (unsigned int k = 0; k < n; ++k)
          {
            gn[k] = step.g_free[normal_row(k)];
            if (closed[k])
              closed_list.push_back(k);
          }
        for (const unsigned int j : closed_list)
          {
            const double *w = W.column(normal_row(j));
            for (unsigned int k = 0; k < n; ++k)
              gn[k] += w[normal_row(k)] * p[j];
          }
        for (unsigned int j = 0; j < a.size(); ++j)
          for (unsigned int k = 0; k < n; ++k)
            gn[k] += step.rigid->gaps(normal_row(k), j) * a[j];
      };
      update_gaps();
      // Lawson-Hanson closes one node per iteration (and opens some
      // again): on distributed contact it needs at least as many
      // iterations as nodes close, whatever the active set method's own
      // limit (3 per node, as NNLS codes commonly allow).
      const unsigned int start_limit = std::max(max_iterations, 3 * n);
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
          if (iterations > start_limit)
            {
              std::ostringstream message;
              message << what
                      << ": the frictionless start (Lawson-Hanson) did not "
                         "finish in "
                      << start_limit << " iterations (3 per slave node, or "
                      << "key '" << max_iterations_key
                      << "' if larger; load step " << step.step
                      << "); the deepest open node still "
                         "penetrates by "
                      << -gn[deepest] << " m.";
              AssertThrow(false, ExcMessage(message.str()));
            }
          closed[deepest]               = true;
          const Vector<double> p_before = p;
          solve_on_closed_set(closed, p, a);
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
            status[k] = mu[k] > 0 ? ContactStatus::stick : ContactStatus::slip;
            sign[k]   = 1;
          }
    }

    // The inner loop of phase 1: solve on the closed set (with the free
    // motions' amplitudes @p a and the equilibrium, if any); step back to
    // the boundary while a force would become negative, and open the
    // nodes whose force reached zero.
    void
    solve_on_closed_set(std::vector<bool> &closed,
                        Vector<double>    &p,
                        Vector<double>    &a)
    {
      std::vector<unsigned int> closed_list;
      const std::vector<double> frictionless(n, 0.);
      while (true)
        {
          std::vector<ContactStatus> slips(n, ContactStatus::open);
          closed_list.clear();
          for (unsigned int k = 0; k < n; ++k)
            if (closed[k])
              {
                closed_list.push_back(k);
                slips[k] = ContactStatus::slip;
              }
          const unsigned int size = closed_list.size();
          Vector<double>     target(2 * n), forces, a_new;
          for (unsigned int r = 0; r < size; ++r)
            target[normal_row(closed_list[r])] =
              -step.g_free[normal_row(closed_list[r])];
          linear.solve(W,
                       slips,
                       std::vector<int>(n, 1),
                       frictionless,
                       step.rigid,
                       target,
                       step.rigid_load,
                       forces,
                       a_new);
          Vector<double> x(size);
          for (unsigned int r = 0; r < size; ++r)
            x[r] = forces[normal_row(closed_list[r])];
          double alpha = 1;
          int    limit = -1;
          for (unsigned int r = 0; r < size; ++r)
            if (x[r] <= 0)
              {
                const unsigned int k = closed_list[r];
                const double       fraction =
                  p[k] - x[r] > 0 ? p[k] / (p[k] - x[r]) : 0.;
                if (fraction < alpha)
                  {
                    alpha = fraction;
                    limit = k;
                  }
              }
          for (unsigned int r = 0; r < size; ++r)
            {
              const unsigned int k = closed_list[r];
              p[k] += alpha * (x[r] - p[k]);
            }
          for (unsigned int j = 0; j < a.size(); ++j)
            a[j] += alpha * (a_new[j] - a[j]);
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
      Vector<double>            target(2 * n);
      std::vector<unsigned int> columns;
      for (unsigned int k = 0; k < n; ++k)
        if (status[k] != ContactStatus::open)
          {
            target[normal_row(k)] = -step.g_free[normal_row(k)];
            columns.push_back(normal_row(k));
            if (mu[k] > 0)
              {
                columns.push_back(tangential_row(k));
                target[tangential_row(k)] = step.g_previous[tangential_row(k)] -
                                            step.g_free[tangential_row(k)];
              }
          }
      linear.solve(W,
                   status,
                   sign,
                   mu,
                   step.rigid,
                   target,
                   step.rigid_load,
                   state.p,
                   state.rigid);
      state.g = gaps_of(W, step.g_free, state.p, columns, &step, state.rigid);
    }

    // The status of node k that the complementarity functions predict.
    std::pair<ContactStatus, int>
    predict(const ContactState &state, const unsigned int k)
    {
      const double a = state.p[normal_row(k)] - c_n(k) * state.g[normal_row(k)];
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
            auto [s, d] = predict(state, k);
            // With bodies held by contact alone, a slipping node does not
            // reverse its slip in one iteration, but sticks first: the
            // free motions answer the friction forces of all slipping
            // nodes at once, and whole-interface reversals would follow
            // each other (a roller rocking from one side to the other).
            if (stick_before_reversal && step.n_motions() > 0 &&
                s == ContactStatus::slip && status[k] == ContactStatus::slip &&
                d != sign[k])
              {
                s = ContactStatus::stick;
                d = 0;
              }
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
    const std::string          max_iterations_key;

    // Scaling of the complementarity functions, from the diagonal of W;
    // computed (and the columns prepared) only for nodes that need it.
    std::vector<double>                       cn, ct;
    const std::function<double(unsigned int)> c_n, c_t;

    const bool                 stick_before_reversal;
    std::vector<ContactStatus> status;
    std::vector<int>           sign;
    unsigned int               iterations = 0;

    // The linear solves: the workspace's (its factor kept between solves)
    // or this step's own.
    StatusSolver  own_linear;
    StatusSolver &linear;
  };
} // namespace FuzzyContact

#endif
