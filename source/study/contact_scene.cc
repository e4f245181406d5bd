#include <fuzzycontact/study/contact_scene.h>

#include <deal.II/base/exceptions.h>

namespace FuzzyContact
{
  ContactScene::ContactScene(const Scene       &scene,
                             const unsigned int mesh_refinements,
                             const double       penetration_tolerance,
                             TimerOutput       *timer)
      : scene_(scene)
  {
    for (const ComponentDescription &d : scene_.components)
      {
        owned.push_back(std::make_unique<Component>(d,
                                                    scene_.plane_model,
                                                    mesh_refinements,
                                                    timer));
        components_.push_back(owned.back().get());
      }
    std::unique_ptr<TimerOutput::Scope> scope;
    if (timer != nullptr)
      scope = std::make_unique<TimerOutput::Scope>(*timer, "contact interface");
    interface_ = std::make_unique<ContactInterface>(scene_,
                                                    components_,
                                                    penetration_tolerance);
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
    for (unsigned int c = 0; c < owned.size(); ++c)
      if (state.zone_moduli[c] != owned[c]->zone_moduli() ||
          state.zone_densities[c] != owned[c]->zone_densities())
        owned[c]->set_zone_materials(state.zone_moduli[c],
                                     state.zone_densities[c]);
  }
} // namespace FuzzyContact
