#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/contact/contact_workspace.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace FuzzyContact
{
  std::string
  to_string(const ContactStatus status)
  {
    switch (status)
      {
        case ContactStatus::open:
          return "open";
        case ContactStatus::stick:
          return "stick";
        case ContactStatus::slip:
          return "slip";
      }
    return "?";
  }


  namespace
  {
    // Every FlexibilityOperator's states are drawn from one counter, so no
    // two operators (nor two values of one) share a state.
    std::atomic<unsigned long> flexibility_states{0};
  } // namespace


  FlexibilityOperator::FlexibilityOperator()
      : state_(++flexibility_states)
  {
  }


  void
  FlexibilityOperator::changed()
  {
    state_ = ++flexibility_states;
  }


  void
  FlexibilityOperator::restored(const unsigned long state)
  {
    Assert(state > 0 && state <= flexibility_states,
           ExcMessage("Not a state this program gave out."));
    state_ = state;
  }


  unsigned long
  FlexibilityOperator::state() const
  {
    return state_;
  }


  void
  FlexibilityOperator::add_columns(const std::vector<unsigned int> &columns,
                                   const Vector<double>            &p,
                                   Vector<double>                  &g)
  {
    AssertDimension(g.size(), size());
    const types::blas_int m = g.size(), one = 1;
    for (const unsigned int j : columns)
      if (p[j] != 0)
        {
          const double pj = p[j];
          axpy(&m, &pj, column(j), &one, g.data(), &one);
        }
  }


  DenseFlexibility::DenseFlexibility(const FullMatrix<double> &W)
      : W(W)
  {
    AssertDimension(W.m(), W.n());
  }

  unsigned int
  DenseFlexibility::size() const
  {
    return W.m();
  }

  void
  DenseFlexibility::prepare(const std::vector<unsigned int> &)
  {
  }

  double
  DenseFlexibility::operator()(const unsigned int i, const unsigned int j) const
  {
    return W(i, j);
  }

  const double *
  DenseFlexibility::column(const unsigned int j)
  {
    AssertIndexRange(j, W.m());
    gathered.resize(W.m());
    for (unsigned int i = 0; i < W.m(); ++i)
      gathered[i] = W(i, j);
    return gathered.data();
  }

  double
  DenseFlexibility::diagonal(const unsigned int i)
  {
    return W(i, i);
  }


  unsigned int
  RigidMotions::size() const
  {
    return gaps.n();
  }

  RigidMotions
  RigidMotions::restricted(const std::vector<unsigned int> &rows) const
  {
    RigidMotions r;
    r.names = names;
    r.gaps.reinit(rows.size(), size());
    for (unsigned int i = 0; i < rows.size(); ++i)
      for (unsigned int j = 0; j < size(); ++j)
        r.gaps(i, j) = gaps(rows[i], j);
    return r;
  }

  unsigned int
  LoadStep::n_motions() const
  {
    return rigid == nullptr ? 0 : rigid->size();
  }


  unsigned int
  ContactProblem::n_nodes() const
  {
    return mu.size();
  }

  unsigned int
  ContactProblem::n_rows() const
  {
    return 2 * mu.size();
  }

  Vector<double>
  ContactProblem::free_gaps(const double load_factor) const
  {
    Vector<double> g = g_initial;
    g.add(load_factor, g_load);
    return g;
  }

  void
  ContactProblem::shift_gaps(const double offset)
  {
    AssertThrow(std::isfinite(offset),
                ExcMessage("gap offset must be a finite number."));
    for (unsigned int k = 0; k < n_nodes(); ++k)
      g_initial[normal_row(k)] += offset;
  }

  void
  ContactProblem::set_friction_coefficient(const double value)
  {
    AssertThrow(std::isfinite(value) && value >= 0,
                ExcMessage("friction coefficient must not be negative, got " +
                           std::to_string(value) + "."));
    std::fill(mu.begin(), mu.end(), value);
  }

  void
  ContactProblem::check() const
  {
    const unsigned int m     = n_rows();
    const bool         dense = flexibility == nullptr;
    AssertThrow((dense ? W.m() == m && W.n() == m : flexibility->size() == m) &&
                  g_initial.size() == m && g_load.size() == m,
                ExcMessage("ContactProblem: W, g_initial and g_load must all "
                           "have 2 rows per node."));
    // (Checked at every solve of a study: one pass without branches.)
    const auto finite = [](const double *begin, const double *end) {
      // x * 0 is NaN where x is not finite; four sums side by side.
      double            zero[4] = {0, 0, 0, 0};
      const std::size_t n       = end - begin;
      std::size_t       i       = 0;
      for (; i + 4 <= n; i += 4)
        for (unsigned int l = 0; l < 4; ++l)
          zero[l] += begin[i + l] * 0.;
      for (; i < n; ++i)
        zero[0] += begin[i] * 0.;
      return zero[0] + zero[1] + zero[2] + zero[3] == 0;
    };
    AssertThrow(finite(g_initial.begin(), g_initial.end()) &&
                  finite(g_load.begin(), g_load.end()),
                ExcMessage("ContactProblem: a gap is not finite."));
    for (unsigned int i = 0; i < m && dense; ++i)
      AssertThrow(finite(&W(i, 0), &W(i, 0) + m),
                  ExcMessage("ContactProblem: W has a non-finite entry."));
    for (const GapLoadStage &stage : stages)
      {
        AssertThrow(stage.g_load.size() == m && stage.n_steps >= 1,
                    ExcMessage("ContactProblem: a load stage needs 2 gap "
                               "rows per node and at least one step."));
        AssertThrow(finite(stage.g_load.begin(), stage.g_load.end()),
                    ExcMessage("ContactProblem: a gap is not finite."));
      }
    for (const double value : mu)
      AssertThrow(std::isfinite(value) && value >= 0,
                  ExcMessage("ContactProblem: friction coefficients must not "
                             "be negative."));
    const unsigned int r = rigid.size();
    AssertThrow((r == 0 || rigid.gaps.m() == m) && rigid.names.size() == r &&
                  rigid_load.size() == r,
                ExcMessage("ContactProblem: the free rigid-body motions need "
                           "a gap row per contact row, a name and a load "
                           "resultant each."));
    for (const GapLoadStage &stage : stages)
      AssertThrow(stage.rigid_load.size() == r,
                  ExcMessage("ContactProblem: a load stage needs the "
                             "resultant of its loads along every free "
                             "rigid-body motion."));
  }


  ContactState
  solve_in_load_steps(
    const Vector<double>                                &g_initial,
    const std::vector<GapLoadStage>                     &stages,
    const double                                         load_factor,
    const std::function<ContactState(const LoadStep &)> &solve_step,
    const RigidMotions                                  *rigid,
    ContactWorkspace                                    *workspace)
  {
    AssertThrow(!stages.empty(),
                ExcMessage("A load history needs at least one stage."));
    const unsigned int n_motions = rigid == nullptr ? 0 : rigid->size();
    AssertThrow(std::isfinite(load_factor),
                ExcMessage("The load factor must be finite."));
    const unsigned int m = g_initial.size();
    for (const GapLoadStage &stage : stages)
      {
        AssertThrow(stage.n_steps >= 1,
                    ExcMessage("The number of load steps must be at least 1."));
        AssertDimension(stage.g_load.size(), m);
        AssertThrow(n_motions == 0 || stage.rigid_load.size() == n_motions,
                    ExcMessage("A load stage needs the resultant of its "
                               "loads along every free rigid-body motion."));
      }

    ContactState state;
    state.p.reinit(m);
    state.g = g_initial;
    state.status.assign(m / 2, ContactStatus::open);
    state.slip_sign.assign(m / 2, 0);

    unsigned int   iterations = 0, step_count = 0;
    double         residual = 0;
    Vector<double> g_held   = g_initial; // the earlier stages at full load
    Vector<double> e_held(n_motions);
    state.rigid.reinit(n_motions);
    if (workspace != nullptr)
      workspace->converged.clear();
    for (unsigned int stage = 0; stage < stages.size(); ++stage)
      {
        const GapLoadStage &current = stages[stage];
        for (unsigned int s = 1; s <= current.n_steps; ++s)
          {
            LoadStep step;
            step.step        = ++step_count;
            step.stage       = stage;
            step.load_factor = load_factor * s / current.n_steps;
            step.g_free      = g_held;
            step.g_free.add(step.load_factor, current.g_load);
            step.g_previous = state.g;
            step.previous   = state;
            if (n_motions > 0)
              {
                step.rigid      = rigid;
                step.rigid_load = e_held;
                step.rigid_load.add(step.load_factor, current.rigid_load);
              }
            if (workspace != nullptr)
              {
                step.workspace = workspace;
                if (step.step <= workspace->start.size() &&
                    workspace->start[step.step - 1].status.size() == m / 2)
                  step.start = &workspace->start[step.step - 1];
              }
            state = solve_step(step);
            if (workspace != nullptr)
              workspace->converged.push_back(state);
            iterations += state.iterations;
            residual = std::max(residual, state.residual);
          }
        g_held.add(load_factor, current.g_load);
        if (n_motions > 0)
          e_held.add(load_factor, current.rigid_load);
      }
    state.iterations = iterations;
    state.residual   = residual;
    return state;
  }


  ContactState
  solve_in_load_steps(
    const Vector<double>                                &g_initial,
    const Vector<double>                                &g_load,
    const double                                         load_factor,
    const unsigned int                                   n_steps,
    const std::function<ContactState(const LoadStep &)> &solve_step)
  {
    AssertThrow(n_steps >= 1,
                ExcMessage("The number of load steps must be at least 1."));
    AssertDimension(g_load.size(), g_initial.size());
    return solve_in_load_steps(g_initial,
                               {GapLoadStage{g_load, n_steps, {}}},
                               load_factor,
                               solve_step);
  }


  double
  complementarity_residual(const unsigned int    k,
                           const Vector<double> &p,
                           const Vector<double> &g,
                           const Vector<double> &g_previous,
                           const double          mu,
                           const std::function<double(unsigned int)> &c_n,
                           const std::function<double(unsigned int)> &c_t)
  {
    const double pn = p[normal_row(k)], pt = p[tangential_row(k)];
    const double gn = g[normal_row(k)];
    // An open node with a non-negative gap and no force satisfies both
    // conditions whatever the scaling.
    if (pn == 0 && pt == 0 && gn >= 0)
      return 0;
    const double a   = std::max(0., pn - c_n(k) * gn);
    const double phi = pn - a;
    double       psi = pt;
    if (mu > 0 && a > 0)
      {
        const double dgt = g[tangential_row(k)] - g_previous[tangential_row(k)];
        const double z   = pt - c_t(k) * dgt;
        psi              = pt - std::clamp(z, -mu * a, mu * a);
      }
    return std::abs(phi) + std::abs(psi);
  }


  std::vector<double>
  complementarity_residuals(const Vector<double>      &p,
                            const Vector<double>      &g,
                            const Vector<double>      &g_previous,
                            const std::vector<double> &mu,
                            const std::function<double(unsigned int)> &c_n,
                            const std::function<double(unsigned int)> &c_t)
  {
    const unsigned int n = mu.size();
    AssertDimension(p.size(), 2 * n);
    AssertDimension(g.size(), 2 * n);
    AssertDimension(g_previous.size(), 2 * n);
    std::vector<double> r(n, 0.);
    for (unsigned int k = 0; k < n; ++k)
      r[k] = complementarity_residual(k, p, g, g_previous, mu[k], c_n, c_t);
    return r;
  }


  double
  residual_scale(const Vector<double>                      &p,
                 const Vector<double>                      &g_free,
                 const std::function<double(unsigned int)> &c_n)
  {
    double total = 0;
    for (unsigned int k = 0; 2 * k < p.size(); ++k)
      total += std::max(p[normal_row(k)], 0.);
    if (total > 0)
      return total;
    // No contact force at all: the force that would close the largest
    // free penetration.
    double scale = 0;
    for (unsigned int k = 0; 2 * k < p.size(); ++k)
      if (g_free[normal_row(k)] < 0)
        scale = std::max(scale, -c_n(k) * g_free[normal_row(k)]);
    return scale;
  }


  void
  add_rigid_gaps(const LoadStep       &step,
                 const Vector<double> &a,
                 Vector<double>       &g)
  {
    for (unsigned int j = 0; j < step.n_motions(); ++j)
      if (a[j] != 0)
        for (unsigned int i = 0; i < g.size(); ++i)
          g[i] += step.rigid->gaps(i, j) * a[j];
  }


  double
  equilibrium_residual(const LoadStep       &step,
                       const Vector<double> &p,
                       const double          force_scale)
  {
    double worst = 0;
    for (unsigned int j = 0; j < step.n_motions(); ++j)
      {
        double sum = step.rigid_load[j], scale = std::abs(step.rigid_load[j]);
        double largest = 0;
        for (unsigned int i = 0; i < p.size(); ++i)
          {
            largest = std::max(largest, std::abs(step.rigid->gaps(i, j)));
            if (p[i] != 0)
              {
                sum += step.rigid->gaps(i, j) * p[i];
                scale += std::abs(step.rigid->gaps(i, j) * p[i]);
              }
          }
        scale += force_scale * largest;
        if (scale > 0)
          worst = std::max(worst, std::abs(sum) / scale);
      }
    return worst;
  }


  void
  check_motions_determined(const LoadStep       &step,
                           const Vector<double> &p,
                           const std::string    &what,
                           const double          force_scale)
  {
    double total = 0;
    for (unsigned int j = 0; j < step.n_motions(); ++j)
      total += std::abs(step.rigid_load[j]);
    for (unsigned int k = 0; 2 * k < p.size(); ++k)
      total += std::abs(p[normal_row(k)]);
    // Forces at the round-off of the problem's force scale are none.
    total = std::max(total, force_scale);
    for (unsigned int j = 0; j < step.n_motions(); ++j)
      {
        double along = std::abs(step.rigid_load[j]);
        for (unsigned int i = 0; i < p.size(); ++i)
          along += std::abs(step.rigid->gaps(i, j) * p[i]);
        AssertThrow(along > 1e-12 * total && total > 0,
                    ExcPositionNotDetermined(
                      what +
                      ": the position of a body held by "
                      "contact alone is not determined (load "
                      "step " +
                      std::to_string(step.step) +
                      "): no load and no contact force acts along " +
                      step.rigid->names[j] +
                      ", so any position that does not penetrate "
                      "is a solution. Hold it by a support, or load "
                      "it onto its contact."));
      }
  }


  double
  ContactSolution::p_n(const unsigned int k) const
  {
    return p[normal_row(k)];
  }

  double
  ContactSolution::p_t(const unsigned int k) const
  {
    return p[tangential_row(k)];
  }

  unsigned int
  ContactSolution::n_nodes() const
  {
    return p.size() / 2;
  }

  unsigned int
  ContactSolution::count(const ContactStatus s) const
  {
    return std::count(status.begin(), status.end(), s);
  }

  void
  ContactSolution::compute_totals()
  {
    normal_force     = 0;
    tangential_force = 0;
    for (unsigned int k = 0; k < n_nodes(); ++k)
      {
        normal_force += p_n(k);
        tangential_force += p_t(k);
      }
  }
} // namespace FuzzyContact
