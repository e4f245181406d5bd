// The full-order reference: the frictional contact of the components' full
// finite element systems, solved exactly. It plays the part of the
// commercial code of the 2013 paper, and it is the exact solver of the
// Extension Principle in the fuzzy study, so each solve is made as cheap
// as it can be without giving up exactness.
//
// With Lagrange multipliers p (contact forces) the saddle-point system is
//
//     K_c u_c = lambda f_c + C_c^T p   for every component c,
//     g = g0 + sum_c C_c u_c,          Signorini + Coulomb on (g, p),
//
// where f_c = sum_l F_l f_l is the component's load, each load l a total
// force F_l times its consistent nodal forces. It is solved by block
// elimination: every K_c is factorised once by a sparse Cholesky (CHOLMOD,
// SparseCholesky; K_c is symmetric positive definite, a body held by
// contact alone being pinned, fe/component.h), or that factorisation is
// shared with whoever already made it
// (set_factorisation_source(): the study's reduced models are built from
// the same one), and the primal-dual active set method
// (ActiveSetSolver) works on the Schur complement W = sum_c C_c K_c^{-1}
// C_c^T, whose columns are computed only when the active set first needs
// them (one back-substitution per component touched) and kept. The
// displacements then follow from one more back-substitution per component,
// and the complementarity residual is evaluated on the gaps g0 + C u of
// those displacements, not on W.
//
// What is reused, and when (all exact):
//  - the factorisations, columns of W and load responses K_c^{-1} f_l,
//    across active set iterations, load steps and solves, while the
//    stiffness does not change;
//  - the same, after set_zone_materials() on a component has scaled all its
//    zone moduli by one factor s (K_c = s K_c,ref, so K_c^{-1} =
//    K_c,ref^{-1} / s): a change of E of a whole body costs no new
//    factorisation;
//  - the response to a body's weight (EdgeLoad::is_weight) is kept per
//    zone, K_c,ref^{-1} w_z at unit density, and combined with the current
//    densities: a change of density costs no back-substitution either;
//  - the statuses of the previous solve, as the start of the next one, if
//    warm starts are switched on (the answer does not depend on the start).
// Any other change of a component's moduli triggers a new factorisation.
//
// The stiffness is read from the components at each solve; the loads, the
// initial gaps and the friction coefficients are this object's own (the
// scene's values until they are set), so that a study sets all of them from
// one SceneState (study/contact_models.h).

#ifndef fuzzycontact_contact_full_order_contact_h
#define fuzzycontact_contact_full_order_contact_h

