#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/contact_workspace.h>
#include <fuzzycontact/contact/fl2c.h>

#include <deal.II/base/exceptions.h>

#include "restricted_flexibility.h"
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace FuzzyContact
{

  double
  FL2CSolver::largest_secant_gain(const MamdaniRegulator &regulator)
  {
    const auto &a    = regulator.input_points();
    const auto &b    = regulator.output_points();
    double      gain = (b[1] * b[1] - b[0] * b[0]) / (2 * a[0] * b[0]);
    for (double x = 1e-6 * a[0]; x <= 2 * a[2]; x *= 1.01)
      gain = std::max(gain, std::abs(regulator(x) / x));
    return gain;
  }


  FL2CSolver::FL2CSolver(const FL2CParameters &parameters)
      : parameters_(parameters)
      , shape({{1., 2., 3.}}, {{1., 2., 3.}}, "FL2C")
  {
    parameters_.check();
    // The secant gain of the shape at its saturation point a3 (= 1: R(x) =
    // -x at the half steps from a1/2 to a3).
    shape_gain = std::abs(shape(3.) / 3.);
  }

  const FL2CParameters &
  FL2CSolver::parameters() const
  {
    return parameters_;
  }


  std::string
  FL2CSolver::name() const
  {
    return "fl2c";
  }


  void
  FL2CSolver::set_monitor(std::function<void(unsigned int, double)> m)
  {
    monitor = std::move(m);
  }


  namespace
  {
    // The regulators of one load step: the calibrated shape, scaled per
    // node by g_ref and the node's flexibility (automatic calibration), or
    // the transition points of the parameter file.
    struct Regulators
    {
      bool                    automatic;
      const MamdaniRegulator &shape;
      double                  shape_gain;
      double                  g_ref;
      MamdaniRegulator        normal, tangential;

      // Normal regulator: gap -> force increment (W_nn of the node).
      double
      normal_change(const double gap, const double w) const
      {
        return automatic ? shape(gap / g_ref) * g_ref / (shape_gain * w)
                         : normal(gap);
      }

      // Tangential regulator: slip of the step -> force increment (W_tt).
      double
      tangential_change(const double slip, const double w) const
      {
        return automatic ? shape(slip / g_ref) * g_ref / (shape_gain * w)
                         : tangential(slip);
      }
    };


    // The status a force implies: open where p_n = 0, slip where |p_t| =
    // mu p_n (or mu = 0), stick elsewhere.
    std::pair<ContactStatus, int>
    status_of(const double pn, const double pt, const double mu)
    {
      if (pn <= 0)
        return {ContactStatus::open, 0};
      if (mu > 0 && std::abs(pt) < mu * pn)
        return {ContactStatus::stick, 0};
      return {ContactStatus::slip, pt >= 0 ? 1 : -1};
    }


    // One load step of FL2C (see fl2c.h): the working set, its sweeps and
    // coarse corrections, and the checks of the whole interface.
    class LoadStepSweeps
    {
    public:
      LoadStepSweeps(const FL2CParameters      &parameters,
                     const MamdaniRegulator    &shape,
                     const double               shape_gain,
                     FlexibilityOperator       &W,
                     const LoadStep            &step,
                     const std::vector<double> &mu,
                     const std::string         &what)
          : parameters(parameters)
          , corrected(parameters.coarse_correction ==
                      FL2CParameters::CoarseCorrection::active_set)
          , W(W)
          , step(step)
          , mu(mu)
          , what(what)
          , n(mu.size())
          , coarse(step.workspace != nullptr ? &step.workspace->coarse(n)
                                             : nullptr)
          , in_working(n, false)
          , c_n([this](const unsigned int k) {
            return 1. / this->W.diagonal(normal_row(k));
          })
          , c_t([this](const unsigned int k) {
            return 1. / this->W.diagonal(tangential_row(k));
          })
          , regulators{parameters.calibration ==
                         FL2CParameters::Calibration::automatic,
                       shape,
                       shape_gain,
                       0.,
                       MamdaniRegulator(parameters.gap_points,
                                        parameters.force_points),
                       MamdaniRegulator(parameters.slip_points,
                                        parameters.friction_points)}
      {
        // From the forces of the same step at a neighbouring point, if the
        // study gave them (contact_workspace.h), else of the previous step.
        const ContactState &from =
          step.start != nullptr && step.start->p.size() == 2 * n &&
              step.start->rigid.size() == step.n_motions()
            ? *step.start
            : step.previous;
        state.p = from.p;
        if (state.p.size() != 2 * n)
          state.p.reinit(2 * n);
        state.rigid = from.rigid;
        if (state.rigid.size() != step.n_motions())
          state.rigid.reinit(step.n_motions());
        state.status.assign(n, ContactStatus::open);
        state.slip_sign.assign(n, 0);
        if (&from == step.start && from.status.size() == n &&
            from.slip_sign.size() == n)
          {
            exact_status = from.status;
            exact_sign   = from.slip_sign;
            exact_known.assign(n, true);
          }
        else
          {
            exact_status.assign(n, ContactStatus::open);
            exact_sign.assign(n, 0);
            exact_known.assign(n, false);
          }
        AssertThrow(corrected || step.n_motions() == 0,
                    ExcMessage(what + ": a body held by contact alone needs "
                                      "FL2C's coarse correction (the "
                                      "regulators alone do not move it): set "
                                      "'coarse correction = active set' in "
                                      "subsection FL2C."));
        start();
      }

      // Sweeps until every node's residual is at most the tolerance;
      // throws after max_iterations sweeps.
      ContactState
      run(const std::function<void(unsigned int, double)> &monitor)
      {
        double       residual     = 0;
        double       force_change = 0;
        unsigned int last_check   = 0;
        if (monitor)
          monitor(0, interface_residual());
        for (unsigned int it = 1;; ++it)
          {
            residual = std::max(working_residual(),
                                equilibrium_residual(step, state.p, scale()));
            if (residual <= parameters.tolerance ||
                (!corrected && it - last_check >= 16))
              {
                residual =
                  std::max(check_interface(),
                           equilibrium_residual(step, state.p, scale()));
                last_check = it;
              }
            // With the coarse correction, nodes that joined at the check
            // (penetrating, however little) are solved for once more: the
            // correction then makes the answer exact. So is a start from a
            // neighbouring point's forces that passes the test as it is
            // (a residual within the tolerance is not the exact answer: on
            // the punch its free motion was 1e-9 m off, 4e-4 of u_y's
            // range): at least one sweep and correction (where there is a
            // working set: a zero load leaves none).
            if (residual <= parameters.tolerance &&
                !(corrected && (joined || (it == 1 && !working.empty()))))
              {
                state.iterations = it;
                break;
              }
            joined = false;
            AssertThrow(it < parameters.max_iterations,
                        ExcMessage(failure(residual, force_change)));
            force_change = sweep();
            if (corrected)
              coarse_correction();
            if (monitor)
              monitor(it, interface_residual());
          }
        for (unsigned int k = 0; k < n; ++k)
          {
            const auto [s, sign] = status_of(state.p[normal_row(k)],
                                             state.p[tangential_row(k)],
                                             mu[k]);
            state.status[k]      = s;
            state.slip_sign[k]   = s == ContactStatus::slip ? sign : 0;
          }
        state.residual = residual;
        return state;
      }

    private:
      // The gaps of the previous step's forces on every row, the scales of
      // the regulators and of the residual, and the working set: the nodes
      // that carry a force, and the most penetrating one (the checks of the
      // whole interface add the others that penetrate, all at once: on
      // `overlap` every node penetrates without contact forces, and one
      // closes). O(m) per loaded node, once.
      void
      start()
      {
        state.g = step.g_free;
        add_rigid_gaps(step, state.rigid, state.g);
        for (unsigned int j = 0; j < 2 * n; ++j)
          if (state.p[j] != 0)
            add_column(j, state.p[j], true);
        // A body held by contact alone whose load the forces do not balance
        // yet has no position: the whole interface is the working set
        // until the first coarse correction places it.
        if (equilibrium_residual(step, state.p) > parameters.tolerance)
          for (unsigned int k = 0; k < n; ++k)
            join(k);
        // The gap scale: the largest free penetration, or the largest free
        // gap if nothing penetrates without contact forces.
        double g_scale = 0, gap = 0;
        int    deepest = -1;
        for (unsigned int k = 0; k < n; ++k)
          {
            const double g = step.g_free[normal_row(k)];
            g_scale        = std::max(g_scale, -g);
            gap            = std::max(gap, std::abs(g));
            if (g < 0)
              free_force = std::max(free_force, -c_n(k) * g);
            if (state.p[normal_row(k)] != 0 || state.p[tangential_row(k)] != 0)
              join(k);
            else if (state.g[normal_row(k)] < 0 &&
                     (deepest < 0 ||
                      state.g[normal_row(k)] < state.g[normal_row(deepest)]))
              deepest = k;
          }
        if (deepest >= 0)
          join(deepest);
        // Without free gaps, from the gaps of the previous forces.
        if (gap == 0)
          for (const unsigned int k : working)
            gap = std::max(gap, std::abs(state.g[normal_row(k)]));
        regulators.g_ref = (g_scale > 0 ? g_scale : gap) / 3;
      }

      // Open nodes that do not touch leave the working set (they rejoin at
      // the next check of the interface if they penetrate).
      void
      prune()
      {
        std::vector<unsigned int> kept;
        for (const unsigned int k : working)
          if (state.p[normal_row(k)] != 0 || state.p[tangential_row(k)] != 0 ||
              state.g[normal_row(k)] <= 0)
            kept.push_back(k);
          else
            in_working[k] = false;
        working.swap(kept);
        rows.clear();
        for (const unsigned int k : working)
          {
            rows.push_back(normal_row(k));
            rows.push_back(tangential_row(k));
          }
      }

      // Node k joins the working set; its gaps are up to date.
      void
      join(const unsigned int k)
      {
        if (in_working[k])
          return;
        in_working[k] = true;
        working.push_back(k);
        rows.push_back(normal_row(k));
        rows.push_back(tangential_row(k));
      }

      // Adds a W e_j to the gaps: of every row, or of the working set's.
      void
      add_column(const unsigned int j, const double a, const bool all)
      {
        const double *w = W.column(j);
        if (all)
          for (unsigned int i = 0; i < 2 * n; ++i)
            state.g[i] += w[i] * a;
        else
          for (const unsigned int i : rows)
            state.g[i] += w[i] * a;
      }

      // The force scale of the relative residual (as residual_scale()):
      // forces are only carried by the working set.
      double
      scale() const
      {
        double total = 0;
        for (const unsigned int k : working)
          total += std::max(state.p[normal_row(k)], 0.);
        return total > 0 ? total : free_force;
      }

      double
      node_residual(const unsigned int k) const
      {
        return complementarity_residual(k,
                                        state.p,
                                        state.g,
                                        step.g_previous,
                                        mu[k],
                                        c_n,
                                        c_t);
      }

      // The relative residual of the working set, O(s).
      double
      working_residual() const
      {
        double worst = 0;
        for (const unsigned int k : working)
          worst = std::max(worst, node_residual(k));
        return worst == 0 ? 0. : worst / scale();
      }

      // The gaps of every row from the forces of the working set; nodes
      // that violate the conditions join the working set. Returns the
      // relative residual of all nodes. O(m) per loaded node.
      double
      check_interface()
      {
        state.g = step.g_free;
        add_rigid_gaps(step, state.rigid, state.g);
        for (const unsigned int j : rows)
          if (state.p[j] != 0)
            add_column(j, state.p[j], true);
        prune();
        double worst = 0;
        joined       = false;
        for (unsigned int k = 0; k < n; ++k)
          {
            const double r = node_residual(k);
            worst          = std::max(worst, r);
            if (r > 0 && !in_working[k])
              {
                join(k);
                joined = true;
              }
          }
        return worst == 0 ? 0. : worst / scale();
      }

      // The residual of all nodes without changing anything (monitor).
      double
      interface_residual()
      {
        const Vector<double> kept = state.g;
        state.g                   = step.g_free;
        add_rigid_gaps(step, state.rigid, state.g);
        for (const unsigned int j : rows)
          if (state.p[j] != 0)
            add_column(j, state.p[j], true);
        double worst = 0;
        for (unsigned int k = 0; k < n; ++k)
          worst = std::max(worst, node_residual(k));
        const double s = scale();
        for (const unsigned int i : rows)
          state.g[i] = kept[i];
        return worst == 0 ? 0. : worst / s;
      }

      // 1. One sweep of the regulators over the working set, most
      // penetrating first; each acts on the gaps left by the force changes
      // before it. Returns the largest force change.
      double
      sweep()
      {
        std::vector<unsigned int> order;
        for (const unsigned int k : working)
          if (state.p[normal_row(k)] > 0 || state.g[normal_row(k)] < 0)
            order.push_back(k);
        std::stable_sort(order.begin(),
                         order.end(),
                         [&](const unsigned int i, const unsigned int j) {
                           return state.g[normal_row(i)] <
                                  state.g[normal_row(j)];
                         });
        double     force_change = 0;
        const auto apply = [&](const unsigned int row, const double change) {
          if (change == 0)
            return;
          state.p[row] += change;
          add_column(row, change, false);
          force_change = std::max(force_change, std::abs(change));
        };
        for (const unsigned int k : order)
          {
            const unsigned int rn = normal_row(k), rt = tangential_row(k);
            // Open and no longer penetrating (a force before it lifted it):
            // the regulators would leave it open, R(g >= 0) <= 0.
            if (state.p[rn] == 0 && state.p[rt] == 0 && state.g[rn] >= 0)
              continue;
            const double pn =
              std::max(0.,
                       state.p[rn] +
                         regulators.normal_change(state.g[rn], W.diagonal(rn)));
            apply(rn, pn - state.p[rn]);
            if (mu[k] == 0)
              continue;
            // Tangential force capped by Coulomb's bound.
            const double dgt = state.g[rt] - step.g_previous[rt];
            const double pt =
              state.p[rt] + regulators.tangential_change(dgt, W.diagonal(rt));
            apply(rt, std::clamp(pt, -mu[k] * pn, mu[k] * pn) - state.p[rt]);
          }
        return force_change;
      }

      // 2. The exact reduced solver on the working set, warm-started from
      // the statuses of the regulators' forces (cold, by its frictionless
      // start, if that fails). With a workspace it is posed on the
      // workspace's coarse nodes, every node a working set held (the
      // working set's join them): the open ones are solved as open, and
      // the factors of its linear systems are kept from one correction,
      // load step and solve to the next (contact_workspace.h).
      void
      coarse_correction()
      {
        if (coarse != nullptr)
          for (const unsigned int k : working)
            if (coarse->place[k] < 0)
              {
                coarse->place[k] = coarse->nodes.size();
                coarse->nodes.push_back(k);
              }
        const std::vector<unsigned int> &nodes =
          coarse != nullptr ? coarse->nodes : working;
        std::vector<unsigned int> local_rows;
        for (const unsigned int k : nodes)
          {
            local_rows.push_back(normal_row(k));
            local_rows.push_back(tangential_row(k));
          }
        const unsigned int  s = nodes.size();
        LoadStep            local;
        std::vector<double> local_mu(s);
        local.step        = step.step;
        local.load_factor = step.load_factor;
        local.g_free.reinit(2 * s);
        local.g_previous.reinit(2 * s);
        local.previous.status.assign(s, ContactStatus::open);
        local.previous.slip_sign.assign(s, 0);
        for (unsigned int i = 0; i < 2 * s; ++i)
          {
            local.g_free[i]     = step.g_free[local_rows[i]];
            local.g_previous[i] = step.g_previous[local_rows[i]];
          }
        bool exact_start = false;
        for (unsigned int i = 0; i < s; ++i)
          {
            const unsigned int k        = nodes[i];
            local_mu[i]                 = mu[k];
            const auto [status, sign]   = status_of(state.p[normal_row(k)],
                                                  state.p[tangential_row(k)],
                                                  mu[k]);
            const bool known            = exact_known[k];
            exact_start                 = exact_start || known;
            local.previous.status[i]    = known ? exact_status[k] : status;
            local.previous.slip_sign[i] = known ? exact_sign[k] : sign;
          }
        const RigidMotions rigid = step.n_motions() > 0
                                     ? step.rigid->restricted(local_rows)
                                     : RigidMotions();
        if (step.n_motions() > 0)
          {
            local.rigid          = &rigid;
            local.rigid_load     = step.rigid_load;
            local.previous.rigid = state.rigid;
          }
        if (coarse != nullptr)
          local.workspace = coarse->workspace.get();
        RestrictedFlexibility restricted(W, local_rows, coarse != nullptr);
        ContactState          solved;
        try
          {
            // Started from exact statuses (a neighbouring point's, an
            // earlier correction's) the solver may take as many iterations
            // as the exact reduced solver would from there; from the
            // regulators' statuses only a few.
            solved = (exact_start ? cold : warm)
                       .solve(restricted, local, local_mu, what);
          }
        catch (const ExceptionBase &)
          {
            local.previous.status.assign(s, ContactStatus::open);
            try
              {
                solved = cold.solve(restricted, local, local_mu, what);
              }
            catch (const ExceptionBase &e)
              {
                // The regulators carry on alone; they cannot move a body
                // held by contact alone, though.
                AssertThrow(step.n_motions() == 0,
                            ExcMessage(what +
                                       ": the coarse correction failed, and "
                                       "without it a body held by contact "
                                       "alone cannot be placed: " +
                                       Input::message_of(e)));
                return;
              }
          }
        for (unsigned int i = 0; i < 2 * s; ++i)
          {
            state.p[local_rows[i]] = solved.p[i];
            state.g[local_rows[i]] = solved.g[i];
          }
        for (unsigned int i = 0; i < s; ++i)
          {
            exact_status[nodes[i]] = solved.status[i];
            exact_sign[nodes[i]]   = solved.slip_sign[i];
            exact_known[nodes[i]]  = true;
          }
        state.rigid = solved.rigid;
        // Coarse nodes outside the working set that the correction closed
        // carry forces: they join it.
        for (const unsigned int k : nodes)
          if (state.p[normal_row(k)] != 0 || state.p[tangential_row(k)] != 0)
            join(k);
        prune();
      }

      std::string
      failure(const double residual, const double force_change) const
      {
        std::ostringstream message;
        message << what << ": the fuzzy regulators did not converge in "
                << parameters.max_iterations
                << " iterations (key 'FL2C/max iterations'; load step "
                << step.step << "); complementarity residual " << residual
                << ", last force change " << force_change << " N.";
        return message.str();
      }

      const FL2CParameters      &parameters;
      const bool                 corrected;
      FlexibilityOperator       &W;
      const LoadStep            &step;
      const std::vector<double> &mu;
      const std::string         &what;
      const unsigned int         n;
      ContactWorkspace::Coarse  *coarse;
      // The statuses of the last exact answer of this step (the start's,
      // then the coarse corrections'): the coarse correction starts from
      // them where a node has one (known), from the regulators' forces
      // elsewhere.
      // The regulators leave a slipping node's friction force a little
      // inside the cone, which reads as sticking: started from there, the
      // exact solver would turn every slipping node back, each time, on new
      // factors.
      std::vector<ContactStatus>                exact_status;
      std::vector<int>                          exact_sign;
      std::vector<bool>                         exact_known;
      std::vector<bool>                         in_working;
      std::vector<unsigned int>                 working, rows;
      const std::function<double(unsigned int)> c_n, c_t;
      Regulators                                regulators;
      ContactState                              state;
      double                                    free_force = 0;
      // Whether the last check of the interface added nodes.
      bool joined = false;
      // The exact solver of the coarse correction: from the regulators'
      // statuses, a few iterations (a poor start may cycle into Murty's
      // one-node-per-iteration rule); else from its own frictionless start.
      const ActiveSetSolver warm{
        ActiveSetParameters{std::min(1e-10, parameters.tolerance),
                            parameters.coarse_warm_iterations,
                            "FL2C/coarse correction warm iterations"}};
      const ActiveSetSolver cold{
        ActiveSetParameters{std::min(1e-10, parameters.tolerance),
                            parameters.coarse_max_iterations,
                            "FL2C/coarse correction max iterations"}};
    };
  } // namespace


  ContactState
  FL2CSolver::solve_step(const ContactProblem &problem,
                         const LoadStep       &step,
                         const std::string    &what) const
  {
    DenseFlexibility     dense(problem.W);
    FlexibilityOperator &W =
      problem.flexibility != nullptr ? *problem.flexibility : dense;
    AssertDimension(W.size(), 2 * problem.n_nodes());
    AssertDimension(step.g_free.size(), 2 * problem.n_nodes());
    LoadStepSweeps
      sweeps(parameters_, shape, shape_gain, W, step, problem.mu, what);
    return sweeps.run(monitor);
  }
} // namespace FuzzyContact
