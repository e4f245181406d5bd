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


    // The entries of one component, its zones and its loads.
    void
    declare_component(ParameterHandler           &prm,
                      const ComponentDescription &component)
    {
      prm.enter_subsection(component_section(component.name));
      prm.declare_entry("mesh file",
                        "",
                        Patterns::Anything(),
                        "A Gmsh mesh (.msh) or geometry (.geo), relative to "
                        "the scene file; empty: a rectangle (corners and "
                        "subdivisions).");
      prm.declare_entry("scale",
                        "1",
                        Patterns::Double(),
                        "Mesh-file units to metres (1e-3 for mm).");
      if (component.mesh_file.empty())
        {
          prm.declare_entry("lower left corner",
                            "0, 0",
                            Patterns::List(Patterns::Double(), 2, 2),
                            "x, y of the lower left corner [m].",
                            /*has_to_be_set=*/true);
          prm.declare_entry("upper right corner",
                            "1, 1",
                            Patterns::List(Patterns::Double(), 2, 2),
                            "x, y of the upper right corner [m].",
                            /*has_to_be_set=*/true);
          prm.declare_entry("subdivisions",
                            "1, 1",
                            Patterns::List(Patterns::Integer(), 2, 2),
                            "Number of cells along x and along y.",
                            /*has_to_be_set=*/true);
        }
      else
        for (const char *key :
             {"lower left corner", "upper right corner", "subdivisions"})
          prm.declare_entry(key,
                            "",
                            Patterns::Anything(),
                            "Rectangles only: must stay empty with a mesh "
                            "file.");
      prm.declare_entry("fe degree",
                        "2",
                        Patterns::Integer(),
                        "Polynomial degree of the FE_Q displacement "
                        "element (1 to 4).");
      prm.declare_entry("thickness",
                        "1",
                        Patterns::Double(),
                        "Out-of-plane thickness t [m].");
      prm.declare_entry("E",
                        "210e9",
                        Patterns::Double(),
                        "Young's modulus [Pa] of zones that do not set "
                        "their own.");
      prm.declare_entry("nu",
                        "0.3",
                        Patterns::Double(),
                        "Poisson's ratio of zones that do not set their "
                        "own.");
      prm.declare_entry("rho",
                        "7900",
                        Patterns::Double(),
                        "Density [kg/m^3] of zones that do not set their "
                        "own.");
      prm.declare_entry("clamped faces",
                        "",
                        Patterns::Anything(),
                        "Faces whose displacements are zero (a mesh file: "
                        "names of its physical curves).");
      prm.declare_entry("supports",
                        "",
                        Patterns::Anything(),
                        "Comma-separated names of supports (rollers, "
                        "symmetry lines, prescribed displacements), each "
                        "with a subsection 'Support <name>'.");
      prm.declare_entry("zones",
                        "",
                        Patterns::Anything(),
                        "Comma-separated names of material zones, each "
                        "with a subsection 'Zone <name>'. Empty: the whole "
                        "component is one zone called 'body'.");
      prm.declare_entry("loads",
                        "",
                        Patterns::Anything(),
                        "Comma-separated names of edge loads, each with a "
                        "subsection 'Load <name>'.");

      if (!component.implicit_zone)
        for (const MaterialZone &zone : component.zones)
          {
            prm.enter_subsection("Zone " + zone.name);
            prm.declare_entry("x range",
                              "",
                              Patterns::Anything(),
                              "x_min, x_max of the zone [m]; empty: the "
                              "whole length.");
            prm.declare_entry("y range",
                              "",
                              Patterns::Anything(),
                              "y_min, y_max of the zone [m]; empty: the "
                              "whole height.");
            prm.declare_entry("E",
                              "",
                              Patterns::Anything(),
                              "Young's modulus [Pa]; empty: the component's.");
            prm.declare_entry("nu",
                              "",
                              Patterns::Anything(),
                              "Poisson's ratio; empty: the component's.");
            prm.declare_entry("rho",
                              "",
                              Patterns::Anything(),
                              "Density [kg/m^3]; empty: the component's.");
            prm.leave_subsection();
          }

      for (const EdgeLoad &load : component.loads)
        {
          if (load.is_displacement)
            continue; // declared as its support
          prm.enter_subsection("Load " + load.name);
          prm.declare_entry("face",
                            "right",
                            Patterns::Anything(),
                            "Face that carries the load.");
          prm.declare_entry("total force",
                            "0",
                            Patterns::Double(),
                            "Resultant of the load [N], spread uniformly "
                            "over the face.");
          prm.declare_entry("pressure",
                            "",
                            Patterns::Anything(),
                            "Instead of a total force: a pressure [Pa] "
                            "normal to the face, pushing into the body.");
          prm.declare_entry("direction",
                            "0, -1",
                            Patterns::List(Patterns::Double(), 2, 2),
                            "Direction of the resultant (normalised).");
          prm.leave_subsection();
        }
      for (const Support &support : component.supports)
        {
          prm.enter_subsection("Support " + support.name);
          prm.declare_entry("face",
                            "",
                            Patterns::Anything(),
                            "Face that is supported.",
                            /*has_to_be_set=*/true);
          prm.declare_entry("fixed components",
                            "x, y",
                            Patterns::Selection("x|y|x, y|x,y|y, x|y,x"),
                            "Displacement components held: x, y or x, y.");
          prm.declare_entry("displacement",
                            "0, 0",
                            Patterns::List(Patterns::Double(), 2, 2),
                            "Prescribed x, y displacement [m]; only the "
                            "fixed components are used.");
          prm.leave_subsection();
        }
      prm.leave_subsection();
    }


    // The entries of one contact pair.
    void
    declare_contact_pair(ParameterHandler             &prm,
                         const ContactPairDescription &pair)
    {
      prm.enter_subsection("Contact " + pair.name);
      prm.declare_entry("slave component",
                        "",
                        Patterns::Anything(),
                        "Component whose face nodes are the slave nodes.",
                        /*has_to_be_set=*/true);
      prm.declare_entry("slave face",
                        "bottom",
                        Patterns::Anything(),
                        "Face of the slave component (a rectangle: left, "
                        "right, bottom or top; a mesh file: a physical "
                        "curve).");
      prm.declare_entry("master component",
                        "",
                        Patterns::Anything(),
                        "Component whose face the slave nodes touch.",
                        /*has_to_be_set=*/true);
      prm.declare_entry("master face",
                        "top",
                        Patterns::Anything(),
                        "Face of the master component.");
      prm.declare_entry("friction coefficient",
                        "0",
                        Patterns::Double(),
                        "Coulomb friction coefficient mu (>= 0).");
      prm.declare_entry("initial gap",
                        "auto",
                        Patterns::Anything(),
                        "Normal gap [m] of every slave node before "
                        "loading, or 'auto' to measure it from the "
                        "geometry.");
      prm.leave_subsection();
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
                                       "> has no physical surface called <" +
                                       zone.name + ">; it has: " +
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
          if (load.is_displacement)
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
                    const std::string    &scene_file)
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


  std::string
  to_string(const PlaneModel model)
  {
    return model == PlaneModel::plane_stress ? "plane stress" : "plane strain";
  }


  std::string
  to_string(const Face face)
  {
    switch (face)
      {
        case Face::left:
          return "left";
        case Face::right:
          return "right";
        case Face::bottom:
          return "bottom";
        case Face::top:
          return "top";
      }
    return "unknown";
  }


  Face
  face_from_string(const std::string &name, const std::string &what)
  {
    const std::string n = Utilities::trim(name);
    if (n == "left")
      return Face::left;
    if (n == "right")
      return Face::right;
    if (n == "bottom")
      return Face::bottom;
    if (n == "top")
      return Face::top;
    AssertThrow(false,
                ExcMessage(what + ": <" + n +
                           "> is not a face of a rectangular component; "
                           "use left, right, bottom or top."));
    return Face::left;
  }


  std::optional<Face>
  rectangle_side(const std::string &name)
  {
    const std::string n = Utilities::trim(name);
    for (const Face f : {Face::left, Face::right, Face::bottom, Face::top})
      if (n == to_string(f))
        return f;
    return std::nullopt;
  }


  bool
  ComponentDescription::is_rectangle() const
  {
    return mesh_file.empty();
  }


  types::boundary_id
  ComponentDescription::boundary_id(const std::string &face,
                                    const std::string &what) const
  {
    if (is_rectangle())
      return static_cast<types::boundary_id>(face_from_string(face, what));
    const auto id = mesh.boundary_ids.find(Utilities::trim(face));
    AssertThrow(id != mesh.boundary_ids.end(),
                ExcMessage(what + ": <" + mesh.file +
                           "> has no physical curve called <" +
                           Utilities::trim(face) +
                           ">; it has: " + mesh.face_names() + "."));
    return id->second;
  }


  std::vector<Support>
  ComponentDescription::all_supports() const
  {
    std::vector<Support> all;
    for (const std::string &face : clamped_faces)
      all.push_back(Support{"clamp " + face, face, {{true, true}}, {}});
    all.insert(all.end(), supports.begin(), supports.end());
    return all;
  }


  unsigned int
  ComponentDescription::n_mesh_faces(const std::string &face) const
  {
    if (is_rectangle())
      {
        const Face f = face_from_string(face, "Component " + name);
        return (f == Face::left || f == Face::right) ? subdivisions[1]
                                                     : subdivisions[0];
      }
    const auto n = mesh.boundary_faces.find(boundary_id(face, name));
    return n == mesh.boundary_faces.end() ? 0 : n->second;
  }


  double
  ComponentDescription::length() const
  {
    return upper_right[0] - lower_left[0];
  }


  double
  ComponentDescription::height() const
  {
    return upper_right[1] - lower_left[1];
  }


  unsigned int
  ComponentDescription::zone_index(const std::string &zone_name) const
  {
    for (unsigned int z = 0; z < zones.size(); ++z)
      if (zones[z].name == zone_name)
        return z;
    AssertThrow(false,
                ExcMessage("Component " + name + " has no zone called <" +
                           zone_name + ">."));
    return 0;
  }


  double
  ComponentDescription::zone_area(const unsigned int z) const
  {
    AssertIndexRange(z, zones.size());
    const MaterialZone &zone = zones[z];
    if (!is_rectangle())
      {
        if (implicit_zone)
          {
            double area = 0;
            for (const auto &[id, a] : mesh.material_areas)
              area += a;
            return area;
          }
        const auto a = mesh.material_areas.find(zone.material_id);
        return a == mesh.material_areas.end() ? 0. : a->second;
      }
    const double dx = std::min(zone.x_range[1], upper_right[0]) -
                      std::max(zone.x_range[0], lower_left[0]);
    const double dy = std::min(zone.y_range[1], upper_right[1]) -
                      std::max(zone.y_range[0], lower_left[1]);
    return std::max(dx, 0.) * std::max(dy, 0.);
  }


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


  // Declares every entry that the names known so far call for. Entries that
  // must be given (corners, subdivisions, the components of a contact pair)
  // are declared mandatory; materials default to the steel of the paper.
  void
  Scene::declare_parameters(ParameterHandler &prm) const
  {
    prm.enter_subsection("Scene");
    {
      prm.declare_entry("name", "", Patterns::Anything(), "Name of the scene.");
      prm.declare_entry("plane model",
                        "plane stress",
                        Patterns::Selection("plane stress|plane strain"),
                        "2D idealisation: plane stress (narrow beam) or "
                        "plane strain (strip much wider than high).");
      prm.declare_entry("components",
                        "",
                        Patterns::Anything(),
                        "Comma-separated names of the components; each has "
                        "a subsection 'Component <name>'.");
      prm.declare_entry("contact pairs",
                        "",
                        Patterns::Anything(),
                        "Comma-separated names of the contact pairs; each "
                        "has a subsection 'Contact <name>'.");
    }
    prm.leave_subsection();

    for (const ComponentDescription &component : components)
      declare_component(prm, component);
    for (const ContactPairDescription &pair : contact_pairs)
      declare_contact_pair(prm, pair);
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
    prm.leave_subsection();

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
    prm.leave_subsection();

    for (ComponentDescription &component : components)
      parse_component(prm, component, source_file);
    for (ContactPairDescription &pair : contact_pairs)
      parse_contact_pair(prm, pair);

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
