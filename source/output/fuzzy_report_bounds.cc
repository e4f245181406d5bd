// The parts of the fuzzy study's report about the bounds themselves
// (fuzzy_report.h): the proof of every bound (the exact value at its
// argument), its shape (vertex, boundary or interior, kinks) and
// convergence, and the comparison with the reference told apart by the
// proofs.

#include <fuzzycontact/output/fuzzy_report.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>

namespace FuzzyContact
{
  namespace
  {
    std::string
    sci(const double x, const int digits = 1)
    {
      if (std::isnan(x))
        return "n/a";
      std::ostringstream s;
      s << std::scientific << std::setprecision(digits) << x;
      return s.str();
    }

    // A number for results.json: null for NaN (no bound, or no exact
    // value: no static equilibrium there, or a point left out near it) and
    // for infinity.
    nlohmann::json
    value(const double x)
    {
      return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
    }

    // "vertex", "boundary (P1.E)", "interior, kink in P1.tip.force",
    // "boundary, edge of equilibrium in interface.mu".
    std::string
    shape(const BoundQuality &q, const std::vector<FuzzyParameter> &p)
    {
      std::string text = q.where;
      if (!q.kinks.empty())
        {
          text += ", kink in";
          for (const unsigned int i : q.kinks)
            text += " " + p[i].quantity.name;
        }
      if (!q.edge.empty())
        {
          text += ", edge of equilibrium in";
          for (const unsigned int i : q.edge)
            text += " " + p[i].quantity.name;
        }
      return text;
    }

    // What was searched for a bound not shown converged, and why not.
    std::string
    searched(const BoundQuality &q)
    {
      std::ostringstream s;
      s << q.n_design << " points of the global stage, " << q.n_roots
        << " basin root(s), " << q.n_starts
        << " local search(es) from distinct basins, " << q.n_agree
        << " reached the bound";
      if (q.other_optimum > 0)
        s << " (another basin's best lies " << sci(q.other_optimum)
          << " of the range away)";
      if (!q.basins_searched)
        s << "; the design showed more basins than 'local starts' searched";
      if (q.design_better)
        s << "; a point of the global stage was better than every local "
             "search";
      if (!q.scanned.empty())
        s << "; lines through the bound scanned along " << q.scanned.size()
          << " parameter(s)";
      if (q.refined)
        s << "; the pattern search "
          << (q.search_converged ? "converged" : "stopped at its limits")
          << " (final step " << sci(q.final_step) << " of the widths, last "
          << "change " << sci(q.last_change) << " of the range)";
      else
        s << "; projected gradient " << sci(q.projected_gradient);
      return s.str();
    }

    // The convergence measure of a bound: the pattern search's last change
    // where it ran, else the projected gradient.
    double
    convergence(const BoundQuality &q)
    {
      return q.refined ? q.last_change : q.projected_gradient;
    }

    nlohmann::json
    to_json(const BoundQuality &q, const std::vector<FuzzyParameter> &p)
    {
      nlohmann::json j;
      j["where"] = q.where;
      for (const auto &[key, set] : {std::pair{"interior", &q.interior},
                                     std::pair{"kinks", &q.kinks},
                                     std::pair{"line_scans", &q.scanned}})
        {
          j[key] = nlohmann::json::array();
          for (const unsigned int i : *set)
            j[key].push_back(p[i].quantity.name);
        }
      j["scan_gain"]           = q.scan_gain;
      j["projected_gradient"]  = q.projected_gradient;
      j["refined"]             = q.refined;
      j["last_change"]         = q.last_change;
      j["final_step"]          = q.final_step;
      j["iteration_limit"]     = q.iteration_limit;
      j["edge_of_equilibrium"] = nlohmann::json::array();
      for (const unsigned int i : q.edge)
        j["edge_of_equilibrium"].push_back(p[i].quantity.name);
      j["converged"]        = q.converged;
      j["search_converged"] = q.search_converged;
      j["n_design"]         = q.n_design;
      j["n_basin_roots"]    = q.n_roots;
      j["n_starts"]         = q.n_starts;
      j["n_agree"]          = q.n_agree;
      j["other_optimum"]    = q.other_optimum;
      j["design_better"]    = q.design_better;
      j["basins_searched"]  = q.basins_searched;
      return j;
    }

