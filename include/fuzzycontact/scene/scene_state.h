// The values of a scene that a study may change from one evaluation to the
// next: the Young's modulus and density of every material zone, the total
// force of every load, and the friction coefficient and the gap offset of
// every contact pair. A state starts as the scene's own values (the nominal
// state); a study changes it through named scene quantities
// (scene_quantity.h), and every model of the scene -- the full finite
// element systems and the reduced models alike -- is set from one state, so
// that they all see the same values.

#ifndef fuzzycontact_scene_scene_state_h
#define fuzzycontact_scene_scene_state_h

#include <fuzzycontact/scene/scene.h>

#include <vector>

namespace FuzzyContact
{
  struct SceneState
  {
    /** An empty state (no components); use the other constructor. */
    SceneState() = default;

    /** The scene's own values. */
    explicit SceneState(const Scene &scene);

    /** E and rho of every zone [Pa, kg/m^3]: zone_moduli[component][zone]. */
    std::vector<std::vector<double>> zone_moduli;
    std::vector<std::vector<double>> zone_densities;
    /** Total force of every load [N]: load_forces[component][load]. */
    std::vector<std::vector<double>> load_forces;
    /** Coulomb coefficient of every contact pair. */
    std::vector<double> friction_coefficients;
    /**
     * Added to the initial normal gap of every slave node of a contact pair
     * [m] (zero in the nominal state).
     */
    std::vector<double> gap_offsets;

    /** sum |F| over all loads [N]. */
    double
    total_load() const;
    /** Multiplies every load force by @p factor. */
    void
    scale_loads(const double factor);

    /**
     * sum |F| over the loads of @p scene (this state's scene) that are
     * forces, prescribed displacements and weights left out [N].
     */
    double
    total_force(const Scene &scene) const;

    /**
     * Scales every load so that total_load() is @p load [N]. Refuses,
     * naming @p key, a scene with a prescribed displacement or with
     * gravity (a force cannot scale either) and a non-zero @p load for a
     * scene without loads.
     */
    void
    scale_forces_to(const Scene       &scene,
                    const double       load,
                    const std::string &key);

    bool
    operator==(const SceneState &other) const;
    bool
    operator!=(const SceneState &other) const;
  };
} // namespace FuzzyContact

#endif