#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/base/stiffness_solver.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/fe/component.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace FuzzyContact
{
  class FullOrderContact
  {
  public:
    /**
     * @p components: one per scene component, in scene order (the objects
     * must outlive this one; their moduli may change between solves).
     */
    FullOrderContact(
      const std::vector<const Component *> &components,
      const ContactInterface               &interface,
      const ActiveSetParameters            &parameters = ActiveSetParameters());

    /**
     * Where the factorisation of a component's stiffness comes from when
     * one is needed: by default this object makes it; @p source(c) may
     * instead return one made elsewhere (ContactScene's, which the reduced
     * models were built from), which must be that of component c's
     * current stiffness. A shared factorisation is not counted by
     * n_factorizations().
     *
     * (Hook for the proofs of a zone study, study/full_order_model.h: the
     * source may return any StiffnessSolver of the current stiffness, e.g.
     * conjugate gradients preconditioned by the nominal factorisation,
     * base/factor_preconditioned_cg.h, instead of a new factorisation.)
     */
    void
    set_factorisation_source(
      std::function<std::shared_ptr<const StiffnessSolver>(unsigned int)>
        source);

    /**
     * The total force of every load [N], load_forces[c][l] for load l of
     * component c (default: the scene's declared forces).
     */
    void
    set_load_forces(const std::vector<std::vector<double>> &load_forces);
    /** Multiplies all loads (default 1); the load steps go up to it. */
    void
    set_load_factor(const double load_factor);
    /**
     * Initial gaps (2 rows per slave node, tangential rows 0) and the
     * friction coefficient of every slave node (default: the interface's,
     * i.e. the scene's).
     */
    void
    set_contact_conditions(const Vector<double>      &initial_gaps,
                           const std::vector<double> &friction_coefficients);
    /** Proportional load steps (default 1). */
    void
    set_n_load_steps(const unsigned int n_load_steps);
    /**
     * The load history (Scene::load_stages): each stage ramps its loads in
     * its own steps (set_n_load_steps() is then not used); empty (the
     * default): one proportional stage.
     */
    void
    set_load_stages(const std::vector<LoadStage> &stages);
    /** Start each solve from the statuses of the previous one. */
    void
    set_warm_start(const bool warm_start);

    /**
     * The DoFs whose displacements solve() returns in
     * ContactSolution::observed (default: none).
     */
    void
    observe(const ObservedDofs &dofs);

    /**
     * With @p fields = false, solve() does not compute the displacement
     * fields: the forces come from the active set solution on W (whose
     * columns carry the accuracy of a plain back-substitution, about 1e-9
     * relative on fine meshes), the residual is measured on W's gaps, and
     * the observed displacements are combined from the load responses and
     * the columns kept at those DoFs. No back-substitution is needed once
     * the columns exist, which makes repeated solves (the Extension
     * Principle's thousands of samples) cheap. Default: true.
     */
    void
    set_displacement_fields(const bool fields);

    /**
     * Solves the contact problem for the current stiffness, loads, gaps and
     * friction coefficients. The observed displacements and the full
     * displacement fields go into the solution; its time covers everything
     * the solve had to do (factorisations, columns of W, active set
     * iterations, final displacements).
     */
    ContactSolution
    solve();

    /**
     * The whole contact flexibility W (every column computed); for tests
     * and for comparison with reduced models.
     */
    FullMatrix<double>
    flexibility();
    /**
     * g_load = C K^{-1} f at load factor 1: of every load, or of the loads
     * of @p stage only.
     */
    Vector<double>
    load_gaps(const LoadStage *stage = nullptr);

    /** How many sparse LU factorisations and back-substitutions so far. */
    unsigned int
    n_factorizations() const;
    unsigned int
    n_back_substitutions() const;
    /** Number of columns of W computed so far. */
    unsigned int
    n_columns() const;

  private:
    class Flexibility;

    /** Factorises what changed. */
    void
    update_factorizations();
    /**
     * The weight's response at component c's current densities, from its
     * zone responses (if they changed since).
     */
    void
    update_weight_response(const unsigned int c);
    /** Makes W's column j available. */
    void
    prepare_column(const unsigned int j);
    double
    entry(const unsigned int i, const unsigned int j) const;
    /** K_c^{-1} rhs with one step of extended-precision refinement. */
    Vector<double>
    accurate_solve(const unsigned int c, const Vector<double> &rhs);
    /** The load of component c at load factor 1. */
    Vector<double>
    load_vector(const unsigned int c) const;
    /**
     * K_c^{-1} f_c at load factor 1 and the current stiffness, from the
     * kept load responses (of the loads of @p stage only, if given).
     */
    Vector<double>
    load_response(const unsigned int c, const LoadStage *stage = nullptr) const;
    /**
     * The factor of load l of component c's kept response at the current
     * load force and stiffness scale.
     */
    double
    load_factor(const unsigned int c, const unsigned int l) const;
    /** The load history as the gaps see it (one stage per load stage). */
    std::vector<GapLoadStage>
    gap_load_stages();
    /**
     * The resultant of the loads (of @p stage only, if given) at load
     * factor 1 along the free motions of the bodies held by contact alone.
     */
    Vector<double>
    rigid_load(const LoadStage *stage = nullptr) const;
    /** u += R_c a: component c's free motions at their amplitudes in a. */
    void
    add_free_motions(const unsigned int    c,
                     const Vector<double> &a,
                     Vector<double>       &u) const;
    /** The displacement of DoF @p dof of component @p c for forces @p p. */
    double
    observed_displacement(const unsigned int            c,
                          const unsigned int            position,
                          const types::global_dof_index dof,
                          const Vector<double>         &p) const;
    /** Solution without fields (see set_displacement_fields()). */
    ContactSolution
    outputs_only(const ContactState &state);
    /** Solution with refined displacement fields. */
    ContactSolution
    with_fields(const ContactState   &state,
                const Vector<double> &g_previous,
                FlexibilityOperator  &W);

    std::vector<const Component *> components;
    const ContactInterface        &interface;
    ActiveSetSolver                solver;
    double                         load_factor_         = 1;
    unsigned int                   n_load_steps_        = 1;
    bool                           warm_start_          = false;
    bool                           displacement_fields_ = true;
    std::vector<LoadStage>         load_stages_;
    // Loads per component and load, and the reference forces of the kept
    // load responses (the declared force, or 1 N for a declared zero).
    std::vector<std::vector<double>> load_forces_, reference_forces_;
    Vector<double>                   initial_gaps_;
    std::vector<double>              friction_;
    ObservedDofs                     observed_dofs;
    // The free motions of the bodies held by contact alone (G = C_c R_c,
    // contact_problem.h), the first of each component's among them, and
    // the resultant of each load l of component c along them, at its
    // reference force.
    RigidMotions                             rigid_;
    std::vector<unsigned int>                first_motion_;
    std::vector<std::vector<Vector<double>>> rigid_loads_;

    // Per component: the factorisation of K_ref, the moduli it was made
    // with, the current scale s (K = s K_ref), K_ref^{-1} f_l at the
    // reference forces, and the columns C_c K_ref^{-1} C_c^T e_j computed so
    // far.
    struct Factorized
    {
      std::shared_ptr<const StiffnessSolver> inverse; // (hook: any solver)
      std::vector<double>                    moduli;
      double                                 scale = 1;
      std::vector<Vector<double>>            load_responses;
      // The weight's: K_ref^{-1} w_z per zone at unit density and the
      // reference force, and the densities its load response is at.
      std::vector<Vector<double>>                  weight_responses;
      std::vector<double>                          densities;
      std::vector<std::unique_ptr<Vector<double>>> columns;
      // K_c,ref^{-1} C_c^T e_j at the observed DoFs, per column j.
      std::vector<std::vector<double>> observed_columns;
    };
    std::vector<Factorized> factorized;
    // Columns of W = sum_c (column of c) / s_c at the current scales.
    std::vector<std::unique_ptr<Vector<double>>> columns;

    std::function<std::shared_ptr<const StiffnessSolver>(unsigned int)>
                                factorisation_source;
    std::optional<ContactState> last_state;
    unsigned int                factorizations     = 0;
    unsigned int                back_substitutions = 0;
  };
} // namespace FuzzyContact

#endif
