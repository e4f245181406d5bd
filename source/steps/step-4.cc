// step-4: a fuzzy contact study, FuzzyContact's main job.
//
// Some parameters of a contact scene are known only as fuzzy numbers: by
// default the Young's modulus of each beam (triangular, +-5 %) and the load
// (triangular, 10-50-100 kN). What is then known of the response? At each
// membership level alpha the parameters span a box, and each output of
// interest (by default the slave node's displacements u_x, u_y and the total
// normal and tangential contact forces F_n, F_t; any of the outputs of
// study/observations.h can be asked for with the key `outputs`) spans an
// interval over it; stacked over alpha, these intervals are the output's
// membership function.
//
// Finding an interval means finding the minimum and maximum of the response
// over a box, which takes many contact solves. This program makes them cheap
// and shows that they stay accurate:
//
//  - the response is evaluated on the reduced model (component modes with
//    static correction, re-analysed for zone parameters, contact forces by
//    the FL2C fuzzy regulator, or the exact reduced solver with `contact
//    solver = reduced exact`), built once;
//  - the bounds come from bound-constrained optimisation (Trilinos ROL)
//    started from the optimum of the level above, the paper's method;
//  - every bound's argument is evaluated once more by the exact full-order
//    solver (the reduction error at the bound);
//  - they are checked against the vertex method on the same reduced model
//    and against the Extension Principle: the exact full-order contact
//    solver on a dense grid of every box.
//
// Both models are set from the same binding of the parameter values to the
// scene (a SceneState), so the reference solves exactly the problem the
// fast path approximates.
//
// With MPI (`mpirun -np 2 step-4 ...`) the components are built on
// different ranks and the evaluations spread over them: the same bounds,
// from as many evaluations as one process makes.
//
// Usage: step-4 prm/step-4.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/parameter_file.h>
#include <fuzzycontact/base/program.h>
#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/base/rank_timers.h>
#include <fuzzycontact/fuzzy/extension_principle.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>
#include <fuzzycontact/fuzzy/proof_feedback.h>
#include <fuzzycontact/fuzzy/vertex_method.h>
#include <fuzzycontact/output/fuzzy_report.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>
#include <fuzzycontact/study/input_checks.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace Step4
{
  using namespace dealii;
  using namespace FuzzyContact;

  // @sect3{Parameters}
  //
  // The step file names its scene, declares which of the scene's
  // quantities are fuzzy and which outputs to bound. Since each fuzzy
  // parameter has a subsection named after it, the file is read in passes
  // (Input::parse_in_passes).
  struct Parameters
  {
    std::string                scene_file;
    std::string                output_directory;
    std::vector<std::string>   outputs;
    unsigned int               n_alpha;
    bool                       vertex_method;
    bool                       extension_principle;
    ExtensionPrincipleSettings reference;
    FuzzyParameterSet          fuzzy;
    FuzzyContactModelSettings  model;
    OptimisationSettings       optimisation;
    ProofSettings              proofs;
    std::vector<std::string>   warnings;

    void
    declare_parameters(ParameterHandler &prm) const
    {
      prm.declare_entry("scene",
                        "overlap.prm",
                        Patterns::Anything(),
                        "Scene file, relative to this parameter file.");
      prm.declare_entry("output directory",
                        "step-4-output",
                        Patterns::Anything(),
                        "Folder for report.txt, results.json and the "
                        "membership plot.");
      prm.declare_entry("outputs",
                        Observations::default_outputs(),
                        Patterns::Anything(),
                        "Comma-separated outputs to bound (doc/scenes.md): "
                        "<component>.node(x, y).ux/.uy, slave.ux/.uy, Fn, "
                        "Ft, <pair>.Fn/.Ft/.max_pressure/.max_shear/...");
      prm.declare_entry("number of alpha levels",
                        "11",
                        Patterns::Integer(),
                        "Membership levels 0, 1/(n-1), ..., 1 (n >= 2).");
      prm.declare_entry("vertex method",
                        "true",
                        Patterns::Bool(),
                        "Also bound the outputs by the vertex method.");
      prm.declare_entry("extension principle",
                        "true",
                        Patterns::Bool(),
                        "Also compute the Extension Principle reference "
                        "(exact full-order solves on a dense grid).");
      ExtensionPrincipleSettings::declare_parameters(prm);
      ProgressLines::declare_parameters(prm);
      fuzzy.declare_parameters(prm);
      FuzzyContactModelSettings::declare_parameters(prm);
      OptimisationSettings::declare_parameters(prm);
      ProofSettings::declare_parameters(prm);
    }

    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &prm_file,
                     Scene             &scene)
    {
      scene_file =
        Input::resolve_relative_to(Utilities::trim(prm.get("scene")), prm_file);
      output_directory = Utilities::trim(prm.get("output directory"));
      Input::check_output_directory(output_directory);
      n_alpha       = Input::integer_in_range(prm.get_integer("number of alpha "
                                                              "levels"),
                                        2,
                                        101,
                                        "number of alpha levels",
                                        "at least the support and the core");
      vertex_method = prm.get_bool("vertex method");
      extension_principle = prm.get_bool("extension principle");
      reference.parse_parameters(prm);
      model.parse_parameters(prm);
      optimisation.parse_parameters(prm);
      proofs.parse_parameters(prm);
      ProgressLines::parse_parameters(prm);
      InputChecks::check(model.modal);
      InputChecks::check(model.fl2c);
      InputChecks::check(model.exact);
      InputChecks::check(optimisation);

      scene = Scene::read(scene_file);
      fuzzy.parse_parameters(prm, scene);
      AssertThrow(!fuzzy.parameters().empty(),
                  ExcMessage("fuzzy parameters: name at least one fuzzy "
                             "parameter of the scene (a subsection 'Fuzzy "
                             "parameter <name>' with its values)."));
      InputChecks::check(fuzzy, scene, model.contact_solver, model.fl2c);
      outputs = Observations::split(prm.get("outputs"));
      Observations::check(outputs, scene);
      check_cost_and_warn(scene);
    }

    // Model and Extension Principle sizes; warnings of unlikely input.
    void
    check_cost_and_warn(const Scene &scene)
    {
      warnings = InputChecks::check_scene(scene,
                                          scene_file,
                                          model.mesh_refinements,
                                          model.reduced.static_correction,
                                          model.modal.n_modes);
      if (extension_principle)
        reference.check_size(n_alpha, fuzzy.parameters().size());
      if (!InputChecks::all_crisp_warning(fuzzy).empty())
        warnings.push_back(InputChecks::all_crisp_warning(fuzzy));
    }
  };


  // The exit status of a run whose results were written but some of whose
  // bounds are not proven within the tolerance (doc/fuzzy-study.md); 1 is
  // an error (nothing written), 0 success.
  constexpr int unproven_exit_status = 3;
  int           exit_status          = 0;

  // @sect3{The FuzzyStudy class}
  class FuzzyStudy
  {
  public:
    FuzzyStudy(const std::string &parameter_file, const MPI_Comm comm);
    void
    run();

  private:
    void
    build_model();
    void
    compute_bounds();
    void
    write_output();

    MPI_Comm           comm;
    ConditionalOStream pcout;
    Report             report;
    TimerOutput        timer;

    Parameters                         parameters;
    Scene                              scene;
    std::unique_ptr<FuzzyContactModel> model;
    FuzzyStudyResults                  results;
  };


  FuzzyStudy::FuzzyStudy(const std::string &parameter_file, const MPI_Comm comm)
      : comm(comm)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , report(std::cout, pcout.is_active())
      , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
  {
    // All input is read and checked before anything is computed or written.
    // A fuzzy parameter is declared by its subsection alone.
    const std::string text = Input::read_text_file(parameter_file);
    parameters.fuzzy.add_names_of_subsections(
      Input::scan_parameter_text(text, parameter_file).top_level_subsections);
    Input::parse_in_passes(
      text,
      parameter_file,
      [&](ParameterHandler &prm) {
        parameters.declare_parameters(prm);
      },
      [&](ParameterHandler &prm) {
        return parameters.fuzzy.learn_names(prm);
      },
      [&](ParameterHandler &prm) {
        parameters.parse_parameters(prm, parameter_file, scene);
      });
    for (const std::string &w : parameters.warnings)
      report.say(w + "\n");
    results.scene       = scene.name;
    results.n_processes = Utilities::MPI::n_mpi_processes(comm);
    results.parameters  = parameters.fuzzy.parameters();
    results.alpha       = alpha_levels(parameters.n_alpha);
  }


  // @sect4{The model}
  //
  // Everything that does not depend on the fuzzy parameters is built once:
  // meshes, matrices, modes, static correction modes, the contact interface,
  // the outputs' nodes and the reduced contact flexibility. On several ranks
  // each component is assembled and reduced on one (FuzzyContactModel).
  void
  FuzzyStudy::build_model()
  {
    report.say(FuzzyStudyReport::study(scene.name,
                                       parameters.scene_file,
                                       results.n_processes,
                                       results.parameters,
                                       parameters.n_alpha));
    Timer wall;
    model = std::make_unique<FuzzyContactModel>(scene,
                                                parameters.fuzzy,
                                                parameters.outputs,
                                                parameters.model,
                                                &timer,
                                                comm);
    results.set_model(*model, Utilities::MPI::max(wall.wall_time(), comm));
    report.say(
      FuzzyStudyReport::model(results.offline_time, model->describe()));
  }


  // @sect4{The bounds, three ways}
  //
  // The optimisation and the vertex method evaluate the reduced model, the
  // Extension Principle the exact full-order one.
  void
  FuzzyStudy::compute_bounds()
  {
    // Parameters that cannot change the answer are crisp here.
    const std::vector<FuzzyNumber> numbers = model->effective_numbers();
    const std::vector<double>     &alpha   = results.alpha;
    results.inert                          = model->inert();
    const std::vector<std::string> names   = model->observations().names();
    const Response                 reduced = [&](const std::vector<double> &p) {
      return model->reduced(p);
    };
    // The reference's samples are counted for the progress lines.
    std::unique_ptr<Progress> progress;
    const Response            exact = [&](const std::vector<double> &p) {
      std::vector<double> values = model->full_order(p);
      if (progress)
        progress->advance();
      return values;
    };
    // Every method through the IntervalMethod interface, timed; on the
    // reduced model, by the ranks that can solve it.
    const auto bounds = [&](const IntervalMethod &method,
                            const Response       &response,
                            const std::string    &section) {
      TimerOutput::Scope scope(timer, section);
      const MPI_Comm     by =
        &response != &exact ? model->reduced_communicator() : comm;
      return bounds_on_ranks(method, numbers, alpha, response, names, comm, by);
    };

    // A body held by contact alone slides where no friction forces can hold
    // its load: where in every box that happens (the fuzzy output "sliding
    // possible"). The methods bound the outputs over the rest.
    if (model->can_lose_equilibrium())
      {
        TimerOutput::Scope scope(timer, "static equilibrium (every box)");
        results.equilibrium     = model->equilibrium_region(numbers, alpha);
        results.has_equilibrium = true;
        results.free_bodies     = model->bodies_held_by_contact();
      }

    // Every bound's proof: its argument once more, exactly, on the
    // factorisations of the offline build (shared by the ranks, in the
    // proofs' time; a changed zone modulus by conjugate gradients on
    // them). A bound the proof does not confirm within the tolerance
    // makes the model richer there, and the bounds are searched again
    // (fuzzy/proof_feedback.h, FuzzyContactModel::proven_bounds()).
    // (Proven also within the accuracy asked of the outputs.)
    ProofSettings proofs = parameters.proofs;
    proofs.accuracy      = parameters.optimisation.response_tolerance;
    EvaluationRecord record; // (the last round's, for the spot checks)
    const Response   searched = record.recording(reduced);
    results.set_proofs(model->proven_bounds(
      [&]() {
        record.clear();
        return bounds(OptimisationMethod(parameters.optimisation),
                      searched,
                      "optimisation (reduced model)");
      },
      proofs,
      [&](const unsigned int round,
          const std::size_t  n_points,
          const unsigned int added) {
        report.say(FuzzyStudyReport::enrichment(round,
                                                n_points,
                                                added,
                                                proofs.tolerance));
      },
      &timer));
    if (parameters.vertex_method)
      {
        results.vertex =
          bounds(VertexMethod(), reduced, "vertex method (reduced model)");
        results.has_vertex = true;
      }
    if (parameters.extension_principle)
      {
        model->set_reuse_factorisations(
          parameters.reference.reuse_factorisations);
        const unsigned long n_samples =
          extension_principle_size(numbers,
                                   results.alpha,
                                   parameters.reference.points_per_dimension);
        report.say(FuzzyStudyReport::extension_principle(
          n_samples,
          parameters.reference.points_per_dimension,
          parameters.reference.reuse_factorisations));
        const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
        progress                   = std::make_unique<Progress>(
          "Extension Principle, full-order solves" +
            std::string(n_ranks > 1 ? " of the first rank" : ""),
          (n_samples + n_ranks - 1) / n_ranks);
        results.reference =
          bounds(ExtensionPrinciple(parameters.reference.points_per_dimension),
                 exact,
                 "extension principle (full order)");
        results.has_reference    = true;
        results.reference_reuses = parameters.reference.reuse_factorisations;
      }
    // Spot checks: some of the optimisation's points solved exactly too
    // (fuzzy/spot_checks.h), last, as FuzzyContactModel::spot_checks() says.
    if (proofs.spot_checks > 0)
      {
        TimerOutput::Scope scope(timer, "spot checks (full order)");
        results.spot_checks = model->spot_checks(record, proofs.spot_checks);
      }
  }


  // @sect4{Output}
  //
  // report.txt, results.json and the membership functions as a picture,
  // written by the first rank at the end (the reporting module makes the
  // tables, the JSON and the plot).
  void
  FuzzyStudy::write_output()
  {
    results.ranks      = model->work_per_rank();
    results.unanswered = model->unanswered().summed_over(comm);
    nlohmann::json json;
    FuzzyStudyReport::bounds(results, report, json);
    json["contact_solver"] = model->contact_solver();
    TimerOutput::Scope scope(timer, "output");
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    FuzzyStudyReport::write(results, report, json, parameters.output_directory);
  }


  void
  FuzzyStudy::run()
  {
    build_model();
    compute_bounds();
    write_output();
    timer.print_summary();
    pcout << sections_per_rank(timer, comm); // with several ranks
    if (!results.unproven.empty() && !parameters.proofs.accept_unproven)
      {
        if (pcout.is_active())
          std::cerr << FuzzyStudyReport::unproven(results, unproven_exit_status)
                    << std::endl;
        exit_status = unproven_exit_status;
      }
  }
} // namespace Step4


int
main(int argc, char **argv)
{
  // One thread per process: the ranks share the cores.
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const int                                status =
    FuzzyContact::run_program(argc,
                              argv,
                              "step-4",
                              [](const std::string &parameter_file) {
                                Step4::FuzzyStudy study(parameter_file,
                                                        MPI_COMM_WORLD);
                                study.run();
                              });
  // A rank that failed alone would leave the others waiting in a
  // collective operation.
  if (status != 0 &&
      dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
    MPI_Abort(MPI_COMM_WORLD, status);
  return status != 0 ? status : Step4::exit_status;
}
