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


  ContactState
  FL2CSolver::solve_step(const ContactProblem &problem,
                         const LoadStep       &step,
                         const std::string    &what) const
  {
    const unsigned int         n  = problem.n_nodes();
    const FullMatrix<double>  &W  = problem.W;
    const std::vector<double> &mu = problem.mu;
    const bool                 automatic =
      parameters_.calibration == FL2CParameters::Calibration::automatic;
    const MamdaniRegulator normal(parameters_.gap_points,
                                  parameters_.force_points);
    const MamdaniRegulator tangential(parameters_.slip_points,
                                      parameters_.friction_points);

    // Scales of the stopping tests.
    double g_scale = 0;
    for (unsigned int k = 0; k < n; ++k)
      g_scale = std::max(g_scale, -step.g_free[normal_row(k)]);
    if (g_scale == 0)
      // Nothing penetrates without contact forces: the gaps themselves
      // set the scale (and the forces of a previous step are released).
      for (unsigned int k = 0; k < n; ++k)
        g_scale = std::max(g_scale, std::abs(step.g_free[normal_row(k)]));
    const double g_ref   = g_scale / 3;
    const double gap_tol = parameters_.tolerance * g_scale;

    ContactState state;
    state.p = step.previous.p;
    if (state.p.size() != 2 * n)
      state.p.reinit(2 * n);
    state.status.assign(n, ContactStatus::open);
    state.slip_sign.assign(n, 0);

    double force_change = std::numeric_limits<double>::infinity();
    for (unsigned int it = 1; it <= parameters_.max_iterations; ++it)
      {
        // 1. Reduced solve: the gaps of the current forces.
        state.g = step.g_free;
        for (unsigned int j = 0; j < 2 * n; ++j)
          if (state.p[j] != 0)
            for (unsigned int i = 0; i < 2 * n; ++i)
              state.g[i] += W(i, j) * state.p[j];

        // Convergence: the gaps, and the force change of the last step.
        double total = 0;
        for (unsigned int k = 0; k < n; ++k)
          total += state.p[normal_row(k)];
        bool gaps_ok = true;
        for (unsigned int k = 0; k < n && gaps_ok; ++k)
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
        if (gaps_ok &&
            (force_change <= parameters_.tolerance * total || total == 0))
          {
            state.iterations = it;
            break;
          }
        if (it == parameters_.max_iterations)
          {
            state.iterations            = it;
            const std::vector<double> r = complementarity_residuals(
              state.p,
              state.g,
              step.g_previous,
              mu,
              [&](unsigned int k) {
                return 1. / W(normal_row(k), normal_row(k));
              },
              [&](unsigned int k) {
                return 1. / W(tangential_row(k), tangential_row(k));
              });
            const double scale =
              residual_scale(state.p, step.g_free, [&](unsigned int k) {
                return 1. / W(normal_row(k), normal_row(k));
              });
            std::ostringstream message;
            message << what << ": the fuzzy regulators did not converge in "
                    << parameters_.max_iterations << " iterations (load step "
                    << step.step << "); complementarity residual "
                    << *std::max_element(r.begin(), r.end()) / scale
                    << ", last force change " << force_change << " N.";
            AssertThrow(false, ExcMessage(message.str()));
          }

        // 2. Regulators, node by node, most penetrating first; each acts on
        // the gaps left by the force changes before it (the reduced solve
        // is incremental: a change dp_j moves the gaps by W e_j dp_j).
        std::vector<unsigned int> order;
        for (unsigned int k = 0; k < n; ++k)
          if (state.p[normal_row(k)] > 0 || state.g[normal_row(k)] < 0)
            order.push_back(k);
        std::stable_sort(order.begin(),
                         order.end(),
                         [&](const unsigned int i, const unsigned int j) {
                           return state.g[normal_row(i)] <
                                  state.g[normal_row(j)];
                         });
        const auto apply = [&](const unsigned int row, const double change) {
          if (change == 0)
            return;
          state.p[row] += change;
          for (unsigned int i = 0; i < 2 * n; ++i)
            state.g[i] += W(i, row) * change;
          force_change = std::max(force_change, std::abs(change));
        };
        force_change = 0;
        for (const unsigned int k : order)
          {
            const unsigned int rn = normal_row(k), rt = tangential_row(k);
            // Normal regulator: gap -> force increment.
            const double dpn = automatic ? shape(state.g[rn] / g_ref) * g_ref /
                                             (shape_gain * W(rn, rn))
                                         : normal(state.g[rn]);
            const double pn  = std::max(0., state.p[rn] + dpn);
            apply(rn, pn - state.p[rn]);
            if (mu[k] == 0)
              continue;
            // Tangential regulator: slip of the step -> force increment,
            // capped by Coulomb's bound.
            const double dgt = state.g[rt] - step.g_previous[rt];
            const double dpt =
              automatic ? shape(dgt / g_ref) * g_ref / (shape_gain * W(rt, rt))
                        : tangential(dgt);
            apply(rt,
                  std::clamp(state.p[rt] + dpt, -mu[k] * pn, mu[k] * pn) -
                    state.p[rt]);
          }
      }

    // 3. Status of the converged forces.
    for (unsigned int k = 0; k < n; ++k)
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
    const auto c_n = [&](unsigned int k) {
      return 1. / W(normal_row(k), normal_row(k));
    };
    const auto c_t = [&](unsigned int k) {
      return 1. / W(tangential_row(k), tangential_row(k));
    };
    const std::vector<double> r     = complementarity_residuals(state.p,
                                                            state.g,
                                                            step.g_previous,
                                                            mu,
                                                            c_n,
                                                            c_t);
    const double              worst = *std::max_element(r.begin(), r.end());
    state.residual =
      worst == 0 ? 0. : worst / residual_scale(state.p, step.g_free, c_n);
    return state;
  }


} // namespace FuzzyContact
