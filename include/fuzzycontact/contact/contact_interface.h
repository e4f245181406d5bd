// The geometry of node-to-segment contact between 2D components, built once
// per scene in the reference configuration (small deformation):
//
//  - every node of a contact pair's slave face (for Q2 elements: vertices and
//    mid-side nodes) is projected onto the master face of the other
//    component; the master segment is the face edge that contains the
//    projection, with its p + 1 nodes (3 for Q2) and their 1D Lagrange shape
//    functions N_i(xi). The meshes need not match.
//  - with the master face's outward normal n and the tangent tau (n turned
//    clockwise by 90 degrees: tau = (n_y, -n_x), i.e. +x on a top face), the
//    normal gap and the tangential relative displacement of slave node k are
//
//        g_n = g0 + n   . (u_s - sum_i N_i(xi) u_mi),
//        g_t =      tau . (u_s - sum_i N_i(xi) u_mi),
//
//    so that g = g0 + C u with a sparse operator C of 2 rows per slave node
//    (row 2k: normal, row 2k+1: tangential) acting on the concatenated DoFs
//    of all components (component c occupies [offset(c), offset(c) +
//    n_dofs(c))).
//  - contact forces p (p_n >= 0 in compression, p_t along tau on the slave)
//    act on both bodies as C^T p: +p_n n + p_t tau on the slave node,
//    -N_i (p_n n + p_t tau) on the master nodes (action and reaction; their
//    sum is zero because sum_i N_i = 1).
//
// Clamped DoFs carry no displacement, so the blocks gap_operator(c) used by
// the solvers leave their columns out (a contact force at a clamped node goes
// straight into the clamp); nodal_forces() keeps them, for equilibrium
// checks. A slave node whose row of C vanishes altogether (slave and master
// nodes all clamped) can neither move nor transmit a force and is not a
// contact candidate.
//
// Bad geometry is refused with a message naming the contact pair: faces
// whose outward normals are not opposite, a slave face no node of which lies
// opposite the master face, and an initial penetration larger than
// penetration_tolerance times the master face length.

#ifndef fuzzycontact_contact_contact_interface_h
#define fuzzycontact_contact_contact_interface_h

