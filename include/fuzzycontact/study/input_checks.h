// The checks of a run's input that need more than one stage: upper limits
// of the solver settings that drive the cost of a run, whether the modes
// asked for fit the mesh, the memory a scene's models need, and the
// warnings of suspicious but valid input. The step programs call these
// after reading their parameter files and before computing anything.

#ifndef fuzzycontact_study_input_checks_h
#define fuzzycontact_study_input_checks_h

#include <fuzzycontact/base/limits.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_limits.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  namespace InputChecks
  {
    /** Upper limits of the settings (the lower ones are checked on parse). */
    constexpr long   max_modes              = 200;
    constexpr double max_modal_tolerance    = 1e-2;
    constexpr double max_shift              = 1e16;
    constexpr double max_cutoff_frequency   = 1e7;
    constexpr long   max_fl2c_iterations    = 1000000;
    constexpr long   max_exact_iterations   = 10000;
    constexpr long   max_optimisation_steps = 10000;
    constexpr double max_solver_tolerance   = 1e-1;
    constexpr double min_solver_tolerance   = 1e-14;

    /** Throws, naming the key, if a value is beyond its upper limit. */
    void
    check(const ModalParameters &modal);
    void
    check(const FL2CParameters &fl2c);
    void
    check(const ActiveSetParameters &exact);
    void
    check(const OptimisationSettings &optimisation);

    /**
     * Throws if a component of @p scene after @p refinements has too few
     * free DoFs for @p n_modes modes (ARPACK's Lanczos basis needs more
     * than twice as many), naming the component and the keys to change.
     */
    void
    check_modes_fit(const Scene       &scene,
                    const unsigned int refinements,
                    const unsigned int n_modes);

    /**
     * The checks of a scene used with @p refinements: memory estimate
     * (SceneLimits::check_memory, naming @p key) and the modes. Returns
     * the scene's warnings (SceneLimits::warnings), each starting with
     * "warning: " and naming @p scene_file.
     */
    std::vector<std::string>
    check_scene(const Scene       &scene,
                const std::string &scene_file,
                const unsigned int refinements,
                const bool         static_correction,
                const unsigned int n_modes,
                const std::string &key = "mesh refinements");

    /** The three checks above for a contact study's solvers. */
    void
    check(const ModalParameters     &modal,
          const ActiveSetParameters &exact,
          const FL2CParameters      &fl2c);

    /**
     * The fuzzy parameters of a study against its scene and contact
     * solver, before anything is computed (the ends of every support were
     * already checked one by one when they were read):
     *  - a fuzzy gap whose support goes below zero is an initial
     *    penetration, refused as a negative gap of the scene is (within
     *    @p penetration_tolerance times the master face's length, the
     *    round-off the contact interface accepts), naming the key;
     *  (a friction coefficient whose support leaves [0, 10] is refused,
     *    naming the key, where the support is read:
     *    SceneLimits::friction_coefficient through FuzzyParameterSet);
     *  - FL2C with calibration = prm (absolute transition points) and
     *    coarse correction = none, the paper's regulators alone, is
     *    refused when a fuzzy parameter changes the contact flexibility or
     *    the gaps (a modulus, a load or a gap): the points' gain must stay
     *    below 2 / W_nn at every point of the box for the sweeps to
     *    converge, which nothing checks before the model is built, and
     *    their gap scale is fixed while the penetrations change with the
     *    parameters. Automatic calibration rescales both at every point;
     *    the coarse correction converges whatever the points.
     */
    void
    check(const FuzzyParameterSet &fuzzy,
          const Scene             &scene,
          const std::string       &contact_solver,
          const FL2CParameters    &fl2c,
          const double             penetration_tolerance = 1e-8);

    /**
     * The warning of a study whose fuzzy parameters are all crisp (their
     * supports have no width: every membership function is then a single
     * value), or an empty string.
     */
    std::string
    all_crisp_warning(const FuzzyParameterSet &fuzzy);

    /**
     * Reads the scene files of a contact study with the same settings:
     * Scene::read(), at least one contact pair, and check_scene(), whose
     * warnings it collects.
     */
    struct SceneReader
    {
      unsigned int             refinements;
      bool                     static_correction;
      unsigned int             n_modes;
      std::vector<std::string> warnings = {};

      Scene
      operator()(const std::string &file);
    };
  } // namespace InputChecks
} // namespace FuzzyContact

#endif
