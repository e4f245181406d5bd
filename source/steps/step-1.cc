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
// Usage: step-1 prm/step-1.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/program.h>
#include <fuzzycontact/fe/beam_theory.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>
#include <deal.II/numerics/data_out.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

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
      AssertThrow(!output_directory.empty(),
                  ExcMessage("output directory must not be empty."));
      mesh_refinements        = prm.get_integer("mesh refinements");
      convergence_refinements = prm.get_integer("convergence refinements");
      compare_with_paper      = prm.get_bool("compare with paper");
      paper_cutoff_frequency =
        Input::positive(prm.get_double("paper cutoff frequency"),
                        "paper cutoff frequency");
      modal.parse_parameters(prm);
    }
  };


  // @sect3{Classifying modes}
  //
  // A mode of a slender beam is either a bending mode (mostly transverse
  // motion) or an axial one (mostly longitudinal). With M-normalised modes,
  // phi_y^T M phi_y is the share of the kinetic energy in the y direction;
  // the mass matrix does not couple x and y, so the two shares add to 1.
  struct ModeKind
  {
    bool         bending;
    unsigned int order; // 1 for the first bending (or axial) mode, ...
    double       transverse_share;

    std::string
    name() const
    {
      return (bending ? "bending " : "axial ") + std::to_string(order);
    }
  };

  std::vector<ModeKind>
  classify(const Component &component, const ModalBasis &basis)
  {
    std::vector<ModeKind> kinds;
    unsigned int          n_bending = 0, n_axial = 0;
    const auto           &direction = component.dof_directions();
    Vector<double>        phi_y(component.n_dofs());
    for (const Vector<double> &phi : basis.modes)
      {
        for (unsigned int i = 0; i < phi.size(); ++i)
          phi_y[i] = (direction[i] == 1 ? phi[i] : 0.);
        const double share = component.mass_matrix().matrix_norm_square(phi_y) /
                             component.mass_matrix().matrix_norm_square(phi);
        const bool bending = share > 0.5;
        kinds.push_back(
          ModeKind{bending, bending ? ++n_bending : ++n_axial, share});
      }
    return kinds;
  }


  // The paper's Table 1: the first nine frequencies of its beams [Hz].
  const std::vector<double> paper_table_1 =
    {174.8, 1087.1, 3007.7, 5796.6, 6449.5, 9387.7, 13693, 18625, 24094};

  std::string
  percent(const double relative)
  {
    std::ostringstream s;
    s << std::showpos << std::fixed << std::setprecision(3) << 100 * relative
      << "%";
    return s.str();
  }

  std::string
  scientific(const double value, const int digits = 1)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << value;
    return s.str();
  }


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
    void
    write_output();

    // Prints to the screen and keeps a copy for report.txt.
    void
    say(const std::string &text);

    Parameters  parameters;
    Scene       scene;
    TimerOutput timer;

    std::ostringstream report;
    OutputFiles        output;
    nlohmann::json     results;
  };


  ModalAnalysis::ModalAnalysis(const std::string &parameter_file)
      : timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
      , output("")
  {
    // All input is read and checked before anything is computed or written.
    ParameterHandler prm;
    Parameters::declare_parameters(prm);
    Input::parse_strictly(prm, parameter_file);
    parameters.parse_parameters(prm, parameter_file);
    scene  = Scene::read(parameters.scene_file);
    output = OutputFiles(parameters.output_directory);
  }


  void
  ModalAnalysis::say(const std::string &text)
  {
    std::cout << text << std::flush;
    report << text;
  }


  // @sect4{Modes of each component, next to beam theory}
  //
  // Bending mode n is compared with the n-th Euler-Bernoulli and Timoshenko
  // frequencies of a clamped-free beam, axial mode n with the bar value
  // (2n-1) c / (4L). The beam formulas apply to a component clamped at one
  // end face only; for others only the FE values are listed.
  void
  ModalAnalysis::analyse_components()
  {
    const ModalSolver solver(parameters.modal);
    results["components"] = nlohmann::json::array();

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
        const std::vector<ModeKind> kinds = classify(component, basis);
        const std::vector<double>   f     = basis.frequencies();

        const bool cantilever = description.clamped_faces.size() == 1 &&
                                (description.clamped_faces[0] == Face::left ||
                                 description.clamped_faces[0] == Face::right);
        bool single_material = true;
        for (const MaterialZone &z : description.zones)
          single_material =
            single_material &&
            z.youngs_modulus == description.zones[0].youngs_modulus &&
            z.poissons_ratio == description.zones[0].poissons_ratio &&
            z.density == description.zones[0].density;
        const bool with_theory = cantilever && single_material;

        std::ostringstream out;
        out << "\nComponent " << description.name << " ("
            << to_string(scene.plane_model) << ", "
            << description.subdivisions[0] * (1u << parameters.mesh_refinements)
            << " x "
            << description.subdivisions[1] * (1u << parameters.mesh_refinements)
            << " cells of Q" << description.fe_degree << ", "
            << component.n_dofs() << " DoFs)\n";
        out << " mode     f_FE [Hz]  kind          Euler-B. [Hz]  "
               "Timoshenko [Hz]  bar [Hz]   FE vs theory  residual\n";

        nlohmann::json entry;
        entry["name"]           = description.name;
        entry["n_dofs"]         = component.n_dofs();
        entry["frequencies_hz"] = f;
        entry["residuals"]      = basis.residuals;
        entry["kinds"]          = nlohmann::json::array();
        entry["theory_hz"]      = nlohmann::json::array();

        for (unsigned int j = 0; j < basis.size(); ++j)
          {
            out << std::setw(5) << j + 1 << std::setw(14) << std::fixed
                << std::setprecision(2) << f[j] << "  " << std::left
                << std::setw(12) << kinds[j].name() << std::right;
            double reference = 0;
            if (with_theory)
              {
                const auto beam =
                  BeamTheory::Beam::of(description, scene.plane_model);
                if (kinds[j].bending)
                  {
                    const double eb =
                      BeamTheory::euler_bernoulli_frequency(beam,
                                                            kinds[j].order);
                    reference =
                      BeamTheory::timoshenko_frequency(beam, kinds[j].order);
                    out << std::setw(15) << eb << std::setw(17) << reference
                        << std::setw(10) << "";
                  }
                else
                  {
                    reference =
                      BeamTheory::axial_frequency(beam, kinds[j].order);
                    out << std::setw(15) << "" << std::setw(17) << ""
                        << std::setw(10) << reference;
                  }
                out << std::setw(14) << percent(f[j] / reference - 1);
              }
            else
              out << std::setw(56) << "";
            out << std::setw(10) << scientific(basis.residuals[j]) << "\n";
            entry["kinds"].push_back(kinds[j].name());
            entry["theory_hz"].push_back(reference);
          }
        out << " largest residual " << scientific(basis.max_residual())
            << (with_theory ? "; theory: Timoshenko for bending modes "
                              "(Cowper's shear coefficient), bar for axial "
                              "modes\n"
                            : "\n");
        say(out.str());

        // Mode shapes for ParaView: one vector field per mode, and the zone
        // of each cell.
        DataOut<2> data_out;
        data_out.attach_dof_handler(component.dof_handler());
        const std::vector<
          DataComponentInterpretation::DataComponentInterpretation>
          vector_field(
            2,
            DataComponentInterpretation::component_is_part_of_vector);
        for (unsigned int j = 0; j < basis.size(); ++j)
          {
            std::ostringstream name;
            name << "mode_" << std::setw(2) << std::setfill('0') << j + 1;
            data_out.add_data_vector(basis.modes[j],
                                     std::vector<std::string>(2, name.str()),
                                     DataOut<2>::type_dof_data,
                                     vector_field);
          }
        Vector<float> zone(component.triangulation().n_active_cells());
        for (const auto &cell :
             component.triangulation().active_cell_iterators())
          zone[cell->active_cell_index()] = cell->material_id();
        data_out.add_data_vector(zone, "zone");
        data_out.build_patches(description.fe_degree);
        std::ostringstream vtu;
        data_out.write_vtu(vtu);
        output.add("modes-" + description.name + ".vtu", vtu.str());

        results["components"].push_back(entry);
      }
  }


  // @sect4{The paper's Table 1}
  //
  // The paper lists nine frequencies up to 25 kHz without saying which 2D
  // model produced them. We compute the first component in both models and
  // find, for each listed value, the nearest FE mode of each; the report
  // then shows which model each paper mode belongs to, and which FE modes
  // the paper does not list.
  void
  ModalAnalysis::compare_with_paper()
  {
    const ComponentDescription &description  = scene.components.front();
    ModalParameters             up_to_cutoff = parameters.modal;
    up_to_cutoff.cutoff_frequency = parameters.paper_cutoff_frequency;
    const ModalSolver solver(up_to_cutoff);

    struct ModelModes
    {
      PlaneModel            model;
      std::vector<double>   f;
      std::vector<ModeKind> kinds;
    };
    std::vector<ModelModes> models;
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
          {model, basis.frequencies(), classify(component, basis)});
      }

    std::ostringstream out;
    out << "\nComparison with Table 1 of the paper (component "
        << description.name << ", modes up to "
        << parameters.paper_cutoff_frequency << " Hz)\n";
    out << " paper mode  paper [Hz]  | nearest plane strain FE mode     "
           "| nearest plane stress FE mode\n";
    nlohmann::json                 comparison = nlohmann::json::array();
    std::vector<std::vector<bool>> matched(models.size());
    // For each paper mode: index of the nearest FE mode in each model.
    std::vector<std::vector<unsigned int>> nearest(paper_table_1.size());
    for (unsigned int m = 0; m < models.size(); ++m)
      matched[m].assign(models[m].f.size(), false);

    for (unsigned int p = 0; p < paper_table_1.size(); ++p)
      {
        out << std::setw(11) << p + 1 << std::setw(12) << std::fixed
            << std::setprecision(1) << paper_table_1[p] << "  |";
        nlohmann::json row;
        row["paper_mode"] = p + 1;
        row["paper_hz"]   = paper_table_1[p];
        for (unsigned int m = 0; m < models.size(); ++m)
          {
            unsigned int best = 0;
            for (unsigned int j = 1; j < models[m].f.size(); ++j)
              if (std::abs(models[m].f[j] - paper_table_1[p]) <
                  std::abs(models[m].f[best] - paper_table_1[p]))
                best = j;
            const double diff = paper_table_1[p] / models[m].f[best] - 1;
            if (std::abs(diff) < 0.01)
              matched[m][best] = true;
            nearest[p].push_back(best);
            std::ostringstream cell;
            cell << " " << std::fixed << std::setw(8) << std::setprecision(1)
                 << models[m].f[best] << " (" << models[m].kinds[best].name()
                 << ") " << percent(diff);
            out << std::left << std::setw(33) << cell.str() << std::right
                << "|";
            const std::string key  = models[m].model == PlaneModel::plane_strain
                                       ? "plane_strain"
                                       : "plane_stress";
            row[key + "_hz"]       = models[m].f[best];
            row[key + "_kind"]     = models[m].kinds[best].name();
            row[key + "_rel_diff"] = diff;
          }
        out << "\n";
        comparison.push_back(row);
      }
    out << " (difference = paper / FE - 1; a match is a difference below "
           "1%)\n";
    for (unsigned int m = 0; m < models.size(); ++m)
      {
        unsigned int n_matched = 0;
        for (const bool b : matched[m])
          n_matched += b;
        out << " " << to_string(models[m].model) << ": matches " << n_matched
            << " of the " << paper_table_1.size()
            << " paper modes; its modes below the cutoff that the paper does "
               "not list:";
        bool any = false;
        for (unsigned int j = 0; j < models[m].f.size(); ++j)
          if (!matched[m][j])
            {
              out << " " << std::setprecision(1) << models[m].f[j] << " Hz ("
                  << models[m].kinds[j].name() << ")";
              any = true;
            }
        out << (any ? "\n" : " none\n");
      }

    // Name the paper modes that the better-matching model does not explain.
    const auto n_matches = [&](const unsigned int m) {
      return std::count(matched[m].begin(), matched[m].end(), true);
    };
    const unsigned int main_model = n_matches(0) >= n_matches(1) ? 0 : 1;
    const unsigned int other      = 1 - main_model;
    for (unsigned int p = 0; p < paper_table_1.size(); ++p)
      {
        const unsigned int jm = nearest[p][main_model];
        const unsigned int jo = nearest[p][other];
        const double       dm = paper_table_1[p] / models[main_model].f[jm] - 1;
        const double       d_o = paper_table_1[p] / models[other].f[jo] - 1;
        if (std::abs(dm) < 0.01)
          continue;
        out << " paper mode " << p + 1 << " (" << paper_table_1[p]
            << " Hz) is no " << to_string(models[main_model].model)
            << " mode (nearest: " << models[main_model].kinds[jm].name() << ", "
            << percent(dm) << ")";
        if (std::abs(d_o) < 0.01)
          {
            out << " but the " << to_string(models[other].model) << " "
                << models[other].kinds[jo].name() << " mode (" << percent(d_o)
                << ")";
            if (!models[other].kinds[jo].bending)
              {
                const auto beam =
                  BeamTheory::Beam::of(description, models[other].model);
                out
                  << ", i.e. the bar value (2n-1) c / (4L) = "
                  << BeamTheory::axial_frequency(beam,
                                                 models[other].kinds[jo].order)
                  << " Hz with c = sqrt(E / rho)";
              }
          }
        out << ".\n";
      }
    say(out.str());
    results["paper_comparison"] = comparison;
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
    results["convergence"] = nlohmann::json::array();
    for (const ComponentDescription &description : scene.components)
      {
        std::vector<std::vector<double>>           frequencies;
        std::vector<unsigned int>                  n_dofs;
        std::vector<double>                        max_residual;
        std::vector<std::map<std::string, double>> times;
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
            frequencies.push_back(basis.frequencies());
            n_dofs.push_back(component.n_dofs());
            max_residual.push_back(basis.max_residual());
            times.push_back(
              level_timer.get_summary_data(TimerOutput::total_wall_time));
          }

        const unsigned int  n_levels     = frequencies.size();
        const unsigned int  n_modes      = frequencies[0].size();
        std::vector<double> extrapolated = frequencies.back();
        const double factor = std::pow(2., 2. * description.fe_degree) - 1.;
        if (n_levels >= 2)
          for (unsigned int j = 0; j < n_modes; ++j)
            extrapolated[j] +=
              (frequencies[n_levels - 1][j] - frequencies[n_levels - 2][j]) /
              factor;

        std::ostringstream out;
        out << "\nMesh convergence, component " << description.name << "\n"
            << "  DoFs   mesh+DoFs [s]  assembly [s]  ARPACK [s]   f1 [Hz]"
               "      f1 error  f"
            << n_modes << " [Hz]      f" << n_modes << " error  max residual\n";
        for (unsigned int r = 0; r < n_levels; ++r)
          {
            const double total = times[r]["mesh and DoFs"] +
                                 times[r]["assembly"] +
                                 times[r]["eigenvalues (ARPACK)"];
            out << std::setw(7) << n_dofs[r] << std::fixed
                << std::setprecision(3) << std::setw(14)
                << times[r]["mesh and DoFs"] << std::setw(14)
                << times[r]["assembly"] << std::setw(12)
                << times[r]["eigenvalues (ARPACK)"] << std::setprecision(4)
                << std::setw(12) << frequencies[r][0] << std::setw(12)
                << scientific(frequencies[r][0] / extrapolated[0] - 1)
                << std::setprecision(2) << std::setw(12)
                << frequencies[r][n_modes - 1] << std::setw(12)
                << scientific(frequencies[r][n_modes - 1] /
                                extrapolated[n_modes - 1] -
                              1)
                << std::setw(14) << scientific(max_residual[r]) << "\n";

            nlohmann::json level;
            level["component"]      = description.name;
            level["refinement"]     = parameters.mesh_refinements + r;
            level["n_dofs"]         = n_dofs[r];
            level["frequencies_hz"] = frequencies[r];
            level["max_residual"]   = max_residual[r];
            level["time_s"]         = total;
            level["stage_times_s"]  = times[r];
            results["convergence"].push_back(level);
          }
        out << " extrapolated (Richardson, error ~ h^"
            << 2 * description.fe_degree << "): f1 = " << std::setprecision(4)
            << extrapolated[0] << " Hz, f" << n_modes << " = "
            << std::setprecision(2) << extrapolated[n_modes - 1]
            << " Hz; errors are relative to it.\n"
            << " The residual floor grows like eps * lambda_max / lambda_1 "
               "~ h^-2 (round-off, see doc/modal-analysis.md).\n";
        say(out.str());
        results["extrapolated_frequencies_hz"][description.name] = extrapolated;
      }
  }


  void
  ModalAnalysis::write_output()
  {
    TimerOutput::Scope scope(timer, "output");
    output.add("report.txt", report.str());
    output.add("results.json", results.dump(2) + "\n");
    output.write_all();
    std::cout << "\nWrote report.txt, results.json and modes-*.vtu to "
              << output.directory() << "/" << std::endl;
  }


  void
  ModalAnalysis::run()
  {
    say("step-1: modal analysis of the scene '" + scene.name + "' (" +
        parameters.scene_file + ")\n");
    results["scene"]       = scene.name;
    results["plane_model"] = to_string(scene.plane_model);

    analyse_components();
    if (parameters.compare_with_paper)
      compare_with_paper();
    if (parameters.convergence_refinements > 0)
      convergence_study();
    write_output();
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
