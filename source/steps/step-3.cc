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
// the displacements of the report's slave node (P1's bottom-right corner)
// and of the two master nodes around it, the total normal and tangential
// contact forces, the errors against full_order, iterations and times.
// It then sets the `overlap` case in plane strain beside the paper's Table
// 3, and writes report.txt, results.json and VTU files of the deformed
// bodies with the contact pressure.
//
// Usage: step-3 prm/step-3.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/program.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/contact/full_order_contact.h>
#include <fuzzycontact/fe/beam_theory.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/reduction/reduced_model.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/sparse_direct.h>
#include <deal.II/numerics/data_out.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

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
    unsigned int             mesh_refinements;
    double                   load;
    std::vector<double>      friction_coefficients;
    unsigned int             n_load_steps;
    double                   penetration_tolerance;
    bool                     write_vtu;
    ModalParameters          modal;
    double                   mode_error_tolerance;
    double                   rank_tolerance;
    ActiveSetParameters      exact;
    FL2CParameters           fl2c;

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
      prm.declare_entry("mesh refinements",
                        "2",
                        Patterns::Integer(0, 5),
                        "Global refinements of each component's mesh.");
      prm.declare_entry("load",
                        "50000",
                        Patterns::Double(),
                        "Total external load [N]; the scene's loads are "
                        "scaled to this resultant.");
      prm.declare_entry("friction coefficients",
                        "0, 0.3",
                        Patterns::Anything(),
                        "Coulomb coefficients (>= 0) to solve each scene "
                        "with.");
      prm.declare_entry("load steps",
                        "1",
                        Patterns::Integer(),
                        "Proportional load steps.");
      prm.declare_entry("penetration tolerance",
                        "1e-8",
                        Patterns::Double(),
                        "Initial penetration accepted as round-off, "
                        "relative to the master face length.");
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
      AssertThrow(!output_directory.empty(),
                  ExcMessage("output directory must not be empty."));
      mesh_refinements = prm.get_integer("mesh refinements");
      load             = Input::finite(prm.get_double("load"), "load");
      friction_coefficients =
        Input::to_doubles(prm.get("friction coefficients"),
                          "friction coefficients");
      AssertThrow(!friction_coefficients.empty(),
                  ExcMessage("friction coefficients: at least one value "
                             "is needed."));
      for (const double mu : friction_coefficients)
        Input::non_negative(mu, "friction coefficients: each value");
      const long steps = prm.get_integer("load steps");
      AssertThrow(steps >= 1,
                  ExcMessage("load steps must be at least 1, got " +
                             std::to_string(steps) + "."));
      n_load_steps = steps;
      penetration_tolerance =
        Input::non_negative(prm.get_double("penetration tolerance"),
                            "penetration tolerance");
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
    }
  };


  // @sect3{Small helpers}

  std::string
  sci(const double value, const int digits = 3)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << value;
    return s.str();
  }

  // |a - b| / |b|; 0 if both vanish, 1 (100 %) if only the reference does.
  double
  relative_error(const double a, const double b)
  {
    if (b == 0)
      return a == 0 ? 0. : 1.;
    return std::abs(a - b) / std::abs(b);
  }

  double
  relative_error(const std::array<double, 2> &a, const std::array<double, 2> &b)
  {
    const double reference = std::hypot(b[0], b[1]);
    const double error     = std::hypot(a[0] - b[0], a[1] - b[1]);
    if (reference == 0)
      return error == 0 ? 0. : 1.;
    return error / reference;
  }


  // One solver's answer with the displacement fields for the VTU files.
  struct SolverRun
  {
    ContactSolution             solution;
    std::vector<Vector<double>> fields;
  };

  // Everything about one scene, plane model and friction coefficient.
  struct CaseResult
  {
    std::string               scene;
    PlaneModel                plane_model;
    double                    load;
    double                    mu;
    std::vector<unsigned int> n_dofs;
    unsigned int              n_nodes;
    std::vector<SolverRun>    runs; // full, reduced_exact, fl2c_modes,
                                    // fl2c_corrected, reduced_exact_modes
    double      full_order_warm_time = 0;
    std::string beam_theory;
  };


  // @sect3{The ContactStudy class}
  class ContactStudy
  {
  public:
    explicit ContactStudy(const std::string &parameter_file);
    void
    run();

  private:
    std::vector<CaseResult>
    analyse(const Scene               &scene,
            const std::vector<double> &friction_coefficients,
            const std::string         &label);
    void
    print_case(const CaseResult &c);
    nlohmann::json
    case_json(const CaseResult &c) const;
    void
    compare_with_paper(const std::vector<CaseResult> &cases);
    void
    add_vtu(const CaseResult                     &c,
            const std::vector<const Component *> &components,
            const ContactInterface               &interface,
            const std::string                    &label);
    void
    say(const std::string &text);

    Parameters         parameters;
    std::vector<Scene> scenes;
    bool               with_paper = false;
    Scene              paper_scene;
    TimerOutput        timer;
    std::ostringstream report;
    OutputFiles        output;
    nlohmann::json     results;
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
    for (const std::string &file : parameters.scene_files)
      {
        scenes.push_back(Scene::read(file));
        AssertThrow(!scenes.back().contact_pairs.empty(),
                    ExcMessage("Scene " + file + " has no contact pairs."));
      }
    if (!parameters.paper_scene_file.empty())
      {
        with_paper              = true;
        paper_scene             = Scene::read(parameters.paper_scene_file);
        paper_scene.plane_model = PlaneModel::plane_strain;
        AssertThrow(!paper_scene.contact_pairs.empty(),
                    ExcMessage("The paper scene has no contact pairs."));
      }
    output = OutputFiles(parameters.output_directory);
  }


  void
  ContactStudy::say(const std::string &text)
  {
    std::cout << text << std::flush;
    report << text;
  }


  // @sect4{One scene: components, contact geometry, reduced models, and the
  // four solvers for every friction coefficient}
  std::vector<CaseResult>
  ContactStudy::analyse(const Scene               &scene,
                        const std::vector<double> &friction_coefficients,
                        const std::string         &label)
  {
    TimerOutput local(std::cout, TimerOutput::never, TimerOutput::wall_times);

    std::vector<std::unique_ptr<Component>> owned;
    std::vector<const Component *>          components;
    for (const ComponentDescription &d : scene.components)
      {
        TimerOutput::Scope scope(timer, "assembly");
        owned.push_back(std::make_unique<Component>(d,
                                                    scene.plane_model,
                                                    parameters.mesh_refinements,
                                                    &local));
        components.push_back(owned.back().get());
      }
    ContactInterface interface(scene,
                               components,
                               parameters.penetration_tolerance);

    // The scene's loads, scaled to the requested resultant.
    double declared = 0;
    for (const ComponentDescription &d : scene.components)
      for (const EdgeLoad &load : d.loads)
        declared += std::abs(load.total_force);
    AssertThrow(declared > 0 || parameters.load == 0,
                ExcMessage("Scene " + scene.name +
                           " declares no load to scale to the requested "
                           "load."));
    const double load_factor = declared > 0 ? parameters.load / declared : 0.;

    // The report's slave node: the candidate farthest along the master
    // tangent (P1's bottom-right corner in both scenes).
    const unsigned int slave  = interface.report_node();
    const ReportNodes  report = interface.report_nodes(slave);
    std::vector<std::vector<types::global_dof_index>> observed(
      components.size());
    for (const FaceNode *node :
         {&report.slave, &report.master[0], &report.master[1]})
      for (unsigned int d = 0; d < 2; ++d)
        observed[node->component].push_back(node->dofs[d]);

    // Modes, and the two reduced models.
    const ModalSolver       modal_solver(parameters.modal);
    std::vector<ModalBasis> bases;
    for (const Component *component : components)
      {
        TimerOutput::Scope scope(timer, "modes (ARPACK)");
        local.enter_subsection("modes");
        bases.push_back(modal_solver.solve(component->stiffness_matrix(),
                                           component->mass_matrix(),
                                           "Component " + component->name()));
        local.leave_subsection();
      }
    if (parameters.mode_error_tolerance > 0)
      for (unsigned int c = 0; c < components.size(); ++c)
        {
          // The component's part of the report node's normal flexibility.
          Vector<double> f(components[c]->n_dofs());
          for (auto it = interface.gap_operator(c).begin(normal_row(slave));
               it != interface.gap_operator(c).end(normal_row(slave));
               ++it)
            f[it->column()] = it->value();
          if (f.linfty_norm() == 0)
            continue;
          SparseDirectUMFPACK inverse;
          inverse.initialize(components[c]->stiffness_matrix());
          Vector<double> u = f;
          inverse.solve(u);
          const unsigned int n =
            modes_for_static_error(bases[c],
                                   f,
                                   u,
                                   parameters.mode_error_tolerance,
                                   "Component " + components[c]->name());
          bases[c].eigenvalues.resize(n);
          bases[c].modes.resize(n);
          bases[c].residuals.resize(n);
        }

    std::vector<std::unique_ptr<ReducedComponent>> reduced[2];
    std::unique_ptr<ReducedContactModel>           models[2];
    for (const bool corrected : {false, true})
      {
        std::vector<ReducedComponentMatrices> matrices;
        for (unsigned int c = 0; c < components.size(); ++c)
          {
            TimerOutput::Scope scope(timer,
                                     corrected ? "static correction modes"
                                               : "reduced matrices");
            local.enter_subsection(corrected ? "static correction"
                                             : "modal reduction");
            reduced[corrected].push_back(
              std::make_unique<ReducedComponent>(*components[c],
                                                 bases[c],
                                                 interface.contact_dofs(c),
                                                 corrected,
                                                 parameters.rank_tolerance));
            matrices.push_back(
              reduced[corrected].back()->matrices(interface.gap_operator(c),
                                                  observed[c]));
            local.leave_subsection();
          }
        TimerOutput::Scope scope(timer, "reduced contact flexibility W");
        local.enter_subsection(corrected ? "W (corrected)" : "W (modes)");
        models[corrected] = std::make_unique<ReducedContactModel>(
          std::move(matrices),
          interface.initial_gaps(),
          interface.friction_coefficients());
        local.leave_subsection();
      }

    {
      std::ostringstream out;
      out << "\n" << label << ": " << components.size() << " components (";
      for (unsigned int c = 0; c < components.size(); ++c)
        out << (c > 0 ? ", " : "") << components[c]->name() << " "
            << components[c]->n_dofs() << " DoFs, " << bases[c].size()
            << " modes up to " << std::fixed << std::setprecision(0)
            << bases[c].frequencies().back() << " Hz + "
            << reduced[1][c]->n_corrections() << " correction modes";
      out << "), " << interface.n_nodes() << " slave nodes\n";
      const auto t = local.get_summary_data(TimerOutput::total_wall_time);
      out << " offline [s]: assembly " << std::setprecision(3)
          << t.at("assembly") << ", modes " << t.at("modes")
          << ", static correction " << t.at("static correction") << ", W "
          << t.at("W (modes)") << " (modes) / " << t.at("W (corrected)")
          << " (corrected)\n";
      say(out.str());
      nlohmann::json offline;
      offline["scene"]       = scene.name;
      offline["plane_model"] = to_string(scene.plane_model);
      offline["times_s"]     = t;
      for (unsigned int c = 0; c < components.size(); ++c)
        {
          offline["components"].push_back(
            {{"name", components[c]->name()},
             {"n_dofs", components[c]->n_dofs()},
             {"n_modes", bases[c].size()},
             {"highest_frequency_hz", bases[c].frequencies().back()},
             {"n_correction_modes", reduced[1][c]->n_corrections()}});
        }
      results["offline"].push_back(offline);
    }

    // The solvers, for every friction coefficient.
    std::vector<CaseResult> cases;
    for (const double mu : friction_coefficients)
      {
        interface.set_friction_coefficient(mu);
        for (auto &model : models)
          model->problem().set_friction_coefficient(mu);

        CaseResult c;
        c.scene       = scene.name;
        c.plane_model = scene.plane_model;
        c.load        = parameters.load;
        c.mu          = mu;
        for (const Component *component : components)
          c.n_dofs.push_back(component->n_dofs());
        c.n_nodes = interface.n_nodes();

        {
          // A fresh full-order solver: its time is that of a cold solve
          // (factorisations included); a second solve shows the warm cost.
          TimerOutput::Scope scope(timer, "full_order");
          FullOrderContact   full(components, interface, parameters.exact);
          full.set_load_factor(load_factor);
          full.set_n_load_steps(parameters.n_load_steps);
          SolverRun run;
          run.solution           = full.solve(&report);
          run.fields             = run.solution.displacements;
          c.full_order_warm_time = full.solve(&report).time;
          c.runs.push_back(std::move(run));
        }

        const auto reduced_run =
          [&](const bool corrected, const bool fuzzy, const std::string &name) {
            TimerOutput::Scope         scope(timer, name);
            const ReducedContactModel &model = *models[corrected];
            Timer                      clock;
            const ContactState state = fuzzy ? FL2CSolver(parameters.fl2c)
                                                 .solve(model.problem(),
                                                        load_factor,
                                                        parameters.n_load_steps,
                                                        name)
                                             : ActiveSetSolver(parameters.exact)
                                                 .solve(model.problem(),
                                                        load_factor,
                                                        parameters.n_load_steps,
                                                        name);
            SolverRun          run;
            run.solution = model.solution(state, load_factor, &report, name);
            run.solution.time         = clock.wall_time();
            run.solution.n_load_steps = parameters.n_load_steps;
            if (parameters.write_vtu)
              {
                const std::vector<Vector<double>> q =
                  model.coordinates(state.p, load_factor);
                for (unsigned int i = 0; i < components.size(); ++i)
                  {
                    Vector<double> u;
                    reduced[corrected][i]->expand(q[i], u);
                    run.fields.push_back(std::move(u));
                  }
              }
            return run;
          };
        c.runs.push_back(reduced_run(true, false, "reduced_exact"));
        c.runs.push_back(reduced_run(false, true, "fl2c_modes"));
        c.runs.push_back(reduced_run(true, true, "fl2c_corrected"));
        c.runs.push_back(reduced_run(false, false, "reduced_exact_modes"));

        // Beam theory beside the full-order answer.
        std::ostringstream theory;
        if (scene.components.size() == 2)
          {
            const auto beam =
              BeamTheory::Beam::of(scene.components[0], scene.plane_model);
            const double F = parameters.load;
            const double EI =
              beam.effective_modulus() * beam.second_moment_of_area();
            const double L = beam.length;
            if (scene.name == "stacked")
              theory << "Euler-Bernoulli tip deflection: load shared equally "
                        "(mu = 0) F L^3 / (3 E' 2I) = "
                     << sci(F * L * L * L / (3 * EI * 2))
                     << " m, composite beam (full stick) F L^3 / (3 E' 8I) = "
                     << sci(F * L * L * L / (3 * EI * 8))
                     << " m; full_order slave uy = "
                     << sci(c.runs[0].solution.slave_displacement[1]) << " m";
            else if (scene.name == "overlap")
              {
                const double a = scene.components[1].upper_right[0] -
                                 scene.components[0].upper_right[0];
                theory
                  << "Euler-Bernoulli with contact at P1's tip only: N = F "
                     "L^3 / (L^3 + a^3) = "
                  << std::fixed << std::setprecision(0)
                  << F * L * L * L / (L * L * L + a * a * a)
                  << " N (L = " << std::setprecision(3) << L << " m, a = " << a
                  << " m); full_order F_n = " << std::setprecision(0)
                  << c.runs[0].solution.normal_force << " N";
              }
          }
        c.beam_theory = theory.str();

        if (parameters.write_vtu)
          add_vtu(c, components, interface, label);
        cases.push_back(std::move(c));
      }
    return cases;
  }


  // @sect4{The table of one case}
  void
  ContactStudy::print_case(const CaseResult &c)
  {
    const ContactSolution &ref = c.runs[0].solution;
    std::ostringstream     out;
    out << "\nCase " << c.scene << " (" << to_string(c.plane_model)
        << "), F = " << c.load << " N, mu = " << c.mu << "; " << c.n_dofs[0]
        << " DoFs per component, " << c.n_nodes << " slave nodes\n";
    out << " solver                slave ux     slave uy    master1 ux   "
           "master1 uy   master2 ux   master2 uy    F_n [N]      F_t [N]   "
           " err F_n   err u_s  err ux   it   residual   time [s]  "
           "speed-up\n";
    for (const SolverRun &run : c.runs)
      {
        const ContactSolution &s = run.solution;
        out << " " << std::left << std::setw(20) << s.solver << std::right;
        for (const double v : {s.slave_displacement[0],
                               s.slave_displacement[1],
                               s.master_displacements[0][0],
                               s.master_displacements[0][1],
                               s.master_displacements[1][0],
                               s.master_displacements[1][1]})
          out << std::setw(13) << sci(v);
        out << std::setw(13) << sci(s.normal_force, 5) << std::setw(13)
            << sci(s.tangential_force, 4);
        out << std::setw(10)
            << sci(relative_error(s.normal_force, ref.normal_force), 1)
            << std::setw(10)
            << sci(relative_error(s.slave_displacement, ref.slave_displacement),
                   1)
            << std::setw(9)
            << sci(relative_error(s.slave_displacement[0],
                                  ref.slave_displacement[0]),
                   1)
            << std::setw(5) << s.iterations << std::setw(11)
            << sci(s.residual, 1) << std::setw(11) << sci(s.time, 2)
            << std::setw(9) << std::fixed << std::setprecision(0)
            << ref.time / std::max(s.time, 1e-9) << "\n";
      }
    out << " closed nodes (full_order): "
        << ref.n_nodes() - ref.count(ContactStatus::open) << " ("
        << ref.count(ContactStatus::stick) << " stick, "
        << ref.count(ContactStatus::slip) << " slip); full_order warm re-solve "
        << sci(c.full_order_warm_time, 2)
        << " s (same stiffness: factorisations and columns of W reused)\n";
    if (!c.beam_theory.empty())
      out << " " << c.beam_theory << "\n";
    out << " errors relative to full_order: F_n, slave displacement vector "
           "(u_s), slave ux; time: one solve (full_order cold, with its "
           "factorisations; reduced solvers on a ready reduced model)\n";
    say(out.str());
  }


  nlohmann::json
  ContactStudy::case_json(const CaseResult &c) const
  {
    const ContactSolution &ref = c.runs[0].solution;
    nlohmann::json         j;
    j["scene"]                  = c.scene;
    j["plane_model"]            = to_string(c.plane_model);
    j["load"]                   = c.load;
    j["mu"]                     = c.mu;
    j["n_dofs_per_component"]   = c.n_dofs;
    j["n_slave_nodes"]          = c.n_nodes;
    j["full_order_warm_time_s"] = c.full_order_warm_time;
    j["solvers"]                = nlohmann::json::array();
    for (const SolverRun &run : c.runs)
      {
        const ContactSolution &s = run.solution;
        nlohmann::json         e;
        e["name"]                 = s.solver;
        e["Fn"]                   = s.normal_force;
        e["Ft"]                   = s.tangential_force;
        e["slave_ux"]             = s.slave_displacement[0];
        e["slave_uy"]             = s.slave_displacement[1];
        e["iterations"]           = s.iterations;
        e["time_s"]               = s.time;
        e["master_displacements"] = s.master_displacements;
        e["residual"]             = s.residual;
        e["closed_nodes"]         = s.n_nodes() - s.count(ContactStatus::open);
        e["Fn_error"] = relative_error(s.normal_force, ref.normal_force);
        e["Ft_error"] =
          relative_error(s.tangential_force, ref.tangential_force);
        e["slave_error"] =
          relative_error(s.slave_displacement, ref.slave_displacement);
        if (s.solver == "reduced_exact_modes")
          j["reduced_exact_modes"] = e;
        else
          j["solvers"].push_back(e);
      }
    return j;
  }


  // @sect4{VTU: deformed bodies with contact pressure}
  void
  ContactStudy::add_vtu(const CaseResult                     &c,
                        const std::vector<const Component *> &components,
                        const ContactInterface               &interface,
                        const std::string                    &label)
  {
    const Vector<double>             &p      = c.runs[0].solution.p;
    const std::vector<Vector<double>> forces = interface.nodal_forces(p);
    for (unsigned int i = 0; i < components.size(); ++i)
      {
        const Component &component = *components[i];
        // Contact pressure and shear traction at the slave nodes, as the
        // two scalar fields of one DoF vector (x slot: pressure, y slot:
        // shear).
        Vector<double> traction(component.n_dofs());
        for (unsigned int k = 0; k < interface.n_nodes(); ++k)
          {
            const ContactNode &node = interface.node(k);
            if (node.slave.component != i)
              continue;
            const double area =
              node.tributary_length * component.description().thickness;
            traction[node.slave.dofs[0]] = p[normal_row(k)] / area;
            traction[node.slave.dofs[1]] = p[tangential_row(k)] / area;
          }
        DataOut<2> data_out;
        data_out.attach_dof_handler(component.dof_handler());
        const std::vector<
          DataComponentInterpretation::DataComponentInterpretation>
          vector(2, DataComponentInterpretation::component_is_part_of_vector),
          scalars(2, DataComponentInterpretation::component_is_scalar);
        for (const SolverRun &run : c.runs)
          if (run.fields.size() == components.size())
            data_out.add_data_vector(
              run.fields[i],
              std::vector<std::string>(2, "u_" + run.solution.solver),
              DataOut<2>::type_dof_data,
              vector);
        data_out.add_data_vector(forces[i],
                                 std::vector<std::string>(2, "contact_force"),
                                 DataOut<2>::type_dof_data,
                                 vector);
        data_out.add_data_vector(traction,
                                 std::vector<std::string>{"contact_pressure",
                                                          "contact_shear"},
                                 DataOut<2>::type_dof_data,
                                 scalars);
        data_out.build_patches(component.fe().degree);
        std::ostringstream vtu;
        data_out.write_vtu(vtu);
        std::ostringstream name;
        name << "contact-" << label << "-mu" << c.mu << "-" << component.name()
             << ".vtu";
        output.add(name.str(), vtu.str());
      }
  }


  // @sect4{The paper's Table 3}
  //
  // The paper does not give its friction coefficient; the cases of the
  // paper scene (mu = 0 and the scene's mu) are all set beside it.
  void
  ContactStudy::compare_with_paper(const std::vector<CaseResult> &cases)
  {
    struct Column
    {
      std::string           name;
      std::array<double, 7> values;
    };
    // Table 3 of Massa et al. (2013): Ux^e, Uy^e, Ux^m1, Uy^m1, Ux^m2,
    // Uy^m2 [m], F_n [N].
    const Column abaqus{
      "Abaqus (paper)",
      {{5.20e-5, -1.50e-3, 7.54e-5, -1.59e-3, 7.64e-5, -1.50e-3, 44407}}};
    const Column paper_fl2c{
      "FL2C (paper)",
      {{4.48e-5, -1.50e-3, 9.01e-5, -1.59e-3, 9.00e-5, -1.50e-3, 44505}}};
    std::vector<Column> columns = {abaqus, paper_fl2c};
    for (const CaseResult &c : cases)
      for (const SolverRun &run : c.runs)
        {
          const ContactSolution &s = run.solution;
          if (s.solver != "full_order" && s.solver != "fl2c_modes" &&
              s.solver != "fl2c_corrected")
            continue;
          std::ostringstream name;
          name << s.solver << " mu=" << c.mu;
          columns.push_back({name.str(),
                             {{s.slave_displacement[0],
                               s.slave_displacement[1],
                               s.master_displacements[0][0],
                               s.master_displacements[0][1],
                               s.master_displacements[1][0],
                               s.master_displacements[1][1],
                               s.normal_force}}});
        }
    const std::array<std::string, 7> rows = {
      {"Ux slave", "Uy slave", "Ux m1", "Uy m1", "Ux m2", "Uy m2", "F_n [N]"}};

    std::ostringstream out;
    out << "\nComparison with Table 3 of the paper: " << cases[0].scene
        << " in plane strain, F = " << cases[0].load
        << " N (our reconstruction of the lost Fig. 4)\n";
    out << " quantity ";
    for (const Column &col : columns)
      out << std::setw(col.name.size() > 15 ? col.name.size() + 2 : 17)
          << col.name;
    out << "\n";
    for (unsigned int r = 0; r < rows.size(); ++r)
      {
        out << " " << std::left << std::setw(8) << rows[r] << std::right;
        for (const Column &col : columns)
          out << std::setw(col.name.size() > 15 ? col.name.size() + 2 : 17)
              << (r < 6 ? sci(col.values[r], 3) : sci(col.values[r], 5));
        out << "\n";
      }
    out << " |ours| / |Abaqus| for full_order mu=" << cases[0].mu << ":";
    for (unsigned int r = 0; r < rows.size(); ++r)
      out << " " << rows[r] << " " << std::fixed << std::setprecision(3)
          << std::abs(columns[2].values[r] / abaqus.values[r]) << ";";
    out << "\n (the paper lists Ux as positive where our fibres move towards "
           "-x; m1, m2 are the vertices of the master segment under the "
           "slave node)\n";
    if (!cases[0].beam_theory.empty())
      out << " " << cases[0].beam_theory << "\n";
    say(out.str());

    nlohmann::json j;
    for (const CaseResult &c : cases)
      j["cases"].push_back(case_json(c));
    for (unsigned int i = 0; i < 2; ++i)
      j["paper"][i == 0 ? "abaqus" : "fl2c"] = {
        {"slave_ux", columns[i].values[0]},
        {"slave_uy", columns[i].values[1]},
        {"master_displacements",
         {{columns[i].values[2], columns[i].values[3]},
          {columns[i].values[4], columns[i].values[5]}}},
        {"Fn", columns[i].values[6]}};
    results["paper_comparison"] = j;
  }


  void
  ContactStudy::run()
  {
    say("step-3: frictional contact solved four ways (full order, reduced "
        "exact, FL2C on modes, FL2C with static correction)\n");
    results["cases"] = nlohmann::json::array();
    for (const Scene &scene : scenes)
      {
        const std::vector<CaseResult> cases =
          analyse(scene,
                  parameters.friction_coefficients,
                  scene.name + "-" +
                    (scene.plane_model == PlaneModel::plane_stress ? "stress"
                                                                   : "strain"));
        for (const CaseResult &c : cases)
          {
            print_case(c);
            results["cases"].push_back(case_json(c));
          }
      }
    if (with_paper)
      {
        // The paper does not say which friction coefficient it used:
        // frictionless and the scene's own.
        std::vector<double> mus = {0.};
        const double mu = paper_scene.contact_pairs[0].friction_coefficient;
        if (mu > 0)
          mus.push_back(mu);
        const std::vector<CaseResult> cases =
          analyse(paper_scene, mus, paper_scene.name + "-strain");
        for (const CaseResult &c : cases)
          print_case(c);
        compare_with_paper(cases);
      }

    {
      TimerOutput::Scope scope(timer, "output");
      output.add("report.txt", report.str());
      output.add("results.json", results.dump(2) + "\n");
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
