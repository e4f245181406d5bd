// step-4: a fuzzy contact study, FuzzyContact's main job.
//
// Some parameters of a contact scene are known only as fuzzy numbers: by
// default the Young's modulus of each beam (triangular, +-5 %) and the load
// (triangular, 10-50-100 kN). What is then known of the response? At each
// membership level alpha the parameters span a box, and each output of
// interest (the slave node's displacements u_x, u_y, the total normal and
// tangential contact forces F_n, F_t) spans an interval over it; stacked
// over alpha, these intervals are the output's membership function.
//
// Finding an interval means finding the minimum and maximum of the response
// over a box, which takes many contact solves. This program makes them cheap
// and shows that they stay accurate:
//
//  - the response is evaluated on the reduced model (component modes with
//    static correction, re-analysed for zone parameters, contact forces by
//    the FL2C fuzzy regulator), built once;
//  - the bounds come from bound-constrained optimisation (Trilinos ROL)
//    started from the optimum of the level above, the paper's method;
//  - they are checked against the vertex method on the same reduced model
//    and against the Extension Principle: the exact full-order contact
//    solver on a dense grid of every box.
//
// The samples of the vertex method and of the Extension Principle, and the
// optimisation chains, are spread over MPI ranks: `mpirun -np 2 step-4 ...`
// gives the same bounds.
//
// Usage: step-4 prm/step-4.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/program.h>
#include <fuzzycontact/fuzzy/extension_principle.h>
#include <fuzzycontact/fuzzy/fuzzy_number.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>
#include <fuzzycontact/fuzzy/vertex_method.h>
#include <fuzzycontact/output/membership_plot.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace Step4
{
  using namespace dealii;
  using namespace FuzzyContact;

  // @sect3{Parameters}
  //
  // The step file names its scene and declares which of the scene's
  // quantities are fuzzy. Since each fuzzy parameter has a subsection named
  // after it, the file is read in passes (Input::parse_in_passes).
  struct Parameters
  {
    std::string               scene_file;
    std::string               output_directory;
    unsigned int              n_alpha;
    bool                      vertex_method;
    bool                      extension_principle;
    unsigned int              points_per_dimension;
    bool                      reuse_factorisations;
    FuzzyParameterSet         fuzzy;
    FuzzyContactModelSettings model;
    OptimisationSettings      optimisation;

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
      prm.enter_subsection("Extension principle");
      prm.declare_entry("points per dimension",
                        "4",
                        Patterns::Integer(2, 100),
                        "Every alpha level's box is sampled on a grid of "
                        "this many equally spaced values per parameter "
                        "(both ends included).");
      prm.declare_entry("reuse factorisations",
                        "false",
                        Patterns::Bool(),
                        "false: every sample is an independent full-order "
                        "analysis (new factorisations, refined displacement "
                        "fields), the cost of a study without reduced "
                        "models. true: keep the nominal factorisations and "
                        "contact flexibility columns and reuse them where "
                        "exact (stiffness a multiple of the nominal one): "
                        "the same answers to about 1e-9, much cheaper.");
      prm.leave_subsection();
      fuzzy.declare_parameters(prm);
      FuzzyContactModelSettings::declare_parameters(prm);
      OptimisationSettings::declare_parameters(prm);
    }

    void
    parse_parameters(ParameterHandler  &prm,
                     const std::string &prm_file,
                     Scene             &scene)
    {
      scene_file =
        Input::resolve_relative_to(Utilities::trim(prm.get("scene")), prm_file);
      output_directory = Utilities::trim(prm.get("output directory"));
      AssertThrow(!output_directory.empty(),
                  ExcMessage("output directory must not be empty."));
      const long n = prm.get_integer("number of alpha levels");
      AssertThrow(n >= 2,
                  ExcMessage("number of alpha levels must be at least 2 (the "
                             "support and the core), got " +
                             std::to_string(n) + "."));
      n_alpha             = n;
      vertex_method       = prm.get_bool("vertex method");
      extension_principle = prm.get_bool("extension principle");
      prm.enter_subsection("Extension principle");
      points_per_dimension = prm.get_integer("points per dimension");
      reuse_factorisations = prm.get_bool("reuse factorisations");
      prm.leave_subsection();
      model.parse_parameters(prm);
      optimisation.parse_parameters(prm);

      scene = Scene::read(scene_file);
      fuzzy.parse_parameters(prm, scene);
      AssertThrow(!fuzzy.parameters().empty(),
                  ExcMessage("fuzzy parameters: name at least one fuzzy "
                             "parameter of the scene."));
    }
  };


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
    report_bounds();
    void
    write_output();

    void
    say(const std::string &text);

    MPI_Comm           comm;
    ConditionalOStream pcout;
    TimerOutput        timer;

    Parameters                         parameters;
    Scene                              scene;
    std::unique_ptr<FuzzyContactModel> model;
    std::vector<double>                alpha;

    FuzzyOutputBounds optimisation, vertex, reference;
    double            offline_time = 0;

    std::ostringstream report;
    OutputFiles        output;
    nlohmann::json     results;
  };


  FuzzyStudy::FuzzyStudy(const std::string &parameter_file, const MPI_Comm comm)
      : comm(comm)
      , pcout(std::cout, Utilities::MPI::this_mpi_process(comm) == 0)
      , timer(pcout, TimerOutput::never, TimerOutput::wall_times)
      , output("")
  {
    // All input is read and checked before anything is computed or written.
    Input::parse_in_passes(
      Input::read_text_file(parameter_file),
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
    alpha  = alpha_levels(parameters.n_alpha);
    output = OutputFiles(parameters.output_directory);
  }


  void
  FuzzyStudy::say(const std::string &text)
  {
    pcout << text << std::flush;
    report << text;
  }


  // @sect4{The model}
  //
  // Everything that does not depend on the fuzzy parameters is built once:
  // meshes, matrices, modes, static correction modes, the contact interface
  // and the reduced contact flexibility, plus the factorisations of the
  // exact solver. On several ranks each builds its own copy.
  void
  FuzzyStudy::build_model()
  {
    std::ostringstream out;
    out << "step-4: fuzzy contact study of the scene '" << scene.name << "' ("
        << parameters.scene_file << "), "
        << Utilities::MPI::n_mpi_processes(comm) << " MPI process(es)\n"
        << "fuzzy parameters:\n";
    for (const FuzzyParameter &p : parameters.fuzzy.parameters())
      out << "  " << std::left << std::setw(16) << p.quantity.name << std::right
          << p.number.to_string() << "\n";
    out << parameters.n_alpha << " alpha levels\n";
    say(out.str());

    Timer wall;
    model        = std::make_unique<FuzzyContactModel>(scene,
                                                parameters.fuzzy,
                                                parameters.model,
                                                &timer);
    offline_time = Utilities::MPI::max(wall.wall_time(), comm);
    std::ostringstream built;
    built << "model (built once, " << std::fixed << std::setprecision(2)
          << offline_time << " s):\n"
          << model->describe();
    say(built.str());
  }


  // @sect4{The bounds, three ways}
  void
  FuzzyStudy::compute_bounds()
  {
    const std::vector<FuzzyNumber> numbers = parameters.fuzzy.numbers();
    const std::vector<std::string> names   = FuzzyContactModel::output_names();
    const Response                 reduced = [&](const std::vector<double> &p) {
      return model->reduced(p);
    };
    const Response exact = [&](const std::vector<double> &p) {
      return model->full_order(p);
    };

    {
      TimerOutput::Scope scope(timer, "optimisation (reduced model)");
      optimisation = OptimisationMethod(parameters.optimisation)
                       .bounds(numbers, alpha, reduced, names, comm);
    }
    if (parameters.vertex_method)
      {
        TimerOutput::Scope scope(timer, "vertex method (reduced model)");
        vertex = VertexMethod().bounds(numbers, alpha, reduced, names, comm);
      }
    if (parameters.extension_principle)
      {
        model->set_reuse_factorisations(parameters.reuse_factorisations);
        say("Extension Principle: " +
            std::to_string(
              extension_principle_size(numbers,
                                       alpha,
                                       parameters.points_per_dimension)) +
            " exact full-order solves (" +
            std::to_string(parameters.points_per_dimension) +
            " points per parameter and level; " +
            (parameters.reuse_factorisations
               ? "factorisations reused where exact"
               : "independent analyses") +
            ")\n");
        TimerOutput::Scope scope(timer, "extension principle (full order)");
        reference = ExtensionPrinciple(parameters.points_per_dimension)
                      .bounds(numbers, alpha, exact, names, comm);
      }
  }


  // @sect4{Reporting}
  //
  // One table per output: the alpha-cut of each method and the relative
  // difference of the optimisation's (and the vertex method's) bounds from
  // the Extension Principle's. Then evaluation counts and times.
  namespace
  {
    std::string
    number(const double x)
    {
      std::ostringstream s;
      s << std::scientific << std::setprecision(5) << x;
      return s.str();
    }

    // Relative differences, with a floor for an output that is zero at
    // every level (F_t without friction).
    double
    difference(const std::vector<Interval> &b, const std::vector<Interval> &r)
    {
      double scale = 0;
      for (const Interval &i : r)
        scale = std::max({scale, std::abs(i.lower), std::abs(i.upper)});
      return max_relative_difference(b,
                                     r,
                                     scale > 0
                                       ? 1e-9 * scale
                                       : std::numeric_limits<double>::min());
    }
  } // namespace

  void
  FuzzyStudy::report_bounds()
  {
    const std::vector<std::string> names  = FuzzyContactModel::output_names();
    const std::vector<std::string> units  = {"m", "m", "N", "N"};
    const std::vector<std::string> titles = {"u_x of the slave node",
                                             "u_y of the slave node",
                                             "total normal force F_n",
                                             "total tangential force F_t"};
    const bool                     has_vertex = parameters.vertex_method;
    const bool                     has_ep     = parameters.extension_principle;

    results["scene"]            = scene.name;
    results["mpi_processes"]    = Utilities::MPI::n_mpi_processes(comm);
    results["n_dofs"]           = model->n_dofs();
    results["fuzzy_parameters"] = nlohmann::json::array();
    for (const FuzzyParameter &p : parameters.fuzzy.parameters())
      results["fuzzy_parameters"].push_back(
        {{"name", p.quantity.name},
         {"membership", p.number.to_string()},
         {"points", p.number.points()}});
    results["outputs"] = nlohmann::json::array();

    for (unsigned int k = 0; k < names.size(); ++k)
      {
        std::ostringstream out;
        out << "\n"
            << titles[k] << ", " << names[k] << " [" << units[k] << "]\n"
            << "  alpha   optimisation: lower      upper     ";
        if (has_vertex)
          out << "  vertex: lower      upper      ";
        if (has_ep)
          out << "  Extension Principle: lower  upper        rel. diff";
        out << "\n";
        nlohmann::json entry;
        entry["name"]  = names[k];
        entry["unit"]  = units[k];
        entry["alpha"] = alpha;
        std::vector<double> lo, hi, rlo, rhi, vlo, vhi;
        for (unsigned int l = 0; l < alpha.size(); ++l)
          {
            const Interval o = optimisation.bounds[k][l];
            lo.push_back(o.lower);
            hi.push_back(o.upper);
            out << "  " << std::fixed << std::setprecision(2) << alpha[l]
                << "   " << std::setw(12) << number(o.lower) << " "
                << std::setw(12) << number(o.upper);
            if (has_vertex)
              {
                const Interval v = vertex.bounds[k][l];
                vlo.push_back(v.lower);
                vhi.push_back(v.upper);
                out << "   " << std::setw(12) << number(v.lower) << " "
                    << std::setw(12) << number(v.upper);
              }
            if (has_ep)
              {
                const Interval r = reference.bounds[k][l];
                rlo.push_back(r.lower);
                rhi.push_back(r.upper);
                out << "   " << std::setw(12) << number(r.lower) << " "
                    << std::setw(12) << number(r.upper) << "   "
                    << std::setprecision(1) << std::scientific
                    << difference({o}, {r});
              }
            out << "\n";
          }
        entry["lower"] = lo;
        entry["upper"] = hi;
        if (has_vertex)
          {
            entry["vertex_lower"] = vlo;
            entry["vertex_upper"] = vhi;
          }
        if (has_ep)
          {
            entry["reference_lower"] = rlo;
            entry["reference_upper"] = rhi;
            entry["max_rel_error"] =
              difference(optimisation.bounds[k], reference.bounds[k]);
            out << "  largest relative difference from the Extension "
                   "Principle: optimisation "
                << std::scientific << std::setprecision(2)
                << double(entry["max_rel_error"]);
            if (has_vertex)
              {
                entry["vertex_max_rel_error"] =
                  difference(vertex.bounds[k], reference.bounds[k]);
                out << ", vertex method "
                    << double(entry["vertex_max_rel_error"]);
              }
            out << "\n";
          }
        results["outputs"].push_back(entry);
        say(out.str());
      }

    // Non-monotone responses found by the optimisation.
    std::ostringstream notes;
    notes << "\nmonotonicity: ";
    if (optimisation.notes.empty())
      notes << "no non-monotone response detected (no interior optimum, no "
               "vertex better than a local optimum, no sensitivity changing "
               "sign)\n";
    else
      {
        notes << optimisation.notes.size() << " finding(s):\n";
        for (const std::string &n : optimisation.notes)
          notes << "  " << n << "\n";
      }
    results["notes"] = optimisation.notes;
    say(notes.str());

    // Cost: evaluations and wall times, the fast study against the
    // reference run beside it.
    const double       study = offline_time + optimisation.wall_time;
    std::ostringstream cost;
    cost << "\ncost (wall time, " << Utilities::MPI::n_mpi_processes(comm)
         << " process(es))\n"
         << "  offline (model built once)            " << std::fixed
         << std::setprecision(2) << std::setw(8) << offline_time << " s\n"
         << "  optimisation, reduced model           " << std::setw(8)
         << optimisation.wall_time << " s  " << optimisation.n_evaluations
         << " evaluations\n";
    results["time_s"]["offline"]           = offline_time;
    results["time_s"]["optimisation"]      = optimisation.wall_time;
    results["time_s"]["fuzzy_study"]       = study;
    results["evaluations"]["optimisation"] = optimisation.n_evaluations;
    if (has_vertex)
      {
        cost << "  vertex method, reduced model          " << std::setw(8)
             << vertex.wall_time << " s  " << vertex.n_evaluations
             << " evaluations\n";
        results["time_s"]["vertex"]      = vertex.wall_time;
        results["evaluations"]["vertex"] = vertex.n_evaluations;
      }
    if (has_ep)
      {
        cost << "  Extension Principle, full order       " << std::setw(8)
             << reference.wall_time << " s  " << reference.n_evaluations
             << " evaluations\n"
             << "  the fuzzy study (offline + optimisation) takes "
             << std::setw(6) << study << " s, " << std::setprecision(1)
             << reference.wall_time / study
             << "x less than the Extension Principle\n";
        results["time_s"]["extension_principle"]      = reference.wall_time;
        results["evaluations"]["extension_principle"] = reference.n_evaluations;
        results["speed_up"] = reference.wall_time / study;
      }
    say(cost.str());
  }


  // @sect4{Output}
  //
  // report.txt, results.json and the membership functions as a picture
  // (membership.png, drawn by gnuplot from membership.dat/.gp), written by
  // the first rank at the end.
  void
  FuzzyStudy::write_output()
  {
    TimerOutput::Scope             scope(timer, "output");
    const std::vector<std::string> titles = {"u_x of the slave node",
                                             "u_y of the slave node",
                                             "normal contact force F_n",
                                             "tangential contact force F_t"};
    const std::vector<std::string> units  = {"u_x [mm]",
                                             "u_y [mm]",
                                             "F_n [kN]",
                                             "F_t [kN]"};
    const std::vector<double>      scales = {1e-3, 1e-3, 1e3, 1e3};
    std::vector<MembershipPanel>   panels;
    for (unsigned int k = 0; k < titles.size(); ++k)
      {
        MembershipPanel panel{titles[k], units[k], scales[k], {}};
        if (parameters.extension_principle)
          panel.curves.push_back({"Extension Principle (full order)",
                                  alpha,
                                  reference.bounds[k],
                                  "points pt 7 ps 0.9 lc rgb '#444444'"});
        panel.curves.push_back({"optimisation (reduced model)",
                                alpha,
                                optimisation.bounds[k],
                                "lines lw 2 lc rgb '#1f77b4'"});
        if (parameters.vertex_method)
          panel.curves.push_back({"vertex method (reduced model)",
                                  alpha,
                                  vertex.bounds[k],
                                  "lines lw 2 dt 2 lc rgb '#d62728'"});
        panels.push_back(panel);
      }

    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return;
    std::string message;
    if (!add_membership_plot(output,
                             "membership",
                             "Fuzzy response of the scene '" + scene.name + "'",
                             panels,
                             message))
      say("warning: " + message + "\n");
    output.add("report.txt", report.str());
    output.add("results.json", results.dump(2) + "\n");
    output.write_all();
    pcout << "\nWrote report.txt, results.json and membership.png (.dat, .gp) "
             "to "
          << output.directory() << "/" << std::endl;
  }


  void
  FuzzyStudy::run()
  {
    build_model();
    compute_bounds();
    report_bounds();
    write_output();
    timer.print_summary();
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
  return status;
}
