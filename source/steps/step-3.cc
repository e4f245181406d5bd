// step-3: the static frictional contact of two beams, solved four ways, so
// that a user sees what the speed of the reduced solvers costs in accuracy.
//
//  - full_order:      both components' full finite element systems with
//                     Lagrange multipliers, solved exactly (primal-dual
//                     active set on the Schur complement, UMFPACK);
//  - reduced_exact:   the same complementarity problem on the reduced
//                     model with static correction, solved exactly;
//  - fl2c_modes:      FL2C's fuzzy regulators on 9 modes per component (the
//                     paper's model);
//  - fl2c_corrected:  FL2C on the modes plus static correction modes.
//
// For every scene and friction coefficient the program prints one table:
// the outputs asked for in the parameter file (by default the displacements
// of the report's slave node, P1's bottom-right corner, and of the two
// master nodes around it, and the total normal and tangential contact
// forces), their errors against full_order, iterations and times. It then
// sets the `overlap` case in plane strain beside the paper's Table 3, and
// writes report.txt, results.json, VTU files (displacements, stresses, contact
// pressure) and a plot of the pressure and shear along each contact face.
//
// Every solver is set from the same SceneState (the scene with the load and
// friction coefficient of the case), so they all solve the same problem.
//
// Usage: step-3 prm/step-3.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/program.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/fe/beam_contact.h>
#include <fuzzycontact/output/contact_face_plot.h>
#include <fuzzycontact/output/contact_report.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/study/full_order_model.h>
#include <fuzzycontact/study/input_checks.h>
#include <fuzzycontact/study/observations.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <optional>

namespace Step3
{
  using namespace dealii;
  using namespace FuzzyContact;

  // @sect3{Parameters}
  struct Parameters
  {
    std::vector<std::string> scene_files;
    std::string              paper_scene_file;
    std::string              output_directory;
    std::vector<std::string> outputs;
    unsigned int             mesh_refinements;
    // The resultant to scale the scene's loads to; none: as declared.
    std::optional<double> load;
    // Each case's coefficient for every pair; none: the scene's own.
    std::vector<std::optional<double>> friction_coefficients;
    unsigned int                       n_load_steps;
    ContactFormulation                 contact;
    bool                               write_vtu;
    ModalParameters                    modal;
    double                             mode_error_tolerance;
    double                             rank_tolerance;
    ActiveSetParameters                exact;
    FL2CParameters                     fl2c;

    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("scenes",
                        "overlap.prm, stacked.prm",
                        Patterns::Anything(),
                        "Scene files, relative to this parameter file.");
      prm.declare_entry("paper scene",
                        "overlap.prm",
                        Patterns::Anything(),
                        "Scene solved in plane strain beside the paper's "
                        "Table 3 (empty: none).");
      prm.declare_entry("output directory",
                        "step-3-output",
                        Patterns::Anything(),
                        "Folder for report.txt, results.json and the VTU "
                        "files.");
      prm.declare_entry("outputs",
                        ContactReport::default_outputs(),
                        Patterns::Anything(),
                        "Comma-separated outputs of the tables (see "
                        "study/observations.h).");
      prm.declare_entry("mesh refinements",
                        "2",
                        Patterns::Integer(0, 5),
                        "Global refinements of each component's mesh.");
      prm.declare_entry("load",
                        "50000",
                        Patterns::Anything(),
                        "Total external load [N]; the scene's loads are "
                        "scaled to this resultant. 'scene': the scene's "
                        "loads and prescribed displacements as declared.");
      prm.declare_entry("friction coefficients",
                        "0, 0.3",
                        Patterns::Anything(),
                        "Coulomb coefficients (>= 0) to solve each scene "
                        "with, each for every contact pair; 'scene' solves "
                        "it with the scene's own coefficient of each pair.");
      prm.declare_entry("load steps",
                        "1",
                        Patterns::Integer(),
                        "Proportional load steps (a scene with load stages "
                        "uses its stages' own).");
      ContactFormulation::declare_parameters(prm);
      prm.declare_entry("write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write the deformed bodies with contact pressure.");
      ModalParameters::declare_parameters(prm);
      prm.enter_subsection("Reduced models");
      prm.declare_entry("mode error tolerance",
                        "0",
                        Patterns::Double(),
                        "If positive: the fewest computed modes whose modal "
                        "contact flexibility at the report node is within "
                        "this relative error.");
      prm.declare_entry("rank tolerance",
                        "1e-12",
                        Patterns::Double(),
                        "Static correction modes with a Gram eigenvalue "
                        "below this fraction of the largest are dropped.");
      prm.leave_subsection();
      ActiveSetParameters::declare_parameters(prm);
      FL2CParameters::declare_parameters(prm);
    }

