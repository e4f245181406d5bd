#include <fuzzycontact/study/full_order_model.h>

#include <deal.II/base/exceptions.h>

namespace FuzzyContact
{
  FullOrderModel::FullOrderModel(ContactScene              &bodies,
                                 const ObservedDofs        &observed,
                                 const ActiveSetParameters &parameters)
      : bodies(bodies)
      , observed(observed)
      , parameters(parameters)
      , state(bodies.scene())
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
      solver->set_factorisation_source([this](const unsigned int c) {
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
        current = make_solver();
        current->set_displacement_fields(false);
        current->solve();
      }
    bodies.set_materials(state);
    current->set_load_forces(state.load_forces);
    current->set_contact_conditions(interface.initial_gaps(state.gap_offsets),
                                    interface.friction_coefficients(
                                      state.friction_coefficients));
    return current->solve();
  }


  void
  FullOrderModel::set_reuse_factorisations(const bool reuse_)
  {
    if (reuse_ != reuse)
      current.reset();
    reuse = reuse_;
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
