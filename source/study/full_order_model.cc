#include <fuzzycontact/study/full_order_model.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>

namespace FuzzyContact
{
  FullOrderModel::FullOrderModel(ContactScene              &bodies,
                                 const ObservedDofs        &observed,
                                 const ActiveSetParameters &parameters)
      : bodies(bodies)
      , observed(observed)
      , parameters(parameters)
      , state(bodies.scene())
      , cg_statistics(std::make_shared<IterativeSolveStatistics>())
  {
  }


  std::string
  FullOrderModel::name() const
  {
    return "full_order";
  }


  void
  FullOrderModel::set_state(const SceneState &new_state)
  {
    // Checked here, before anything changes: a gap offset that makes a gap
    // negative, a negative friction coefficient, loads of the wrong shape.
    const ContactInterface &interface = bodies.interface();
    interface.initial_gaps(new_state.gap_offsets);
    interface.friction_coefficients(new_state.friction_coefficients);
    AssertThrow(new_state.load_forces.size() == bodies.n_components(),
                ExcMessage("FullOrderModel: the state is not one of this "
                           "scene."));
    state = new_state;
  }


  std::unique_ptr<FullOrderContact>
  FullOrderModel::make_solver() const
  {
    auto solver = std::make_unique<FullOrderContact>(bodies.components(),
                                                     bodies.interface(),
                                                     parameters);
    solver->observe(observed);
    solver->set_n_load_steps(n_load_steps);
    solver->set_load_stages(bodies.scene().load_stages);
    // Reused factorisations are the scene's own, which the reduced models
    // were built from: the nominal stiffness is not factorised twice.
    if (reuse)
      solver->set_factorisation_source(
        [this](const unsigned int c) -> std::shared_ptr<const StiffnessSolver> {
          const Component &component = bodies.component(c);
          const bool       nominal   = component.zone_moduli() ==
                               SceneState(bodies.scene()).zone_moduli[c];
          // The nominal factorisation, kept (the scene drops its own when a
          // modulus changes).
          if (nominal && c < nominal_factors.size())
            return nominal_factors[c];
          bool cg = changed_stiffness != ChangedStiffness::factorisation &&
                    c < nominal_factors.size();
          if (cg && changed_stiffness == ChangedStiffness::automatic)
            {
              // CG's steps for this stiffness, times the solves of an exact
              // solve, against a factorisation counted in solves.
              const SparseCholesky      &f   = *nominal_factors[c];
              const std::vector<double> &now = component.zone_moduli();
              const std::vector<double>  ref =
                SceneState(bodies.scene()).zone_moduli[c];
              double lower = 1e300, upper = 0;
              for (unsigned int z = 0; z < now.size(); ++z)
                {
                  lower = std::min(lower, now[z] / ref[z]);
                  upper = std::max(upper, now[z] / ref[z]);
                }
              const double solves        = std::max(1u, nominal_solves);
              const double factorisation = f.n_factor_entries() > 0
                                             ? f.n_factor_flops() /
                                                 (4 * f.n_factor_entries()) /
                                                 factor_to_solve_speed
                                             : 0.;
              cg = solves * cg_steps_bound(lower, upper, cg_tolerance) <=
                   factorisation + solves;
            }
          if (changed_stiffness != ChangedStiffness::factorisation)
            ++(cg ? cg_statistics->by_cg : cg_statistics->factorised);
          if (cg)
            return std::make_shared<FactorPreconditionedCG>(
              component.stiffness_matrix(),
              nominal_factors[c],
              cg_tolerance,
              cg_max_iterations,
              cg_keys,
              "Component " + component.name() + " (exact solve)",
              cg_statistics);
          return bodies.stiffness_factorisation(c);
        });
    return solver;
  }


  ContactSolution
  FullOrderModel::solve()
  {
    const ContactInterface &interface = bodies.interface();
    if (!reuse)
      current = make_solver();
    else if (current == nullptr)
      {
        // Factorise the nominal stiffness first: every later stiffness
        // that is a multiple of it then reuses these factorisations, on
        // every MPI rank alike, so all ranks compute the same numbers.
        bodies.set_materials(SceneState(bodies.scene()));
        if (nominal_factors.empty())
          for (unsigned int c = 0; c < bodies.n_components(); ++c)
            nominal_factors.push_back(bodies.stiffness_factorisation(c));
        current = make_solver();
        current->set_displacement_fields(false);
        current->solve();
        nominal_solves = current->n_back_substitutions();
      }
    bodies.set_materials(state);
    current->set_load_forces(state.load_forces);
    current->set_contact_conditions(interface.initial_gaps(state.gap_offsets),
                                    interface.friction_coefficients(
                                      state.friction_coefficients));
    ContactSolution solution = current->solve();
    check_small_sliding(interface,
                        solution,
                        bodies.sliding_limit(),
                        "full-order contact solver");
    return solution;
  }


  void
  FullOrderModel::set_reuse_factorisations(const bool reuse_)
  {
    if (reuse_ != reuse)
      current.reset();
    reuse = reuse_;
  }


  void
  FullOrderModel::set_iterative_solves(const ChangedStiffness mode,
                                       const double           tolerance,
                                       const unsigned int     max_iterations,
                                       const std::string     &keys)
  {
    AssertThrow(tolerance > 0 && max_iterations > 0,
                ExcMessage("FullOrderModel: conjugate gradients need a "
                           "positive tolerance and iteration limit."));
    // A changed setting changes the solver of a changed stiffness.
    if (mode != changed_stiffness || tolerance != cg_tolerance ||
        max_iterations != cg_max_iterations)
      current.reset();
    changed_stiffness = mode;
    cg_tolerance      = tolerance;
    cg_max_iterations = max_iterations;
    cg_keys           = keys;
  }


  const IterativeSolveStatistics &
  FullOrderModel::iterative_statistics() const
  {
    return *cg_statistics;
  }


  ContactSolution
  FullOrderModel::solve_with_fields()
  {
    if (!reuse)
      return solve(); // (independent analyses compute the fields)
    if (current == nullptr)
      solve(); // (the nominal factorisations first)
    current->set_displacement_fields(true);
    try
      {
        ContactSolution s = solve();
        current->set_displacement_fields(false);
        return s;
      }
    catch (...)
      {
        current->set_displacement_fields(false);
        throw;
      }
  }


  void
  FullOrderModel::set_n_load_steps(const unsigned int n)
  {
    AssertThrow(n >= 1, ExcMessage("load steps must be at least 1."));
    n_load_steps = n;
    current.reset();
  }


  FullOrderContact &
  FullOrderModel::solver()
  {
    AssertThrow(current != nullptr,
                ExcMessage("FullOrderModel: no solve has been made yet."));
    return *current;
  }
} // namespace FuzzyContact
