#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/base/timer_section.h>
#include <fuzzycontact/study/contact_scene.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <boost/serialization/vector.hpp>

#include <algorithm>

namespace FuzzyContact
{
  namespace
  {
    // The limit of small sliding [degrees], refused outside (0, 90).
    double
    checked_sliding_limit(const double limit)
    {
      AssertThrow(limit > 0 && limit < 90,
                  ExcMessage("sliding angle limit must lie between 0 and 90 "
                             "degrees, got " +
                             Utilities::to_string(limit) + "."));
      return limit;
    }
  } // namespace


  void
  ContactFormulation::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("penetration tolerance",
                      "1e-8",
                      Patterns::Double(),
                      "Initial penetration accepted as round-off, "
                      "relative to the master face length.");
    declare_sliding_limit(prm);
  }


  void
  ContactFormulation::parse_parameters(ParameterHandler &prm)
  {
    penetration_tolerance =
      Input::non_negative(prm.get_double("penetration tolerance"),
                          "penetration tolerance");
    sliding_limit = parse_sliding_limit(prm);
  }


  void
  ContactFormulation::declare_sliding_limit(ParameterHandler &prm)
  {
    prm.declare_entry("sliding angle limit",
                      "5",
                      Patterns::Double(),
                      "Small sliding's limit [degrees]: the largest turn of "
                      "the master face's normal along a closed slave node's "
                      "slide (a slide along a flat face is within it at any "
                      "length; sliding off the master face never is). "
                      "Node-to-segment contact keeps the unloaded geometry: "
                      "an answer beyond the limit is refused (step-3), or "
                      "its point counts as without static equilibrium "
                      "(step-4; an error if every body is supported).");
  }


  double
  ContactFormulation::parse_sliding_limit(ParameterHandler &prm)
  {
    return checked_sliding_limit(prm.get_double("sliding angle limit"));
  }


  ContactScene::ContactScene(const Scene             &scene,
                             const unsigned int       mesh_refinements,
                             const double             penetration_tolerance,
                             TimerOutput             *timer,
                             const std::vector<bool> &assemble)
      : scene_(scene)
  {
    Assert(assemble.empty() || assemble.size() == scene_.components.size(),
           ExcDimensionMismatch(assemble.size(), scene_.components.size()));
    for (const ComponentDescription &d : scene_.components)
      {
        // A body its supports leave free is held by contact alone: it is
        // pinned off its contact faces (fe/component.h), and the contact
        // solvers find its rigid-body motion with the contact forces.
        std::vector<std::string> contact_faces;
        for (const ContactPairDescription &pair : scene_.contact_pairs)
          {
            if (pair.slave_component == d.name)
              contact_faces.push_back(pair.slave_face);
            if (pair.master_component == d.name)
              contact_faces.push_back(pair.master_face);
          }
        const unsigned int c = owned.size();
        owned.push_back(
          std::make_unique<Component>(d,
                                      scene_.plane_model,
                                      mesh_refinements,
                                      timer,
                                      contact_faces,
                                      assemble.empty() || assemble[c]));
        components_.push_back(owned.back().get());
        const std::string free = owned.back()->free_rigid_motion();
        AssertThrow(free.empty() || !contact_faces.empty(),
                    ExcMessage("Component " + d.name +
                               ": its clamps and supports leave a rigid-body "
                               "motion free (" +
                               free +
                               "), and no contact pair can hold it. Clamp a "
                               "face, or add supports ('supports', with "
                               "'fixed components') that hold it in x, in y "
                               "and against rotation, or a contact pair."));
      }
    const auto scope = timer_section(timer, "contact interface");
    interface_       = std::make_unique<ContactInterface>(scene_,
                                                    components_,
                                                    penetration_tolerance);
    factorisations.resize(owned.size());
    n_factorised.assign(owned.size(), 0);
  }


  void
  ContactScene::set_sliding_limit(const double limit)
  {
    sliding_limit_ = checked_sliding_limit(limit);
  }


  double
  ContactScene::sliding_limit() const
  {
    return sliding_limit_;
  }


  const Scene &
  ContactScene::scene() const
  {
    return scene_;
  }


  unsigned int
  ContactScene::n_components() const
  {
    return owned.size();
  }


  const Component &
  ContactScene::component(const unsigned int c) const
  {
    AssertIndexRange(c, owned.size());
    return *owned[c];
  }


  const std::vector<const Component *> &
  ContactScene::components() const
  {
    return components_;
  }


  const ContactInterface &
  ContactScene::interface() const
  {
    return *interface_;
  }


  std::vector<unsigned int>
  ContactScene::n_dofs() const
  {
    std::vector<unsigned int> n;
    for (const auto &c : owned)
      n.push_back(c->n_dofs());
    return n;
  }


  void
  ContactScene::set_materials(const SceneState &state)
  {
    AssertThrow(state.zone_moduli.size() == owned.size() &&
                  state.zone_densities.size() == owned.size(),
                ExcMessage("ContactScene: the state is not one of this "
                           "scene (wrong number of components)."));
    // (The stiffness does not depend on the densities: its factorisation
    // stays when they alone change.)
    for (unsigned int c = 0; c < owned.size(); ++c)
      if (state.zone_moduli[c] != owned[c]->zone_moduli() ||
          state.zone_densities[c] != owned[c]->zone_densities())
        {
          if (state.zone_moduli[c] != owned[c]->zone_moduli())
            factorisations[c].reset();
          owned[c]->set_zone_materials(state.zone_moduli[c],
                                       state.zone_densities[c]);
        }
  }


  std::vector<types::global_dof_index>
  ContactScene::boundary_dofs(const unsigned int c) const
  {
    AssertIndexRange(c, owned.size());
    std::vector<types::global_dof_index> dofs = interface_->contact_dofs(c);
    const Component                     &component = *owned[c];
    // (Not the weight's: it acts on every DoF, and its response is carried
    // whole, ReducedComponentMatrices::weight_gaps.)
    for (unsigned int l = 0; l < component.description().loads.size(); ++l)
      {
        if (component.description().loads[l].is_weight)
          continue;
        const Vector<double> &f = component.unit_load_vector(l);
        for (types::global_dof_index d = 0; d < f.size(); ++d)
          if (f[d] != 0)
            dofs.push_back(d);
      }
    std::sort(dofs.begin(), dofs.end());
    dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
    return dofs;
  }


  std::shared_ptr<const SparseCholesky>
  ContactScene::stiffness_factorisation(const unsigned int c,
                                        TimerOutput       *timer) const
  {
    AssertIndexRange(c, owned.size());
    if (factorisations[c] == nullptr)
      {
        const auto scope =
          timer_section(timer, "stiffness factorisation (CHOLMOD)");
        auto factorisation = std::make_shared<SparseCholesky>();
        factorisation->factorize(owned[c]->stiffness_matrix(),
                                 boundary_dofs(c),
                                 "Component " + owned[c]->name() +
                                   ": the stiffness matrix");
        factorisations[c] = std::move(factorisation);
        ++n_factorised[c];
        ProgressLines::stage("stiffness of " + owned[c]->name() + " factorised",
                             c + 1,
                             owned.size());
      }
    return factorisations[c];
  }


  bool
  ContactScene::has_stiffness_factorisation(const unsigned int c) const
  {
    AssertIndexRange(c, owned.size());
    return factorisations[c] != nullptr;
  }


  void
  ContactScene::set_stiffness_factorisation(
    const unsigned int                    c,
    std::shared_ptr<const SparseCholesky> factorisation)
  {
    AssertIndexRange(c, owned.size());
    AssertThrow(factorisation != nullptr &&
                  factorisation->n() == owned[c]->n_dofs(),
                ExcMessage("ContactScene: the factorisation given for "
                           "component " +
                           owned[c]->name() + " is not one of its stiffness."));
    factorisations[c] = std::move(factorisation);
  }


  void
  ContactScene::share_stiffness_factorisations(
    const std::vector<unsigned int> &owner,
    const MPI_Comm                   comm,
    TimerOutput                     *timer)
  {
    AssertDimension(owner.size(), owned.size());
    set_materials(SceneState(scene_));
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    std::vector<std::shared_ptr<const SparseCholesky>> mine(owned.size());
    for (unsigned int c = 0; c < owned.size(); ++c)
      if (rank == owner[c])
        mine[c] = stiffness_factorisation(c, timer);
    const auto scope = timer_section(timer, "factorisations shared (MPI)");
    factorisations   = SparseCholesky::broadcast(mine, owner, comm);
    // The loads of prescribed displacements come from the stiffness too.
    for (unsigned int c = 0; c < owned.size(); ++c)
      for (const EdgeLoad &load : owned[c]->description().loads)
        if (load.is_displacement)
          {
            std::vector<std::vector<Vector<double>>> forces;
            if (rank == owner[c])
              forces = owned[c]->displacement_zone_loads();
            forces = Utilities::MPI::broadcast(comm, forces, owner[c]);
            if (rank != owner[c])
              owned[c]->set_displacement_zone_loads(forces);
            break;
          }
  }


  unsigned int
  ContactScene::n_factorisations(const unsigned int c) const
  {
    AssertIndexRange(c, owned.size());
    return n_factorised[c];
  }
} // namespace FuzzyContact
