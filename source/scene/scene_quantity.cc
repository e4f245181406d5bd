#include <fuzzycontact/base/input.h>
#include <fuzzycontact/scene/scene_quantity.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <cmath>

namespace FuzzyContact
{
  using namespace dealii;

  SceneQuantity
  SceneQuantity::parse(const std::string &name, const Scene &scene)
  {
    const std::vector<std::string> parts =
      Utilities::split_string_list(name, '.');
    const std::string where = "Scene quantity <" + name + ">";
    AssertThrow(parts.size() == 2 || parts.size() == 3,
                ExcMessage(where +
                           ": expected <component>.E, <component>.rho, "
                           "<component>.<zone>.E, <component>.<zone>.rho, "
                           "<component>.<load>.force, <contact pair>.mu or "
                           "<contact pair>.gap."));
    SceneQuantity q;
    q.name = name;

    if (parts.size() == 2 && (parts[1] == "mu" || parts[1] == "gap"))
      {
        for (unsigned int p = 0; p < scene.contact_pairs.size(); ++p)
          if (scene.contact_pairs[p].name == parts[0])
            {
              q.kind         = parts[1] == "mu" ? Kind::friction : Kind::gap;
              q.contact_pair = p;
              return q;
            }
        AssertThrow(false,
                    ExcMessage(where + ": the scene has no contact pair <" +
                               parts[0] + ">."));
      }

    bool found = false;
    for (unsigned int c = 0; c < scene.components.size(); ++c)
      if (scene.components[c].name == parts[0])
        {
          q.component = c;
          found       = true;
        }
    AssertThrow(found,
                ExcMessage(where + ": the scene has no component <" + parts[0] +
                           "> (nor a contact pair of that name)."));
    const ComponentDescription &component = scene.components[q.component];

    const std::string &what = parts.back();
    if (parts.size() == 3 && what == "force")
      {
        for (unsigned int l = 0; l < component.loads.size(); ++l)
          if (component.loads[l].name == parts[1])
            {
              q.kind = Kind::load;
              q.load = l;
              return q;
            }
        AssertThrow(false,
                    ExcMessage(where + ": component " + component.name +
                               " has no load <" + parts[1] + ">."));
      }
    AssertThrow(what == "E" || what == "rho",
                ExcMessage(where + ": <" + what +
                           "> is not a quantity; use E, rho, force, mu or "
                           "gap."));
    q.kind = what == "E" ? Kind::youngs_modulus : Kind::density;
    if (parts.size() == 3)
      {
        bool zone_found = false;
        for (unsigned int z = 0; z < component.zones.size(); ++z)
          if (component.zones[z].name == parts[1])
            {
              q.zone     = z;
              zone_found = true;
            }
        AssertThrow(zone_found,
                    ExcMessage(where + ": component " + component.name +
                               " has no zone <" + parts[1] + ">."));
      }
    else
      for (const MaterialZone &zone : component.zones)
        {
          const double first = q.kind == Kind::youngs_modulus
                                 ? component.zones[0].youngs_modulus
                                 : component.zones[0].density;
          const double v =
            q.kind == Kind::youngs_modulus ? zone.youngs_modulus : zone.density;
          AssertThrow(v == first,
                      ExcMessage(where + ": the zones of " + component.name +
                                 " differ in " + what +
                                 ", so a single value cannot stand for them; "
                                 "name a zone (" +
                                 component.name + ".<zone>." + what + ")."));
        }
    return q;
  }


  double
  SceneQuantity::value(const Scene &scene) const
  {
    switch (kind)
      {
        case Kind::youngs_modulus:
          return scene.components[component]
            .zones[zone < 0 ? 0 : zone]
            .youngs_modulus;
        case Kind::density:
          return scene.components[component].zones[zone < 0 ? 0 : zone].density;
        case Kind::load:
          return scene.components[component].loads[load].total_force;
        case Kind::friction:
          return scene.contact_pairs[contact_pair].friction_coefficient;
        case Kind::gap:
          {
            const ContactPairDescription &pair =
              scene.contact_pairs[contact_pair];
            if (pair.has_initial_gap)
              return pair.initial_gap;
            const ComponentDescription &s =
              scene.components[scene.component_index(pair.slave_component)];
            const ComponentDescription &m =
              scene.components[scene.component_index(pair.master_component)];
            // Distance between two facing sides of axis-aligned rectangles.
            const auto side = [](const ComponentDescription &c, const Face f) {
              switch (f)
                {
                  case Face::left:
                    return c.lower_left[0];
                  case Face::right:
                    return c.upper_right[0];
                  case Face::bottom:
                    return c.lower_left[1];
                  case Face::top:
                    return c.upper_right[1];
                }
              return 0.;
            };
            const bool facing = (pair.slave_face == Face::bottom &&
                                 pair.master_face == Face::top) ||
                                (pair.slave_face == Face::top &&
                                 pair.master_face == Face::bottom) ||
                                (pair.slave_face == Face::left &&
                                 pair.master_face == Face::right) ||
                                (pair.slave_face == Face::right &&
                                 pair.master_face == Face::left);
            AssertThrow(facing,
                        ExcMessage(name +
                                   ": the slave and master faces of "
                                   "contact pair " +
                                   pair.name + " do not face each other."));
            const double s_side = side(s, pair.slave_face);
            const double m_side = side(m, pair.master_face);
            return (pair.slave_face == Face::bottom ||
                    pair.slave_face == Face::left)
                     ? s_side - m_side
                     : m_side - s_side;
          }
      }
    return 0;
  }


  void
  SceneQuantity::apply(Scene &scene, const double v) const
  {
    switch (kind)
      {
        case Kind::youngs_modulus:
        case Kind::density:
          {
            Input::positive(v, name);
            ComponentDescription &c = scene.components[component];
            for (unsigned int z = 0; z < c.zones.size(); ++z)
              if (zone < 0 || static_cast<int>(z) == zone)
                (kind == Kind::youngs_modulus ? c.zones[z].youngs_modulus
                                              : c.zones[z].density) = v;
            break;
          }
        case Kind::load:
          scene.components[component].loads[load].total_force =
            Input::finite(v, name);
          break;
        case Kind::friction:
          scene.contact_pairs[contact_pair].friction_coefficient =
            Input::non_negative(v, name);
          break;
        case Kind::gap:
          scene.contact_pairs[contact_pair].has_initial_gap = true;
          scene.contact_pairs[contact_pair].initial_gap =
            Input::finite(v, name);
          break;
      }
  }
} // namespace FuzzyContact
