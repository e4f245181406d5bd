// One 2D linear-elastic component: its mesh, its degrees of freedom, its
// clamps, and the stiffness and mass matrices split by material zone,
//
//     K = sum_z E_z K_z,     M = sum_z rho_z M_z,
//
// where K_z, M_z are assembled once with unit modulus and unit density over
// the cells of zone z. The derivatives dK/dE_z = K_z and dM/drho_z = M_z are
// then exact matrices, and a new set of moduli or densities costs a few
// sparse matrix additions instead of an assembly.
//
// Clamped degrees of freedom are eliminated through AffineConstraints. Their
// rows and columns in K and K_z are empty but for a positive diagonal entry
// (so that K stays invertible), and their rows in M and M_z are zero, so
// that they carry no mass: in K phi = lambda M phi they have infinite
// eigenvalues and never appear among the computed modes.
//
// A support with a prescribed displacement u_p keeps its constraints
// homogeneous and becomes a load of its own (EdgeLoad::is_displacement):
// forces -K_fp u_p on the free rows and K_pp u_p (the diagonal) on the held
// rows, so that K u = f gives u = u_p on the held DoFs and the elastic
// response elsewhere. The forces scale with the zone moduli (a stiffer body
// needs more force for the same displacement); set_zone_materials() updates
// them.
//
// The body's own weight (a scene with gravity g, EdgeLoad::is_weight) is
// rho g integrated over the body: per zone, w_z = t int_z N^T d dx at unit
// density along d = g / |g|, and the weight's nodal forces are |g| sum_z
// rho_z w_z; set_zone_materials() updates them with the densities, as it
// updates the forces of prescribed displacements with the moduli. It acts
// on every DoF (no face).
//
// A body whose clamps and supports leave rigid-body motions free (a body
// held by contact alone: a block resting on a slope, a roller under a
// force) has a singular stiffness. Built for a contact problem (with its
// contact faces given), such a body is pinned: one DoF per free motion,
// off its contact and loaded faces, is held like a support, so that the
// stiffness K~ of the pinned body is positive definite. The free motions R
// (one field each, zero on the DoFs supports hold) are kept: for forces g
// in equilibrium along them (R^T g = 0), u = K~^{-1} g solves K u = g (the
// pins' rows follow from the others', since R^T K = 0 and the pins' rows of
// R are independent), and the body's displacement is u + R a. The
// amplitudes a are unknowns of the contact problem, with the equilibrium
// R^T (f + C^T p) = 0 as their equations (contact/contact_problem.h).
//
// The matrices and loads are assembled when the component is built, or, if
// it is built without (a rank of an MPI study that does not build this
// body's reduced model needs only its mesh and DoFs, for the contact
// interface and the outputs), when they are first asked for: the loads
// (face integrals) on their own, the matrices with everything that needs
// them (the loads of prescribed displacements among them).

#ifndef fuzzycontact_fe_component_h
#define fuzzycontact_fe_component_h