    // The output's range: over every level and both methods.
    double
    range_of(const FuzzyStudyResults &r, const unsigned int k)
    {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const FuzzyOutputBounds *b : {&r.optimisation, &r.reference})
        if (b->bounds.size() > k)
          for (const Interval &i : b->bounds[k])
            if (!std::isnan(i.lower) && !std::isnan(i.upper))
              {
                lo = std::min(lo, i.lower);
                hi = std::max(hi, i.upper);
              }
      return hi > lo ? hi - lo : 0.;
    }
  } // namespace


  namespace FuzzyStudyReport
  {
    void
    proofs(const FuzzyStudyResults &r,
           const unsigned int       k,
           std::ostringstream      &out,
           nlohmann::json          &entry)
    {
      const bool proved = r.has_proofs;
      out << "  the bounds' " << (proved ? "proofs and " : "") << "shapes ("
          << (proved ? "reduced - exact: the exact full-order "
                       "solver at the bound's argument, on the stiffness "
                       "factorisations the model was built from; "
                     : "")
          << "conv.: change of the bound over its last refinements, or "
             "its projected gradient, relative to the output's range, and "
             "whether the bound is shown converged)\n"
          << "  alpha   " << (proved ? "lower: red.-exact " : "lower: ")
          << std::left << std::setw(34) << "shape" << std::setw(14) << "conv."
          << (proved ? "upper: red.-exact " : "upper: ") << std::setw(34)
          << "shape"
          << "conv.\n"
          << std::right;
      nlohmann::json shapes, proof;
      for (unsigned int l = 0; l < r.alpha.size(); ++l)
        {
          out << "  " << std::fixed << std::setprecision(2) << r.alpha[l]
              << "   ";
          for (const bool upper : {false, true})
            {
              const BoundQuality &q    = upper
                                           ? r.optimisation.upper_quality[k][l]
                                           : r.optimisation.lower_quality[k][l];
              const std::string   side = upper ? "upper" : "lower";
              if (proved)
                {
                  const BoundProof &p =
                    upper ? r.proofs.upper[k][l] : r.proofs.lower[k][l];
                  // (!): beyond the proofs' tolerance, see the warnings.
                  bool proven = true;
                  for (const UnprovenBound &u : r.unproven)
                    if (u.output == k && u.level == l && u.upper == upper)
                      proven = false;
                  out << std::setw(10) << sci(p.difference())
                      << (proven ? "        " : " (!)    ");
                  proof[side + "_reduced"].push_back(value(p.reduced));
                  proof[side + "_exact"].push_back(value(p.exact));
                  proof[side + "_difference"].push_back(value(p.difference()));
                  proof[side + "_proven"].push_back(proven);
                }
              else
                out << "       ";
              out << std::left << std::setw(34) << shape(q, r.parameters) << " "
                  << std::setw(14)
                  << (q.where == "none"
                        ? std::string("n/a")
                        : sci(convergence(q)) + (q.converged ? " yes" : " NO"))
                  << std::right;
              shapes[side].push_back(to_json(q, r.parameters));
            }
          out << "\n";
        }
      entry["shape"] = shapes;
      if (proved)
        {
          // The largest reduction error at a bound, relative to the range.
          double largest = 0;
          for (const auto *side : {&r.proofs.lower[k], &r.proofs.upper[k]})
            for (const BoundProof &p : *side)
              if (!std::isnan(p.difference()))
                largest = std::max(largest, std::abs(p.difference()));
          const double range = range_of(r, k);
          proof["max_abs_difference_over_range"] =
            range > 0 ? largest / range : largest;
          entry["proof"] = proof;
          out << "  largest |reduced - exact| at a bound: " << sci(largest, 2)
              << (range > 0 ? " (" + sci(largest / range, 2) + " of the range)"
                            : std::string())
              << "\n";
        }

      // The bounds not shown converged: what was searched for each.
      nlohmann::json not_converged = nlohmann::json::array();
      for (unsigned int l = 0; l < r.alpha.size(); ++l)
        for (const bool upper : {false, true})
          {
            const BoundQuality &q = upper ? r.optimisation.upper_quality[k][l]
                                          : r.optimisation.lower_quality[k][l];
            if (q.converged || q.where == "none")
              continue;
            std::ostringstream level;
            level << std::fixed << std::setprecision(2) << r.alpha[l];
            out << "  not shown converged: " << (upper ? "upper" : "lower")
                << " bound at alpha = " << level.str() << ": " << searched(q)
                << "\n";
            not_converged.push_back({{"alpha", r.alpha[l]},
                                     {"side", upper ? "upper" : "lower"},
                                     {"searched", searched(q)}});
          }
      entry["converged"]     = not_converged.empty();
      entry["not_converged"] = not_converged;
      if (!not_converged.empty())
        out << "warning: " << r.outputs[k].name << ": " << not_converged.size()
            << " bound(s) not shown converged (the design showed more "
               "basins than were searched and the searches disagree, or a "
               "search stopped at its limits, or the design found a better "
               "point); they are the best points found\n";

      // Kinks and interior optima, per side.
      for (const bool upper : {false, true})
        {
          unsigned int n_interior = 0, n_kinks = 0;
          for (unsigned int l = 0; l < r.alpha.size(); ++l)
            {
              const BoundQuality &q = upper
                                        ? r.optimisation.upper_quality[k][l]
                                        : r.optimisation.lower_quality[k][l];
              n_interior += !q.interior.empty();
              n_kinks += !q.kinks.empty();
            }
          if (n_interior > 0)
            out << "  " << (upper ? "upper" : "lower") << " bound: inside the "
                << "box at " << n_interior << " level(s)"
                << (n_kinks > 0 ? ", at a kink of the response at " +
                                    std::to_string(n_kinks) + " level(s)"
                                : std::string(", no kink"))
                << "\n";
        }
    }


    void
    comparison(const FuzzyStudyResults &r,
               const unsigned int       k,
               std::ostringstream      &out,
               nlohmann::json          &entry)
    {
      if (!r.has_reference || !r.has_proofs)
        return;
      const double range = range_of(r, k);
      // A shortfall within the outputs' accuracy (the proofs' floor, of the
      // output's magnitude) is round-off: an output the parameters cannot
      // change has a range of round-off only.
      double magnitude = 0;
      for (const FuzzyOutputBounds *b : {&r.optimisation, &r.reference})
        if (b->bounds.size() > k)
          for (const Interval &i : b->bounds[k])
            for (const double v : {i.lower, i.upper})
              if (std::isfinite(v))
                magnitude = std::max(magnitude, std::abs(v));
      const double   allowed  = std::max(r.proof_settings.tolerance * range,
                                      r.proof_settings.accuracy * magnitude);
      double         short_of = 0, missed = 0, unverified = 0;
      unsigned int   n_missed = 0, n_unverified = 0;
      nlohmann::json short_bounds = nlohmann::json::array();
      std::string    short_levels;
      for (unsigned int l = 0; l < r.alpha.size(); ++l)
        for (const bool upper : {false, true})
          {
            const BoundProof &p =
              upper ? r.proofs.upper[k][l] : r.proofs.lower[k][l];
            const Interval &ref = r.reference.bounds[k][l];
            if (std::isnan(p.reduced) || std::isnan(p.exact) ||
                std::isnan(ref.lower) || std::isnan(ref.upper))
              continue; // (no bound there, or no equilibrium at it)
            const auto c = compare_with_reference(p.reduced,
                                                  p.exact,
                                                  upper ? ref.upper : ref.lower,
                                                  upper,
                                                  range);
            short_of     = std::max(short_of, c.short_of_reference);
            // The reference's sample is a real point of the box: a bound
            // short of it by more than the proofs' tolerance is not the
            // optimum, whatever its search said.
            if (c.short_of_reference * range > allowed)
              {
                std::ostringstream level;
                level << std::fixed << std::setprecision(2) << r.alpha[l];
                short_bounds.push_back({{"alpha", r.alpha[l]},
                                        {"side", upper ? "upper" : "lower"},
                                        {"short", c.short_of_reference}});
                short_levels += std::string(short_levels.empty() ? "" : ", ") +
                                (upper ? "upper" : "lower") +
                                " at alpha = " + level.str();
              }
            missed     = std::max(missed, c.reference_missed);
            unverified = std::max(unverified, c.outside_not_verified);
            n_missed += c.reference_missed > 0;
            n_unverified += c.outside_not_verified > 0;
          }
      out << "  against the Extension Principle, relative to the output's "
             "range ("
          << sci(range, 3) << "): the optimisation is short of it by at most "
          << sci(short_of);
      // A shortfall above the tolerance of the range but within the
      // output's accuracy (a range of round-off) is said to be round-off,
      // not left to read as a miss.
      // (The same words for a reduction error of that size, below.)
      const auto round_off = [&](const double relative) {
        return " (" + sci(relative * range) +
               " in the output's units: within its accuracy, " +
               sci(r.proof_settings.accuracy) + " of its magnitude " +
               sci(magnitude, 3) + ", so round-off)";
      };
      if (short_of > r.proof_settings.tolerance && short_bounds.empty())
        out << round_off(short_of);
      out << "\n";
      if (n_missed > 0)
        out << "  " << n_missed << " bound(s) lie beyond the Extension "
            << "Principle's interval and the exact solver confirms them at "
               "their arguments: the reference missed them, by up to "
            << sci(missed)
            << " (a sampled reference can only under-estimate an "
               "interval)\n";
      if (n_unverified > 0)
        {
          out << "  " << n_unverified << " bound(s) lie beyond the Extension "
              << "Principle's interval only by the reduction error (the exact "
                 "value at the argument does not), by up to "
              << sci(unverified);
          // (As for the shortfall: within the output's accuracy, a
          // reduction error of round-off.)
          if (unverified * range <= allowed)
            out << round_off(unverified);
          out << "\n";
        }
      if (!short_bounds.empty())
        {
          out << "warning: " << r.outputs[k].name << ": " << short_bounds.size()
              << " bound(s) fall short of the Extension Principle's sampled "
                 "interval by more than "
              << sci(r.proof_settings.tolerance) << " of the range and "
              << sci(r.proof_settings.accuracy) << " of the magnitude ("
              << short_levels
              << "): a better point exists, the search missed it\n";
          entry["converged"] = false;
        }
      entry["reference_comparison"] = {{"range", range},
                                       {"short_of_reference", short_of},
                                       {"short_bounds", short_bounds},
                                       {"reference_missed", missed},
                                       {"n_reference_missed", n_missed},
                                       {"outside_not_verified", unverified},
                                       {"n_outside_not_verified",
                                        n_unverified}};
    }


    std::string
    enrichment(const unsigned int round,
               const std::size_t  n_points,
               const unsigned int added,
               const double       tolerance)
    {
      std::ostringstream out;
      out << "proofs, round " << round << ": bounds beyond " << sci(tolerance)
          << " of their output's range; the model is made richer with the "
             "exact solutions at their "
          << n_points << " distinct argument(s): " << added
          << " vector(s) added"
          << (added > 0 ? ", the bounds are searched again"
                        : ", nothing new (the rounds stop)")
          << "\n";
      return out.str();
    }


    void
    proof_summary(const FuzzyStudyResults &r,
                  Report                  &report,
                  nlohmann::json          &json)
    {
      if (!r.has_proofs)
        return;
      const ProofSettings &ps = r.proof_settings;
      std::ostringstream   out;
      out << "\nproofs: a bound is proven when |reduced - exact| at its "
             "argument is at most "
          << sci(ps.tolerance) << " of its output's range, or "
          << sci(ps.accuracy)
          << " of its magnitude (the outputs' accuracy, Optimisation: "
             "response tolerance) ("
          << r.proof_rounds.size() << " round(s) of search and proofs; "
          << r.proof_stop << ")\n";
      nlohmann::json rounds = nlohmann::json::array();
      for (unsigned int i = 0; i < r.proof_rounds.size(); ++i)
        {
          const ProofRound &p = r.proof_rounds[i];
          out << "  round " << i << ": " << p.evaluations
              << " reduced evaluations, " << p.proofs << " exact solves, "
              << p.n_unproven << " bound(s) beyond the tolerance";
          if (p.n_unproven > 0)
            out << " (largest " << sci(p.largest, 2) << " of the range)";
          if (p.added > 0)
            out << "; " << p.added << " vector(s) added to the model";
          out << "\n";
          rounds.push_back({{"evaluations", p.evaluations},
                            {"exact_solves", p.proofs},
                            {"n_unproven", p.n_unproven},
                            {"largest_relative_error", value(p.largest)},
                            {"vectors_added", p.added},
                            {"search_time_s", p.search_time},
                            {"proof_time_s", p.proof_time},
                            {"enrichment_time_s", p.enrichment_time}});
        }
      if (r.proof_cg.by_cg + r.proof_cg.factorised > 0)
        {
          out << "  changed stiffnesses (Proofs: solver = "
              << (ps.solver == ProofSettings::Solver::cg ? "cg" : "automatic")
              << "): " << r.proof_cg.by_cg
              << " solved by conjugate gradients on the nominal "
                 "factorisations, "
              << r.proof_cg.factorised << " factorised";
          if (r.proof_cg.solves > 0)
            out << "; " << r.proof_cg.solves << " CG solves, "
                << sci(double(r.proof_cg.iterations) / r.proof_cg.solves, 2)
                << " steps each on average (at most "
                << r.proof_cg.max_iterations << "), relative residual "
                << sci(ps.cg_tolerance);
          out << "\n";
        }
      if (!r.model_after.empty())
        out << "  the model after the last round:\n" << r.model_after;
      report.say(out.str());

      // One warning line per unproven bound.
      nlohmann::json     unproven = nlohmann::json::array();
      std::ostringstream warnings;
      for (const UnprovenBound &u : r.unproven)
        {
          const std::string name = r.outputs[u.output].name;
          warnings << "warning: the " << (u.upper ? "upper" : "lower")
                   << " bound of " << name << " at alpha = " << std::fixed
                   << std::setprecision(2) << r.alpha[u.level]
                   << " is not proven: reduced - exact = "
                   << sci(u.difference, 2) << " at its argument, "
                   << sci(u.relative, 2) << " of the output's range (tolerance "
                   << sci(ps.tolerance) << ")\n";
          unproven.push_back({{"output", name},
                              {"alpha", r.alpha[u.level]},
                              {"side", u.upper ? "upper" : "lower"},
                              {"difference", value(u.difference)},
                              {"relative_error", value(u.relative)},
                              {"argument", u.argument}});
        }
      if (!r.unproven.empty())
        warnings << "warning: " << r.unproven.size()
                 << " bound(s) are not proven within the tolerance after "
                 << r.proof_rounds.size() << " round(s); "
                 << (ps.accept_unproven
                       ? "accepted ('accept unproven = true'): exit status 0"
                       : "step-4 exits with status 3 ('accept unproven' of "
                         "subsection Proofs accepts them)")
                 << "\n";
      report.say(warnings.str());
      json["proofs"] = {{"tolerance", ps.tolerance},
                        {"accuracy", ps.accuracy},
                        {"max_rounds", ps.max_rounds},
                        {"rounds", rounds},
                        {"stopped", r.proof_stop},
                        {"all_proven", r.unproven.empty()},
                        {"accepted", ps.accept_unproven},
                        {"unproven", unproven},
                        {"solver",
                         ps.solver == ProofSettings::Solver::cg ? "cg"
                         : ps.solver == ProofSettings::Solver::factorisation
                           ? "factorisation"
                           : "automatic"},
                        {"stiffnesses_by_cg", r.proof_cg.by_cg},
                        {"stiffnesses_factorised", r.proof_cg.factorised},
                        {"cg_solves", r.proof_cg.solves},
                        {"cg_iterations", r.proof_cg.iterations},
                        {"cg_tolerance", ps.cg_tolerance}};
    }


    void
    spot_checks(const FuzzyStudyResults &r,
                Report                  &report,
                nlohmann::json          &json)
    {
      if (r.proof_settings.spot_checks == 0)
        return;
      const SpotChecks    &c  = r.spot_checks;
      const ProofSettings &ps = r.proof_settings;
      const auto           at = [&r](const std::vector<double> &p) {
        return "(" + point_text(r.parameters, p) + ")";
      };
      std::ostringstream out, warnings;
      out << "\nspot checks (Proofs: spot checks = " << ps.spot_checks
          << "): " << c.n_checked << " of the optimisation's " << c.n_recorded
          << " evaluations (of its last round), evenly spread, solved by the "
             "full-order model too, on reused factorisations\n";
      nlohmann::json outputs = nlohmann::json::array();
      unsigned int   beyond  = 0;
      for (unsigned int k = 0;
           k < c.largest_difference.size() && k < r.outputs.size();
           ++k)
        {
          const double d     = c.largest_difference[k];
          const double range = proof_range(r.optimisation, r.proofs, k);
          const double relative =
            range > 0 ? d / range
                      : (d > 0 ? std::numeric_limits<double>::infinity() : 0.);
          // Beyond the tolerance of the range and the accuracy of the
          // magnitude, as a proof (proof_feedback.h).
          const bool within =
            relative <= ps.tolerance ||
            d <= ps.accuracy * proof_magnitude(r.optimisation, r.proofs, k);
          out << "  " << r.outputs[k].name << ": largest |reduced - exact| "
              << sci(d, 2) << " (" << sci(relative, 2) << " of the range)"
              << (within ? "" : ", beyond the tolerance") << "\n";
          if (!within)
            {
              ++beyond;
              warnings << "warning: spot checks: " << r.outputs[k].name
                       << ": reduced - exact reaches " << sci(d, 2) << ", "
                       << sci(relative, 2)
                       << " of the output's range (tolerance "
                       << sci(ps.tolerance) << "), at " << at(c.argument[k])
                       << ": the bounds are proven at their arguments only, "
                          "and the optimisation may have missed a larger "
                          "value where the reduced model is this far off\n";
            }
          outputs.push_back({{"name", r.outputs[k].name},
                             {"largest_difference", value(d)},
                             {"relative_error", value(relative)},
                             {"argument", c.argument[k]},
                             {"within_tolerance", within}});
        }
      if (c.n_without_solution > 0)
        out << "  " << c.n_without_solution
            << " point(s) without a static solution in both models\n";
      if (c.n_disagreeing > 0)
        {
          warnings << "warning: spot checks: at " << c.n_disagreeing
                   << " point(s) one model has a static solution and the "
                      "other none (the reduced model none at "
                   << c.n_fast_without << ", the full-order one none at "
                   << c.n_disagreeing - c.n_fast_without << "), e.g. at "
                   << at(c.disagreeing.front()) << "\n";
        }
      const double fast  = c.n_checked > 0 ? c.fast_seconds / c.n_checked : 0,
                   exact = c.n_checked > 0 ? c.exact_seconds / c.n_checked : 0;
      if (c.n_checked > 0)
        {
          out << "  one evaluation at these points: " << std::fixed
              << std::setprecision(3) << 1e3 * fast
              << " ms reduced (as the optimisation ran it, from its "
                 "neighbours), "
              << 1e3 * exact << " ms full order (each point alone)";
          if (fast > 0)
            out << ": " << std::setprecision(1) << exact / fast << "x";
          out << "\n";
        }
      report.say(out.str() + warnings.str());
      nlohmann::json disagreeing = nlohmann::json::array();
      for (const std::vector<double> &p : c.disagreeing)
        disagreeing.push_back(p);
      json["spot_checks"] = {
        {"requested", ps.spot_checks},
        {"recorded", c.n_recorded},
        {"checked", c.n_checked},
        {"without_solution", c.n_without_solution},
        {"disagreeing", c.n_disagreeing},
        {"disagreeing_without_reduced", c.n_fast_without},
        {"disagreeing_points", disagreeing},
        {"reduced_ms", 1e3 * fast},
        {"full_order_ms", 1e3 * exact},
        {"ratio", fast > 0 ? value(exact / fast) : nlohmann::json()},
        {"outputs", outputs},
        {"all_within_tolerance", beyond == 0 && c.n_disagreeing == 0}};
    }


    std::string
    inert(const FuzzyStudyResults &r, nlohmann::json &json)
    {
      std::ostringstream out;
      json["inert_parameters"] = nlohmann::json::array();
      for (unsigned int i = 0; i < r.inert.size(); ++i)
        if (!r.inert[i].empty())
          {
            out << "  " << r.parameters[i].quantity.name
                << " cannot change the answer (" << r.inert[i]
                << "): it is held at its nominal value, and the outputs are "
                   "crisp in it\n";
            json["inert_parameters"].push_back(
              {{"name", r.parameters[i].quantity.name},
               {"reason", r.inert[i]}});
          }
      return out.str();
    }
  } // namespace FuzzyStudyReport
} // namespace FuzzyContact