    void
    parse_parameters(ParameterHandler &prm, const std::string &prm_file)
    {
      scene_files.clear();
      for (const std::string &name :
           Utilities::split_string_list(prm.get("scenes"), ','))
        scene_files.push_back(Input::resolve_relative_to(name, prm_file));
      AssertThrow(!scene_files.empty(),
                  ExcMessage("scenes: at least one scene file is needed."));
      const std::string paper = Utilities::trim(prm.get("paper scene"));
      paper_scene_file =
        paper.empty() ? "" : Input::resolve_relative_to(paper, prm_file);
      output_directory = Utilities::trim(prm.get("output directory"));
      Input::check_output_directory(output_directory);
      outputs          = Observations::split(prm.get("outputs"));
      mesh_refinements = prm.get_integer("mesh refinements");
      load = SceneLimits::optional_force(prm.get("load"), "scene", "load");
      friction_coefficients.clear();
      for (const std::string &mu :
           Utilities::split_string_list(prm.get("friction coefficients")))
        friction_coefficients.push_back(
          mu == "scene"
            ? std::optional<double>()
            : Input::non_negative(Input::to_double(mu, "friction coefficients"),
                                  "friction coefficients: each value"));
      AssertThrow(!friction_coefficients.empty(),
                  ExcMessage("friction coefficients: at least one value "
                             "is needed."));
      n_load_steps = Input::integer_in_range(prm.get_integer("load steps"),
                                             1,
                                             1000,
                                             "load steps");
      contact.parse_parameters(prm);
      write_vtu = prm.get_bool("write vtu");
      modal.parse_parameters(prm);
      prm.enter_subsection("Reduced models");
      mode_error_tolerance =
        Input::non_negative(prm.get_double("mode error tolerance"),
                            "Reduced models: mode error tolerance");
      rank_tolerance = Input::positive(prm.get_double("rank tolerance"),
                                       "Reduced models: rank tolerance");
      prm.leave_subsection();
      exact.parse_parameters(prm);
      fl2c.parse_parameters(prm);
      InputChecks::check(modal, exact, fl2c);
    }
  };


  // @sect3{The ContactStudy class}
  class ContactStudy
  {
  public:
    explicit ContactStudy(const std::string &parameter_file);
    void
    run();

  private:
    void
    analyse(const Scene                              &scene,
            const std::vector<std::optional<double>> &friction_coefficients,
            const std::string                        &label,
            const bool                                paper);

    SceneState
    loaded_state(const Scene &scene) const;

    Parameters         parameters;
    std::vector<Scene> scenes;
    bool               with_paper = false;
    Scene              paper_scene;
    TimerOutput        timer;
    Report             report;
    nlohmann::json     results;
    OutputFiles        output;
    // The outputs observed: the chosen ones, then those the report always
    // needs (the paper's nodes, the totals).
    std::vector<std::string> observed;
  };


  ContactStudy::ContactStudy(const std::string &parameter_file)
      : timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
      , output("")
  {
    // All input is read and checked before anything is computed or
    // written; what needs a mesh (the contact geometry) is checked before
    // anything is written.
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    Input::parse_strictly(prm, parameter_file);
    parameters.parse_parameters(prm, parameter_file);
    observed = ContactReport::observed_outputs(parameters.outputs);
    InputChecks::SceneReader read{parameters.mesh_refinements,
                                  true,
                                  parameters.modal.n_modes};
    for (const std::string &file : parameters.scene_files)
      {
        scenes.push_back(read(file));
        Observations::check(observed, scenes.back());
      }
    if (!parameters.paper_scene_file.empty())
      {
        with_paper              = true;
        paper_scene             = read(parameters.paper_scene_file);
        paper_scene.plane_model = PlaneModel::plane_strain;
        Observations::check(observed, paper_scene);
      }
    for (const std::string &w : read.warnings)
      report.say(w + "\n");
    output = OutputFiles(parameters.output_directory);
  }


  // The scene's loads, scaled to the requested resultant (none: as
  // declared).
  SceneState
  ContactStudy::loaded_state(const Scene &scene) const
  {
    SceneState state(scene);
    if (parameters.load)
      state.scale_forces_to(scene, *parameters.load, "load");
    return state;
  }


  // @sect4{One scene: components, contact geometry, reduced models, and the
  // four solvers for every friction coefficient}
  //
  // The paper scene's cases are set beside the paper's Table 3 (@p paper).
  void
  ContactStudy::analyse(
    const Scene                              &scene,
    const std::vector<std::optional<double>> &friction_coefficients,
    const std::string                        &label,
    const bool                                paper)
  {
    // The bodies, the outputs, the modes, and the reduced models without
    // and with static correction, each stage timed on its own.
    const auto  never = TimerOutput::never;
    const auto  wall  = TimerOutput::wall_times;
    TimerOutput scene_timer(std::cout, never, wall);
    TimerOutput modes_timer(std::cout, never, wall);
    TimerOutput corrected_timer(std::cout, never, wall);
    timer.enter_subsection("assembly");
    ContactScene bodies(scene,
                        parameters.mesh_refinements,
                        parameters.contact.penetration_tolerance,
                        &scene_timer);
    bodies.set_sliding_limit(parameters.contact.sliding_limit);
    timer.leave_subsection();
    const Observations outputs(observed, bodies);
    const unsigned int n_shown = parameters.outputs.size();

    timer.enter_subsection("modes (ARPACK)");
    std::vector<ModalBasis> modes =
      component_modes(bodies, parameters.modal, &scene_timer);
    if (parameters.mode_error_tolerance > 0)
      truncate_to_static_error(modes,
                               bodies,
                               outputs.slave_node(),
                               parameters.mode_error_tolerance);
    timer.leave_subsection();
    const auto reduce = [&](const bool corrected, TimerOutput &local) {
      ReducedModelSettings settings;
      settings.rank_tolerance    = parameters.rank_tolerance;
      settings.static_correction = corrected;
      return std::make_unique<ReducedOrderModel>(bodies,
                                                 modes,
                                                 outputs.dofs(),
                                                 std::vector<VaryingQuantity>(),
                                                 settings,
                                                 &local);
    };
    timer.enter_subsection("reduced models");
    const auto modal_model     = reduce(false, modes_timer);
    const auto corrected_model = reduce(true, corrected_timer);
    timer.leave_subsection();
    nlohmann::json offline;
    report.say(ContactReport::offline(label,
                                      bodies,
                                      modes,
                                      *corrected_model,
                                      scene_timer,
                                      modes_timer,
                                      corrected_timer,
                                      offline));
    results["offline"].push_back(offline);
    const auto theory = BeamTheory::two_beam_contact(scene);

    // The solvers, for every friction coefficient.
    std::vector<ContactCase> cases;
    for (const std::optional<double> &mu : friction_coefficients)
      {
        SceneState state = loaded_state(scene);
        if (mu)
          std::fill(state.friction_coefficients.begin(),
                    state.friction_coefficients.end(),
                    *mu);
        ContactCase c(bodies, state, state.total_force(scene));
        {
          // A fresh full-order solver: its time is that of a cold solve
          // (factorisations included); a second solve shows the warm cost.
          TimerOutput::Scope scope(timer, "full_order");
          FullOrderModel     full(bodies, outputs.dofs(), parameters.exact);
          full.set_n_load_steps(parameters.n_load_steps);
          full.set_state(state);
          SolverRun run;
          run.solution           = full.solve();
          run.fields             = run.solution.displacements;
          run.outputs            = outputs.values(run.solution);
          c.full_order_warm_time = full.solver().solve().time;
          c.runs.push_back(std::move(run));
        }

        const auto reduced_run = [&](ReducedOrderModel   &model,
                                     const ContactSolver &solver,
                                     const std::string   &name) {
          TimerOutput::Scope scope(timer, name);
          // A diagnostic solver that fails leaves a "failed" row.
          return SolverRun::attempt(name, [&](SolverRun &run) {
            model.set_n_load_steps(parameters.n_load_steps);
            model.set_state(state);
            run.solution = model.solve(solver, name);
            run.outputs  = outputs.values(run.solution);
            if (parameters.write_vtu)
              run.fields = model.displacement_fields(run.solution);
          });
        };
        const ActiveSetSolver exact(parameters.exact);
        const FL2CSolver      fl2c(parameters.fl2c);
        c.runs.push_back(reduced_run(*corrected_model, exact, "reduced_exact"));
        c.runs.push_back(reduced_run(*modal_model, fl2c, "fl2c_modes"));
        c.runs.push_back(reduced_run(*corrected_model, fl2c, "fl2c_corrected"));
        c.runs.push_back(
          reduced_run(*modal_model, exact, "reduced_exact_modes"));

        // Beam theory beside the full-order answer.
        if (theory)
          c.beam_theory =
            theory->compare(c.load,
                            c.runs[0].solution.normal_force,
                            c.runs[0].outputs[outputs.index("slave.uy")]);
        std::string plot_message;
        if (parameters.write_vtu)
          ContactReport::add_vtu(output, c, bodies, label);
        if (!add_contact_face_plot(output, c, bodies, label, plot_message))
          report.say("warning: " + plot_message + "\n");
        report.say(ContactReport::case_table(c, outputs, n_shown));
        cases.push_back(std::move(c));
      }
    if (paper)
      report.say(
        ContactReport::paper_comparison(cases, outputs, n_shown, results));
    else
      for (const ContactCase &c : cases)
        results["cases"].push_back(
          ContactReport::case_json(c, outputs, n_shown));
  }


  void
  ContactStudy::run()
  {
    report.say("step-3: frictional contact solved four ways (full order, "
               "reduced exact, FL2C on modes, FL2C with static correction)\n");
    results["cases"] = nlohmann::json::array();
    for (const Scene &scene : scenes)
      analyse(scene,
              parameters.friction_coefficients,
              scene.name + "-" +
                (scene.plane_model == PlaneModel::plane_stress ? "stress"
                                                               : "strain"),
              false);
    if (with_paper)
      {
        // The paper does not say which friction coefficient it used:
        // frictionless and the scene's own.
        std::vector<std::optional<double>> mus = {0.};
        if (paper_scene.contact_pairs[0].friction_coefficient > 0)
          mus.push_back({});
        analyse(paper_scene, mus, paper_scene.name + "-strain", true);
      }

    {
      TimerOutput::Scope scope(timer, "output");
      output.add("report.txt", report.text());
      output.add_json("results.json", results);
      output.write_all();
    }
    std::cout << "\nWrote report.txt, results.json"
              << (parameters.write_vtu ? " and contact-*.vtu" : "") << " to "
              << output.directory() << "/" << std::endl;
    timer.print_summary();
  }
} // namespace Step3


int
main(int argc, char **argv)
{
  return FuzzyContact::run_program(argc,
                                   argv,
                                   "step-3",
                                   [](const std::string &parameter_file) {
                                     Step3::ContactStudy study(parameter_file);
                                     study.run();
                                   });
}