#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/timer.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/mapping.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * Stress from strain for a 2D model with Young's modulus @p E and Poisson's
   * ratio @p nu: sigma = lambda tr(eps) I + 2 mu eps with the plane-stress
   * or plane-strain value of lambda.
   */
  SymmetricTensor<4, 2>
  elasticity_tensor(const PlaneModel model, const double E, const double nu);

  class Component
  {
  public:
    /**
     * Builds the mesh (the description's subdivisions, refined globally
     * @p n_refinements times), the DoFs and the clamp constraints, and
     * assembles all matrices and the load vector. Throws if the zones do
     * not tile the mesh. If @p timer is given, the stages "mesh and DoFs"
     * and "assembly" are timed in it. With @p assemble = false, only the
     * mesh, the DoFs and the constraints are built; the matrices and loads
     * are assembled on first use (see the top of this file).
     */
    Component(const ComponentDescription &description,
              const PlaneModel            plane_model,
              const unsigned int          n_refinements = 0,
              TimerOutput                *timer         = nullptr);
    /**
     * As above, for a contact problem: @p contact_faces are the component's
     * faces in contact pairs. A body its supports do not hold is then
     * pinned (see the top of this file), with its pins off those faces.
     * With @p assemble = false the matrices and loads are assembled on
     * first use (see the top of this file).
     */
    Component(const ComponentDescription     &description,
              const PlaneModel                plane_model,
              const unsigned int              n_refinements,
              TimerOutput                    *timer,
              const std::vector<std::string> &contact_faces,
              const bool                      assemble = true);

    /**
     * Whether the matrices have been assembled (at construction or on
     * first use).
     */
    bool
    is_assembled() const;

    const std::string &
    name() const;
    const ComponentDescription &
    description() const;
    PlaneModel
    plane_model() const;

    unsigned int
    n_dofs() const;
    const Triangulation<2> &
    triangulation() const;
    const DoFHandler<2> &
    dof_handler() const;
    const FESystem<2> &
    fe() const;
    /**
     * The mapping of the cells: bilinear, or of the element's degree when
     * the mesh has circular arcs (their nodes then lie on the arcs).
     */
    const Mapping<2> &
    mapping() const;
    /** Length [m] of the boundary with id @p id (through the mapping). */
    double
    boundary_length(const types::boundary_id id) const;
    const AffineConstraints<double> &
    constraints() const;
    /** True for DoFs held by a clamp, a support or a pin. */
    bool
    is_constrained(const types::global_dof_index dof) const;
    /** True for DoFs held at a non-zero prescribed displacement. */
    bool
    is_prescribed(const types::global_dof_index dof) const;

    unsigned int
    n_zones() const;
    const SparseMatrix<double> &
    zone_stiffness_matrix(const unsigned int zone) const;
    const SparseMatrix<double> &
    zone_mass_matrix(const unsigned int zone) const;

    /** Young's modulus and density of each zone as currently set. */
    const std::vector<double> &
    zone_moduli() const;
    const std::vector<double> &
    zone_densities() const;

    /**
     * New zone moduli and densities (one value per zone, all finite and
     * positive). K and M are re-formed from the zone matrices when they are
     * next used, so that a caller who only reads zone_moduli() (a solver
     * that reuses a factorisation of a scaled stiffness) pays nothing.
     */
    void
    set_zone_materials(const std::vector<double> &moduli,
                       const std::vector<double> &densities);

    const SparseMatrix<double> &
    stiffness_matrix() const;
    const SparseMatrix<double> &
    mass_matrix() const;
    const SparsityPattern &
    sparsity_pattern() const;

    /**
     * Consistent nodal forces of all the component's edge loads at their
     * declared total force.
     */
    const Vector<double> &
    load_vector() const;
    /**
     * Per support with a prescribed displacement, per zone: the nodal
     * forces -K_z,fp u_p and K_z,pp u_p at unit modulus along the unit
     * displacement (see the top of this file), from which the loads of
     * prescribed displacements are formed. They come from the cell
     * matrices (assembled for them if not yet).
     */
    const std::vector<std::vector<Vector<double>>> &
    displacement_zone_loads() const;
    /**
     * Gives this component the forces of displacement_zone_loads() made
     * elsewhere (by the MPI rank that assembled the component), so that
     * its loads need no assembly here.
     */
    void
    set_displacement_zone_loads(
      const std::vector<std::vector<Vector<double>>> &loads);

    /**
     * The index of the component's weight among its loads
     * (EdgeLoad::is_weight), or -1 if the scene has no gravity.
     */
    int
    weight_load() const;
    /**
     * Per zone z: the weight's nodal forces at unit density and |g| = 1,
     * w_z = t int_z N^T d dx along the direction d of gravity (the DoFs
     * that supports and pins hold left out). Empty without gravity.
     */
    const std::vector<Vector<double>> &
    weight_zone_loads() const;
    /**
     * Per zone z: the resultant of w_z along each free motion R_j, t int_z
     * d . R_j dx, with the pinned DoFs' share that w_z leaves out (see
     * rigid_load()).
     */
    const std::vector<Vector<double>> &
    weight_zone_resultants() const;

    /** Nodal forces of load @p l for a total force of 1 N. */
    const Vector<double> &
    unit_load_vector(const unsigned int l) const;

    /**
     * The force at which the solvers keep the response to load @p l: its
     * declared total force, or 1 N if that is zero. A load at total force F
     * is then (F / reference) times the reference load, which is exactly
     * the declared load when F is the declared force.
     */
    double
    reference_load_force(const unsigned int l) const;

    /** reference_load_force(l) times unit_load_vector(l). */
    Vector<double>
    reference_load_vector(const unsigned int l) const;

    /**
     * The two DoFs (x, y) of the mesh vertex at @p p; throws if no vertex
     * lies within a relative distance 1e-10 of the component's size.
     */
    std::array<types::global_dof_index, 2>
    vertex_dofs(const Point<2> &p) const;

    /** Location of every DoF (for Q_p elements, the nodes). */
    const std::vector<Point<2>> &
    support_points() const;

    /** Direction of every DoF: 0 for u_x, 1 for u_y. */
    const std::vector<unsigned char> &
    dof_directions() const;

    /**
     * Assembles K and M again in one pass with each cell's own E and rho
     * (instead of summing zone matrices). Independent route for tests.
     */
    void
    assemble_directly(SparseMatrix<double> &K, SparseMatrix<double> &M) const;

    /**
     * The three rigid-body motions (x translation, y translation, rotation
     * about the component's centre), evaluated at the DoFs, ignoring clamps.
     */
    std::vector<Vector<double>>
    rigid_body_motions() const;

    /**
     * The rigid-body motion the clamps and supports leave free, in words
     * ("translation along (0, 1)", "rotation about (0.2, 0.01)"), or an
     * empty string if they hold all three. A static solve needs them held:
     * a body held by contact alone is not handled.
     */
    std::string
    free_rigid_motion() const;

    /**
     * The rigid-body motions the supports leave free, if the body was
     * pinned (constructed with its contact faces): one field each, of unit
     * size (a rotation of 1/size radians about the pole, size the bounding
     * box's diagonal), zero on the DoFs the supports hold. Empty for a body
     * its supports hold.
     */
    const std::vector<Vector<double>> &
    free_motions() const;
    /** Each free motion in words ("translation along (1, 0)", ...). */
    const std::vector<std::string> &
    free_motion_names() const;
    /**
     * The angle [rad] of each free motion per unit amplitude: 0 for a
     * translation (its amplitude is its displacement [m]), else its
     * rotation about the pole its name gives.
     */
    const std::vector<double> &
    free_motion_angles() const;
    /**
     * The amplitudes of the free motions that fit the displacement field
     * @p u best, in the least-squares sense over all DoFs: the rigid-body
     * part of the body's displacement (the solvers' own amplitudes are
     * those of the pins, whose choice is arbitrary).
     */
    Vector<double>
    rigid_part(const Vector<double> &u) const;
    /** The pinned DoFs, one per free motion. */
    const std::vector<types::global_dof_index> &
    pinned_dofs() const;
    /**
     * R^T f_l: the resultant of load @p l at its reference force along each
     * free motion. For the weight, the whole of it: the pinned DoFs' share
     * too, which the condensed load vector leaves out.
     */
    Vector<double>
    rigid_load(const unsigned int l) const;

  private:
    void
    pin_free_motions(const std::vector<std::string> &avoid);
    void
    make_mesh(const unsigned int n_refinements);
    void
    make_mesh_from_file();
    void
    add_displacement_loads(
      const unsigned int                          z,
      const FullMatrix<double>                   &cell_k,
      const std::vector<types::global_dof_index> &dofs) const;
    // The loads of prescribed displacements at the current zone moduli,
    // the weight at the current densities, and load_.
    void
    update_material_loads() const;
    // The weight's zone forces and their resultants along the free motions.
    void
    assemble_weight() const;
    /** DoFs, supports, and pins if @p contact_faces are given. */
    void
    setup_dofs(const std::vector<std::string> &contact_faces);
    // The sparsity pattern and the zone matrices, if not yet assembled.
    void
    ensure_matrices() const;
    // The loads, if not yet assembled (with the matrices first if a support
    // prescribes a displacement).
    void
    ensure_loads() const;
    void
    assemble_zone_matrices() const;
    void
    assemble_loads() const;
    void
    form_global_matrices() const;

    ComponentDescription description_;
    PlaneModel           plane_model_;

    Triangulation<2>            triangulation_;
    std::unique_ptr<Mapping<2>> mapping_;
    FESystem<2>                 fe_;
    DoFHandler<2>               dof_handler_;
    AffineConstraints<double>   constraints_;
    std::vector<Point<2>>       support_points_;
    std::vector<unsigned char>  dof_directions_;

    std::vector<double> zone_moduli_;
    std::vector<double> zone_densities_;
    // Assembled at construction or on first use (see the top of this file).
    mutable bool                              assembled_       = false;
    mutable bool                              loads_assembled_ = false;
    mutable SparsityPattern                   sparsity_pattern_;
    mutable std::vector<SparseMatrix<double>> zone_stiffness_;
    mutable std::vector<SparseMatrix<double>> zone_mass_;
    // Formed from the zone matrices on demand (see set_zone_materials()).
    mutable SparseMatrix<double>        stiffness_;
    mutable SparseMatrix<double>        mass_;
    mutable bool                        matrices_current_ = false;
    mutable std::vector<Vector<double>> unit_loads_;
    mutable Vector<double>              load_;
    // Per support with a non-zero displacement: the field of unit
    // magnitude along it on the DoFs it holds, and per zone the nodal
    // forces -K_z,fp u_p (free rows) and K_z,pp u_p (held rows) it needs.
    std::vector<Vector<double>>                      displacement_fields_;
    mutable std::vector<std::vector<Vector<double>>> displacement_zone_loads_;
    // Whether they are formed (by the assembly, or given).
    mutable bool      displacement_loads_formed_ = false;
    std::vector<bool> prescribed_;
    // The weight (see weight_zone_loads()), assembled with the loads.
    int                                 weight_load_ = -1;
    mutable std::vector<Vector<double>> weight_zone_loads_;
    mutable std::vector<Vector<double>> weight_zone_resultants_;
    // A pinned body's free motions, their names and its pins.
    std::vector<Vector<double>>          free_motions_;
    std::vector<std::string>             free_motion_names_;
    std::vector<double>                  free_motion_angles_;
    std::vector<types::global_dof_index> pinned_dofs_;
  };
} // namespace FuzzyContact

#endif
