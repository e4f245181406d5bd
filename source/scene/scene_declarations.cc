// Scene::declare_parameters(): every entry of a scene file whose names are
// known (see Scene::read(), which parses in passes).

#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/exceptions.h>

namespace FuzzyContact
{
  namespace
  {
    std::string
    component_section(const std::string &name)
    {
      return "Component " + name;
    }


    // The Zone subsections of a component that lists its zones.
    void
    declare_zones(ParameterHandler &prm, const ComponentDescription &component)
    {
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
    }


    // The Load subsections of a component (not those of its supports).
    void
    declare_loads(ParameterHandler &prm, const ComponentDescription &component)
    {
      for (const EdgeLoad &load : component.loads)
        {
          if (load.is_displacement || load.is_weight)
            continue; // declared as its support, or by the scene's gravity
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
    }


    // The Support subsections of a component.
    void
    declare_supports(ParameterHandler           &prm,
                     const ComponentDescription &component)
    {
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
                        "A Gmsh mesh (.msh) or geometry (.geo) or an Abaqus "
                        "input file (.inp), relative to the scene file; "
                        "empty: a rectangle (corners and subdivisions).");
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

      declare_zones(prm, component);
      declare_loads(prm, component);
      declare_supports(prm, component);
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


  } // namespace


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
      prm.declare_entry("gravity",
                        "0, 0",
                        Patterns::Anything(),
                        "Acceleration of gravity [m/s^2], x, y (e.g. 0, "
                        "-9.81): every component then carries its own "
                        "weight, a load called 'weight'. 0, 0: no weight.");
      prm.declare_entry("load stages",
                        "",
                        Patterns::Anything(),
                        "Comma-separated names of the stages of the load "
                        "history, in order; each has a subsection 'Stage "
                        "<name>'. Empty: all loads in one proportional "
                        "stage.");
    }
    prm.leave_subsection();
    declare_load_stages(prm);

    for (const ComponentDescription &component : components)
      declare_component(prm, component);
    for (const ContactPairDescription &pair : contact_pairs)
      declare_contact_pair(prm, pair);
  }
} // namespace FuzzyContact
