// The description of a scene: 2D components, their material zones, clamps,
// loads and the contact pairs between them, read from a deal.II parameter
// file.
//
// A scene file names its components, contact pairs, zones and loads in
// lists, and each name opens a subsection of its own:
//
//   subsection Scene
//     set plane model   = plane stress
//     set components    = P1, P2
//     set contact pairs = interface
//   end
//   subsection Component P1
//     set lower left corner  = 0, 1e-8
//     ...
//     set loads = tip
//     subsection Load tip
//       set face        = right
//       set total force = 50000
//     end
//   end
//
// Since the subsections depend on the names, Scene::read() parses the file
// in passes: each pass declares what the previous one has learnt and skips
// the rest; the last pass is strict, so that a misspelt key is reported
// rather than ignored. This header holds plain descriptions only (no
// deal.II mesh objects), so it is cheap to include.

#ifndef fuzzycontact_scene_scene_h
#define fuzzycontact_scene_scene_h

#include <fuzzycontact/scene/mesh_file.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * The 2D idealisation of the bodies: plane stress for a narrow beam
   * (sigma_zz = 0), plane strain for a strip much wider than it is high
   * (eps_zz = 0).
   */
  enum class PlaneModel
  {
    plane_stress,
    plane_strain
  };

  std::string
  to_string(PlaneModel model);

  /**
   * The four straight faces of a rectangular component, numbered as deal.II's
   * colorized hyper rectangle numbers its boundary ids (left = 0, right = 1,
   * bottom = 2, top = 3).
   */
  enum class Face : unsigned int
  {
    left   = 0,
    right  = 1,
    bottom = 2,
    top    = 3
  };

  std::string
  to_string(Face face);

  /**
   * Parses "left", "right", "bottom" or "top"; throws a message naming
   * @p what otherwise.
   */
  Face
  face_from_string(const std::string &name, const std::string &what);

  /** The side called @p name of a rectangle, if it is one. */
  std::optional<Face>
  rectangle_side(const std::string &name);

  /**
   * A material zone of a component. In a rectangle, the cells whose centre
   * lies in [x_range] x [y_range]; the zones of a component must cover every
   * cell exactly once, and their edges must lie on mesh lines (checked when
   * the mesh is built). In a mesh file, the cells of the physical surface
   * of the zone's name (material_id is its tag).
   */
  struct MaterialZone
  {
    std::string           name;
    std::array<double, 2> x_range;
    std::array<double, 2> y_range;
    double                youngs_modulus;
    double                poissons_ratio;
    double                density;
    types::material_id    material_id = 0;
  };

  /**
   * A load on one face. Either a constant traction whose resultant is
   * total_force * direction (direction has unit length; on a curved face the
   * traction per unit length is total_force / face length), or, if
   * is_pressure, a pressure of total_force [Pa] normal to the face, pushing
   * into the body (its resultant follows the face's shape).
   */
  struct EdgeLoad
  {
    std::string  name;
    std::string  face;
    double       total_force;
    Tensor<1, 2> direction;
    bool         is_pressure = false;
    /**
     * True for the load that stands for a support's prescribed
     * displacement (the scene adds one per support with a non-zero
     * displacement, named after it): total_force is then the displacement's
     * magnitude [m] and direction its direction, and the nodal forces are
     * those that impose it, -K_fp u_p (see Component).
     */
    bool is_displacement = false;
    /**
     * True for the body's own weight (the scene adds one, called "weight",
     * to every component when its `gravity` is not zero): no face;
     * total_force is the acceleration's magnitude |g| [m/s^2] and
     * direction g / |g|, and the nodal forces are rho g integrated over the
     * body, per zone with the zone's density (see Component).
     */
    bool is_weight = false;
  };

  /**
   * A support on one face: the displacement components it fixes (x, y or
   * both) and their prescribed values [m] (zero for a clamp, a roller or a
   * symmetry line). A clamped face is a support fixing both at zero. Where
   * supports share nodes, the first one listed holds them (clamps first).
   */
  struct Support
  {
    std::string         name;
    std::string         face;
    std::array<bool, 2> fixed = {{true, true}};
    Tensor<1, 2>        displacement;
  };

  /**
   * One 2D component: a rectangle (a beam, say) or a mesh file. For a mesh
   * file, lower_left and upper_right hold its bounding box.
   */
  struct ComponentDescription
  {
    std::string name;
    /** The mesh file (resolved), empty for a rectangle. */
    std::string mesh_file;
    /** Mesh units to metres. */
    double scale = 1;
    /** What the mesh file holds (names, sizes); empty for a rectangle. */
    MeshFileInfo              mesh;
    Point<2>                  lower_left;
    Point<2>                  upper_right;
    std::array<unsigned, 2>   subdivisions;
    unsigned int              fe_degree;
    double                    thickness;
    std::vector<MaterialZone> zones;
    /**
     * True if the parameter file lists no zones: then zones holds one zone
     * called "body" over the whole component, with the component's
     * material, and the file has no 'Zone' subsection for it.
     */
    bool                     implicit_zone = false;
    std::vector<std::string> clamped_faces;
    std::vector<Support>     supports;
    std::vector<EdgeLoad>    loads;

    /** True unless the component comes from a mesh file. */
    bool
    is_rectangle() const;

    /**
     * The boundary id of the face called @p face; throws naming @p what and
     * the faces the component has.
     */
    types::boundary_id
    boundary_id(const std::string &face, const std::string &what) const;

    /**
     * Every support of the component: one per clamped face (both
     * components fixed at zero) followed by the declared supports.
     */
    std::vector<Support>
    all_supports() const;

    /** Number of mesh faces (edges) on face @p face before refinement. */
    unsigned int
    n_mesh_faces(const std::string &face) const;

    /**
     * Length of face @p face [m] (of a mesh file: of its straight mesh
     * edges, before refinement).
     */
    double
    face_length(const std::string &face) const;

    double
    length() const;
    double
    height() const;

    /** Index of the zone called @p zone_name; throws if there is none. */
    unsigned int
    zone_index(const std::string &zone_name) const;

    /**
     * Area of zone @p z [m^2]: its rectangle clipped to the component (the
     * zones tile the component, see MaterialZone).
     */
    double
    zone_area(const unsigned int z) const;
  };

  /**
   * A node-to-segment contact pair: the nodes of the slave face touch the
   * master face of another component.
   */
  struct ContactPairDescription
  {
    std::string name;
    std::string slave_component;
    std::string slave_face;
    std::string master_component;
    std::string master_face;
    double      friction_coefficient;
    /**
     * Gap of every slave node in the reference configuration. If false,
     * the gap is measured from the geometry of the two faces.
     */
    bool   has_initial_gap;
    double initial_gap;
  };

  /**
   * One stage of a load history (scene key `load stages`, one `Stage
   * <name>` subsection each): the loads it ramps from 0 to their full value
   * in its own load steps, on top of the earlier stages' loads held at
   * full value. A support's prescribed displacement is a load of the
   * support's name (EdgeLoad::is_displacement).
   */
  struct LoadStage
  {
    std::string name;
    /** The loads it ramps, as {component index, load index}. */
    std::vector<std::array<unsigned int, 2>> loads;
    unsigned int                             n_load_steps = 1;

    /** True if the stage ramps load @p l of component @p c. */
    bool
    ramps(const unsigned int c, const unsigned int l) const;
  };

  /**
   * A scene: the plane model, the components and the contact pairs.
   */
  class Scene
  {
  public:
    /**
     * Reads and checks a scene file. Throws an exception whose message names
     * the offending parameter (with file and line where ParameterHandler
     * knows them) for unknown keys, malformed numbers, NaN, non-positive
     * lengths, moduli, densities, thicknesses, subdivisions, unknown faces
     * and components.
     */
    static Scene
    read(const std::string &filename);

    /** Same as read(), from the text of a parameter file. */
    static Scene
    read_from_string(const std::string &text,
                     const std::string &source_name = "scene");

    /**
     * Declares the entries of a scene whose names are those of this object
     * (no components at all for a default-constructed one).
     */
    void
    declare_parameters(ParameterHandler &prm) const;

    /**
     * Reads the declared entries back, checking each value.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /** Index of the component called @p name; throws if there is none. */
    unsigned int
    component_index(const std::string &name) const;

    std::string name;
    /** The file the scene was read from: mesh files are relative to it. */
    std::string                         source_file;
    PlaneModel                          plane_model = PlaneModel::plane_stress;
    std::vector<ComponentDescription>   components;
    std::vector<ContactPairDescription> contact_pairs;
    /**
     * The acceleration of gravity [m/s^2] (scene key `gravity`); zero: no
     * body weight. Otherwise every component has a load called "weight"
     * (EdgeLoad::is_weight), listed last.
     */
    Tensor<1, 2> gravity;
    /**
     * The load history; empty: every load applied proportionally in one
     * stage (the step program's `load steps`). When given, every load of
     * the scene is in exactly one stage.
     */
    std::vector<LoadStage> load_stages;

  private:
    /**
     * Reads only the lists of names (components, zones, loads, contact
     * pairs) from @p prm, leaving numbers alone. Used by the passes of
     * read().
     */
    void
    parse_names(ParameterHandler &prm);

    /** All names (components, zones, loads, pairs) in one string. */
    std::string
    names_signature() const;

    /** Declares the `Stage <name>` subsections of the known stages. */
    void
    declare_load_stages(ParameterHandler &prm) const;

    /**
     * Reads the stages' loads and steps (after the components, whose loads
     * they name) and checks that every load is in exactly one stage.
     */
    void
    parse_load_stages(ParameterHandler &prm);

    /** Checks what can be checked without a mesh. */
    void
    check() const;
  };
} // namespace FuzzyContact

#endif
