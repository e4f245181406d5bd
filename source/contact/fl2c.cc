#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/fl2c.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace FuzzyContact
{
  void
  FL2CParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("FL2C");
    prm.declare_entry("calibration",
                      "automatic",
                      Patterns::Selection("automatic|prm"),
                      "Transition points of the regulators: calibrated "
                      "from the reduced contact flexibility (automatic) or "
                      "the points below (prm), as in the paper's Table 2.");
    prm.declare_entry("gap points",
                      "1e-3, 5e-3, 1e-2",
                      Patterns::Anything(),
                      "Normal regulator input a1 < a2 < a3 [m] (prm).");
    prm.declare_entry("force points",
                      "500, 5000, 15000",
                      Patterns::Anything(),
                      "Normal regulator output b1 < b2 < b3 [N] (prm).");
    prm.declare_entry("slip points",
                      "1e-3, 5e-3, 1e-2",
                      Patterns::Anything(),
                      "Tangential regulator input a1 < a2 < a3 [m] (prm).");
    prm.declare_entry("friction points",
                      "500, 5000, 15000",
                      Patterns::Anything(),
                      "Tangential regulator output b1 < b2 < b3 [N] (prm).");
    prm.declare_entry("tolerance",
                      "1e-4",
                      Patterns::Double(),
                      "Relative tolerance on the gaps (times the largest "
                      "free penetration) and on the force change (times "
                      "the total normal force).");
    prm.declare_entry("max iterations",
                      "20000",
                      Patterns::Integer(),
                      "Regulator iterations per load step before FL2C "
                      "gives up with an error.");
    prm.leave_subsection();
  }


  void
  FL2CParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("FL2C");
    calibration       = prm.get("calibration") == "prm" ? Calibration::prm
                                                        : Calibration::automatic;
    const auto points = [&](const std::string &key) {
      const std::vector<double> v =
        Input::to_doubles(prm.get(key), "FL2C: " + key, 3);
      return std::array<double, 3>{{v[0], v[1], v[2]}};
    };
    gap_points      = points("gap points");
    force_points    = points("force points");
    slip_points     = points("slip points");
    friction_points = points("friction points");
    tolerance = Input::positive(prm.get_double("tolerance"), "FL2C: tolerance");
    const long n = prm.get_integer("max iterations");
    AssertThrow(n >= 1,
                ExcMessage("FL2C: max iterations must be at least 1, got " +
                           std::to_string(n) + "."));
    max_iterations = n;
    prm.leave_subsection();
    check();
  }


  void
  FL2CParameters::check() const
  {
    MamdaniRegulator(gap_points,
                     force_points,
                     "FL2C: gap points / force points");
    MamdaniRegulator(slip_points,
                     friction_points,
                     "FL2C: slip points / friction points");
    AssertThrow(tolerance > 0 && tolerance < 1,
                ExcMessage("FL2C: tolerance must lie in (0, 1)."));
  }


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

    // The scale of the gap tolerance: the largest free penetration, or, if
    // nothing penetrates without contact forces, the largest free gap (and
    // the forces of a previous step are released).
    double
    gap_scale(const LoadStep &step, const unsigned int n)
    {
      double g_scale = 0;
      for (unsigned int k = 0; k < n; ++k)
        g_scale = std::max(g_scale, -step.g_free[normal_row(k)]);
      if (g_scale == 0)
        for (unsigned int k = 0; k < n; ++k)
          g_scale = std::max(g_scale, std::abs(step.g_free[normal_row(k)]));
      return g_scale;
    }

    // 1. Reduced solve: the gaps g = g_free + W p of the current forces.
    void
    compute_gaps(ContactState         &state,
                 FlexibilityOperator  &W,
                 const Vector<double> &g_free)
    {
      state.g = g_free;
      for (unsigned int j = 0; j < state.p.size(); ++j)
        if (state.p[j] != 0)
          {
            const double *w = W.column(j);
            for (unsigned int i = 0; i < state.p.size(); ++i)
              state.g[i] += w[i] * state.p[j];
          }
    }

    // Whether the gaps satisfy the contact conditions within @p gap_tol.
    bool
    gaps_converged(const ContactState        &state,
                   const LoadStep            &step,
                   const std::vector<double> &mu,
                   const double               gap_tol)
    {
      bool gaps_ok = true;
      for (unsigned int k = 0; k < mu.size() && gaps_ok; ++k)
        {
          const double pn = state.p[normal_row(k)];
          const double pt = state.p[tangential_row(k)];
          const double gn = state.g[normal_row(k)];
          const double dgt =
            state.g[tangential_row(k)] - step.g_previous[tangential_row(k)];
          if (pn > 0)
            {
              gaps_ok = std::abs(gn) <= gap_tol;
              if (mu[k] > 0 && std::abs(pt) < mu[k] * pn)
                gaps_ok = gaps_ok && std::abs(dgt) <= gap_tol;
              else if (mu[k] > 0)
                gaps_ok = gaps_ok && (pt > 0 ? dgt : -dgt) <= gap_tol;
            }
          else
            gaps_ok = gn >= -gap_tol;
        }
      return gaps_ok;
    }

    // The complementarity residuals of @p state and their scale, with c_n
    // and c_t from the diagonal of W.
    std::pair<std::vector<double>, double>
    residuals(const ContactState        &state,
              const LoadStep            &step,
              FlexibilityOperator       &W,
              const std::vector<double> &mu)
    {
      const auto c_n = [&](unsigned int k) {
        return 1. / W.diagonal(normal_row(k));
      };
      const auto c_t = [&](unsigned int k) {
        return 1. / W.diagonal(tangential_row(k));
      };
      return {complementarity_residuals(state.p,
                                        state.g,
                                        step.g_previous,
                                        mu,
                                        c_n,
                                        c_t),
              residual_scale(state.p, step.g_free, c_n)};
    }

    // 2. One sweep of the regulators, node by node, most penetrating first;
    // each acts on the gaps left by the force changes before it (the
    // reduced solve is incremental: a change dp_j moves the gaps by W e_j
    // dp_j). Returns the largest force change.
    double
    sweep(ContactState              &state,
          const LoadStep            &step,
          FlexibilityOperator       &W,
          const std::vector<double> &mu,
          const Regulators          &regulators)
    {
      const unsigned int        n = mu.size();
      std::vector<unsigned int> order;
      for (unsigned int k = 0; k < n; ++k)
        if (state.p[normal_row(k)] > 0 || state.g[normal_row(k)] < 0)
          order.push_back(k);
      std::stable_sort(order.begin(),
                       order.end(),
                       [&](const unsigned int i, const unsigned int j) {
                         return state.g[normal_row(i)] < state.g[normal_row(j)];
                       });
      double     force_change = 0;
      const auto apply = [&](const unsigned int row, const double change) {
        if (change == 0)
          return;
        state.p[row] += change;
        const double *w = W.column(row);
        for (unsigned int i = 0; i < 2 * n; ++i)
          state.g[i] += w[i] * change;
        force_change = std::max(force_change, std::abs(change));
      };
      for (const unsigned int k : order)
        {
          const unsigned int rn = normal_row(k), rt = tangential_row(k);
          const double       dpn =
            regulators.normal_change(state.g[rn], W.diagonal(rn));
          const double pn = std::max(0., state.p[rn] + dpn);
          apply(rn, pn - state.p[rn]);
          if (mu[k] == 0)
            continue;
          // Tangential force capped by Coulomb's bound.
          const double dgt = state.g[rt] - step.g_previous[rt];
          const double dpt = regulators.tangential_change(dgt, W.diagonal(rt));
          apply(rt,
                std::clamp(state.p[rt] + dpt, -mu[k] * pn, mu[k] * pn) -
                  state.p[rt]);
        }
      return force_change;
    }

    // 3. Status of the forces: open where p_n = 0, slip where |p_t| = mu
    // p_n, stick elsewhere.
    void
    set_statuses(ContactState &state, const std::vector<double> &mu)
    {
      for (unsigned int k = 0; k < mu.size(); ++k)
        {
          const double pn = state.p[normal_row(k)],
                       pt = state.p[tangential_row(k)];
          if (pn <= 0)
            state.status[k] = ContactStatus::open;
          else if (mu[k] > 0 && std::abs(pt) < mu[k] * pn)
            state.status[k] = ContactStatus::stick;
          else
            {
              state.status[k]    = ContactStatus::slip;
              state.slip_sign[k] = pt >= 0 ? 1 : -1;
            }
        }
    }
  } // namespace


  ContactState
  FL2CSolver::solve_step(const ContactProblem &problem,
                         const LoadStep       &step,
                         const std::string    &what) const
  {
    const unsigned int         n  = problem.n_nodes();
    const std::vector<double> &mu = problem.mu;
    DenseFlexibility           dense(problem.W);
    FlexibilityOperator       &W =
      problem.flexibility != nullptr ? *problem.flexibility : dense;

    // Scales of the stopping tests.
    const double     g_scale = gap_scale(step, n);
    const double     gap_tol = parameters_.tolerance * g_scale;
    const Regulators regulators{
      parameters_.calibration == FL2CParameters::Calibration::automatic,
      shape,
      shape_gain,
      g_scale / 3,
      MamdaniRegulator(parameters_.gap_points, parameters_.force_points),
      MamdaniRegulator(parameters_.slip_points, parameters_.friction_points)};

    ContactState state;
    state.p = step.previous.p;
    if (state.p.size() != 2 * n)
      state.p.reinit(2 * n);
    state.status.assign(n, ContactStatus::open);
    state.slip_sign.assign(n, 0);

    double force_change = std::numeric_limits<double>::infinity();
    for (unsigned int it = 1; it <= parameters_.max_iterations; ++it)
      {
        compute_gaps(state, W, step.g_free);

        // Convergence: the gaps, and the force change of the last sweep.
        double total = 0;
        for (unsigned int k = 0; k < n; ++k)
          total += state.p[normal_row(k)];
        if (gaps_converged(state, step, mu, gap_tol) &&
            (force_change <= parameters_.tolerance * total || total == 0))
          {
            state.iterations = it;
            break;
          }
        if (it == parameters_.max_iterations)
          {
            state.iterations      = it;
            const auto [r, scale] = residuals(state, step, W, mu);
            std::ostringstream message;
            message << what << ": the fuzzy regulators did not converge in "
                    << parameters_.max_iterations << " iterations (load step "
                    << step.step << "); complementarity residual "
                    << *std::max_element(r.begin(), r.end()) / scale
                    << ", last force change " << force_change << " N.";
            AssertThrow(false, ExcMessage(message.str()));
          }
        force_change = sweep(state, step, W, mu, regulators);
      }

    set_statuses(state, mu);
    const auto [r, scale] = residuals(state, step, W, mu);
    const double worst    = *std::max_element(r.begin(), r.end());
    state.residual        = worst == 0 ? 0. : worst / scale;
    return state;
  }
} // namespace FuzzyContact
