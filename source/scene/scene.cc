#include <fuzzycontact/base/input.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_limits.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    std::string
    component_section(const std::string &name)
    {
      return "Component " + name;
    }

    // Reads a comma-separated pair "a, b" into an array.
    std::array<double, 2>
    read_pair(const std::string &text, const std::string &what)
    {
      const std::vector<double> v = Input::to_doubles(text, what, 2);
      return {{v[0], v[1]}};
    }


    // The material zones of a component (one implicit zone over all of it
    // if the file lists none), with the component's material as default.
    void
    parse_zones(ParameterHandler     &prm,
                ComponentDescription &component,
                const std::string    &where,
                const double          E,
                const double          nu,
                const double          rho)
    {
      if (component.zones.empty() || component.implicit_zone)
        {
          // One implicit zone over everything, with the component's
          // material (in a mesh file: over every physical surface).
          component.implicit_zone = true;
          component.zones         = {
                    MaterialZone{"body",
                         {{component.lower_left[0], component.upper_right[0]}},
                         {{component.lower_left[1], component.upper_right[1]}},
                         E,
                         nu,
                         rho}};
        }
      else
        for (MaterialZone &zone : component.zones)
          {
            const std::string zwhere = where + ", zone " + zone.name;
            prm.enter_subsection("Zone " + zone.name);
            const auto range_or_all =
              [&](const std::string &key, const double lo, const double hi) {
                const std::string text = Utilities::trim(prm.get(key));
                if (text.empty())
                  return std::array<double, 2>{{lo, hi}};
                const auto r = read_pair(text, zwhere + ": " + key);
                AssertThrow(r[0] < r[1],
                            ExcMessage(zwhere + ": " + key +
                                       " must be increasing, got <" + text +
                                       ">."));
                return r;
              };
            zone.x_range = range_or_all("x range",
                                        component.lower_left[0],
                                        component.upper_right[0]);
            zone.y_range = range_or_all("y range",
                                        component.lower_left[1],
                                        component.upper_right[1]);
            if (!component.is_rectangle())
              {
                for (const char *key : {"x range", "y range"})
                  AssertThrow(Utilities::trim(prm.get(key)).empty(),
                              ExcMessage(zwhere + ": " + key +
                                         " is for rectangles; in a mesh "
                                         "file a zone is the physical "
                                         "surface of its name."));
                const auto id = component.mesh.material_ids.find(zone.name);
                AssertThrow(id != component.mesh.material_ids.end(),
                            ExcMessage(zwhere + ": <" + component.mesh.file +
                                       "> has no " +
                                       component.mesh.zone_kind() +
                                       " called <" + zone.name + ">; it has: " +
                                       component.mesh.zone_names() + "."));
                zone.material_id = id->second;
              }
            const auto value_or = [&](const std::string &key,
                                      const double       fallback) {
              const std::string text = Utilities::trim(prm.get(key));
              return text.empty() ? fallback
                                  : Input::to_double(text, zwhere + ": " + key);
            };
            zone.youngs_modulus = value_or("E", E);
            zone.poissons_ratio = value_or("nu", nu);
            zone.density        = value_or("rho", rho);
            prm.leave_subsection();
          }
    }


    // The edge loads of a component.
    void
    parse_loads(ParameterHandler     &prm,
                ComponentDescription &component,
                const std::string    &where)
    {
      for (EdgeLoad &load : component.loads)
        {
          if (load.is_displacement || load.is_weight)
            continue;
          const std::string lwhere = where + ", load " + load.name;
          prm.enter_subsection("Load " + load.name);
          load.face = Utilities::trim(prm.get("face"));
          component.boundary_id(load.face, lwhere + ": face");
          load.total_force = Input::finite(prm.get_double("total force"),
                                           lwhere + ": total force");
          const std::string pressure = Utilities::trim(prm.get("pressure"));
          load.is_pressure           = !pressure.empty();
          if (load.is_pressure)
            {
              AssertThrow(load.total_force == 0,
                          ExcMessage(lwhere +
                                     ": set either total force or pressure, "
                                     "not both."));
              load.total_force =
                Input::to_double(pressure, lwhere + ": pressure");
            }
          const auto d =
            read_pair(prm.get("direction"), lwhere + ": direction");
          const double norm = std::hypot(d[0], d[1]);
          AssertThrow(norm > 0,
                      ExcMessage(lwhere +
                                 ": direction must not be the zero vector."));
          load.direction[0] = d[0] / norm;
          load.direction[1] = d[1] / norm;
          prm.leave_subsection();
        }
    }


    // A support on a face whose every fixed component the clamps and the
    // supports listed before it already fix on that face would hold
    // nothing (its displacement with it): refused here, where the scene
    // file is known (Component checks the DoFs themselves).
    void
    check_not_shadowed(const ComponentDescription &component,
                       const Support              &support,
                       const std::string          &where)
    {
      std::array<bool, 2> held = {{false, false}};
      for (const Support &earlier : component.all_supports())
        {
          if (earlier.name == support.name)
            break;
          if (earlier.face == support.face)
            for (unsigned int i = 0; i < 2; ++i)
              held[i] = held[i] || earlier.fixed[i];
        }
      const bool fixes_any = support.fixed[0] || support.fixed[1];
      AssertThrow(!fixes_any || (support.fixed[0] && !held[0]) ||
                    (support.fixed[1] && !held[1]),
                  ExcMessage(where +
                             ": the supports listed before it already hold "
                             "every DoF it fixes on the face '" +
                             support.face +
                             "', so it would have no effect (nor its "
                             "displacement): fix other components, another "
                             "face, or remove it."));
    }


    // The supports of a component.
    void
    parse_supports(ParameterHandler     &prm,
                   ComponentDescription &component,
                   const std::string    &where)
    {
      component.loads.erase(std::remove_if(component.loads.begin(),
                                           component.loads.end(),
                                           [](const EdgeLoad &load) {
                                             return load.is_displacement;
                                           }),
                            component.loads.end());
      for (Support &support : component.supports)
        {
          for (const EdgeLoad &load : component.loads)
            AssertThrow(load.name != support.name,
                        ExcMessage(where + ": support " + support.name +
                                   " has the name of a load; name them "
                                   "apart."));
          const std::string swhere = where + ", support " + support.name;
          prm.enter_subsection("Support " + support.name);
          support.face = Utilities::trim(prm.get("face"));
          component.boundary_id(support.face, swhere + ": face");
          const std::string fixed = prm.get("fixed components");
          support.fixed           = {{fixed.find('x') != std::string::npos,
                                      fixed.find('y') != std::string::npos}};
          const auto d =
            read_pair(prm.get("displacement"), swhere + ": displacement");
          for (unsigned int i = 0; i < 2; ++i)
            support.displacement[i] =
              support.fixed[i] ? Input::finite(d[i], swhere + ": displacement")
                               : 0.;
          prm.leave_subsection();
          check_not_shadowed(component, support, swhere);
          // A prescribed displacement acts like a load of its own (whose
          // force is the displacement's magnitude), so that it can be made
          // fuzzy and is solved for like any load.
          if (support.displacement.norm() > 0)
            {
              EdgeLoad load{support.name,
                            support.face,
                            support.displacement.norm(),
                            support.displacement / support.displacement.norm()};
              load.is_displacement = true;
              component.loads.push_back(load);
            }
        }
    }


    // The component's own weight, a load called "weight" listed last, if
    // gravity is on (EdgeLoad::is_weight).
    void
    add_weight(ComponentDescription &component,
               const Tensor<1, 2>   &gravity,
               const std::string    &where)
    {
      component.loads.erase(std::remove_if(component.loads.begin(),
                                           component.loads.end(),
                                           [](const EdgeLoad &load) {
                                             return load.is_weight;
                                           }),
                            component.loads.end());
      if (gravity.norm() == 0)
        return;
      for (const EdgeLoad &load : component.loads)
        AssertThrow(load.name != "weight",
                    ExcMessage(where + ": " +
                               (load.is_displacement ? "support" : "load") +
                               " <weight>: with the scene's gravity on, "
                               "every component has a load called "
                               "'weight' (its own weight); give this " +
                               (load.is_displacement ? "support" : "load") +
                               " another name."));
      for (const Support &support : component.supports)
        AssertThrow(support.name != "weight",
                    ExcMessage(where +
                               ": support <weight>: with the scene's "
                               "gravity on, every component has a load "
                               "called 'weight' (its own weight); give this "
                               "support another name."));
      EdgeLoad weight{"weight", "", gravity.norm(), gravity / gravity.norm()};
      weight.is_weight = true;
      component.loads.push_back(weight);
    }


    // The geometry of a component: a mesh file, or a rectangle's corners and
    // subdivisions.
    void
    parse_geometry(ParameterHandler     &prm,
                   ComponentDescription &component,
                   const std::string    &where,
                   const std::string    &scene_file)
    {
      const std::string file = Utilities::trim(prm.get("mesh file"));
      component.scale =
        Input::positive(prm.get_double("scale"), where + ": scale");
      if (!file.empty())
        {
          for (const char *key :
               {"lower left corner", "upper right corner", "subdivisions"})
            AssertThrow(Utilities::trim(prm.get(key)).empty(),
                        ExcMessage(where + ": " + key +
                                   " is for rectangles; a component with a "
                                   "mesh file takes its geometry from the "
                                   "file."));
          component.mesh_file    = Input::resolve_relative_to(file, scene_file);
          component.mesh         = read_mesh_file(component.mesh_file,
                                          component.scale,
                                          where + ": mesh file");
          component.lower_left   = component.mesh.lower_left;
          component.upper_right  = component.mesh.upper_right;
          component.subdivisions = {{1, 1}};
          return;
        }
      const auto lower =
        read_pair(prm.get("lower left corner"), where + ": lower left corner");
      const auto upper      = read_pair(prm.get("upper right corner"),
                                   where + ": upper right corner");
      component.lower_left  = Point<2>(lower[0], lower[1]);
      component.upper_right = Point<2>(upper[0], upper[1]);

      const std::vector<std::string> subdivisions =
        Utilities::split_string_list(prm.get("subdivisions"), ',');
      for (unsigned int d = 0; d < 2; ++d)
        {
          const int n = Utilities::string_to_int(subdivisions[d]);
          AssertThrow(n >= 1,
                      ExcMessage(where +
                                 ": subdivisions must be positive integers, "
                                 "got <" +
                                 prm.get("subdivisions") + ">."));
          component.subdivisions[d] = static_cast<unsigned int>(n);
        }
    }


    // One component: its geometry, element, material, clamps, supports,
    // zones and loads.
    void
    parse_component(ParameterHandler     &prm,
                    ComponentDescription &component,
                    const std::string    &scene_file,
                    const Tensor<1, 2>   &gravity)
    {
      const std::string where = "Component " + component.name;
      prm.enter_subsection(component_section(component.name));
      parse_geometry(prm, component, where, scene_file);

      const long degree = prm.get_integer("fe degree");
      AssertThrow(degree >= 1 && degree <= 4,
                  ExcMessage(where + ": fe degree must be 1, 2, 3 or 4, got " +
                             std::to_string(degree) + "."));
      component.fe_degree = static_cast<unsigned int>(degree);

      component.thickness =
        Input::positive(prm.get_double("thickness"), where + ": thickness");
      const double E   = prm.get_double("E");
      const double nu  = prm.get_double("nu");
      const double rho = prm.get_double("rho");

      component.clamped_faces.clear();
      for (const std::string &f :
           Utilities::split_string_list(prm.get("clamped faces"), ','))
        {
          component.boundary_id(f, where + ": clamped faces");
          for (const std::string &other : component.clamped_faces)
            AssertThrow(other != f,
                        ExcMessage(where + ": clamped faces lists <" + f +
                                   "> twice."));
          component.clamped_faces.push_back(f);
        }
      parse_zones(prm, component, where, E, nu, rho);
      parse_loads(prm, component, where);
      parse_supports(prm, component, where);
      add_weight(component, gravity, where);
      prm.leave_subsection();
    }


    // One contact pair.
    void
    parse_contact_pair(ParameterHandler &prm, ContactPairDescription &pair)
    {
      const std::string where = "Contact " + pair.name;
      prm.enter_subsection("Contact " + pair.name);
      pair.slave_component  = Utilities::trim(prm.get("slave component"));
      pair.master_component = Utilities::trim(prm.get("master component"));
      pair.slave_face       = Utilities::trim(prm.get("slave face"));
      pair.master_face      = Utilities::trim(prm.get("master face"));
      pair.friction_coefficient =
        Input::non_negative(prm.get_double("friction coefficient"),
                            where + ": friction coefficient");
      const std::string gap = Utilities::trim(prm.get("initial gap"));
      pair.has_initial_gap  = (gap != "auto");
      pair.initial_gap =
        pair.has_initial_gap
          ? Input::to_double(gap, where + ": initial gap (a number or auto)")
          : 0.;
      prm.leave_subsection();
    }
  } // namespace


  unsigned int
  Scene::component_index(const std::string &component_name) const
  {
    for (unsigned int c = 0; c < components.size(); ++c)
      if (components[c].name == component_name)
        return c;
    AssertThrow(false,
                ExcMessage("The scene has no component called <" +
                           component_name + ">."));
    return 0;
  }


  std::string
  Scene::names_signature() const
  {
    std::string signature;
    for (const ComponentDescription &c : components)
      {
        signature += c.name + "(";
        for (const MaterialZone &z : c.zones)
          signature += z.name + ",";
        signature += ";";
        for (const EdgeLoad &l : c.loads)
          signature += l.name + ",";
        signature += ";";
        for (const Support &support : c.supports)
          signature += support.name + ",";
        signature += ";" + c.mesh_file + ")";
      }
    for (const ContactPairDescription &p : contact_pairs)
      signature += p.name + ",";
    signature += ";";
    for (const LoadStage &stage : load_stages)
      signature += stage.name + ",";
    return signature;
  }


  void
  Scene::parse_names(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    const std::vector<std::string> component_names =
      Input::to_names(prm.get("components"), "Scene: components");
    const std::vector<std::string> pair_names =
      Input::to_names(prm.get("contact pairs"), "Scene: contact pairs");
    const std::vector<std::string> stage_names =
      Input::to_names(prm.get("load stages"), "Scene: load stages");
    prm.leave_subsection();
    load_stages.clear();
    for (const std::string &stage : stage_names)
      load_stages.push_back(LoadStage{stage, {}, 1});

    // Keep what earlier passes learnt about components that are still there.
    std::vector<ComponentDescription> new_components(component_names.size());
    for (unsigned int c = 0; c < component_names.size(); ++c)
      {
        new_components[c].name = component_names[c];
        for (const ComponentDescription &old : components)
          if (old.name == component_names[c])
            {
              prm.enter_subsection(component_section(old.name));
              const std::string              where = "Component " + old.name;
              const std::vector<std::string> zone_names =
                Input::to_names(prm.get("zones"), where + ": zones");
              const std::vector<std::string> load_names =
                Input::to_names(prm.get("loads"), where + ": loads");
              const std::vector<std::string> support_names =
                Input::to_names(prm.get("supports"), where + ": supports");
              // Only whether there is a mesh file matters here: it
              // changes which keys the component has.
              new_components[c].mesh_file =
                Utilities::trim(prm.get("mesh file"));
              prm.leave_subsection();
              for (const std::string &z : zone_names)
                new_components[c].zones.push_back(
                  MaterialZone{z, {{0, 0}}, {{0, 0}}, 0, 0, 0});
              for (const std::string &l : load_names)
                new_components[c].loads.push_back(
                  EdgeLoad{l, "right", 0, Tensor<1, 2>()});
              for (const std::string &name : support_names)
                new_components[c].supports.push_back(
                  Support{name, "", {{true, true}}, {}});
            }
      }
    components = std::move(new_components);

    contact_pairs.clear();
    for (const std::string &p : pair_names)
      contact_pairs.push_back(
        ContactPairDescription{p, "", "bottom", "", "top", 0, false, 0});
  }


  void
  Scene::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Scene");
    name        = prm.get("name");
    plane_model = prm.get("plane model") == "plane strain"
                    ? PlaneModel::plane_strain
                    : PlaneModel::plane_stress;
    const std::vector<double> g =
      Input::to_doubles(prm.get("gravity"), "Scene: gravity", 2);
    gravity[0] = g[0];
    gravity[1] = g[1];
    prm.leave_subsection();
    SceneLimits::gravity(gravity, "Scene: gravity");

    for (ComponentDescription &component : components)
      parse_component(prm, component, source_file, gravity);
    for (ContactPairDescription &pair : contact_pairs)
      parse_contact_pair(prm, pair);
    parse_load_stages(prm);

    check();
  }


  void
  Scene::check() const
  {
    AssertThrow(!components.empty(),
                ExcMessage("Scene: components: a scene needs at least one "
                           "component."));
    for (const ComponentDescription &component : components)
      {
        const std::string where = "Component " + component.name;
        Input::positive(component.length(),
                        where + ": length (upper right x - lower left x)");
        Input::positive(component.height(),
                        where + ": height (upper right y - lower left y)");
        for (const MaterialZone &zone : component.zones)
          {
            const std::string zwhere =
              component.implicit_zone ? where : where + ", zone " + zone.name;
            Input::positive(zone.youngs_modulus, zwhere + ": E");
            Input::positive(zone.density, zwhere + ": rho");
            std::ostringstream message;
            message << zwhere << ": nu must lie in (-1, 0.5), got "
                    << zone.poissons_ratio << ".";
            AssertThrow(std::isfinite(zone.poissons_ratio) &&
                          zone.poissons_ratio > -1 && zone.poissons_ratio < 0.5,
                        ExcMessage(message.str()));
          }
      }

    for (const ContactPairDescription &pair : contact_pairs)
      {
        const std::string where = "Contact " + pair.name;
        AssertThrow(!pair.slave_component.empty() &&
                      !pair.master_component.empty(),
                    ExcMessage(where + ": both the slave component and the "
                                       "master component must be given."));
        for (const std::string &c :
             {pair.slave_component, pair.master_component})
          {
            bool found = false;
            for (const ComponentDescription &component : components)
              found = found || component.name == c;
            AssertThrow(found,
                        ExcMessage(where + ": there is no component called <" +
                                   c + "> in this scene."));
          }
        components[component_index(pair.slave_component)]
          .boundary_id(pair.slave_face, where + ": slave face");
        components[component_index(pair.master_component)]
          .boundary_id(pair.master_face, where + ": master face");
        AssertThrow(pair.slave_component != pair.master_component,
                    ExcMessage(where + ": slave and master must be different "
                                       "components."));
      }
    SceneLimits::check_ranges(*this);
  }


  Scene
  Scene::read_from_string(const std::string &text,
                          const std::string &source_name)
  {
    // The first pass learns the component and contact pair names, the
    // second the zone and load names of each component; the last one is
    // strict.
    Scene scene;
    scene.source_file = source_name;
    try
      {
        Input::parse_in_passes(
          text,
          source_name,
          [&](ParameterHandler &prm) {
            scene.declare_parameters(prm);
          },
          [&](ParameterHandler &prm) {
            const std::string before = scene.names_signature();
            scene.parse_names(prm);
            return scene.names_signature() != before;
          },
          [&](ParameterHandler &prm) {
            scene.parse_parameters(prm);
          });
      }
    catch (const ExceptionBase &e)
      {
        // A step file may name several scenes: say which one is meant.
        const std::string message = Input::message_of(e);
        AssertThrow(false,
                    ExcMessage(message.find(source_name) == std::string::npos
                                 ? "Scene file <" + source_name +
                                     ">: " + message
                                 : message));
      }
    return scene;
  }


  Scene
  Scene::read(const std::string &filename)
  {
    return read_from_string(Input::read_text_file(filename), filename);
  }
} // namespace FuzzyContact
