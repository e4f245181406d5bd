#include <fuzzycontact/contact/full_order_contact.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace FuzzyContact
{
  // The Schur complement W seen by the active set solver.
  class FullOrderContact::Flexibility : public FlexibilityOperator
  {
  public:
    explicit Flexibility(FullOrderContact &owner)
        : owner(owner)
    {
    }
    unsigned int
    size() const override
    {
      return owner.interface.n_rows();
    }
    void
    prepare(const std::vector<unsigned int> &js) override
    {
      for (const unsigned int j : js)
        owner.prepare_column(j);
    }
    double
    operator()(const unsigned int i, const unsigned int j) const override
    {
      return owner.entry(i, j);
    }
    const double *
    column(const unsigned int j) override
    {
      owner.prepare_column(j);
      return owner.columns[j]->data();
    }
    double
    diagonal(const unsigned int i) override
    {
      owner.prepare_column(i);
      return owner.entry(i, i);
    }

  private:
    FullOrderContact &owner;
  };


  FullOrderContact::FullOrderContact(
    const std::vector<const Component *> &components,
    const ContactInterface               &interface,
    const ActiveSetParameters            &parameters)
      : components(components)
      , interface(interface)
      , solver(parameters)
      , initial_gaps_(interface.initial_gaps())
      , friction_(interface.friction_coefficients())
      , observed_dofs(components.size())
      , factorized(components.size())
  {
    AssertThrow(components.size() == interface.n_components(),
                ExcMessage("FullOrderContact: one component per component of "
                           "the contact interface is needed."));
    for (const Component *component : components)
      {
        std::vector<double> declared, reference;
        for (unsigned int l = 0; l < component->description().loads.size(); ++l)
          {
            declared.push_back(component->description().loads[l].total_force);
            reference.push_back(component->reference_load_force(l));
          }
        load_forces_.push_back(declared);
        reference_forces_.push_back(reference);
      }
    // The free motions of the bodies held by contact alone: G = C_c R_c,
    // and the resultant of each load along them.
    unsigned int n_motions = 0;
    for (const Component *component : components)
      {
        first_motion_.push_back(n_motions);
        n_motions += component->free_motions().size();
        std::vector<Vector<double>> e;
        for (unsigned int l = 0; l < component->description().loads.size(); ++l)
          e.push_back(component->rigid_load(l));
        rigid_loads_.push_back(std::move(e));
      }
    rigid_.gaps.reinit(interface.n_rows(), n_motions);
    for (unsigned int c = 0; c < components.size(); ++c)
      for (unsigned int j = 0; j < components[c]->free_motions().size(); ++j)
        {
          Vector<double> g(interface.n_rows());
          interface.gap_operator(c).vmult(g, components[c]->free_motions()[j]);
          for (unsigned int i = 0; i < g.size(); ++i)
            rigid_.gaps(i, first_motion_[c] + j) = g[i];
          rigid_.names.push_back(components[c]->name() + ": " +
                                 components[c]->free_motion_names()[j]);
        }
  }

  void
  FullOrderContact::set_load_forces(
    const std::vector<std::vector<double>> &load_forces)
  {
    AssertThrow(load_forces.size() == components.size(),
                ExcMessage("FullOrderContact: one list of load forces per "
                           "component is expected."));
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        AssertThrow(load_forces[c].size() == load_forces_[c].size(),
                    ExcMessage("FullOrderContact: one force per load of "
                               "component " +
                               components[c]->name() + " is expected."));
        for (const double f : load_forces[c])
          AssertThrow(std::isfinite(f),
                      ExcMessage("FullOrderContact: the load forces of "
                                 "component " +
                                 components[c]->name() + " must be finite."));
      }
    load_forces_ = load_forces;
  }

  void
  FullOrderContact::set_load_factor(const double load_factor)
  {
    AssertThrow(std::isfinite(load_factor),
                ExcMessage("The load factor must be finite."));
    load_factor_ = load_factor;
  }

  void
  FullOrderContact::set_contact_conditions(
    const Vector<double>      &initial_gaps,
    const std::vector<double> &friction_coefficients)
  {
    AssertThrow(initial_gaps.size() == interface.n_rows() &&
                  friction_coefficients.size() == interface.n_nodes(),
                ExcMessage("FullOrderContact: two gaps and one friction "
                           "coefficient per slave node are expected."));
    initial_gaps_ = initial_gaps;
    friction_     = friction_coefficients;
  }

  void
  FullOrderContact::set_factorisation_source(
    std::function<std::shared_ptr<const StiffnessSolver>(unsigned int)> source)
  {
    factorisation_source = std::move(source);
  }


  void
  FullOrderContact::set_n_load_steps(const unsigned int n_load_steps)
  {
    AssertThrow(n_load_steps >= 1,
                ExcMessage("n_load_steps must be at least 1."));
    n_load_steps_ = n_load_steps;
  }

  void
  FullOrderContact::set_load_stages(const std::vector<LoadStage> &stages)
  {
    for (const LoadStage &stage : stages)
      {
        AssertThrow(stage.n_load_steps >= 1,
                    ExcMessage("FullOrderContact: stage " + stage.name +
                               " needs at least one load step."));
        for (const auto &[c, l] : stage.loads)
          AssertThrow(c < components.size() && l < load_forces_[c].size(),
                      ExcMessage("FullOrderContact: stage " + stage.name +
                                 " names a load the components do not "
                                 "have."));
      }
    load_stages_ = stages;
  }

  void
  FullOrderContact::set_warm_start(const bool warm_start)
  {
    warm_start_ = warm_start;
  }

  void
  FullOrderContact::set_displacement_fields(const bool fields)
  {
    displacement_fields_ = fields;
  }


  void
  FullOrderContact::observe(const ObservedDofs &dofs)
  {
    AssertThrow(dofs.size() == components.size(),
                ExcMessage("FullOrderContact: one list of observed DoFs per "
                           "component is expected."));
    for (unsigned int c = 0; c < components.size(); ++c)
      for (const types::global_dof_index dof : dofs[c])
        AssertThrow(dof < components[c]->n_dofs(),
                    ExcMessage("FullOrderContact: an observed DoF does not "
                               "exist in component " +
                               components[c]->name() + "."));
    if (dofs == observed_dofs)
      return;
    // Columns computed for other DoFs would lack the values at these.
    observed_dofs = dofs;
    for (Factorized &F : factorized)
      {
        F.columns.clear();
        F.columns.resize(interface.n_rows());
        F.observed_columns.clear();
        F.observed_columns.resize(interface.n_rows());
      }
    columns.clear();
    columns.resize(interface.n_rows());
  }


  Vector<double>
  FullOrderContact::load_vector(const unsigned int c) const
  {
    Vector<double> f(components[c]->n_dofs());
    for (unsigned int l = 0; l < load_forces_[c].size(); ++l)
      if (load_forces_[c][l] != 0)
        f.add(load_forces_[c][l], components[c]->unit_load_vector(l));
    return f;
  }


  Vector<double>
  FullOrderContact::load_response(const unsigned int c,
                                  const LoadStage   *stage) const
  {
    const Factorized &F = factorized[c];
    Vector<double>    u(components[c]->n_dofs());
    for (unsigned int l = 0; l < F.load_responses.size(); ++l)
      {
        if (stage != nullptr && !stage->ramps(c, l))
          continue;
        const double factor = load_factor(c, l);
        if (factor == 1)
          u += F.load_responses[l];
        else if (factor != 0)
          u.add(factor, F.load_responses[l]);
      }
    return u;
  }


  double
  FullOrderContact::load_factor(const unsigned int c,
                                const unsigned int l) const
  {
    // K = s K_ref: a force's response is K_ref^{-1} f / s; the forces that
    // impose a displacement are s times those of K_ref, so their response
    // does not change.
    const double s = components[c]->description().loads[l].is_displacement
                       ? 1.
                       : 1. / factorized[c].scale;
    return s * load_forces_[c][l] / reference_forces_[c][l];
  }


  double
  FullOrderContact::observed_displacement(const unsigned int c,
                                          const unsigned int position,
                                          const types::global_dof_index dof,
                                          const Vector<double>         &p) const
  {
    const Factorized &F = factorized[c];
    double            u = 0;
    for (unsigned int j = 0; j < p.size(); ++j)
      if (p[j] != 0 && !F.observed_columns[j].empty())
        u += p[j] * F.observed_columns[j][position];
    u /= F.scale;
    for (unsigned int l = 0; l < F.load_responses.size(); ++l)
      u += load_factor_ * load_factor(c, l) * F.load_responses[l][dof];
    return u;
  }


  void
  FullOrderContact::update_factorizations()
  {
    const unsigned int m             = interface.n_rows();
    bool               scale_changed = false;
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        Factorized                &F      = factorized[c];
        const std::vector<double> &moduli = components[c]->zone_moduli();
        bool                       reuse  = (F.inverse != nullptr);
        double                     scale  = 1;
        if (reuse)
          {
            scale = moduli[0] / F.moduli[0];
            for (unsigned int z = 0; z < moduli.size(); ++z)
              reuse = reuse && std::abs(moduli[z] / F.moduli[z] - scale) <=
                                 1e-14 * scale;
          }
        if (reuse)
          {
            if (scale != F.scale)
              scale_changed = true;
            F.scale = scale;
            update_weight_response(c);
            continue;
          }
        if (factorisation_source)
          F.inverse = factorisation_source(c);
        else
          {
            auto inverse = std::make_shared<SparseCholesky>();
            inverse->factorize(components[c]->stiffness_matrix(),
                               {},
                               "Component " + components[c]->name() +
                                 ": the stiffness matrix");
            F.inverse = std::move(inverse);
            ++factorizations;
          }
        Assert(F.inverse != nullptr &&
                 F.inverse->n() == components[c]->n_dofs(),
               ExcInternalError());
        F.moduli = moduli;
        F.scale  = 1;
        F.load_responses.clear();
        F.weight_responses.clear();
        for (unsigned int l = 0; l < reference_forces_[c].size(); ++l)
          {
            if (static_cast<int>(l) == components[c]->weight_load())
              {
                // Per zone, at unit density (update_weight_response()).
                for (const Vector<double> &w :
                     components[c]->weight_zone_loads())
                  {
                    Vector<double> u = w;
                    u *= reference_forces_[c][l];
                    F.inverse->solve(u);
                    ++back_substitutions;
                    F.weight_responses.push_back(std::move(u));
                  }
                F.load_responses.emplace_back(components[c]->n_dofs());
                continue;
              }
            Vector<double> u = components[c]->reference_load_vector(l);
            F.inverse->solve(u);
            ++back_substitutions;
            F.load_responses.push_back(std::move(u));
          }
        F.densities.clear();
        update_weight_response(c);
        F.columns.clear();
        F.columns.resize(m);
        F.observed_columns.clear();
        F.observed_columns.resize(m);
        scale_changed = true;
      }
    if (scale_changed || columns.size() != m)
      {
        columns.clear();
        columns.resize(m);
      }
  }


  void
  FullOrderContact::update_weight_response(const unsigned int c)
  {
    Factorized                &F         = factorized[c];
    const int                  l         = components[c]->weight_load();
    const std::vector<double> &densities = components[c]->zone_densities();
    if (l < 0 || densities == F.densities)
      return;
    // sum_z rho_z K_ref^{-1} w_z: no back-substitution.
    F.load_responses[l] = 0;
    for (unsigned int z = 0; z < densities.size(); ++z)
      F.load_responses[l].add(densities[z], F.weight_responses[z]);
    F.densities = densities;
  }


  void
  FullOrderContact::prepare_column(const unsigned int j)
  {
    AssertIndexRange(j, interface.n_rows());
    if (columns[j] != nullptr)
      return;
    const unsigned int m   = interface.n_rows();
    auto               sum = std::make_unique<Vector<double>>(m);
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        const SparseMatrix<double> &C = interface.gap_operator(c);
        if (C.begin(j) == C.end(j))
          continue; // row j does not touch component c
        Factorized &F = factorized[c];
        if (F.columns[j] == nullptr)
          {
            Vector<double> z(components[c]->n_dofs());
            for (auto it = C.begin(j); it != C.end(j); ++it)
              z[it->column()] = it->value();
            F.inverse->solve(z);
            ++back_substitutions;
            F.columns[j] = std::make_unique<Vector<double>>(m);
            C.vmult(*F.columns[j], z);
            if (!observed_dofs[c].empty())
              {
                F.observed_columns[j].clear();
                for (const types::global_dof_index dof : observed_dofs[c])
                  F.observed_columns[j].push_back(z[dof]);
              }
          }
        sum->add(1. / F.scale, *F.columns[j]);
      }
    columns[j] = std::move(sum);
  }


  double
  FullOrderContact::entry(const unsigned int i, const unsigned int j) const
  {
    Assert(columns[j] != nullptr, ExcInternalError());
    return (*columns[j])[i];
  }


  FullMatrix<double>
  FullOrderContact::flexibility()
  {
    update_factorizations();
    const unsigned int m = interface.n_rows();
    FullMatrix<double> W(m, m);
    for (unsigned int j = 0; j < m; ++j)
      {
        prepare_column(j);
        for (unsigned int i = 0; i < m; ++i)
          W(i, j) = entry(i, j);
      }
    return W;
  }


  Vector<double>
  FullOrderContact::load_gaps(const LoadStage *stage)
  {
    update_factorizations();
    Vector<double> g(interface.n_rows());
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        interface.gap_operator(c).vmult_add(g, load_response(c, stage));
      }
    return g;
  }


  std::vector<GapLoadStage>
  FullOrderContact::gap_load_stages()
  {
    if (load_stages_.empty())
      return {GapLoadStage{load_gaps(), n_load_steps_, rigid_load()}};
    std::vector<GapLoadStage> stages;
    for (const LoadStage &stage : load_stages_)
      stages.push_back(GapLoadStage{load_gaps(&stage),
                                    stage.n_load_steps,
                                    rigid_load(&stage)});
    return stages;
  }


  Vector<double>
  FullOrderContact::rigid_load(const LoadStage *stage) const
  {
    Vector<double> e(rigid_.size());
    for (unsigned int c = 0; c < components.size(); ++c)
      for (unsigned int l = 0; l < rigid_loads_[c].size(); ++l)
        if (stage == nullptr || stage->ramps(c, l))
          {
            // (The weight's follows the current densities.)
            const Vector<double> e_l =
              static_cast<int>(l) == components[c]->weight_load()
                ? components[c]->rigid_load(l)
                : rigid_loads_[c][l];
            for (unsigned int j = 0; j < e_l.size(); ++j)
              e[first_motion_[c] + j] +=
                load_forces_[c][l] / reference_forces_[c][l] * e_l[j];
          }
    return e;
  }


  void
  FullOrderContact::add_free_motions(const unsigned int    c,
                                     const Vector<double> &a,
                                     Vector<double>       &u) const
  {
    for (unsigned int j = 0; j < components[c]->free_motions().size(); ++j)
      u.add(a[first_motion_[c] + j], components[c]->free_motions()[j]);
  }


  ContactSolution
  FullOrderContact::solve()
  {
    Timer timer;
    update_factorizations();

    const std::vector<GapLoadStage> stages = gap_load_stages();
    Flexibility                     W(*this);
    Vector<double>                  last_g_previous;
    unsigned int                    n_steps = 0;
    for (const GapLoadStage &stage : stages)
      n_steps += stage.n_steps;
    const ContactState state = solve_in_load_steps(
      initial_gaps_,
      stages,
      load_factor_,
      [&](const LoadStep &step) {
        LoadStep start = step;
        if (step.step == 1 && warm_start_ && last_state)
          start.previous = *last_state;
        last_g_previous = step.g_previous;
        return solver.solve(W, start, friction_, "full-order contact solver");
      },
      rigid_.size() > 0 ? &rigid_ : nullptr);
    last_state = state;

    ContactSolution solution = displacement_fields_
                                 ? with_fields(state, last_g_previous, W)
                                 : outputs_only(state);
    solution.solver          = "full_order";
    solution.iterations      = state.iterations;
    solution.n_load_steps    = n_steps;
    solution.compute_totals();
    solution.time = timer.wall_time();
    return solution;
  }


  unsigned int
  FullOrderContact::n_factorizations() const
  {
    return factorizations;
  }

  unsigned int
  FullOrderContact::n_back_substitutions() const
  {
    return back_substitutions;
  }

  unsigned int
  FullOrderContact::n_columns() const
  {
    unsigned int n = 0;
    for (const auto &column : columns)
      n += (column != nullptr);
    return n;
  }
} // namespace FuzzyContact