#include <fuzzycontact/contact/slide_profile.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /** A node of a component: its position and its x and y DoFs. */
  struct FaceNode
  {
    unsigned int                           component;
    Point<2>                               position;
    std::array<types::global_dof_index, 2> dofs;
  };

  /** One slave node and its projection onto the master face. */
  struct ContactNode
  {
    /** Index of the contact pair in Scene::contact_pairs. */
    unsigned int pair;
    FaceNode     slave;
    /** Nodes of the master segment (p + 1 of them) and N_i(xi). */
    std::vector<FaceNode> master_nodes;
    std::vector<double>   shape_values;
    /** Local coordinate of the projection in [0, 1] along the segment. */
    double xi;
    /** The projection x_m(xi) of the slave node. */
    Point<2> projection;
    /** Outward normal n of the master face and tangent tau. */
    Tensor<1, 2> normal;
    Tensor<1, 2> tangent;
    /**
     * Initial normal gap: from the geometry, n . (x_s - x_m), or the
     * pair's declared initial gap.
     */
    double initial_gap;
    /** Coulomb coefficient of the pair, as read from the scene. */
    double friction_coefficient;
    /**
     * How the master face turns along a slide of this node, and where it
     * ends (slide_profile.h; small sliding's measure, small_sliding.h).
     */
    SlideProfile slide;
    /** Slave-face length this node stands for (integral of its shape
     * function along the slave face): pressure = p_n / (length * t). */
    double tributary_length;
  };

  /**
   * One master segment of a contact pair: a face of a master cell, its p +
   * 1 nodes sorted along the tangent, and the coordinates of its ends along
   * the tangent.
   */
  struct MasterSegment
  {
    std::vector<FaceNode> nodes;
    double                s_begin, s_end;
  };

  class ContactInterface
  {
  public:
    /**
     * Builds the contact geometry of all contact pairs of @p scene between
     * the given components (one per scene component, in scene order).
     * Throws with a message naming the pair for faces that cannot touch and
     * for initial penetration beyond @p penetration_tolerance times the
     * master face length.
     */
    ContactInterface(const Scene                          &scene,
                     const std::vector<const Component *> &components,
                     const double penetration_tolerance = 1e-8);

    /** Number of slave nodes (contact candidates) over all pairs. */
    unsigned int
    n_nodes() const;
    /** Rows of C: 2 n_nodes(). Row 2k is normal, row 2k+1 tangential. */
    unsigned int
    n_rows() const;
    const ContactNode &
    node(const unsigned int k) const;
    const std::vector<ContactNode> &
    nodes() const;

    unsigned int
    n_components() const;
    /** Start of component @p c in the concatenated DoF vector. */
    types::global_dof_index
    dof_offset(const unsigned int c) const;
    types::global_dof_index
    n_total_dofs() const;

    /**
     * The block of C acting on component @p c (n_rows() x n_dofs(c)),
     * without the columns of clamped DoFs.
     */
    const SparseMatrix<double> &
    gap_operator(const unsigned int c) const;

    /**
     * DoFs of component @p c that C touches (slave and master face DoFs of
     * the contact candidates, clamped ones excluded), sorted.
     */
    const std::vector<types::global_dof_index> &
    contact_dofs(const unsigned int c) const;

    /** Number of contact pairs (those of the scene, in its order). */
    unsigned int
    n_pairs() const;
    /** Name of contact pair @p pair. */
    const std::string &
    pair_name(const unsigned int pair) const;

    /**
     * Gaps of the unloaded configuration: normal rows g0, tangential rows 0.
     */
    Vector<double>
    initial_gaps() const;

    /**
     * The same with the initial gap of every slave node of pair p shifted by
     * @p gap_offsets[p] [m] (a fuzzy initial gap, say). Refuses an offset
     * that would make any gap negative beyond the penetration tolerance,
     * naming the pair and the node.
     */
    Vector<double>
    initial_gaps(const std::vector<double> &gap_offsets) const;

    /**
     * Friction coefficient of every node, from its pair in the scene; 0 at
     * a node whose tangential motion is held on both bodies (its
     * tangential row of C vanishes: a symmetry line through the contact
     * held on both sides), where the tangential force is a support
     * reaction, not friction.
     */
    std::vector<double>
    friction_coefficients() const;

    /**
     * Friction coefficient of every node when pair p has @p per_pair[p]
     * (each >= 0; 0 at a node held tangentially, as above).
     */
    std::vector<double>
    friction_coefficients(const std::vector<double> &per_pair) const;

    /** g = g0 + C u for displacements @p u, one vector per component. */
    Vector<double>
    gaps(const std::vector<Vector<double>> &u) const;

    /**
     * The nodal forces C^T p on every component, including the clamped
     * DoFs (there the clamp takes them).
     */
    std::vector<Vector<double>>
    nodal_forces(const Vector<double> &p) const;

    /**
     * Index of the slave node nearest to @p point (among all candidates).
     */
    unsigned int
    nearest_node(const Point<2> &point) const;

    /** The master segments of pair @p pair, sorted along its tangent. */
    const std::vector<MasterSegment> &
    master_segments(const unsigned int pair) const;

    /** Coordinate along the tangent of the centre of pair @p pair's slave
     * face. */
    double
    slave_face_centre(const unsigned int pair) const;

    /** Largest initial penetration allowed for pair @p pair [m]. */
    double
    penetration_tolerance(const unsigned int pair) const;

  private:
    void
    add_pair(const Scene                          &scene,
             const std::vector<const Component *> &components,
             const unsigned int                    pair_index);
    void
    build_operators(const std::vector<const Component *> &components);

    std::vector<ContactNode>                          nodes_;
    std::vector<types::global_dof_index>              offsets_;
    std::vector<SparsityPattern>                      patterns_;
    std::vector<SparseMatrix<double>>                 operators_;
    std::vector<std::vector<types::global_dof_index>> contact_dofs_;
    std::vector<std::vector<bool>>                    constrained_;
    // Per node: its tangential row of C vanishes (friction_coefficients()).
    std::vector<bool> tangentially_held_;
    // Per pair: master segments, the centre of the slave face along tau,
    // the penetration tolerance, the name.
    std::vector<std::vector<MasterSegment>> segments_;
    std::vector<double>                     slave_face_centre_;
    std::vector<double>                     penetration_tolerance_;
    std::vector<std::string>                pair_names_;
  };
} // namespace FuzzyContact

#endif
