// The report of a contact study (step-3): for every scene, friction
// coefficient and solver the chosen outputs, their errors against the
// full-order answer, iterations, residuals and times; the offline cost of
// the reduced models; the deformed bodies with the contact pressure as VTU
// files; and the paper's Table 3 beside the results.
//
// results.json keeps the keys step-3 has always written (per solver: name,
// Fn, Ft, slave_ux, slave_uy, master_displacements, iterations, time_s,
// residual, closed_nodes, Fn_error, Ft_error, slave_error) and adds the
// chosen outputs under "outputs" and their errors under "output_errors",
// keyed by the outputs' names.

#ifndef fuzzycontact_output_contact_report_h
#define fuzzycontact_output_contact_report_h

#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_state.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/observations.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <nlohmann/json.hpp>

#include <functional>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /** One solver's answer to one case. */
  struct SolverRun
  {
    ContactSolution solution;
    /** The values of every observation (shown or not). */
    std::vector<double> outputs;
    /** Displacement fields for the VTU files (empty if not computed). */
    std::vector<Vector<double>> fields;
    /**
     * Why the solver failed (empty if it did not): the reports then give
     * its row as "failed: <failure>" and leave it out of every comparison.
     */
    std::string failure;

    /**
     * Runs @p solve on a new SolverRun; an exception becomes the run's
     * failure (solver named @p name) instead of ending the program.
     */
    static SolverRun
    attempt(const std::string                      &name,
            const std::function<void(SolverRun &)> &solve);
  };

  /** One scene, plane model and friction coefficient, all solvers. */
  struct ContactCase
  {
    /** The case of @p bodies at @p state (total load @p load), no runs. */
    ContactCase(const ContactScene &bodies,
                const SceneState   &state,
                const double        load);

    std::string scene;
    PlaneModel  plane_model;
    double      load;
    /**
     * "F = 50000 N along (0, -1)"; with several loads each force with its
     * direction and their resultant vector, each pressure; or the
     * prescribed displacements and the weight (and the forces if any).
     */
    std::string loading;
    /** The Young's modulus of every zone: zone_moduli[component][zone]
     * (the state's: the VTU files' stresses use them). */
    std::vector<std::vector<double>> zone_moduli;
    /** The friction coefficient of every contact pair, and the pairs. */
    std::vector<double>                 mu;
    std::vector<ContactPairDescription> pairs;
    std::vector<unsigned int>           n_dofs;
    unsigned int                        n_nodes;
    /**
     * The free rigid-body motions of the bodies held by contact alone
     * ("Block: translation along (1, 0)"), whose amplitudes the solvers
     * find with the contact forces.
     */
    std::vector<std::string> free_motions;
    /** The bodies (for the rigid-body part of a displacement field). */
    const ContactScene *bodies = nullptr;
    /** runs[0] is the full-order reference. */
    std::vector<SolverRun> runs;
    double                 full_order_warm_time = 0;
    std::string            beam_theory;

    /** True if every pair has the same friction coefficient. */
    bool
    uniform_friction() const;
    /** "0.3" if every pair has it, else "lower 0, upper 0.5". */
    std::string
    friction_label() const;
    /** The start of the case's file names: "contact-<label>-mu<mu>"
     * (spaces as underscores, no commas). */
    std::string
    file_stem(const std::string &label) const;
  };

  namespace ContactReport
  {
    /**
     * The outputs step-3 observes: @p chosen, then those the report always
     * needs that are not among them (the slave node and its two master
     * nodes of the paper's Table 3, and the total forces).
     */
    std::vector<std::string>
    observed_outputs(const std::vector<std::string> &chosen);

    /** step-3's default outputs: the paper's Table 3 and F_t. */
    std::string
    default_outputs();

    /**
     * The table of a case: the first @p n_shown observations of
     * @p observations for every solver, then their errors against the
     * full-order answer.
     */
    std::string
    case_table(const ContactCase  &c,
               const Observations &observations,
               const unsigned int  n_shown);

    /** The case's entry of results.json. */
    nlohmann::json
    case_json(const ContactCase  &c,
              const Observations &observations,
              const unsigned int  n_shown);

    /**
     * The offline line of a scene: its components, modes and correction
     * modes, and the stage times: assembly and modes from @p scene_timer
     * (ContactScene, component_modes()), W of the modal model from
     * @p modal_timer, the static correction and W of @p corrected from
     * @p corrected_timer (the timers of the ReducedOrderModel
     * constructors). @p json receives the same.
     */
    std::string
    offline(const std::string             &label,
            const ContactScene            &bodies,
            const std::vector<ModalBasis> &modes,
            const ReducedOrderModel       &corrected,
            const TimerOutput             &scene_timer,
            const TimerOutput             &modal_timer,
            const TimerOutput             &corrected_timer,
            nlohmann::json                &json);

    /**
     * Queues one VTU file per component: the displacement field of every
     * solver that computed one, the contact forces and the contact
     * pressure and shear of the full-order answer.
     */
    void
    add_vtu(OutputFiles        &output,
            const ContactCase  &c,
            const ContactScene &bodies,
            const std::string  &label);

    /**
     * The paper's Table 3 (Massa et al. 2013) beside the full-order and
     * FL2C answers of @p cases (the paper scene in plane strain);
     * @p json receives "paper_comparison".
     */
    std::string
    paper_comparison(const std::vector<ContactCase> &cases,
                     const Observations             &observations,
                     const unsigned int              n_shown,
                     nlohmann::json                 &json);
  } // namespace ContactReport
} // namespace FuzzyContact

#endif
