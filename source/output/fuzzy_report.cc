#include <fuzzycontact/output/fuzzy_report.h>
#include <fuzzycontact/output/membership_plot.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    // (A level without a point with a solution has no bound: "n/a".)
    std::string
    number(const double x)
    {
      if (std::isnan(x))
        return "n/a";
      std::ostringstream s;
      s << std::scientific << std::setprecision(5) << x;
      return s.str();
    }

    // A bound for results.json: null where there is none.
    nlohmann::json
    value(const double x)
    {
      return std::isnan(x) ? nlohmann::json() : nlohmann::json(x);
    }

    // Whether sliding is possible at level @p l (the bounds there are over
    // the part of the box with an equilibrium).
    bool
    sliding(const FuzzyStudyResults &r, const unsigned int l)
    {
      return r.has_equilibrium && l < r.equilibrium.levels.size() &&
             r.equilibrium.levels[l].possible;
    }

    // Relative differences, with a floor for an output that is zero at
    // every level (F_t without friction).
    double
    difference(const std::vector<Interval> &b, const std::vector<Interval> &r)
    {
      double scale = 0;
      for (const Interval &i : r)
        if (!std::isnan(i.lower) && !std::isnan(i.upper))
          scale = std::max({scale, std::abs(i.lower), std::abs(i.upper)});
      return max_relative_difference(b,
                                     r,
                                     scale > 0
                                       ? 1e-9 * scale
                                       : std::numeric_limits<double>::min());
    }

    // The table of output k, and its entry of results.json.
    nlohmann::json
    output_table(const FuzzyStudyResults &r,
                 const unsigned int       k,
                 std::ostringstream      &out)
    {
      const Observation &o = r.outputs[k];
      out << "\n"
          << o.description() << ", " << o.name << " [" << o.unit() << "]\n"
          << "  alpha   optimisation: lower      upper     ";
      if (r.has_vertex)
        out << "  vertex: lower      upper      ";
      if (r.has_reference)
        out << "  Extension Principle: lower  upper        rel. diff";
      out << "\n";
      nlohmann::json entry;
      entry["name"]  = o.name;
      entry["unit"]  = o.unit();
      entry["alpha"] = r.alpha;
      nlohmann::json lo, hi, rlo, rhi, vlo, vhi;
      bool           any_sliding = false;
      for (unsigned int l = 0; l < r.alpha.size(); ++l)
        {
          const Interval b = r.optimisation.bounds[k][l];
          lo.push_back(value(b.lower));
          hi.push_back(value(b.upper));
          any_sliding = any_sliding || sliding(r, l);
          out << "  " << std::fixed << std::setprecision(2) << r.alpha[l]
              << (sliding(r, l) ? "*  " : "   ") << std::setw(12)
              << number(b.lower) << " " << std::setw(12) << number(b.upper);
          if (r.has_vertex)
            {
              const Interval v = r.vertex.bounds[k][l];
              vlo.push_back(value(v.lower));
              vhi.push_back(value(v.upper));
              out << "   " << std::setw(12) << number(v.lower) << " "
                  << std::setw(12) << number(v.upper);
            }
          if (r.has_reference)
            {
              const Interval e = r.reference.bounds[k][l];
              rlo.push_back(value(e.lower));
              rhi.push_back(value(e.upper));
              out << "   " << std::setw(12) << number(e.lower) << " "
                  << std::setw(12) << number(e.upper) << "   "
                  << std::setprecision(1) << std::scientific
                  << difference({b}, {e});
            }
          out << "\n";
        }
      if (any_sliding)
        {
          out << "  *: sliding is possible at this level; the bounds are "
                 "over the part of the box with a static equilibrium (n/a: "
                 "no point of the box has one)\n";
          std::vector<bool> flags;
          for (unsigned int l = 0; l < r.alpha.size(); ++l)
            flags.push_back(sliding(r, l));
          entry["sliding_possible"] = flags;
        }
      entry["lower"] = lo;
      entry["upper"] = hi;
      if (r.has_vertex)
        {
          entry["vertex_lower"] = vlo;
          entry["vertex_upper"] = vhi;
        }
      if (r.has_reference)
        {
          entry["reference_lower"] = rlo;
          entry["reference_upper"] = rhi;
          entry["max_rel_error"] =
            difference(r.optimisation.bounds[k], r.reference.bounds[k]);
          out << "  largest relative difference from the Extension "
                 "Principle: optimisation "
              << std::scientific << std::setprecision(2)
              << double(entry["max_rel_error"]);
          if (r.has_vertex)
            {
              entry["vertex_max_rel_error"] =
                difference(r.vertex.bounds[k], r.reference.bounds[k]);
              out << ", vertex method "
                  << double(entry["vertex_max_rel_error"]);
            }
          out << "\n";
        }
      if (!r.optimisation.lower_quality.empty())
        FuzzyStudyReport::proofs(r, k, out, entry);
      FuzzyStudyReport::comparison(r, k, out, entry);
      return entry;
    }

    // The line under a method's cost: its time inside the model (summed
    // over the ranks), per evaluation, apart from the method's own work.
    std::string
    inside(const FuzzyOutputBounds &b,
           const std::string       &model,
           const unsigned int       n_processes)
    {
      if (b.n_evaluations == 0 || b.evaluation_time <= 0)
        return "";
      std::ostringstream out;
      out << "    inside " << model << std::fixed << std::setprecision(2)
          << std::setw(std::max<int>(1, 37 - model.size())) << b.evaluation_time
          << " s  " << std::setprecision(3)
          << 1e3 * b.evaluation_time / b.n_evaluations << " ms per evaluation ("
          << (n_processes > 1 ? "the ranks' times added; " : "")
          << "the rest: the method's own work)\n";
      return out.str();
    }

    // Evaluations and wall times, the fast study against the reference
    // run beside it.
    void
    cost(const FuzzyStudyResults &r, Report &report, nlohmann::json &json)
    {
      const double proofs = r.has_proofs ? r.proofs.wall_time : 0.;
      const double study  = r.offline_time + r.optimisation.wall_time + proofs;
      std::ostringstream out;
      out << "\ncost (wall time, " << r.n_processes << " process(es))\n"
          << "  offline (model built once)            " << std::fixed
          << std::setprecision(2) << std::setw(8) << r.offline_time << " s\n"
          << "  optimisation, reduced model           " << std::setw(8)
          << r.optimisation.wall_time << " s  " << r.optimisation.n_evaluations
          << " evaluations (global stage: " << r.optimisation.design_points
          << " Sobol points per alpha-box"
          << (r.optimisation.design_cut
                ? ", cut from " + std::to_string(r.optimisation.design_wanted) +
                    " by the global time limit: the number depends on the "
                    "machine's speed"
                : std::string())
          << ")\n"
          << inside(r.optimisation, "the reduced model", r.n_processes);
      json["time_s"]["offline"]           = r.offline_time;
      json["time_s"]["optimisation"]      = r.optimisation.wall_time;
      json["time_s"]["fuzzy_study"]       = study;
      json["evaluations"]["optimisation"] = r.optimisation.n_evaluations;
      json["evaluation_time_s"]["optimisation"] =
        r.optimisation.evaluation_time;
      json["global_stage"] = {{"design_points", r.optimisation.design_points},
                              {"design_cut_by_time_limit",
                               r.optimisation.design_cut}};
      if (r.has_proofs)
        {
          out << "  proofs, full order at the bounds      " << std::setw(8)
              << proofs << " s  " << r.proofs.n_evaluations
              << " evaluations (the distinct arguments of "
              << 2 * r.outputs.size() * r.alpha.size() << " bounds"
              << (r.proof_rounds.size() > 1
                    ? ", over " + std::to_string(r.proof_rounds.size()) +
                        " rounds, with making the model richer"
                    : std::string())
              << ")\n";
          json["time_s"]["proofs"]      = proofs;
          json["evaluations"]["proofs"] = r.proofs.n_evaluations;
        }
      if (r.proof_settings.spot_checks > 0)
        {
          out << "  spot checks, full order               " << std::setw(8)
              << r.spot_checks.wall_time << " s  " << r.spot_checks.n_checked
              << " evaluations (at the optimisation's points)\n";
          json["time_s"]["spot_checks"]      = r.spot_checks.wall_time;
          json["evaluations"]["spot_checks"] = r.spot_checks.n_checked;
        }
      if (r.has_vertex)
        {
          out << "  vertex method, reduced model          " << std::setw(8)
              << r.vertex.wall_time << " s  " << r.vertex.n_evaluations
              << " evaluations\n"
              << inside(r.vertex, "the reduced model", r.n_processes);
          json["time_s"]["vertex"]            = r.vertex.wall_time;
          json["evaluation_time_s"]["vertex"] = r.vertex.evaluation_time;
          json["evaluations"]["vertex"]       = r.vertex.n_evaluations;
        }
      if (r.has_reference)
        {
          const std::string kind  = r.reference_reuses
                                      ? "factorisations reused where exact"
                                      : "independent analyses";
          const double      ratio = r.reference.wall_time / study;
          out << "  Extension Principle, full order       " << std::setw(8)
              << r.reference.wall_time << " s  " << r.reference.n_evaluations
              << " evaluations (" << kind << ")\n"
              << inside(r.reference, "the full-order model", r.n_processes)
              << "  the fuzzy study (offline + optimisation"
              << (r.has_proofs ? " + proofs" : "") << ") takes "
              << std::setprecision(2) << study << " s: ";
          if (ratio >= 1)
            out << std::setprecision(1) << ratio
                << "x faster than this Extension Principle\n";
          else
            out << "this Extension Principle was " << std::setprecision(1)
                << 1 / ratio << "x faster"
                << (r.reference_reuses
                      ? " (its full-order solves reuse the stiffness "
                        "factorisations the model was built from; "
                        "doc/performance.md gives the cost of independent "
                        "analyses)"
                      : "")
                << "\n";
          json["extension_principle_reference"] = kind;
          json["time_s"]["extension_principle"] = r.reference.wall_time;
          json["evaluation_time_s"]["extension_principle"] =
            r.reference.evaluation_time;
          json["evaluations"]["extension_principle"] =
            r.reference.n_evaluations;
          json["speed_up"] = r.reference.wall_time / study;
        }
      // With several ranks, who built what.
      if (r.ranks.size() > 1)
        out << "  MPI ranks:";
      for (unsigned int rank = 0; rank < r.ranks.size(); ++rank)
        {
          const auto names = [](const std::vector<std::string> &list) {
            std::string all;
            for (const std::string &name : list)
              all += (all.empty() ? "" : ", ") + name;
            return all.empty() ? std::string("none") : all;
          };
          const RankWork &work = r.ranks[rank];
          if (r.ranks.size() > 1)
            out << (rank > 0 ? ";" : "") << " rank " << rank << " assembled "
                << names(work.assembled) << " and factorised "
                << names(work.factorised);
          json["ranks"].push_back(
            {{"assembled", work.assembled}, {"factorised", work.factorised}});
        }
      if (r.ranks.size() > 1)
        out << "\n";
      report.say(out.str());
    }
  } // namespace


  void
  FuzzyStudyResults::set_model(const FuzzyContactModel &model,
                               const double             offline_time)
  {
    this->offline_time = offline_time;
    n_dofs             = model.n_dofs();
    for (unsigned int k = 0; k < model.observations().size(); ++k)
      outputs.push_back(model.observations()[k]);
  }


  void
  FuzzyStudyResults::set_proofs(const ModelProofs &p)
  {
    optimisation   = p.proven.bounds;
    proofs         = p.proven.proofs;
    has_proofs     = true;
    proof_rounds   = p.proven.rounds;
    unproven       = p.proven.unproven;
    proof_stop     = p.proven.stopped;
    proof_settings = p.settings;
    proof_cg       = p.cg;
    model_after    = p.model_after;
  }


  namespace FuzzyStudyReport
  {
    std::string
    study(const std::string                 &scene_name,
          const std::string                 &scene_file,
          const unsigned int                 n_processes,
          const std::vector<FuzzyParameter> &parameters,
          const unsigned int                 n_alpha)
    {
      std::ostringstream out;
      out << "step-4: fuzzy contact study of the scene '" << scene_name << "' ("
          << scene_file << "), " << n_processes << " MPI process(es)\n"
          << "fuzzy parameters:\n";
      std::size_t width = 15;
      for (const FuzzyParameter &p : parameters)
        width = std::max(width, p.quantity.name.size());
      for (const FuzzyParameter &p : parameters)
        out << "  " << std::left << std::setw(width + 1) << p.quantity.name
            << std::right << p.number.to_string() << "\n";
      out << n_alpha << " alpha levels\n";
      return out.str();
    }


    std::string
    model(const double offline_time, const std::string &description)
    {
      std::ostringstream built;
      built << "model (built once, " << std::fixed << std::setprecision(2)
            << offline_time << " s):\n"
            << description;
      return built.str();
    }


    std::string
    extension_principle(const unsigned long n_samples,
                        const unsigned int  points,
                        const bool          reuse_factorisations)
    {
      return "Extension Principle: " + std::to_string(n_samples) +
             " exact full-order solves (" + std::to_string(points) +
             " points per parameter and level; " +
             (reuse_factorisations ? "factorisations reused where exact"
                                   : "independent analyses") +
             ")\n";
    }


    void
    bounds(const FuzzyStudyResults &r, Report &report, nlohmann::json &json)
    {
      json["scene"]            = r.scene;
      json["mpi_processes"]    = r.n_processes;
      json["n_dofs"]           = r.n_dofs;
      json["fuzzy_parameters"] = nlohmann::json::array();
      for (const FuzzyParameter &p : r.parameters)
        json["fuzzy_parameters"].push_back(
          {{"name", p.quantity.name},
           {"membership", p.number.to_string()},
           {"points", p.number.points()}});
      const std::string inert = FuzzyStudyReport::inert(r, json);
      if (!inert.empty())
        report.say("\nparameters that cannot change the answer:\n" + inert);
      report.say(FuzzyStudyReport::equilibrium(r, json));
      json["outputs"] = nlohmann::json::array();
      for (unsigned int k = 0; k < r.outputs.size(); ++k)
        {
          std::ostringstream out;
          json["outputs"].push_back(output_table(r, k, out));
          report.say(out.str());
        }

      // Non-monotone responses found by the optimisation.
      std::ostringstream notes;
      notes << "\nmonotonicity: ";
      if (r.optimisation.notes.empty())
        notes << "no non-monotone response detected (no interior optimum, "
                 "no point of the global stage better than a local optimum, "
                 "no sensitivity changing sign)\n";
      else
        {
          notes << r.optimisation.notes.size() << " finding(s):\n";
          for (const std::string &n : r.optimisation.notes)
            notes << "  " << n << "\n";
        }
      json["notes"] = r.optimisation.notes;
      report.say(notes.str());
      FuzzyStudyReport::proof_summary(r, report, json);
      FuzzyStudyReport::spot_checks(r, report, json);
      cost(r, report, json);
    }


    void
    plot(const FuzzyStudyResults &r, OutputFiles &files, Report &report)
    {
      std::vector<MembershipPanel> panels;
      for (unsigned int k = 0; k < r.outputs.size(); ++k)
        {
          const Observation &o = r.outputs[k];
          // Millimetres, kilonewtons and megapascals read best here.
          const std::string unit  = o.unit();
          const double      scale = unit == "m"    ? 1e-3
                                    : unit == "N"  ? 1e3
                                    : unit == "Pa" ? 1e6
                                                   : 1;
          const std::string shown = unit == "m"    ? "mm"
                                    : unit == "N"  ? "kN"
                                    : unit == "Pa" ? "MPa"
                                                   : unit;
          MembershipPanel   panel{o.description(),
                                o.name + " [" + shown + "]",
                                scale,
                                {}};
          if (r.has_reference)
            panel.curves.push_back({"Extension Principle (full order)",
                                    r.alpha,
                                    r.reference.bounds[k],
                                    "points pt 7 ps 0.9 lc rgb '#444444'"});
          panel.curves.push_back({"optimisation (reduced model)",
                                  r.alpha,
                                  r.optimisation.bounds[k],
                                  "lines lw 2 lc rgb '#1f77b4'"});
          if (r.has_vertex)
            panel.curves.push_back({"vertex method (reduced model)",
                                    r.alpha,
                                    r.vertex.bounds[k],
                                    "lines lw 2 dt 2 lc rgb '#d62728'"});
          panels.push_back(panel);
        }
      std::string message;
      if (!add_membership_plot(files,
                               "membership",
                               "Fuzzy response of the scene '" + r.scene + "'",
                               panels,
                               message))
        report.say("warning: " + message + "\n");
    }


    void
    write(const FuzzyStudyResults &results,
          Report                  &report,
          const nlohmann::json    &json,
          const std::string       &directory)
    {
      OutputFiles output(directory);
      plot(results, output, report);
      output.add("report.txt", report.text());
      output.add_json("results.json", json);
      output.write_all();
      std::cout << "\nWrote report.txt, results.json and membership.png (.dat, "
                   ".gp) to "
                << output.directory() << "/" << std::endl;
    }


    std::string
    unproven(const FuzzyStudyResults &results, const int exit_status)
    {
      std::ostringstream out;
      out << "step-4: " << results.unproven.size()
          << " bound(s) not proven within " << results.proof_settings.tolerance
          << " of their output's range (the warnings in "
             "report.txt); exit status "
          << exit_status
          << " ('accept unproven' of subsection Proofs accepts "
             "them)";
      return out.str();
    }
  } // namespace FuzzyStudyReport
} // namespace FuzzyContact
