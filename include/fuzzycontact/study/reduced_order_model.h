// The reduced model of a study: every component reduced to its modes with
// or without static correction modes (reduction/reduced_model.h), the
// reduced contact problem solved by a ContactSolver, and set from a
// SceneState like the full-order model (contact_model.h).
//
// Everything that does not depend on the state is computed once: the
// reduced matrices of every component and the reduced contact flexibility,
// and for components whose zone moduli vary, a parameter-independent
// reanalysis. Per state, component by component:
//  - zone moduli that are all the nominal ones times one factor s (a
//    modulus of a whole component, or no change) scale its stiffness
//    exactly: the modes stay, and so does its part of the contact
//    flexibility, divided by s;
//  - densities do not change the static stiffness (nor the span of the
//    modes it was reduced with); with gravity, a body's weight follows
//    them exactly: its response is carried whole, per zone K^{-1} w_z
//    (ReducedComponentMatrices::weight_gaps), times rho_z / s;
//  - zone moduli that change the shape of the stiffness (those of single
//    zones) are re-analysed. By default ("krylov") the static correction
//    itself is: the stiffness is projected onto the nominal static
//    correction, its Krylov vectors (K0^{-1} K_k)^j K0^{-1} E compressed
//    level by level, and the modes and their HPTP terms if the study
//    computes modes (reduction/zone_static_correction.h); the number of
//    vectors is chosen offline by a tolerance on the contact flexibility
//    at the corners of the quantities' ranges, checked against exact
//    factorisations there, and a state costs O(rows k) with one zone
//    parameter (a diagonalised pencil). The paper's way goes through the
//    parameter-independent HPTP (modes T Y(p), the order chosen offline
//    from a tolerance at the corners), and the static correction then
//    enters one of two ways: "residual flexibility" keeps the flexibility
//    of the static correction modes at its nominal value and adds it to
//    that of the re-analysed modes (MacNeal), O(rows^2 n_modes) per state,
//    but wrong by the change of the correction's flexibility; "galerkin"
//    projects the stiffness onto the basis [T Y(p), Psi] (zone projections
//    precomputed offline), more accurate but a dense factorisation of the
//    whole reduced stiffness per state;
//  - loads scale their load terms, friction coefficients and gaps enter the
//    small contact problem directly.
// A state that changes a component in a way the model was not built for
// (zone moduli of a component without reanalysis) is refused, and so is a
// reanalysis of a body with a weight (SceneQuantity::parse() refuses the
// zone moduli of a scene with gravity: the weight's exact response would
// change with them).
//
// With a weight the reduced answer stays exact: the weight's part of the
// displacement is its exact static response, and the contact forces' part
// V K_r^{-1} C_r^T p is exact by the static correction.

#ifndef fuzzycontact_study_reduced_order_model_h
#define fuzzycontact_study_reduced_order_model_h

