// The bodies of a study, built once from a scene description: one Component
// (mesh, DoFs, zone matrices, loads) per scene component and the contact
// interface of all its contact pairs. Every program, test and benchmark
// builds its bodies here, so a scene means the same everywhere.
//
// The components' zone materials are the one part of a scene's state that
// lives in the bodies (their stiffness and mass matrices depend on it);
// set_materials() sets them from a SceneState. Loads, friction coefficients
// and gaps are applied by the models (contact_model.h).

#ifndef fuzzycontact_study_contact_scene_h
#define fuzzycontact_study_contact_scene_h

#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/small_sliding.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_state.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <memory>
#include <vector>

namespace FuzzyContact
{
  /**
   * The keys of the contact formulation a step file sets: "penetration
   * tolerance" (initial penetration accepted as round-off, relative to the
   * master face length) and "sliding angle limit"
   * (contact/small_sliding.h).
   */
  struct ContactFormulation
  {
    double penetration_tolerance = 1e-8;
    double sliding_limit         = default_sliding_limit;

    /** Declares both keys (step-3). */
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
    /** "sliding angle limit" alone (step-4, whose penetration tolerance is
     * fixed). */
    static void
    declare_sliding_limit(ParameterHandler &prm);
    static double
    parse_sliding_limit(ParameterHandler &prm);
  };

  class ContactScene
  {
  public:
    /**
     * Meshes every component of @p scene (refined globally
     * @p mesh_refinements times), assembles it, and builds the contact
     * interface (initial penetration beyond @p penetration_tolerance times
     * the master face length is refused). Stages are timed in @p timer if
     * given ("mesh and DoFs", "assembly", "contact interface").
     *
     * @p assemble: which components to assemble now (empty: all); the
     * others get their mesh and DoFs only, and are assembled where their
     * matrices or loads are first needed (an MPI rank that does not build
     * a component's reduced model needs its geometry only).
     */
    ContactScene(const Scene             &scene,
                 const unsigned int       mesh_refinements,
                 const double             penetration_tolerance = 1e-8,
                 TimerOutput             *timer                 = nullptr,
                 const std::vector<bool> &assemble              = {});

    const Scene &
    scene() const;
    unsigned int
    n_components() const;
    const Component &
    component(const unsigned int c) const;
    /** The components in scene order (for the solvers). */
    const std::vector<const Component *> &
    components() const;
    const ContactInterface &
    interface() const;
    /**
     * The limit of small sliding (contact/small_sliding.h) [degrees]: the
     * largest turn of the master normal along a slide; the full-order and
     * reduced models refuse an answer beyond it (ExcBeyondSmallSliding).
     * Default default_sliding_limit.
     */
    void
    set_sliding_limit(const double limit);
    double
    sliding_limit() const;
    /** DoFs of each component. */
    std::vector<unsigned int>
    n_dofs() const;

    /**
     * Sets every component's zone moduli and densities to those of
     * @p state (a state of scene()); components whose materials do not
     * change are left alone.
     */
    void
    set_materials(const SceneState &state);

    /**
     * The DoFs of component @p c on which its reduced model lives: its
     * contact DoFs and the DoFs its loads act on (sorted), its weight's
     * left out (it acts on every DoF; its response is carried whole).
     */
    std::vector<types::global_dof_index>
    boundary_dofs(const unsigned int c) const;

    /**
     * The sparse Cholesky factorisation of component @p c's stiffness at
     * its current materials, with boundary_dofs(c) ordered last. It is made
     * on first use ("stiffness factorisation (CHOLMOD)" in @p timer) and
     * kept until set_materials() changes the component; its holders keep
     * theirs (a change of the densities alone keeps it: the stiffness does
     * not depend on them). The modes, the static correction and the load
     * responses of a reduced model all use it.
     */
    std::shared_ptr<const SparseCholesky>
    stiffness_factorisation(const unsigned int c,
                            TimerOutput       *timer = nullptr) const;

    /**
     * Whether component @p c's stiffness is factorised at its current
     * materials (made here or set by set_stiffness_factorisation()).
     */
    bool
    has_stiffness_factorisation(const unsigned int c) const;

    /**
     * Gives component @p c the factorisation @p factorisation of its
     * stiffness at its current materials, made elsewhere (by another MPI
     * rank, see share_stiffness_factorisations()), instead of making it.
     */
    void
    set_stiffness_factorisation(
      const unsigned int                    c,
      std::shared_ptr<const SparseCholesky> factorisation);

    /**
     * Every component's stiffness factorisation at the scene's materials,
     * made on rank @p owner[c] of @p comm (and there only, if not made
     * yet), on every rank: the other ranks receive a copy of the factor
     * (SparseCholesky::broadcast()) instead of factorising the stiffness
     * again. So are the forces of prescribed displacements
     * (Component::displacement_zone_loads()), which come from the
     * stiffness: the other ranks need not assemble the component for its
     * loads. The components are set to the scene's materials first.
     * Collective.
     */
    void
    share_stiffness_factorisations(const std::vector<unsigned int> &owner,
                                   const MPI_Comm                   comm,
                                   TimerOutput *timer = nullptr);

    /**
     * How many times component @p c's stiffness was factorised here (not
     * counting factorisations set from elsewhere).
     */
    unsigned int
    n_factorisations(const unsigned int c) const;

  private:
    Scene                                   scene_;
    std::vector<std::unique_ptr<Component>> owned;
    std::vector<const Component *>          components_;
    std::unique_ptr<ContactInterface>       interface_;
    double sliding_limit_ = default_sliding_limit;
    mutable std::vector<std::shared_ptr<const SparseCholesky>> factorisations;
    mutable std::vector<unsigned int>                          n_factorised;
  };
} // namespace FuzzyContact

#endif
