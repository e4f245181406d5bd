#include <fuzzycontact/output/reanalysis_report.h>
#include <fuzzycontact/reanalysis/eigen_derivatives.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace FuzzyContact
{
  using Format::fixed;
  using Format::scientific;

  std::string
  changes_label(const std::vector<double> &changes_percent)
  {
    std::ostringstream s;
    for (unsigned int k = 0; k < changes_percent.size(); ++k)
      s << (k ? "/" : "") << std::showpos << changes_percent[k] << "%";
    return s.str();
  }


  ReanalysisReport::ReanalysisReport(const std::string        &output_directory,
                                     const ReanalysisSettings &settings,
                                     const unsigned int        n_modes,
                                     const unsigned int        mesh_refinements)
      : settings(settings)
      , n_modes(n_modes)
      , mesh_refinements(mesh_refinements)
      , output(output_directory)
  {
  }


  void
  ReanalysisReport::start(const unsigned int n_cases)
  {
    report.say("step-2: modal reanalysis (" + std::to_string(n_cases) +
               " cases, " + std::to_string(n_modes) + " modes, orders up to " +
               std::to_string(settings.max_order) + ")\n");
    results["cases"]                = nlohmann::json::array();
    results["mesh_refinements"]     = mesh_refinements;
    results["order_tolerance"]      = settings.order_tolerance;
    results["truncation_tolerance"] = settings.truncation_tolerance;
    results["cluster_gap"]          = settings.cluster_gap;
  }


  void
  ReanalysisReport::add_case(
    const ReanalysisCase                                 &c,
    const std::string                                    &scene_name,
    const ParameterModel                                 &model,
    const ModalBasis                                     &nominal,
    const std::vector<std::unique_ptr<ReanalysisMethod>> &methods,
    const std::vector<double>                            &offline_times)
  {
    const Component &component = model.component();
    const auto clusters = reanalysis_clusters(nominal, settings.cluster_gap);
    case_name           = c.name;
    parameter_names.clear();
    for (const ReanalysisParameter &p : model.parameters())
      parameter_names.push_back(p.name);

    std::ostringstream out;
    out << "\n=== Case " << c.name << ": " << c.description << "\n"
        << " scene " << scene_name << ", component " << component.name() << " ("
        << to_string(component.plane_model()) << ", " << component.n_dofs()
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
    if (nominal.size() > n_modes)
      out << " mode " << n_modes
          << " is in a cluster that reaches above it: " << nominal.size()
          << " modes are reanalysed, the lowest " << n_modes << " reported\n";

    nlohmann::json info;
    out << " offline [s]:";
    const ParameterIndependentReanalysis *pi = nullptr;
    for (unsigned int m = 0; m < methods.size(); ++m)
      {
        const std::string name = methods[m]->name();
        out << " " << name << " " << fixed(offline_times[m], 3);
        info["time_offline_s"][name] = offline_times[m];
        if (const auto *p =
              dynamic_cast<const ParameterIndependentReanalysis *>(
                methods[m].get()))
          pi = p;
      }
    if (pi != nullptr)
      {
        out << "\n hptp-pi basis size by order (truncation tolerance "
            << scientific(settings.truncation_tolerance) << "):";
        for (unsigned int p = 0; p <= pi->max_order(); ++p)
          {
            out << " " << p << ": " << pi->basis_size(p);
            info["hptp_pi_basis_size"].push_back(pi->basis_size(p));
          }
      }
    out << "\n";
    report.say(out.str());

    info["description"] = c.description;
    info["scene"]       = scene_name;
    info["component"]   = component.name();
    info["n_dofs"]      = component.n_dofs();
    info["parameters"]  = parameter_names;
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
    results["case_info"][c.name] = info;
  }


  std::pair<double, double>
  ReanalysisReport::measure(const ReanalysisAnswer &answer) const
  {
    // Only the lowest n_modes are reported (the comparison covered the
    // whole cluster-completed basis).
    double max_error = 0, min_mac = 1;
    for (unsigned int j = 0; j < n_modes; ++j)
      {
        max_error = std::max(max_error, answer.comparison.relative_error[j]);
        min_mac   = std::min(min_mac, answer.comparison.mac[j]);
      }
    return std::make_pair(max_error, min_mac);
  }


  std::string
  ReanalysisReport::answers_table(const ReanalysisSampleSummary &sample) const
  {
    std::ostringstream table;
    table << "\n Sample " << case_name << " "
          << changes_label(sample.changes_percent) << " (";
    for (unsigned int k = 0; k < parameter_names.size(); ++k)
      table << (k ? ", " : "") << parameter_names[k] << " " << std::showpos
            << sample.changes_percent[k] << std::noshowpos << " %";
    table << "): exact re-solve " << fixed(sample.time_exact, 3) << " s\n"
          << "  method   order  basis  max rel. err  min MAC        "
             "residual  energy res.  est. error  online [s]  speed-up\n";
    const std::string tolerance = scientific(settings.order_tolerance, 0);
    for (const ReanalysisAnswer &row : sample.answers)
      {
        const auto [max_error, min_mac] = measure(row);
        table << "  " << std::left << std::setw(9) << row.method << std::right
              << std::setw(5) << row.order << std::setw(7)
              << (row.result.basis_size ? std::to_string(row.result.basis_size)
                                        : "-")
              << std::setw(14) << scientific(max_error) << std::setw(14)
              << fixed(min_mac, 10) << std::setw(10) << scientific(row.residual)
              << std::setw(13) << scientific(row.energy_residual)
              << std::setw(12) << scientific(row.estimate.estimate)
              << std::setw(12) << scientific(row.time_online, 2)
              << std::setw(10) << fixed(sample.time_exact / row.time_online, 0)
              << "x"
              << (row.selected && row.has_order
                    ? (row.tolerance_met
                         ? "  <- order for tolerance " + tolerance
                         : "  <- tolerance " + tolerance +
                             " not met by any order")
                    : "")
              << "\n";
      }
    return table.str();
  }


  nlohmann::json
  ReanalysisReport::answer_json(const ReanalysisSampleSummary &sample,
                                const ReanalysisAnswer        &row) const
  {
    const auto [max_error, min_mac] = measure(row);
    bool reordered                  = false;
    for (unsigned int j = 0; j < n_modes; ++j)
      reordered = reordered || row.comparison.match[j] != j;

    nlohmann::json entry;
    entry["name"] = case_name + " " + changes_label(sample.changes_percent);
    entry["case"] = case_name;
    entry["changes_percent"]    = sample.changes_percent;
    entry["method"]             = row.method;
    entry["order"]              = row.order;
    entry["basis_size"]         = row.result.basis_size;
    entry["selected"]           = row.selected;
    std::vector<double>       f = row.result.frequencies(), ef, errors, macs;
    std::vector<unsigned int> matched;
    f.resize(n_modes);
    const std::vector<double> exact_f = sample.exact->frequencies();
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
    if (std::isfinite(row.estimate.estimate))
      entry["estimated_error"] = row.estimate.estimate;
    if (std::isfinite(row.estimate.change_to_next_order))
      entry["change_to_next_order"] = row.estimate.change_to_next_order;
    if (row.selected && row.has_order)
      entry["tolerance_met"] = row.tolerance_met;
    entry["time_online_s"]  = row.time_online;
    entry["time_offline_s"] = row.time_offline;
    entry["time_exact_s"]   = sample.time_exact;
    return entry;
  }


  // Per mode, each method at its selected order. The exact mode each
  // answer is paired with is shown in brackets where it is not the mode of
  // the same rank; a '*' marks exact modes that come from another nominal
  // mode, i.e. eigenvalues that crossed.
  std::string
  ReanalysisReport::modes_table(const ReanalysisSampleSummary &sample) const
  {
    std::vector<const ReanalysisAnswer *> shown;
    for (const ReanalysisAnswer &row : sample.answers)
      if (row.selected)
        shown.push_back(&row);
    std::ostringstream table;
    table << "  per mode, each method at the order above (error = |f - "
             "f_exact| / f_exact; exact mode paired by MAC):\n"
          << "  mode    exact [Hz]  from nominal";
    for (const ReanalysisAnswer *row : shown)
      table << std::setw(14) << (row->method + " " + std::to_string(row->order))
            << "   rel. err      MAC     ";
    table << "\n";
    const std::vector<double> exact_f      = sample.exact->frequencies();
    const ModeComparison     &from_nominal = sample.exact_from_nominal;
    for (unsigned int j = 0; j < n_modes; ++j)
      {
        table << std::setw(6) << j + 1 << std::setw(14) << fixed(exact_f[j], 3)
              << std::setw(11) << from_nominal.match[j] + 1
              << (from_nominal.match[j] != j ? " *" : "  ") << " ";
        for (const ReanalysisAnswer *row : shown)
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
    return table.str();
  }


  void
  ReanalysisReport::add_sample(const ReanalysisSampleSummary &sample)
  {
    AssertThrow(sample.changes_percent.size() == parameter_names.size() &&
                  sample.exact != nullptr,
                ExcMessage("ReanalysisReport: a sample must belong to the "
                           "case added last."));
    for (const ReanalysisAnswer &row : sample.answers)
      results["cases"].push_back(answer_json(sample, row));
    std::vector<unsigned int> nominal_of_exact;
    for (const unsigned int i : sample.exact_from_nominal.match)
      nominal_of_exact.push_back(i + 1);
    results["case_info"][case_name]["exact_from_nominal"]
           [changes_label(sample.changes_percent)] = nominal_of_exact;
    report.say(answers_table(sample) + modes_table(sample));
  }


  void
  ReanalysisReport::write()
  {
    output.add("report.txt", report.text());
    output.add_json("results.json", results);
    output.write_all();
    std::cout << "\nWrote report.txt and results.json to " << output.directory()
              << "/" << std::endl;
  }
} // namespace FuzzyContact