#include <fuzzycontact/contact/contact_solver.h>
#include <fuzzycontact/contact/contact_workspace.h>
#include <fuzzycontact/fuzzy/fuzzy_number.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reduction/reduced_model.h>
#include <fuzzycontact/reduction/zone_static_correction.h>
#include <fuzzycontact/scene/scene_quantity.h>
#include <fuzzycontact/study/component_modes.h>
#include <fuzzycontact/study/contact_model.h>
#include <fuzzycontact/study/contact_scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /** A scene quantity a study varies, and the range of its values. */
  struct VaryingQuantity
  {
    SceneQuantity quantity;
    Interval      range;
  };

  struct ReducedModelSettings
  {
    /** Static correction modes in the reduced model (else modes only). */
    bool static_correction = true;
    /** How the static correction enters for zone parameters (see above). */
    enum class ZoneCorrection
    {
      residual_flexibility,
      galerkin,
      krylov
    };
    ZoneCorrection zone_correction = ZoneCorrection::krylov;
    /** The Krylov static correction's tolerance and levels (krylov). */
    ZoneCorrectionSettings krylov;
    /**
     * Static correction modes whose Gram eigenvalue is below this fraction
     * of the largest are linearly dependent and dropped.
     */
    double             rank_tolerance = 1e-12;
    ReanalysisSettings reanalysis;
  };

  class ReducedOrderModel : public ContactModel
  {
  public:
    /**
     * Reduces every component of @p bodies with its @p modes (copied) and,
     * if asked, static correction modes for its contact DoFs and loads, and
     * builds the reanalysis of the components whose zone materials the
     * @p varying quantities change. @p observed: the DoFs whose
     * displacements solve() reports. Stages are timed in @p timer if given.
     * The components' current materials are the nominal ones (those of
     * @p bodies' scene).
     */
    ReducedOrderModel(const ContactScene                 &bodies,
                      const std::vector<ModalBasis>      &modes,
                      const ObservedDofs                 &observed,
                      const std::vector<VaryingQuantity> &varying,
                      const ReducedModelSettings         &settings,
                      TimerOutput                        *timer = nullptr,
                      const MPI_Comm                      comm = MPI_COMM_SELF);
    ~ReducedOrderModel() override;

    /**
     * The rank of @p comm that builds each of the @p n_components
     * components (its basis, reduced matrices and blocks of the reduced
     * contact problem, sent to the other ranks): component c on rank
     * c mod n; but if the @p varying quantities make some components
     * re-analysed (zone parameters), those on the first rank, which alone
     * can then solve (it holds their reanalyses), and the others on the
     * other ranks in turn. All 0 with one rank.
     */
    static std::vector<unsigned int>
    builders(const unsigned int                  n_components,
             const std::vector<VaryingQuantity> &varying,
             const MPI_Comm                      comm);

    /**
     * Whether this rank can solve: it holds the reanalysis of every
     * re-analysed component (always with one rank, or without re-analysed
     * components). set_state() and solve() are refused on the others.
     */
    bool
    solves_here() const;

    /** "reduced" and the solver's name, e.g. "reduced (fl2c)". */
    std::string
    name() const override;
    void
    set_state(const SceneState &state) override;
    /** With the solver of set_contact_solver() (default: FL2C). */
    ContactSolution
    solve() override;
    /**
     * With @p solver; @p what names the solve in messages and in the
     * solution (default: the solver's name).
     */
    ContactSolution
    solve(const ContactSolver &solver, const std::string &what = "");

    /** The solver of solve(), and the name of its solves (see above). */
    void
    set_contact_solver(std::unique_ptr<ContactSolver> solver,
                       const std::string             &what = "");
    /** Proportional load steps up to the state's loads (default 1). */
    void
    set_n_load_steps(const unsigned int n_load_steps);

    /** The reduced contact problem at the current state. */
    const ContactProblem &
    problem() const;

    /**
     * What the solves carry from one to the next (contact_workspace.h): the
     * factor of the closed set, always; the start of each load step, if
     * set here (the states of a neighbouring point), and the converged
     * states of the last solve.
     */
    ContactWorkspace &
    workspace();

    unsigned int
    n_modes(const unsigned int c) const;
    unsigned int
    n_corrections(const unsigned int c) const;
    /** HPTP order of each component (0: exact scaling, no reanalysis). */
    std::vector<unsigned int>
    reanalysis_orders() const;
    /** A line per component: DoFs, modes, corrections, treatment. */
    std::string
    describe() const;

    /**
     * Makes the model richer where it was found wrong (the feedback of the
     * proofs of a fuzzy study's bounds): @p fields[c] holds displacement
     * fields of component c (exact solutions at the points where the
     * reduced answer missed), which join its basis, K-orthogonalised; a
     * component whose zone moduli are re-analysed by HPTP is first given
     * the Krylov static correction (its residual flexibility or Galerkin
     * form gives way to it). Vectors already in a basis's span are
     * dropped. Returns how many were added over all components.
     * Collective over the constructor's communicator; @p fields need only
     * be given on the rank that built each component.
     */
    unsigned int
    add_snapshots(const std::vector<std::vector<Vector<double>>> &fields,
                  TimerOutput *timer = nullptr);

    /**
     * The Krylov static correction's check of every component that has
     * one (else nullptr), on the rank that built it.
     */
    const ZoneCorrectionCheck *
    zone_correction_check(const unsigned int c) const;

    /**
     * The displacement fields u_c = V_c q_c of @p solution (a solution of
     * this model at its current state); not for re-analysed components.
     */
    std::vector<Vector<double>>
    displacement_fields(const ContactSolution &solution) const;

  private:
    struct ComponentModel;

    void
    build_reanalysis(ComponentModel    &m,
                     const unsigned int c,
                     TimerOutput       *timer);
    ReducedComponentMatrices
    reanalysed_matrices(const ComponentModel &m, const SceneState &state) const;
    void
    build_zone_correction(ComponentModel    &m,
                          const unsigned int c,
                          TimerOutput       *timer);
    std::vector<double>
    zone_values(const ComponentModel &m, const SceneState &state) const;
    void
    set_inert_part(const unsigned int c);
    void
    build_component(ComponentModel                             &m,
                    const unsigned int                          c,
                    const std::vector<types::global_dof_index> &observed,
                    TimerOutput                                *timer);
    static void
    exchange_component(ComponentModel    &m,
                       const unsigned int owner,
                       const MPI_Comm     comm);

    const ContactScene                          &bodies;
    ReducedModelSettings                         settings;
    std::vector<std::unique_ptr<ComponentModel>> models;
    std::unique_ptr<ReducedContactModel>         reduced;
    std::unique_ptr<ContactSolver>               solver;
    ContactWorkspace                             workspace_;
    std::string                                  label;
    unsigned int                                 n_load_steps = 1;
    // The gap offsets and friction coefficients (per pair) the contact
    // problem's initial gaps and friction coefficients were last set from
    // (set_state() sets them anew only when they change).
    std::vector<double> gap_offsets, friction_coefficients;
    bool                contact_conditions_set = false;
    // The quantities varied and their ranges, the communicator and the
    // rank that built each component (for add_snapshots()).
    std::vector<VaryingQuantity> varying;
    MPI_Comm                     comm;
    std::vector<unsigned int>    owner;
  };
} // namespace FuzzyContact

#endif
