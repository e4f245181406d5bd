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
// successive orders. Every answer comes with its error and its time.
//
// Usage: step-2 prm/step-2.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/program.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/modal/mode_comparison.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/reanalysis/exact_resolve.h>
#include <fuzzycontact/reanalysis/order_selection.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>
#include <fuzzycontact/reanalysis/reanalysis_factory.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/reanalysis/residual_check.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <limits>
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
  // <name>'. As in a scene file, the names are read in a first, lenient
  // pass, and the whole file is then parsed strictly.
  struct CaseDescription
  {
    std::string              name;
    std::string              description;
    std::string              scene_file;
    std::string              component;
    std::vector<std::string> parameters;
    // Relative changes, one vector per sample (and the same in percent).
    std::vector<std::vector<double>> samples;
    std::vector<std::vector<double>> samples_percent;
  };

  struct Parameters
  {
    std::string                  output_directory;
    unsigned int                 mesh_refinements;
    std::vector<std::string>     methods;
    ModalParameters              modal;
    ReanalysisSettings           reanalysis;
    std::vector<CaseDescription> cases;

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
        {
          prm.enter_subsection("Case " + name);
          prm.declare_entry("description",
                            "",
                            Patterns::Anything(),
                            "One line saying what the case shows.");
          prm.declare_entry("scene",
                            "cantilever-zones.prm",
                            Patterns::Anything(),
                            "Scene file, relative to this parameter file.");
          prm.declare_entry("component",
                            "",
                            Patterns::Anything(),
                            "The component whose modes are reanalysed.",
                            /*has_to_be_set=*/true);
          prm.declare_entry("parameters",
                            "",
                            Patterns::Anything(),
                            "The parameters declared variable: "
                            "<component>.<zone>.<E|rho> or "
                            "<component>.<E|rho>, comma-separated.",
                            /*has_to_be_set=*/true);
          prm.declare_entry("changes in percent",
                            "",
                            Patterns::Anything(),
                            "Samples separated by ';', each a comma-separated "
                            "list of relative changes [%], one per parameter.",
                            /*has_to_be_set=*/true);
          prm.leave_subsection();
        }
    }

    void
    parse_parameters(ParameterHandler &prm, const std::string &prm_file)
    {
      output_directory = Utilities::trim(prm.get("output directory"));
      AssertThrow(!output_directory.empty(),
                  ExcMessage("output directory must not be empty."));
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
      cases.clear();
      for (const std::string &name : names)
        {
          const std::string what = "Case " + name;
          prm.enter_subsection(what);
          CaseDescription c;
          c.name        = name;
          c.description = Utilities::trim(prm.get("description"));
          c.scene_file =
            Input::resolve_relative_to(Utilities::trim(prm.get("scene")),
                                       prm_file);
          c.component = Utilities::trim(prm.get("component"));
          AssertThrow(!c.component.empty(),
                      ExcMessage(what + ": component must not be empty."));
          for (const std::string &p :
               Utilities::split_string_list(prm.get("parameters"), ','))
            c.parameters.push_back(p);
          AssertThrow(!c.parameters.empty(),
                      ExcMessage(what +
                                 ": no parameter is declared variable."));
          const std::vector<std::string> samples =
            Utilities::split_string_list(prm.get("changes in percent"), ';');
          AssertThrow(!samples.empty(),
                      ExcMessage(what + ": 'changes in percent' lists no "
                                        "sample."));
          for (unsigned int s = 0; s < samples.size(); ++s)
            {
              const std::string sample_what = what + ", sample " +
                                              std::to_string(s + 1) +
                                              " of 'changes in percent'";
              const std::vector<double> percent =
                Input::to_doubles(samples[s], sample_what);
              AssertThrow(percent.size() == c.parameters.size(),
                          ExcMessage(sample_what + ": " +
                                     std::to_string(percent.size()) +
                                     " changes given for " +
                                     std::to_string(c.parameters.size()) +
                                     " parameters."));
              std::vector<double> relative;
              for (const double p : percent)
                relative.push_back(p / 100.);
              c.samples.push_back(relative);
              c.samples_percent.push_back(percent);
            }
          prm.leave_subsection();
          cases.push_back(c);
        }
    }
  };


  std::string
  scientific(const double value, const int digits = 1)
  {
    if (!std::isfinite(value))
      return "-";
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << value;
    return s.str();
  }

  std::string
  fixed(const double value, const int digits)
  {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << value;
    return s.str();
  }

  // "+5%/-10%/+8%"
  std::string
  changes_label(const std::vector<double> &percent)
  {
    std::ostringstream s;
    for (unsigned int k = 0; k < percent.size(); ++k)
      s << (k ? "/" : "") << std::showpos << percent[k] << "%";
    return s.str();
  }

  // Runs f at least once and until @p min_seconds have passed; returns the
  // mean wall time of one call.
  double
  time_per_call(const std::function<void()> &f, const double min_seconds = 0.05)
  {
    Timer        timer;
    unsigned int calls = 0;
    do
      {
        f();
        ++calls;
      }
    while (timer.wall_time() < min_seconds);
    return timer.wall_time() / calls;
  }


  // @sect3{The ModalReanalysis class}
  class ModalReanalysis
  {
  public:
    explicit ModalReanalysis(const std::string &parameter_file);
    void
    run();

  private:
    void
    check_cases();
    void
    run_case(const CaseDescription &c);
    void
    write_output();
    void
    say(const std::string &text);

    Parameters                   parameters;
    std::map<std::string, Scene> scenes;
    TimerOutput                  timer;

    std::ostringstream report;
    OutputFiles        output;
    nlohmann::json     results;
  };


  ModalReanalysis::ModalReanalysis(const std::string &parameter_file)
      : timer(std::cout, TimerOutput::never, TimerOutput::wall_times)
      , output("")
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
    check_cases();
    output = OutputFiles(parameters.output_directory);
  }


  // Everything that can be checked without a mesh is checked before any
  // computation: scenes, components, parameter names, and that no sample
  // makes a modulus or density non-positive.
  void
  ModalReanalysis::check_cases()
  {
    for (const CaseDescription &c : parameters.cases)
      {
        if (scenes.find(c.scene_file) == scenes.end())
          scenes[c.scene_file] = Scene::read(c.scene_file);
        const Scene                &scene = scenes[c.scene_file];
        const ComponentDescription &component =
          scene.components[scene.component_index(c.component)];
        std::vector<ReanalysisParameter> declared;
        for (const std::string &name : c.parameters)
          {
            try
              {
                declared.push_back(
                  ReanalysisParameter::parse(name, scene, c.component));
              }
            catch (const ExceptionBase &e)
              {
                AssertThrow(false,
                            ExcMessage("Case " + c.name + ": " +
                                       Input::message_of(e)));
              }
          }
        try
          {
            check_distinct(declared, component);
          }
        catch (const ExceptionBase &e)
          {
            AssertThrow(false,
                        ExcMessage("Case " + c.name + ": " +
                                   Input::message_of(e)));
          }
        std::vector<double> moduli, densities;
        for (const MaterialZone &zone : component.zones)
          {
            moduli.push_back(zone.youngs_modulus);
            densities.push_back(zone.density);
          }
        for (unsigned int s = 0; s < c.samples.size(); ++s)
          try
            {
              perturbed_zone_materials(component,
                                       declared,
                                       moduli,
                                       densities,
                                       c.samples[s]);
            }
          catch (const ExceptionBase &e)
            {
              AssertThrow(false,
                          ExcMessage("Case " + c.name + ", sample " +
                                     std::to_string(s + 1) + ": " +
                                     Input::message_of(e)));
            }
      }
  }


  void
  ModalReanalysis::say(const std::string &text)
  {
    std::cout << text << std::flush;
    report << text;
  }


  // @sect4{One case}
  //
  // The nominal modes are computed with a few more modes than reported, so
  // that a cluster of close eigenvalues at the top of the reported range is
  // seen whole (its partner modes are then reanalysed too).
  void
  ModalReanalysis::run_case(const CaseDescription &c)
  {
    const Scene                &scene = scenes.at(c.scene_file);
    const ComponentDescription &description =
      scene.components[scene.component_index(c.component)];
    const ReanalysisSettings &settings = parameters.reanalysis;
    const unsigned int        n_modes  = parameters.modal.n_modes;

    const Component component(description,
                              scene.plane_model,
                              parameters.mesh_refinements,
                              &timer);

    ModalParameters with_extra = parameters.modal;
    with_extra.n_modes         = n_modes + 3;
    ModalBasis all_nominal;
    {
      TimerOutput::Scope scope(timer, "nominal modes (ARPACK)");
      all_nominal = ModalSolver(with_extra)
                      .solve(component.stiffness_matrix(),
                             component.mass_matrix(),
                             "Component " + c.component);
    }
    const unsigned int n_basis =
      modes_with_complete_clusters(all_nominal, n_modes, settings.cluster_gap);
    const ModalBasis nominal = leading_modes(all_nominal, n_basis);
    const auto clusters = reanalysis_clusters(nominal, settings.cluster_gap);

    const ParameterModel model(component, c.parameters);

    std::ostringstream out;
    out << "\n=== Case " << c.name << ": " << c.description << "\n"
        << " scene " << scene.name << ", component " << c.component << " ("
        << to_string(scene.plane_model) << ", " << component.n_dofs()
        << " DoFs)\n parameters:";
    for (unsigned int k = 0; k < model.n_parameters(); ++k)
      out << (k ? "," : "") << " " << model.parameter(k).name << " (nominal "
          << scientific(model.nominal_value(k), 4) << ")";
    out << "\n nominal frequencies [Hz]:";
    for (const double f : nominal.frequencies())
      out << " " << fixed(f, 2);
    out << "\n clusters of close eigenvalues (relative gap <= "
        << std::max(settings.cluster_gap, minimum_cluster_gap) << "):";
    bool any_cluster = false;
    for (const auto &cluster : clusters)
      if (cluster.size() > 1)
        {
          out << " " << describe_modes(nominal, cluster) << ";";
          any_cluster = true;
        }
    out << (any_cluster ? " each is expanded as a subspace\n" : " none\n");
    if (n_basis > n_modes)
      out << " mode " << n_modes
          << " is in a cluster that reaches above it: " << n_basis
          << " modes are reanalysed, the lowest " << n_modes << " reported\n";

    // Offline stage of every method, timed.
    std::vector<std::unique_ptr<ReanalysisMethod>> methods;
    std::vector<double>                            offline_time;
    const ParameterIndependentReanalysis          *pi = nullptr;
    for (const std::string &name : parameters.methods)
      {
        Timer t;
        methods.push_back(
          create_reanalysis_method(name, model, nominal, settings));
        offline_time.push_back(t.wall_time());
        if (const auto *p =
              dynamic_cast<const ParameterIndependentReanalysis *>(
                methods.back().get()))
          pi = p;
      }
    out << " offline [s]:";
    for (unsigned int m = 0; m < methods.size(); ++m)
      out << " " << methods[m]->name() << " " << fixed(offline_time[m], 3);
    if (pi != nullptr)
      {
        out << "\n hptp-pi basis size by order (truncation tolerance "
            << scientific(settings.truncation_tolerance) << "):";
        for (unsigned int p = 0; p <= pi->max_order(); ++p)
          out << " " << p << ": " << pi->basis_size(p);
      }
    out << "\n";
    say(out.str());

    nlohmann::json info;
    info["description"] = c.description;
    info["scene"]       = scene.name;
    info["component"]   = c.component;
    info["n_dofs"]      = component.n_dofs();
    info["parameters"]  = c.parameters;
    info["nominal_hz"]  = nominal.frequencies();
    info["clusters"]    = nlohmann::json::array();
    for (const auto &cluster : clusters)
      if (cluster.size() > 1)
        {
          std::vector<unsigned int> one_based;
          for (const unsigned int j : cluster)
            one_based.push_back(j + 1);
          info["clusters"].push_back(one_based);
        }
    for (unsigned int m = 0; m < methods.size(); ++m)
      info["time_offline_s"][methods[m]->name()] = offline_time[m];
    if (pi != nullptr)
      for (unsigned int p = 0; p <= pi->max_order(); ++p)
        info["hptp_pi_basis_size"].push_back(pi->basis_size(p));
    results["case_info"][c.name] = info;

    std::unique_ptr<ResidualCheck> residual_check;
    if (settings.residual_check)
      {
        TimerOutput::Scope scope(timer, "residual check: K0 factorisation");
        residual_check = std::make_unique<ResidualCheck>(model);
      }

    const ExactResolve exact_n(model, parameters.modal);
    ModalParameters    for_matching = parameters.modal;
    for_matching.n_modes            = n_basis + 3;
    const ExactResolve exact_matching(model, for_matching);

    for (unsigned int s = 0; s < c.samples.size(); ++s)
      {
        const std::vector<double> &t     = c.samples[s];
        const std::string          label = changes_label(c.samples_percent[s]);
        const std::string          name  = c.name + " " + label;

        // The reference: its time is that of the n_modes wanted; a second
        // solve with more modes serves the matching of reordered modes.
        ModalBasis exact;
        double     time_exact;
        {
          TimerOutput::Scope scope(timer, "exact re-solves (ARPACK)");
          Timer              tt;
          exact_n.solve(t);
          time_exact = tt.wall_time();
          exact      = exact_matching.solve(t);
        }
        SparseMatrix<double> K, M;
        model.matrices(t, K, M);

        struct Row
        {
          std::string      method;
          unsigned int     order;
          ReanalysisResult result;
          ModeComparison   comparison;
          double           residual = std::numeric_limits<double>::quiet_NaN();
          double energy_residual    = std::numeric_limits<double>::quiet_NaN();
          double time_online;
          double time_offline;
          double estimate = std::numeric_limits<double>::quiet_NaN();
          double change   = std::numeric_limits<double>::quiet_NaN();
          bool   selected = false;
          bool   not_met  = false;
        };
        std::vector<Row> rows;
        {
          TimerOutput::Scope scope(timer, "reanalyses");
          for (unsigned int m = 0; m < methods.size(); ++m)
            {
              const ReanalysisMethod &method = *methods[m];
              const unsigned int      max_order =
                method.has_order() ? settings.max_order : 1;
              std::vector<Row> own;
              for (unsigned int order = 1; order <= max_order; ++order)
                {
                  Row row;
                  row.method       = method.name();
                  row.order        = order;
                  row.time_offline = offline_time[m];
                  if (pi != nullptr && &method == pi)
                    {
                      // The online stage proper: eigenvalues and Y, no n_dofs
                      // work.
                      row.time_online = time_per_call([&]() {
                        pi->online(t, order);
                      });
                      row.result      = pi->reanalyse(t, order);
                    }
                  else
                    row.time_online = time_per_call([&]() {
                      row.result = method.reanalyse(t, order);
                    });
                  row.comparison = compare_modes(row.result.eigenvalues,
                                                 row.result.modes,
                                                 exact,
                                                 M);
                  if (residual_check)
                    {
                      const ResidualCheck::Residuals r =
                        residual_check->check(t,
                                              row.result.eigenvalues,
                                              row.result.modes);
                      row.residual =
                        *std::max_element(r.relative.begin(),
                                          r.relative.begin() + n_modes);
                      row.energy_residual =
                        *std::max_element(r.energy.begin(),
                                          r.energy.begin() + n_modes);
                    }
                  own.push_back(std::move(row));
                }
              // The order a tolerance asks for, by the library's rule
              // (reanalysis/order_selection.h): the estimate of order n is
              // its change to order n + 1 and, with the residual check,
              // eta^2 / 2 from the energy-norm residual eta; the order is
              // the lowest whose estimate meets the tolerance. Every order
              // is estimated here, for the table.
              if (method.has_order())
                {
                  const OrderSelection selection = order_for_tolerance(
                    own.size(),
                    settings.order_tolerance,
                    n_modes,
                    [&](const unsigned int n) {
                      return own[n - 1].result.eigenvalues;
                    },
                    [&](const unsigned int n) {
                      return own[n - 1].energy_residual;
                    },
                    /*all_orders=*/true);
                  for (unsigned int i = 0; i < own.size(); ++i)
                    {
                      own[i].change =
                        selection.estimates[i].change_to_next_order;
                      own[i].estimate = selection.estimates[i].estimate;
                    }
                  own[selection.order - 1].selected = true;
                  own[selection.order - 1].not_met  = !selection.tolerance_met;
                }
              else
                own[0].selected = true;
              for (Row &r : own)
                rows.push_back(std::move(r));
            }
        }

        // Only the lowest n_modes are reported (the comparison covered the
        // whole cluster-completed basis).
        const auto measure = [&](const Row &row) {
          double max_error = 0, min_mac = 1;
          for (unsigned int j = 0; j < n_modes; ++j)
            {
              max_error = std::max(max_error, row.comparison.relative_error[j]);
              min_mac   = std::min(min_mac, row.comparison.mac[j]);
            }
          return std::make_pair(max_error, min_mac);
        };

        std::ostringstream table;
        table << "\n Sample " << name << " (";
        for (unsigned int k = 0; k < model.n_parameters(); ++k)
          table << (k ? ", " : "") << model.parameter(k).name << " "
                << std::showpos << c.samples_percent[s][k] << std::noshowpos
                << " %";
        table << "): exact re-solve " << fixed(time_exact, 3) << " s\n"
              << "  method   order  basis  max rel. err  min MAC        "
                 "residual  energy res.  est. error  online [s]  speed-up\n";
        for (const Row &row : rows)
          {
            const auto [max_error, min_mac] = measure(row);
            table << "  " << std::left << std::setw(9) << row.method
                  << std::right << std::setw(5) << row.order << std::setw(7)
                  << (row.result.basis_size
                        ? std::to_string(row.result.basis_size)
                        : "-")
                  << std::setw(14) << scientific(max_error) << std::setw(14)
                  << fixed(min_mac, 10) << std::setw(10)
                  << scientific(row.residual) << std::setw(13)
                  << scientific(row.energy_residual) << std::setw(12)
                  << scientific(row.estimate) << std::setw(12)
                  << scientific(row.time_online, 2) << std::setw(10)
                  << fixed(time_exact / row.time_online, 0) << "x"
                  << (row.selected && row.method != "taylor"
                        ? (row.not_met
                             ? "  <- tolerance " +
                                 scientific(settings.order_tolerance, 0) +
                                 " not met by any order"
                             : "  <- order for tolerance " +
                                 scientific(settings.order_tolerance, 0))
                        : "")
                  << "\n";
            bool reordered = false;
            for (unsigned int j = 0; j < n_modes; ++j)
              reordered = reordered || row.comparison.match[j] != j;

            nlohmann::json entry;
            entry["name"]            = name;
            entry["case"]            = c.name;
            entry["changes_percent"] = c.samples_percent[s];
            entry["method"]          = row.method;
            entry["order"]           = row.order;
            entry["basis_size"]      = row.result.basis_size;
            entry["selected"]        = row.selected;
            std::vector<double> f = row.result.frequencies(), ef, errors, macs;
            std::vector<unsigned int> matched;
            f.resize(n_modes);
            const std::vector<double> exact_f = exact.frequencies();
            for (unsigned int j = 0; j < n_modes; ++j)
              {
                ef.push_back(exact_f[row.comparison.match[j]]);
                errors.push_back(row.comparison.relative_error[j]);
                macs.push_back(row.comparison.mac[j]);
                matched.push_back(row.comparison.match[j] + 1);
              }
            entry["frequencies_hz"]  = f;
            entry["exact_hz"]        = ef;
            entry["exact_mode"]      = matched;
            entry["reordered"]       = reordered;
            entry["relative_errors"] = errors;
            entry["macs"]            = macs;
            entry["max_rel_error"]   = max_error;
            entry["min_mac"]         = min_mac;
            if (std::isfinite(row.residual))
              {
                entry["max_residual"]        = row.residual;
                entry["max_energy_residual"] = row.energy_residual;
              }
            if (std::isfinite(row.estimate))
              entry["estimated_error"] = row.estimate;
            if (std::isfinite(row.change))
              entry["change_to_next_order"] = row.change;
            if (row.selected && row.method != "taylor")
              entry["tolerance_met"] = !row.not_met;
            entry["time_online_s"]  = row.time_online;
            entry["time_offline_s"] = row.time_offline;
            entry["time_exact_s"]   = time_exact;
            results["cases"].push_back(entry);
          }

        // Per mode, each method at its selected order.
        std::vector<const Row *> shown;
        for (const Row &row : rows)
          if (row.selected)
            shown.push_back(&row);
        table << "  per mode, each method at the order above (error = |f - "
                 "f_exact| / f_exact; exact mode paired by MAC):\n"
              << "  mode    exact [Hz]  from nominal";
        for (const Row *row : shown)
          table << std::setw(14)
                << (row->method + " " + std::to_string(row->order))
                << "   rel. err      MAC     ";
        table << "\n";
        const std::vector<double> exact_f = exact.frequencies();
        // Which nominal mode each exact mode comes from (by MAC): a '*' marks
        // modes that changed places, i.e. eigenvalues that crossed.
        const ModeComparison from_nominal = compare_modes(
          std::vector<double>(exact.eigenvalues.begin(),
                              exact.eigenvalues.begin() + n_modes),
          std::vector<Vector<double>>(exact.modes.begin(),
                                      exact.modes.begin() + n_modes),
          all_nominal,
          M);
        std::vector<unsigned int> nominal_of_exact;
        for (const unsigned int i : from_nominal.match)
          nominal_of_exact.push_back(i + 1);
        results["case_info"][c.name]["exact_from_nominal"][label] =
          nominal_of_exact;
        for (unsigned int j = 0; j < n_modes; ++j)
          {
            table << std::setw(6) << j + 1 << std::setw(14)
                  << fixed(exact_f[j], 3) << std::setw(11)
                  << from_nominal.match[j] + 1
                  << (from_nominal.match[j] != j ? " *" : "  ") << " ";
            for (const Row *row : shown)
              {
                const unsigned int i = row->comparison.match[j];
                table << std::setw(14) << fixed(row->result.frequencies()[j], 3)
                      << std::setw(10)
                      << scientific(row->comparison.relative_error[j])
                      << std::setw(14) << fixed(row->comparison.mac[j], 8)
                      << (i != j ? "(" + std::to_string(i + 1) + ")" : "   ");
              }
            table << "\n";
          }
        say(table.str());
      }
  }


  void
  ModalReanalysis::write_output()
  {
    TimerOutput::Scope scope(timer, "output");
    output.add("report.txt", report.str());
    output.add("results.json", results.dump(2) + "\n");
    output.write_all();
    std::cout << "\nWrote report.txt and results.json to " << output.directory()
              << "/" << std::endl;
  }


  void
  ModalReanalysis::run()
  {
    say("step-2: modal reanalysis (" + std::to_string(parameters.cases.size()) +
        " cases, " + std::to_string(parameters.modal.n_modes) +
        " modes, orders up to " +
        std::to_string(parameters.reanalysis.max_order) + ")\n");
    results["cases"]            = nlohmann::json::array();
    results["mesh_refinements"] = parameters.mesh_refinements;
    results["order_tolerance"]  = parameters.reanalysis.order_tolerance;
    results["truncation_tolerance"] =
      parameters.reanalysis.truncation_tolerance;
    results["cluster_gap"] = parameters.reanalysis.cluster_gap;
    for (const CaseDescription &c : parameters.cases)
      run_case(c);
    write_output();
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
