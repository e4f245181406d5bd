// The outputs of a study: what a user asks a contact solve for, by name, in
// the key `outputs` of step-3 and step-4 (comma-separated):
//
//   <component>.node(x, y).ux   displacement u_x [m] of the component's node
//   <component>.node(x, y).uy   nearest to the point (x, y) (which must lie
//                               in the component's bounding box)
//   slave.ux, slave.uy          the report node of the paper: the slave node
//                               farthest along its master tangent over all
//                               pairs (P1's bottom-right corner in the
//                               default scenes)
//   master1.ux, ..., master2.uy the two vertices of the master segment under
//                               the report node (the paper's m1, m2)
//   Fn, Ft                      total normal and tangential contact force
//                               over all pairs [N]
//   <pair>.Fn, <pair>.Ft        the same for one contact pair [N]
//   <pair>.max_pressure         largest nodal normal force of the pair over
//                               its slave node's tributary area (tributary
//                               length x thickness) [Pa]
//   <pair>.max_shear            largest |nodal tangential force| of the pair
//                               over its slave node's tributary area [Pa]
//   <pair>.contact_length       length of the closed part of the pair's slave
//                               face: the tributary lengths of its closed
//                               slave nodes, summed [m]
//
// The default is "slave.ux, slave.uy, Fn, Ft". Names are checked against the
// scene before anything is meshed (check()); the nodes are found once the
// meshes exist. Every solver returns the displacements at the DoFs that
// dofs() lists, so that values() turns any solver's ContactSolution into the
// outputs, the full-order and the reduced ones alike.

#ifndef fuzzycontact_study_observations_h
#define fuzzycontact_study_observations_h

#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/study/contact_scene.h>

#include <deal.II/base/point.h>

#include <array>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /** One output of a study. */
  struct Observation
  {
    enum class Kind
    {
      displacement,
      normal_force,
      tangential_force,
      max_pressure,
      max_shear,
      contact_length
    };

    /** The name as the user wrote it (trimmed), e.g. "P1.node(0.2, 0).uy". */
    std::string name;
    Kind        kind = Kind::displacement;
    /** The contact pair; -1 for the totals over all pairs. */
    int pair = -1;
    /** For a displacement: the node, its component, direction and DoF. */
    unsigned int            component = 0;
    unsigned int            direction = 0;
    types::global_dof_index dof       = 0;
    Point<2>                position;
    /** The size of the node's body (its nodes' bounding box diagonal):
     * description() gives the position to 1e-9 of it, the mesh's
     * precision (0, not 2.4e-14, for a node on an axis). */
    double body_size = 0;

    /** "m", "N" or "Pa". */
    std::string
    unit() const;
    /** A phrase for reports, e.g. "u_y of P1's node (0.2, 0.008)". */
    std::string
    description() const;
  };

  class Observations
  {
  public:
    /** "slave.ux, slave.uy, Fn, Ft". */
    static std::string
    default_outputs();

    /**
     * The names of a comma-separated list; commas inside parentheses (the
     * coordinates of a node) do not separate names. Throws, naming
     * @p what, for an empty name or a name given twice.
     */
    static std::vector<std::string>
    split(const std::string &list, const std::string &what = "outputs");

    /**
     * Checks every name against @p scene without meshing it: the syntax, the
     * components and contact pairs named, the coordinates. Throws a message
     * naming @p what and the output, and saying what would be accepted.
     */
    static void
    check(const std::vector<std::string> &names,
          const Scene                    &scene,
          const std::string              &what = "outputs");

    /** Resolves the names on the meshes and contact interface of @p bodies. */
    Observations(const std::vector<std::string> &names,
                 const ContactScene             &bodies);

    unsigned int
    size() const;
    const Observation &
    operator[](const unsigned int i) const;
    std::vector<std::string>
    names() const;
    /** Position of the output called @p name; throws if there is none. */
    unsigned int
    index(const std::string &name) const;

    /** The DoFs every solver must report for these outputs. */
    const ObservedDofs &
    dofs() const;

    /** The value of every output for the solution @p solution. */
    std::vector<double>
    values(const ContactSolution &solution) const;

    /** The report node of the "slave" alias (index in the interface). */
    unsigned int
    slave_node() const;

  private:
    // Adds the DoF of @p node in direction @p d to the observed DoFs.
    void
    observe(Observation &observation, const FaceNode &node, const int d);

    const ContactInterface &interface;
    std::vector<double>     thickness; // of each pair's slave component
    // Per slave node: its pair, and the area its normal force acts on
    // (tributary length times thickness).
    std::vector<int>         node_pair;
    std::vector<double>      pressure_area;
    unsigned int             slave_node_;
    std::array<FaceNode, 2>  master_nodes;
    std::vector<Observation> observations;
    ObservedDofs             dofs_;
    // For each displacement output: its position in dofs_[component].
    std::vector<unsigned int> positions;
  };
} // namespace FuzzyContact

#endif
