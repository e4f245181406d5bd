#include <fuzzycontact/base/input.h>
#include <fuzzycontact/scene/scene_limits.h>
#include <fuzzycontact/scene/scene_quantity.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  using namespace dealii;

  namespace
  {
    // "a, b, c" for messages.
    template <typename T, typename Name>
    std::string
    list_of(const std::vector<T> &items, const Name &name)
    {
      std::string list;
      for (const T &item : items)
        list += (list.empty() ? "" : ", ") + name(item);
      return list.empty() ? "none" : list;
    }

    // The zone property a material quantity reads and sets.
    std::vector<std::vector<double>> &
    zone_values(SceneState &state, const SceneQuantity::Kind kind)
    {
      return kind == SceneQuantity::Kind::youngs_modulus ? state.zone_moduli
                                                         : state.zone_densities;
    }

    const std::vector<std::vector<double>> &
    zone_values(const SceneState &state, const SceneQuantity::Kind kind)
    {
      return kind == SceneQuantity::Kind::youngs_modulus ? state.zone_moduli
                                                         : state.zone_densities;
    }

    // The scene's own values of a zone property of component @p c.
    std::vector<double>
    scene_zone_values(const Scene              &scene,
                      const unsigned int        c,
                      const SceneQuantity::Kind kind)
    {
      std::vector<double> values;
      for (const MaterialZone &z : scene.components[c].zones)
        values.push_back(kind == SceneQuantity::Kind::youngs_modulus
                           ? z.youngs_modulus
                           : z.density);
      return values;
    }

    // The value of zone @p zone of @p values, or for every zone (-1) their
    // common value, else their area-weighted mean over component @p c.
    double
    zone_value(const std::vector<double>  &values,
               const int                   zone,
               const ComponentDescription &c)
    {
      if (zone >= 0)
        return values[zone];
      if (std::all_of(values.begin(), values.end(), [&](const double v) {
            return v == values[0];
          }))
        return values[0];
      double weighted = 0, area = 0;
      for (unsigned int z = 0; z < values.size(); ++z)
        {
          weighted += values[z] * c.zone_area(z);
          area += c.zone_area(z);
        }
      return weighted / area;
    }

    // Distance between the facing sides of two axis-aligned rectangles.
    double
    face_distance(const ContactPairDescription &pair,
                  const Scene                  &scene,
                  const std::string            &name)
    {
      const ComponentDescription &s =
        scene.components[scene.component_index(pair.slave_component)];
      const ComponentDescription &m =
        scene.components[scene.component_index(pair.master_component)];
      AssertThrow(s.is_rectangle() && m.is_rectangle(),
                  ExcMessage(name + ": contact pair " + pair.name +
                             " joins a mesh-file component, whose gap is "
                             "only known node by node; set its 'initial gap' "
                             "to make the gap a scene quantity."));
      const Face slave_face  = *rectangle_side(pair.slave_face);
      const Face master_face = *rectangle_side(pair.master_face);
      const auto side        = [](const ComponentDescription &c, const Face f) {
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
      const bool facing =
        (slave_face == Face::bottom && master_face == Face::top) ||
        (slave_face == Face::top && master_face == Face::bottom) ||
        (slave_face == Face::left && master_face == Face::right) ||
        (slave_face == Face::right && master_face == Face::left);
      AssertThrow(facing,
                  ExcMessage(name +
                             ": the slave and master faces of contact pair " +
                             pair.name + " do not face each other."));
      const double s_side = side(s, slave_face);
      const double m_side = side(m, master_face);
      return (slave_face == Face::bottom || slave_face == Face::left)
               ? s_side - m_side
               : m_side - s_side;
    }
  } // namespace


  SceneQuantity
  SceneQuantity::parse(const std::string &full_name, const Scene &scene)
  {
    const std::string              name = Utilities::trim(full_name);
    const std::vector<std::string> parts =
      Utilities::split_string_list(name, '.');
    const std::string where = "Scene quantity <" + name + ">";
    AssertThrow((parts.size() == 2 || parts.size() == 3) &&
                  std::none_of(parts.begin(),
                               parts.end(),
                               [](const std::string &p) {
                                 return p.empty();
                               }),
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
                               parts[0] + "> (its contact pairs: " +
                               list_of(scene.contact_pairs,
                                       [](const auto &p) {
                                         return p.name;
                                       }) +
                               ")."));
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
                           "> (nor a contact pair of that name; its "
                           "components: " +
                           list_of(scene.components,
                                   [](const auto &c) {
                                     return c.name;
                                   }) +
                           ")."));
    const ComponentDescription &component = scene.components[q.component];

    const std::string &what = parts.back();
    if (parts.size() == 3 && (what == "force" || what == "displacement"))
      {
        // A support's prescribed displacement is a load of its name (see
        // EdgeLoad::is_displacement): <component>.<support>.displacement.
        for (unsigned int l = 0; l < component.loads.size(); ++l)
          if (component.loads[l].name == parts[1] &&
              component.loads[l].is_displacement == (what == "displacement"))
            {
              // The weight follows the densities (and the scene's gravity).
              AssertThrow(!component.loads[l].is_weight,
                          ExcMessage(where + ": the weight of component " +
                                     component.name +
                                     " is not a quantity of its own: vary " +
                                     component.name +
                                     ".rho (or the density "
                                     "of one of its zones), which scales "
                                     "its weight."));
              q.kind = Kind::load;
              q.load = l;
              return q;
            }
        AssertThrow(false,
                    ExcMessage(where + ": component " + component.name +
                               (what == "force"
                                  ? " has no load <"
                                  : " has no support with a non-zero "
                                    "displacement called <") +
                               parts[1] + "> (its loads and such supports: " +
                               list_of(component.loads,
                                       [](const auto &l) {
                                         return l.name;
                                       }) +
                               ")."));
      }
    AssertThrow(what == "E" || what == "rho",
                ExcMessage(where + ": <" + what +
                           "> is not a quantity; use E, rho, force, mu or "
                           "gap."));
    q.kind = what == "E" ? Kind::youngs_modulus : Kind::density;
    // The forces that impose a displacement scale with the moduli: with
    // the modulus of the whole body (K = s K_ref) they are s times the
    // nominal ones, which every model follows; a zone's own modulus would
    // change their shape, which the re-analysed reduced models' load
    // vectors do not follow (yet).
    for (const EdgeLoad &load : component.loads)
      AssertThrow(what != "E" || parts.size() != 3 || !load.is_displacement,
                  ExcMessage(
                    where + ": component " + component.name +
                    " has a prescribed displacement (support " + load.name +
                    "), whose forces depend on its zone moduli; "
                    "the modulus of one of its zones cannot vary "
                    "yet. Vary the modulus of the whole body (" +
                    component.name + ".E), or drive this one by a force."));
    // The weight's exact response K^{-1} w of a body whose zone moduli
    // change would need a new factorisation per state, which the
    // re-analysed reduced models do not make.
    AssertThrow(what != "E" || parts.size() != 3 || scene.gravity.norm() == 0,
                ExcMessage(where +
                           ": the scene has gravity, and the "
                           "response to the weight of component " +
                           component.name +
                           " depends on its zone moduli in a way the "
                           "re-analysed reduced models do not follow; the "
                           "modulus of one of its zones cannot vary. Vary "
                           "the modulus of the whole body (" +
                           component.name + ".E)."));
    if (parts.size() == 3)
      {
        for (unsigned int z = 0; z < component.zones.size(); ++z)
          if (component.zones[z].name == parts[1])
            q.zone = z;
        AssertThrow(q.zone >= 0,
                    ExcMessage(where + ": component " + component.name +
                               " has no zone called <" + parts[1] +
                               "> (its zones: " +
                               list_of(component.zones,
                                       [](const auto &z) {
                                         return z.name;
                                       }) +
                               ")."));
      }
    return q;
  }


  bool
  SceneQuantity::is_material() const
  {
    return kind == Kind::youngs_modulus || kind == Kind::density;
  }


  bool
  SceneQuantity::reshapes_stiffness() const
  {
    return kind == Kind::youngs_modulus && zone >= 0;
  }


  std::vector<unsigned int>
  SceneQuantity::zones(const Scene &scene) const
  {
    Assert(is_material(), ExcInternalError());
    if (zone >= 0)
      return {static_cast<unsigned int>(zone)};
    std::vector<unsigned int> all(scene.components[component].zones.size());
    for (unsigned int z = 0; z < all.size(); ++z)
      all[z] = z;
    return all;
  }


  double
  SceneQuantity::value(const Scene &scene) const
  {
    switch (kind)
      {
        case Kind::youngs_modulus:
        case Kind::density:
          return zone_value(scene_zone_values(scene, component, kind),
                            zone,
                            scene.components[component]);
        case Kind::load:
          return scene.components[component].loads[load].total_force;
        case Kind::friction:
          return scene.contact_pairs[contact_pair].friction_coefficient;
        case Kind::gap:
          {
            const ContactPairDescription &pair =
              scene.contact_pairs[contact_pair];
            return pair.has_initial_gap ? pair.initial_gap
                                        : face_distance(pair, scene, name);
          }
      }
    return 0;
  }


  double
  SceneQuantity::value(const SceneState &state, const Scene &scene) const
  {
    switch (kind)
      {
        case Kind::youngs_modulus:
        case Kind::density:
          return zone_value(zone_values(state, kind)[component],
                            zone,
                            scene.components[component]);
        case Kind::load:
          return state.load_forces[component][load];
        case Kind::friction:
          return state.friction_coefficients[contact_pair];
        case Kind::gap:
          return value(scene) + state.gap_offsets[contact_pair];
      }
    return 0;
  }


  void
  SceneQuantity::apply(SceneState  &state,
                       const Scene &scene,
                       const double v) const
  {
    switch (kind)
      {
        case Kind::youngs_modulus:
        case Kind::density:
          {
            if (kind == Kind::youngs_modulus)
              SceneLimits::youngs_modulus(v, name);
            else
              SceneLimits::density(v, name);
            // From the scene's values: every zone takes v, or (zones that
            // differ) its own value times v / their nominal mean.
            const std::vector<double> from =
              scene_zone_values(scene, component, kind);
            std::vector<double> &to = zone_values(state, kind)[component];
            const double         mean =
              zone_value(from, -1, scene.components[component]);
            const bool uniform =
              std::all_of(from.begin(), from.end(), [&](const double x) {
                return x == from[0];
              });
            for (const unsigned int z : zones(scene))
              to[z] = (zone >= 0 || uniform) ? v : from[z] * (v / mean);
            break;
          }
        case Kind::load:
          state.load_forces[component][load] = SceneLimits::force(v, name);
          break;
        case Kind::friction:
          state.friction_coefficients[contact_pair] =
            SceneLimits::friction_coefficient(v, name);
          break;
        case Kind::gap:
          state.gap_offsets[contact_pair] =
            Input::finite(v, name) - value(scene);
          break;
      }
  }


  bool
  SceneQuantity::overlaps(const SceneQuantity &other, const Scene &scene) const
  {
    if (kind != other.kind)
      return false;
    switch (kind)
      {
        case Kind::youngs_modulus:
        case Kind::density:
          {
            if (component != other.component)
              return false;
            const std::vector<unsigned int> mine = zones(scene);
            for (const unsigned int z : other.zones(scene))
              if (std::find(mine.begin(), mine.end(), z) != mine.end())
                return true;
            return false;
          }
        case Kind::load:
          return component == other.component && load == other.load;
        case Kind::friction:
        case Kind::gap:
          return contact_pair == other.contact_pair;
      }
    return false;
  }
} // namespace FuzzyContact
