// step-1: the lowest vibration modes of every component of a scene, and how
// much to trust them.
//
// Everything later in FuzzyContact (the component-mode reduction of the
// contact problem, the reanalysis of modes when a modulus changes) rests on
// the modal bases computed here. So this program does not just print
// frequencies; it sets each one beside an independent value:
//
//  - beam theory: Euler-Bernoulli and Timoshenko bending frequencies and the
//    axial frequencies of a clamped-free bar, for the component's 2D model;
//  - the paper's Table 1 (Massa et al. 2013), computed in both 2D models,
//    since the paper does not say which one it used;
//  - the same modes on finer meshes, with the time each stage took;
//  - the relative residual ||K phi - lambda M phi|| / ||K phi|| of each mode.
//
// The modes are computed here; their kinds and beam theory come from
// modal/mode_classification.h, and the tables, results.json and the mode
// shapes (VTU) from output/modal_report.h.
//
// Usage: step-1 prm/step-1.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/program.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/modal/mode_classification.h>
#include <fuzzycontact/output/modal_report.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/study/input_checks.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <iostream>
#include <memory>

namespace Step1
{
  using namespace dealii;
  using namespace FuzzyContact;

  // @sect3{Parameters}
  //
  // The step file names a scene file (relative to itself) and says how to
  // analyse it; the scene file describes the bodies.
  struct Parameters
  {
    std::string     scene_file;
    std::string     output_directory;
    unsigned int    mesh_refinements;
    unsigned int    convergence_refinements;
    bool            compare_with_paper;
    double          paper_cutoff_frequency;
    ModalParameters modal;

    static void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("scene",
                        "overlap.prm",
                        Patterns::Anything(),
                        "Scene file, relative to this parameter file.");
      prm.declare_entry("output directory",
                        "step-1-output",
                        Patterns::Anything(),
                        "Folder for report.txt, results.json and the mode "
                        "shapes (VTU), relative to the working directory.");
      prm.declare_entry("mesh refinements",
                        "0",
                        Patterns::Integer(0, 6),
                        "Global refinements of each component's mesh.");
      prm.declare_entry("convergence refinements",
                        "3",
                        Patterns::Integer(0, 4),
                        "The convergence study repeats the analysis on this "
                        "many further refinements of each mesh (0: none).");
      prm.declare_entry("compare with paper",
                        "true",
                        Patterns::Bool(),
                        "Set the first component's modes in plane stress "
                        "and plane strain beside Table 1 of the paper.");
      prm.declare_entry("paper cutoff frequency",
                        "25000",
                        Patterns::Double(),
                        "Modes up to this frequency [Hz] enter the "
                        "comparison with the paper (its Table 1 goes to 25 "
                        "kHz).");
      ModalParameters::declare_parameters(prm);
    }

