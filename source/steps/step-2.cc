// step-2: modal reanalysis. When the Young's modulus or the density of a
// zone of a component changes, how well, and how fast, do the reanalysis
// methods give the new frequencies and mode shapes?
//
// For each case of the parameter file (a scene, a component, the parameters
// declared variable, and samples of their changes) the program computes the
// nominal modes once, prepares every method once ("offline"), and then, for
// each sample, sets each method's frequencies and mode shapes beside an exact
// ARPACK re-solve:
//
//  - taylor: first-order Taylor series of eigenvalues and modes (Lee's
//    derivatives), no projection;
//  - ca: Kirsch's Combined Approximations, binomial-series basis and
//    Rayleigh-Ritz;
//  - hptp: the homotopy perturbation basis of the sample's direction
//    (Massa et al.), Rayleigh-Ritz;
//  - hptp-pi: the parameter-independent HPTP, whose online cost does not
//    depend on the mesh.
//
// Modes are paired with the exact ones by MAC (they change order when
// eigenvalues cross). For the ordered methods every order is shown, and the
// order a tolerance asks for is chosen a posteriori from the change between
// successive orders. Every answer comes with its error and its time; the
// tables and results.json come from output/reanalysis_report.h.
//
// Usage: step-2 prm/step-2.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/limits.h>
#include <fuzzycontact/base/program.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/modal/mode_comparison.h>
#include <fuzzycontact/output/reanalysis_report.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/reanalysis/exact_resolve.h>
#include <fuzzycontact/reanalysis/order_selection.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>
#include <fuzzycontact/reanalysis/reanalysis_case.h>
#include <fuzzycontact/reanalysis/reanalysis_factory.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/reanalysis/residual_check.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace Step2
{
  using namespace dealii;
  using namespace FuzzyContact;

  // @sect3{Parameters}
  //
  // The step file lists its cases by name; each opens a subsection 'Case
  // <name>' (reanalysis/reanalysis_case.h). As in a scene file, the names
  // are read in a first, lenient pass, and the whole file is then parsed
  // strictly.
  struct Parameters
  {
    std::string                 output_directory;
    unsigned int                mesh_refinements;
    std::vector<std::string>    methods;
    ModalParameters             modal;
    ReanalysisSettings          reanalysis;
    std::vector<ReanalysisCase> cases;

    static void
    declare_parameters(ParameterHandler               &prm,
                       const std::vector<std::string> &case_names)
    {
      prm.declare_entry("output directory",
                        "step-2-output",
                        Patterns::Anything(),
                        "Folder for report.txt and results.json, relative to "
                        "the working directory.");
      prm.declare_entry("mesh refinements",
                        "2",
                        Patterns::Integer(0, 4),
                        "Global refinements of the component meshes (76 x 2 "
                        "cells of Q2: 0, 1, 2, 3 give 1530, 5490, 20706 and "
                        "80322 DoFs).");
      std::string known;
      for (const std::string &name : reanalysis_method_names())
        known += (known.empty() ? "" : "|") + name;
      prm.declare_entry("methods",
                        "taylor, ca, hptp, hptp-pi",
                        Patterns::MultipleSelection(known),
                        "Reanalysis methods set beside the exact re-solve.");
      prm.declare_entry("cases",
                        "",
                        Patterns::Anything(),
                        "Comma-separated names of the cases; each has a "
                        "subsection 'Case <name>'.");
      ModalParameters::declare_parameters(prm);
      ReanalysisSettings::declare_parameters(prm);
      for (const std::string &name : case_names)
        ReanalysisCase::declare_parameters(prm, name);
    }

    void
    parse_parameters(ParameterHandler &prm, const std::string &prm_file)
    {
      output_directory = Utilities::trim(prm.get("output directory"));
      Input::check_output_directory(output_directory);
      mesh_refinements = prm.get_integer("mesh refinements");
      methods          = Utilities::split_string_list(prm.get("methods"), ',');
      modal.parse_parameters(prm);
      AssertThrow(modal.cutoff_frequency == 0,
                  ExcMessage("Modal analysis: step-2 reanalyses a fixed "
                             "number of modes; set 'cutoff frequency = 0'."));
      reanalysis.parse_parameters(prm);

      const std::vector<std::string> names =
        Input::to_names(prm.get("cases"), "cases");
      AssertThrow(!names.empty(), ExcMessage("cases: no case is listed."));
      cases.resize(names.size());
      for (unsigned int c = 0; c < names.size(); ++c)
        cases[c].parse_parameters(prm, names[c], prm_file);
    }
  };


  // @sect3{The ModalReanalysis class}
  //
  // run() goes through the cases. A case computes the nominal modes,
  // prepares the methods, and then reanalyses each sample; what a case
  // prepares once is kept in a PreparedCase for its samples.
  class ModalReanalysis
  {
  public:
    explicit ModalReanalysis(const std::string &parameter_file);
    void
    run();

  private:
    struct PreparedCase
    {
      ModalBasis                                     all_nominal;
      ModalBasis                                     nominal;
      std::unique_ptr<ParameterModel>                model;
      std::vector<std::unique_ptr<ReanalysisMethod>> methods;
      std::vector<double>                            offline_times;
      std::unique_ptr<ResidualCheck>                 residual_check;
    };

    void
    run_case(const ReanalysisCase &c);
    void
    prepare_methods(PreparedCase &prepared);
    void
    reanalyse_sample(const PreparedCase        &prepared,
                     const std::vector<double> &t,
                     const std::vector<double> &changes_percent);
    std::vector<ReanalysisAnswer>
    answers_at_every_order(const PreparedCase         &prepared,
                           const unsigned int          m,
                           const std::vector<double>  &t,
                           const ModalBasis           &exact,
                           const SparseMatrix<double> &M) const;
    void
    choose_order(std::vector<ReanalysisAnswer> &answers) const;

    Parameters                        parameters;
    std::map<std::string, Scene>      scenes;
    TimerOutput                       timer;
    std::unique_ptr<ReanalysisReport> report;
  };


  ModalReanalysis::ModalReanalysis(const std::string &parameter_file)
      : timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
  {
    // Pass 1: only the list of cases (everything else is skipped).
    std::vector<std::string> case_names;
    {
      ParameterHandler prm;
      prm.declare_entry("cases", "", Patterns::Anything());
      std::istringstream in(Input::read_text_file(parameter_file));
      prm.parse_input(in, parameter_file, "", /*skip_undefined=*/true);
      case_names = Input::to_names(prm.get("cases"), "cases");
    }
    // Pass 2: the whole file, strictly.
    ParameterHandler prm;
    Parameters::declare_parameters(prm, case_names);
    Input::parse_strictly(prm, parameter_file);
    parameters.parse_parameters(prm, parameter_file);
    // Everything that can be checked without a mesh is checked before any
    // computation: scenes, components, parameter names, and that no sample
    // makes a modulus or density non-positive.
    for (const ReanalysisCase &c : parameters.cases)
      {
        if (scenes.count(c.scene_file) == 0)
          scenes[c.scene_file] = Scene::read(c.scene_file);
        c.check(scenes[c.scene_file]);
      }
    report = std::make_unique<ReanalysisReport>(parameters.output_directory,
                                                parameters.reanalysis,
                                                parameters.modal.n_modes,
                                                parameters.mesh_refinements);
  }


  // @sect4{One case}
  //
  // The nominal modes are computed with a few more modes than reported, so
  // that a cluster of close eigenvalues at the top of the reported range is
  // seen whole: its partner modes are then reanalysed too.
  void
  ModalReanalysis::run_case(const ReanalysisCase &c)
  {
    const Scene    &scene = scenes.at(c.scene_file);
    const Component component(
      scene.components[scene.component_index(c.component)],
      scene.plane_model,
      parameters.mesh_refinements,
      &timer);

    PreparedCase    prepared;
    ModalParameters with_extra = parameters.modal;
    with_extra.n_modes         = parameters.modal.n_modes + 3;
    {
      TimerOutput::Scope scope(timer, "nominal modes (ARPACK)");
      prepared.all_nominal = ModalSolver(with_extra)
                               .solve(component.stiffness_matrix(),
                                      component.mass_matrix(),
                                      "Component " + component.name());
    }
    prepared.nominal = leading_modes(
      prepared.all_nominal,
      modes_with_complete_clusters(prepared.all_nominal,
                                   parameters.modal.n_modes,
                                   parameters.reanalysis.cluster_gap));
    prepared.model = std::make_unique<ParameterModel>(component, c.parameters);
    prepare_methods(prepared);

    report->add_case(c,
                     scene.name,
                     *prepared.model,
                     prepared.nominal,
                     prepared.methods,
                     prepared.offline_times);

    if (parameters.reanalysis.residual_check)
      {
        TimerOutput::Scope scope(timer, "residual check: K0 factorisation");
        prepared.residual_check =
          std::make_unique<ResidualCheck>(*prepared.model);
      }
    for (unsigned int s = 0; s < c.samples.size(); ++s)
      reanalyse_sample(prepared, c.samples[s], c.samples_percent[s]);
  }


  // @sect4{The offline stage}
  //
  // Each method is made by the library's factory from its name, and the
  // time that takes is its offline time: Lee's derivatives for Taylor and
  // HPTP, one factorisation for CA, and for the parameter-independent HPTP
  // its whole basis with the projections of the zone matrices.
  void
  ModalReanalysis::prepare_methods(PreparedCase &prepared)
  {
    for (const std::string &name : parameters.methods)
      {
        Timer clock;
        prepared.methods.push_back(
          create_reanalysis_method(name,
                                   *prepared.model,
                                   prepared.nominal,
                                   parameters.reanalysis));
        prepared.offline_times.push_back(clock.wall_time());
      }
  }


  // @sect4{One sample}
  //
  // The reference first: its time is that of the modes wanted; a second
  // solve with more modes serves the matching of modes that changed places.
  // Then every method at every order, the order the tolerance asks for, and
  // which nominal mode each exact mode comes from.
  void
  ModalReanalysis::reanalyse_sample(const PreparedCase        &prepared,
                                    const std::vector<double> &t,
                                    const std::vector<double> &changes_percent)
  {
    const ParameterModel   &model = *prepared.model;
    ReanalysisSampleSummary sample;
    sample.changes_percent = changes_percent;
    ModalBasis exact;
    {
      TimerOutput::Scope scope(timer, "exact re-solves (ARPACK)");
      ModalParameters    for_matching = parameters.modal;
      for_matching.n_modes            = prepared.nominal.size() + 3;
      Timer clock;
      ExactResolve(model, parameters.modal).solve(t);
      sample.time_exact = clock.wall_time();
      exact             = ExactResolve(model, for_matching).solve(t);
    }
    sample.exact = &exact;
    SparseMatrix<double> K, M;
    model.matrices(t, K, M);

    {
      TimerOutput::Scope scope(timer, "reanalyses");
      for (unsigned int m = 0; m < prepared.methods.size(); ++m)
        {
          std::vector<ReanalysisAnswer> answers =
            answers_at_every_order(prepared, m, t, exact, M);
          choose_order(answers);
          for (ReanalysisAnswer &answer : answers)
            sample.answers.push_back(std::move(answer));
        }
    }

    const ModalBasis reported = leading_modes(exact, parameters.modal.n_modes);
    sample.exact_from_nominal = compare_modes(reported.eigenvalues,
                                              reported.modes,
                                              prepared.all_nominal,
                                              M);
    report->add_sample(sample);
  }


  // Each order of a method (the one answer of a method without orders),
  // compared with the exact modes and checked on the full matrices. The
  // online time of the parameter-independent HPTP is that of its online
  // stage proper (eigenvalues and Y, nothing of size n_dofs); the modes are
  // expanded afterwards for the comparison.
  std::vector<ReanalysisAnswer>
  ModalReanalysis::answers_at_every_order(const PreparedCase         &prepared,
                                          const unsigned int          m,
                                          const std::vector<double>  &t,
                                          const ModalBasis           &exact,
                                          const SparseMatrix<double> &M) const
  {
    const ReanalysisMethod &method  = *prepared.methods[m];
    const unsigned int      n_modes = parameters.modal.n_modes;
    const unsigned int      max_order =
      method.has_order() ? parameters.reanalysis.max_order : 1;
    const auto *pi =
      dynamic_cast<const ParameterIndependentReanalysis *>(&method);
    std::vector<ReanalysisAnswer> answers;
    for (unsigned int order = 1; order <= max_order; ++order)
      {
        ReanalysisAnswer answer;
        answer.method       = method.name();
        answer.has_order    = method.has_order();
        answer.order        = order;
        answer.time_offline = prepared.offline_times[m];
        if (pi != nullptr)
          {
            answer.time_online = time_per_call([&]() {
              pi->online(t, order);
            });
            answer.result      = pi->reanalyse(t, order);
          }
        else
          answer.time_online = time_per_call([&]() {
            answer.result = method.reanalyse(t, order);
          });
        answer.comparison = compare_modes(answer.result.eigenvalues,
                                          answer.result.modes,
                                          exact,
                                          M);
        if (prepared.residual_check)
          {
            const ResidualCheck::Residuals r =
              prepared.residual_check->check(t,
                                             answer.result.eigenvalues,
                                             answer.result.modes);
            answer.residual = *std::max_element(r.relative.begin(),
                                                r.relative.begin() + n_modes);
            answer.energy_residual =
              *std::max_element(r.energy.begin(), r.energy.begin() + n_modes);
          }
        answers.push_back(std::move(answer));
      }
    return answers;
  }


  // @sect4{The order a tolerance asks for}
  //
  // The library's rule (reanalysis/order_selection.h): the estimate of order
  // n is its change to order n + 1 and, with the residual check, eta^2 / 2
  // from the energy-norm residual; the order is the lowest whose estimate
  // meets the tolerance. Every order is estimated here, for the table.
  void
  ModalReanalysis::choose_order(std::vector<ReanalysisAnswer> &answers) const
  {
    if (!answers.front().has_order)
      {
        answers.front().selected = true;
        return;
      }
    const OrderSelection selection = order_for_tolerance(
      answers.size(),
      parameters.reanalysis.order_tolerance,
      parameters.modal.n_modes,
      [&](const unsigned int n) {
        return answers[n - 1].result.eigenvalues;
      },
      [&](const unsigned int n) {
        return answers[n - 1].energy_residual;
      },
      /*all_orders=*/true);
    for (unsigned int n = 1; n <= answers.size(); ++n)
      answers[n - 1].estimate = selection.estimates[n - 1];
    answers[selection.order - 1].selected      = true;
    answers[selection.order - 1].tolerance_met = selection.tolerance_met;
  }


  void
  ModalReanalysis::run()
  {
    report->start(parameters.cases.size());
    for (const ReanalysisCase &c : parameters.cases)
      run_case(c);
    {
      TimerOutput::Scope scope(timer, "output");
      report->write();
    }
    timer.print_summary();
  }
} // namespace Step2


int
main(int argc, char **argv)
{
  return FuzzyContact::run_program(argc,
                                   argv,
                                   "step-2",
                                   [](const std::string &parameter_file) {
                                     Step2::ModalReanalysis reanalysis(
                                       parameter_file);
                                     reanalysis.run();
                                   });
}
