// A named scalar of a scene that a study may vary: the Young's modulus or
// density of a component or of one of its zones, the total force of a load,
// the friction coefficient or the initial gap of a contact pair.
//
// Names follow the scene's own names:
//
//   P1.E, P1.rho              every zone of component P1 (they must share
//                             the value: the name sets them all)
//   P1.root.E, P1.root.rho    zone "root" of P1
//   P1.tip.force              total force of load "tip" of P1 [N]
//   interface.mu              friction coefficient of contact pair
//                             "interface"
//   interface.gap             initial gap of every slave node of the pair [m]

#ifndef fuzzycontact_scene_scene_quantity_h
#define fuzzycontact_scene_scene_quantity_h

#include <fuzzycontact/scene/scene.h>

#include <string>

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
     * what does not exist.
     */
    static SceneQuantity
    parse(const std::string &name, const Scene &scene);

    /**
     * Its value in @p scene. For a gap declared 'auto', the distance
     * between the two (parallel, axis-aligned) faces.
     */
    double
    value(const Scene &scene) const;

    /**
     * Sets it in @p scene; throws if the value is not admissible (a
     * non-positive modulus or density, a negative friction coefficient,
     * a non-finite value).
     */
    void
    apply(Scene &scene, const double value) const;
  };
} // namespace FuzzyContact

#endif