    void
    parse_parameters(ParameterHandler &prm, const std::string &prm_file)
    {
      scene_file =
        Input::resolve_relative_to(Utilities::trim(prm.get("scene")), prm_file);
      output_directory = Utilities::trim(prm.get("output directory"));
      Input::check_output_directory(output_directory);
      mesh_refinements        = prm.get_integer("mesh refinements");
      convergence_refinements = prm.get_integer("convergence refinements");
      compare_with_paper      = prm.get_bool("compare with paper");
      paper_cutoff_frequency =
        Input::in_range(prm.get_double("paper cutoff frequency"),
                        1,
                        InputChecks::max_cutoff_frequency,
                        "paper cutoff frequency",
                        "in Hz");
      modal.parse_parameters(prm);
      InputChecks::check(modal);
    }
  };


  // The paper's Table 1: the first nine frequencies of its beams [Hz].
  const std::vector<double> paper_table_1 =
    {174.8, 1087.1, 3007.7, 5796.6, 6449.5, 9387.7, 13693, 18625, 24094};


  // @sect3{The ModalAnalysis class}
  class ModalAnalysis
  {
  public:
    explicit ModalAnalysis(const std::string &parameter_file);
    void
    run();

  private:
    void
    analyse_components();
    void
    compare_with_paper();
    void
    convergence_study();

    Parameters                   parameters;
    Scene                        scene;
    TimerOutput                  timer;
    std::unique_ptr<ModalReport> report;
  };


  ModalAnalysis::ModalAnalysis(const std::string &parameter_file)
      : timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
  {
    // All input is read and checked before anything is computed or written.
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    Input::parse_strictly(prm, parameter_file);
    parameters.parse_parameters(prm, parameter_file);
    scene = Scene::read(parameters.scene_file);
    // The convergence study refines furthest: it sets the memory needed.
    SceneLimits::check_memory(scene,
                              parameters.mesh_refinements +
                                parameters.convergence_refinements,
                              /*static_correction=*/false,
                              "mesh refinements + convergence refinements");
    InputChecks::check_modes_fit(scene,
                                 parameters.mesh_refinements,
                                 parameters.modal.n_modes);
    report = std::make_unique<ModalReport>(parameters.output_directory);
  }


  // @sect4{Modes of each component, next to beam theory}
  //
  // Each component's mesh and matrices, and its lowest modes by ARPACK in
  // shift-invert mode. Each mode is classified as a bending or an axial
  // mode by the share of its kinetic energy in the transverse direction.
  // Bending mode n is compared with the n-th Euler-Bernoulli and Timoshenko
  // frequencies of a clamped-free beam, axial mode n with the bar value
  // (2n-1) c / (4L). The beam formulas apply to a component of one material
  // clamped at one end face only; for others only the FE values are listed.
  void
  ModalAnalysis::analyse_components()
  {
    const ModalSolver solver(parameters.modal);
    for (const ComponentDescription &description : scene.components)
      {
        const Component component(description,
                                  scene.plane_model,
                                  parameters.mesh_refinements,
                                  &timer);
        ModalBasis      basis;
        {
          TimerOutput::Scope scope(timer, "eigenvalues (ARPACK)");
          basis = solver.solve(component.stiffness_matrix(),
                               component.mass_matrix(),
                               "Component " + description.name);
        }
        const std::vector<ModeKind> kinds = classify_modes(component, basis);
        report->add_component(component,
                              parameters.mesh_refinements,
                              basis,
                              kinds,
                              beam_theory_frequencies(description,
                                                      scene.plane_model,
                                                      kinds));
      }
  }


  // @sect4{The paper's Table 1}
  //
  // The paper lists nine frequencies up to 25 kHz without saying which 2D
  // model produced them. We compute the first component in both models; the
  // report finds, for each listed value, the nearest FE mode of each, and
  // so shows which model each paper mode belongs to, and which FE modes the
  // paper does not list.
  void
  ModalAnalysis::compare_with_paper()
  {
    const ComponentDescription &description  = scene.components.front();
    ModalParameters             up_to_cutoff = parameters.modal;
    up_to_cutoff.cutoff_frequency = parameters.paper_cutoff_frequency;
    const ModalSolver solver(up_to_cutoff);

    std::vector<PlaneModelModes> models;
    for (const PlaneModel model :
         {PlaneModel::plane_strain, PlaneModel::plane_stress})
      {
        const Component    component(description,
                                  model,
                                  parameters.mesh_refinements,
                                  &timer);
        TimerOutput::Scope scope(timer, "eigenvalues (ARPACK)");
        const ModalBasis   basis = solver.solve(component.stiffness_matrix(),
                                              component.mass_matrix(),
                                              "Component " + description.name +
                                                " (" + to_string(model) + ")");
        models.push_back(
          {model, basis.frequencies(), classify_modes(component, basis)});
      }
    report->add_paper_comparison(description,
                                 parameters.paper_cutoff_frequency,
                                 paper_table_1,
                                 models);
  }


  // @sect4{Mesh convergence}
  //
  // Each component again on successively refined meshes. The time of each
  // stage is measured per mesh. Since the eigenvalue error of Q_p elements
  // falls like h^{2p}, Richardson extrapolation of the two finest meshes
  // estimates the converged frequencies, against which every mesh (and so
  // the one used above) is measured.
  void
  ModalAnalysis::convergence_study()
  {
    TimerOutput::Scope scope(timer, "convergence study");
    const ModalSolver  solver(parameters.modal);
    for (const ComponentDescription &description : scene.components)
      {
        std::vector<MeshLevelModes> levels;
        for (unsigned int r = 0; r <= parameters.convergence_refinements; ++r)
          {
            TimerOutput     level_timer(std::cout,
                                    TimerOutput::never,
                                    TimerOutput::wall_times);
            const Component component(description,
                                      scene.plane_model,
                                      parameters.mesh_refinements + r,
                                      &level_timer);
            ModalBasis      basis;
            {
              TimerOutput::Scope scope(level_timer, "eigenvalues (ARPACK)");
              basis = solver.solve(component.stiffness_matrix(),
                                   component.mass_matrix(),
                                   "Component " + description.name);
            }
            levels.push_back(
              {parameters.mesh_refinements + r,
               component.n_dofs(),
               basis.frequencies(),
               basis.max_residual(),
               level_timer.get_summary_data(TimerOutput::total_wall_time)});
          }

        const unsigned int  n_levels     = levels.size();
        std::vector<double> extrapolated = levels.back().frequencies;
        const double factor = std::pow(2., 2. * description.fe_degree) - 1.;
        if (n_levels >= 2)
          for (unsigned int j = 0; j < extrapolated.size(); ++j)
            extrapolated[j] += (levels[n_levels - 1].frequencies[j] -
                                levels[n_levels - 2].frequencies[j]) /
                               factor;
        report->add_convergence(description, levels, extrapolated);
      }
  }


  void
  ModalAnalysis::run()
  {
    report->start(scene, parameters.scene_file);
    analyse_components();
    if (parameters.compare_with_paper)
      compare_with_paper();
    if (parameters.convergence_refinements > 0)
      convergence_study();
    {
      TimerOutput::Scope scope(timer, "output");
      report->write();
    }
    timer.print_summary();
  }
} // namespace Step1


int
main(int argc, char **argv)
{
  return FuzzyContact::run_program(argc,
                                   argv,
                                   "step-1",
                                   [](const std::string &parameter_file) {
                                     Step1::ModalAnalysis analysis(
                                       parameter_file);
                                     analysis.run();
                                   });
}
