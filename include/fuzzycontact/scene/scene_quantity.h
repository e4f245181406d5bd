// A named scalar of a scene that a study may vary: the Young's modulus or
// density of a component or of one of its zones, the total force of a load,
// the friction coefficient or the initial gap of a contact pair. This is the
// one parser of such names in FuzzyContact: fuzzy parameters, the modal
// reanalysis and every model of a study read them through it.
//
// Names follow the scene's own names:
//
//   P1.E, P1.rho              every zone of component P1, scaled together:
//                             the value is the area-weighted mean over the
//                             zones (the common value if they agree), and
//                             setting it multiplies every zone's value by
//                             (new mean / old mean)
//   P1.root.E, P1.root.rho    zone "root" of P1
//   P1.tip.force              total force of load "tip" of P1 [N]
//   interface.mu              friction coefficient of contact pair
//                             "interface"
//   interface.gap             initial gap of the pair's slave nodes [m]: a
//                             new value shifts the gap of every slave node
//                             by (new value - nominal value)
//
// A quantity reads and sets values of a SceneState (scene_state.h): the
// study starts from the scene's nominal state and sets each quantity's
// value, and every model is set from the resulting state.

#ifndef fuzzycontact_scene_scene_quantity_h
#define fuzzycontact_scene_scene_quantity_h

#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_state.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  struct SceneQuantity
  {
    enum class Kind
    {
      youngs_modulus,
      density,
      load,
      friction,
      gap
    };

    std::string  name;
    Kind         kind;
    unsigned int component = 0;
    /** Zone index, or -1 for every zone of the component. */
    int          zone         = -1;
    unsigned int load         = 0;
    unsigned int contact_pair = 0;

    /**
     * The quantity called @p name in @p scene; throws a message naming
     * what does not exist (and what does).
     */
    static SceneQuantity
    parse(const std::string &name, const Scene &scene);

    /** True for a Young's modulus or a density. */
    bool
    is_material() const;

    /**
     * True for the modulus of one zone: it changes the shape of the
     * stiffness (the reduced models re-analyse the component's modes). A
     * density never changes the (static) stiffness; with gravity it scales
     * the weight of its zone.
     */
    bool
    reshapes_stiffness() const;

    /** The zones of the component a material quantity acts on. */
    std::vector<unsigned int>
    zones(const Scene &scene) const;

    /**
     * Its nominal value in @p scene. For a gap declared 'auto', the
     * distance between the two (parallel, axis-aligned) faces.
     */
    double
    value(const Scene &scene) const;

    /** Its value in @p state (a state of @p scene). */
    double
    value(const SceneState &state, const Scene &scene) const;

    /**
     * Sets it to @p value in @p state, a state of @p scene; throws,
     * naming the quantity, if the value is not admissible (a non-positive
     * modulus or density, a negative friction coefficient, a non-finite
     * value).
     */
    void
    apply(SceneState &state, const Scene &scene, const double value) const;

    /**
     * True if this quantity and @p other set the same value of a scene (the
     * same property of a shared zone, the same load or the same pair
     * property): a study may then not vary both.
     */
    bool
    overlaps(const SceneQuantity &other, const Scene &scene) const;
  };
} // namespace FuzzyContact

#endif
