#include <fuzzycontact/fe/beam_theory.h>
#include <fuzzycontact/output/modal_report.h>

#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace FuzzyContact
{
  using Format::percent;
  using Format::scientific;

  namespace
  {
    // The mode shapes for ParaView: one vector field per mode, and the zone
    // of each cell.
    std::string
    mode_shapes_vtu(const Component &component, const ModalBasis &basis)
    {
      DataOut<2> data_out;
      data_out.attach_dof_handler(component.dof_handler());
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        vector_field(2,
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
      for (const auto &cell : component.triangulation().active_cell_iterators())
        zone[cell->active_cell_index()] = cell->material_id();
      data_out.add_data_vector(zone, "zone");
      data_out.build_patches(component.description().fe_degree);
      std::ostringstream vtu;
      data_out.write_vtu(vtu);
      return vtu.str();
    }
  } // namespace


  ModalReport::ModalReport(const std::string &output_directory)
      : output(output_directory)
  {
  }


  void
  ModalReport::start(const Scene &scene, const std::string &scene_file)
  {
    report.say("step-1: modal analysis of the scene '" + scene.name + "' (" +
               scene_file + ")\n");
    results["scene"]       = scene.name;
    results["plane_model"] = to_string(scene.plane_model);
    results["components"]  = nlohmann::json::array();
  }


  void
  ModalReport::add_component(const Component             &component,
                             const unsigned int           mesh_refinements,
                             const ModalBasis            &basis,
                             const std::vector<ModeKind> &kinds,
                             const std::vector<BeamTheoryFrequency> &theory)
  {
    const ComponentDescription &description = component.description();
    const std::vector<double>   f           = basis.frequencies();
    const bool                  with_theory = !theory.empty();

    std::ostringstream out;
    out << "\nComponent " << description.name << " ("
        << to_string(component.plane_model()) << ", "
        << description.subdivisions[0] * (1u << mesh_refinements) << " x "
        << description.subdivisions[1] * (1u << mesh_refinements)
        << " cells of Q" << description.fe_degree << ", " << component.n_dofs()
        << " DoFs)\n";
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
            reference = theory[j].reference();
            if (kinds[j].bending)
              out << std::setw(15) << theory[j].euler_bernoulli << std::setw(17)
                  << theory[j].timoshenko << std::setw(10) << "";
            else
              out << std::setw(15) << "" << std::setw(17) << "" << std::setw(10)
                  << theory[j].bar;
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
    report.say(out.str());

    output.add("modes-" + description.name + ".vtu",
               mode_shapes_vtu(component, basis));
    results["components"].push_back(entry);
  }


  void
  ModalReport::add_paper_comparison(const ComponentDescription &description,
                                    const double               cutoff_frequency,
                                    const std::vector<double> &paper_table_1,
                                    const std::vector<PlaneModelModes> &models)
  {
    std::ostringstream out;
    out << "\nComparison with Table 1 of the paper (component "
        << description.name << ", modes up to " << cutoff_frequency << " Hz)\n";
    out << " paper mode  paper [Hz]  | nearest plane strain FE mode     "
           "| nearest plane stress FE mode\n";
    nlohmann::json                 comparison = nlohmann::json::array();
    std::vector<std::vector<bool>> matched(models.size());
    // For each paper mode: index of the nearest FE mode in each model.
    std::vector<std::vector<unsigned int>> nearest(paper_table_1.size());
    for (unsigned int m = 0; m < models.size(); ++m)
      matched[m].assign(models[m].frequencies.size(), false);

    for (unsigned int p = 0; p < paper_table_1.size(); ++p)
      {
        out << std::setw(11) << p + 1 << std::setw(12) << std::fixed
            << std::setprecision(1) << paper_table_1[p] << "  |";
        nlohmann::json row;
        row["paper_mode"] = p + 1;
        row["paper_hz"]   = paper_table_1[p];
        for (unsigned int m = 0; m < models.size(); ++m)
          {
            const std::vector<double> &f    = models[m].frequencies;
            unsigned int               best = 0;
            for (unsigned int j = 1; j < f.size(); ++j)
              if (std::abs(f[j] - paper_table_1[p]) <
                  std::abs(f[best] - paper_table_1[p]))
                best = j;
            const double diff = paper_table_1[p] / f[best] - 1;
            if (std::abs(diff) < 0.01)
              matched[m][best] = true;
            nearest[p].push_back(best);
            std::ostringstream cell;
            cell << " " << std::fixed << std::setw(8) << std::setprecision(1)
                 << f[best] << " (" << models[m].kinds[best].name() << ") "
                 << percent(diff);
            out << std::left << std::setw(33) << cell.str() << std::right
                << "|";
            const std::string key  = models[m].model == PlaneModel::plane_strain
                                       ? "plane_strain"
                                       : "plane_stress";
            row[key + "_hz"]       = f[best];
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
        for (unsigned int j = 0; j < models[m].frequencies.size(); ++j)
          if (!matched[m][j])
            {
              out << " " << std::setprecision(1) << models[m].frequencies[j]
                  << " Hz (" << models[m].kinds[j].name() << ")";
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
        const double       dm =
          paper_table_1[p] / models[main_model].frequencies[jm] - 1;
        const double d_o = paper_table_1[p] / models[other].frequencies[jo] - 1;
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
    report.say(out.str());
    results["paper_comparison"] = comparison;
  }


  void
  ModalReport::add_convergence(const ComponentDescription        &description,
                               const std::vector<MeshLevelModes> &levels,
                               const std::vector<double>         &extrapolated)
  {
    const unsigned int n_modes = levels[0].frequencies.size();
    std::ostringstream out;
    out << "\nMesh convergence, component " << description.name << "\n"
        << "  DoFs   mesh+DoFs [s]  assembly [s]  ARPACK [s]   f1 [Hz]"
           "      f1 error  f"
        << n_modes << " [Hz]      f" << n_modes << " error  max residual\n";
    if (!results.contains("convergence"))
      results["convergence"] = nlohmann::json::array();
    for (const MeshLevelModes &level : levels)
      {
        std::map<std::string, double> times = level.stage_times;
        const std::vector<double>    &f     = level.frequencies;
        const double total = times["mesh and DoFs"] + times["assembly"] +
                             times["eigenvalues (ARPACK)"];
        out << std::setw(7) << level.n_dofs << std::fixed
            << std::setprecision(3) << std::setw(14) << times["mesh and DoFs"]
            << std::setw(14) << times["assembly"] << std::setw(12)
            << times["eigenvalues (ARPACK)"] << std::setprecision(4)
            << std::setw(12) << f[0] << std::setw(12)
            << scientific(f[0] / extrapolated[0] - 1) << std::setprecision(2)
            << std::setw(12) << f[n_modes - 1] << std::setw(12)
            << scientific(f[n_modes - 1] / extrapolated[n_modes - 1] - 1)
            << std::setw(14) << scientific(level.max_residual) << "\n";

        nlohmann::json entry;
        entry["component"]      = description.name;
        entry["refinement"]     = level.refinement;
        entry["n_dofs"]         = level.n_dofs;
        entry["frequencies_hz"] = f;
        entry["max_residual"]   = level.max_residual;
        entry["time_s"]         = total;
        entry["stage_times_s"]  = times;
        results["convergence"].push_back(entry);
      }
    out << " extrapolated (Richardson, error ~ h^" << 2 * description.fe_degree
        << "): f1 = " << std::setprecision(4) << extrapolated[0] << " Hz, f"
        << n_modes << " = " << std::setprecision(2) << extrapolated[n_modes - 1]
        << " Hz; errors are relative to it.\n"
        << " The residual floor grows like eps * lambda_max / lambda_1 "
           "~ h^-2 (round-off, see doc/modal-analysis.md).\n";
    report.say(out.str());
    results["extrapolated_frequencies_hz"][description.name] = extrapolated;
  }


  void
  ModalReport::write()
  {
    output.add("report.txt", report.text());
    output.add_json("results.json", results);
    output.write_all();
    std::cout << "\nWrote report.txt, results.json and modes-*.vtu to "
              << output.directory() << "/" << std::endl;
  }
} // namespace FuzzyContact
