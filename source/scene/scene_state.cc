#include <fuzzycontact/scene/scene_state.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace FuzzyContact
{
  SceneState::SceneState(const Scene &scene)
  {
    for (const ComponentDescription &c : scene.components)
      {
        std::vector<double> moduli, densities, forces;
        for (const MaterialZone &zone : c.zones)
          {
            moduli.push_back(zone.youngs_modulus);
            densities.push_back(zone.density);
          }
        for (const EdgeLoad &load : c.loads)
          forces.push_back(load.total_force);
        zone_moduli.push_back(moduli);
        zone_densities.push_back(densities);
        load_forces.push_back(forces);
      }
    for (const ContactPairDescription &pair : scene.contact_pairs)
      {
        friction_coefficients.push_back(pair.friction_coefficient);
        gap_offsets.push_back(0.);
      }
  }


  double
  SceneState::total_load() const
  {
    double total = 0;
    for (const std::vector<double> &forces : load_forces)
      for (const double f : forces)
        total += std::abs(f);
    return total;
  }


  void
  SceneState::scale_loads(const double factor)
  {
    for (std::vector<double> &forces : load_forces)
      for (double &f : forces)
        f *= factor;
  }


  double
  SceneState::total_force(const Scene &scene) const
  {
    double total = 0;
    for (unsigned int c = 0; c < scene.components.size(); ++c)
      for (unsigned int l = 0; l < scene.components[c].loads.size(); ++l)
        if (!scene.components[c].loads[l].is_displacement &&
            !scene.components[c].loads[l].is_weight)
          total += std::abs(load_forces[c][l]);
    return total;
  }


  void
  SceneState::scale_forces_to(const Scene       &scene,
                              const double       load,
                              const std::string &key)
  {
    for (const ComponentDescription &c : scene.components)
      for (const EdgeLoad &l : c.loads)
        AssertThrow(!l.is_displacement,
                    ExcMessage(key + " = " + std::to_string(load) + ": scene " +
                               scene.name +
                               " prescribes a displacement (component " +
                               c.name + ", support " + l.name +
                               "), which a force cannot scale; set " + key +
                               " = scene."));
    // A force cannot scale a body's weight either: its density can.
    AssertThrow(scene.gravity.norm() == 0,
                ExcMessage(
                  key + " = " + std::to_string(load) + ": scene " + scene.name +
                  " has gravity (the weight of every component), "
                  "which a force cannot scale; set " +
                  key + " = scene (a density scales a body's weight)."));
    const double declared = total_load();
    AssertThrow(declared > 0 || load == 0,
                ExcMessage("Scene " + scene.name +
                           " declares no load to scale to the requested " +
                           key + "."));
    scale_loads(declared > 0 ? load / declared : 0.);
  }


  bool
  SceneState::operator==(const SceneState &other) const
  {
    return zone_moduli == other.zone_moduli &&
           zone_densities == other.zone_densities &&
           load_forces == other.load_forces &&
           friction_coefficients == other.friction_coefficients &&
           gap_offsets == other.gap_offsets;
  }


  bool
  SceneState::operator!=(const SceneState &other) const
  {
    return !(*this == other);
  }
} // namespace FuzzyContact
