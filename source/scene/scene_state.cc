#include <fuzzycontact/scene/scene_state.h>

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
