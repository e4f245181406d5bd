// The part of the fuzzy study's report about static equilibrium
// (fuzzy_report.h): where the bodies held by contact alone can slide (the
// fuzzy output "sliding possible", with where it starts), the share of
// every box with an equilibrium, and the points each method left out of
// its bounds.

#include <fuzzycontact/output/fuzzy_report.h>

#include <iomanip>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    std::string
    number(const double x, const int digits = 6)
    {
      std::ostringstream s;
      s << std::setprecision(digits) << x;
      return s.str();
    }

    // "mu = 0.15, P1.tip.force = 1.5e+04": the fuzzy parameters of
    // @p point (all, or only @p only).
    std::string
    values(const std::vector<FuzzyParameter> &parameters,
           const std::vector<double>         &point,
           const int                          only = -1)
    {
      std::string text;
      for (unsigned int i = 0; i < point.size() && i < parameters.size(); ++i)
        if (only < 0 || static_cast<unsigned int>(only) == i)
          text += (text.empty() ? "" : ", ") + parameters[i].quantity.name +
                  " = " + number(point[i], 9);
      return text;
    }

    nlohmann::json
    values_json(const std::vector<FuzzyParameter> &parameters,
                const std::vector<double>         &point)
    {
      nlohmann::json j = nlohmann::json::object();
      for (unsigned int i = 0; i < point.size() && i < parameters.size(); ++i)
        j[parameters[i].quantity.name] = point[i];
      return j;
    }

    // Per level, the points @p b evaluated and those left out.
    nlohmann::json
    excluded_json(const FuzzyOutputBounds &b)
    {
      return {{"n_points", b.n_points},
              {"n_without_equilibrium", b.n_infeasible}};
    }

    unsigned long
    sum(const std::vector<unsigned long> &v)
    {
      unsigned long s = 0;
      for (const unsigned long x : v)
        s += x;
      return s;
    }

    // A line about @p n evaluations that were counted as without
    // equilibrium or left out (none: no line); a warning if @p warning.
    void
    evaluations_line(std::ostream       &out,
                     const unsigned long n,
                     const bool          warning,
                     const std::string  &text)
    {
      if (n > 0)
        out << "  " << (warning ? "warning: " : "") << n << " evaluation(s) "
            << text << "\n";
    }
  } // namespace


  namespace FuzzyStudyReport
  {
    std::string
    equilibrium(const FuzzyStudyResults &r, nlohmann::json &json)
    {
      std::ostringstream out;
      nlohmann::json     j;
      j["checked"] = r.has_equilibrium;
      if (!r.has_equilibrium)
        {
          json["static_equilibrium"] = j;
          return "";
        }
      const FeasibleRegion &e = r.equilibrium;
      out << "\nstatic equilibrium (bodies held by contact alone: "
          << r.free_bodies << "):\n";
      if (!e.possible)
        out << "  sliding is not possible: every point of every alpha-box "
               "has a static equilibrium (the vertices of every box and "
            << (e.levels.empty() ? 0 : e.levels.front().n_design)
            << " design points per box checked; the vertices also by a "
               "contact solve within small sliding)\n";
      else
        {
          out << "  sliding possible (no static equilibrium at some point of "
                 "the alpha-box) at every level below alpha = "
              << number(e.membership, 9)
              << ", the membership of the fuzzy output 'sliding possible'";
          if (!e.starts_at.empty())
            out << "; it starts at " << values(r.parameters, e.starts_at);
          out << "\n";
          if (!e.vertices_decide)
            out << "  warning: a design point without equilibrium lies in "
                   "a box whose vertices all have one: the vertices do not "
                   "decide, and the membership is that of the levels "
                   "only\n";
          out << "  alpha   sliding    share with equilibrium   where it is "
                 "lost along the box's edges (from a vertex without "
                 "equilibrium)\n";
          for (const LevelFeasibility &level : e.levels)
            {
              out << "  " << std::fixed << std::setprecision(2) << level.alpha
                  << "    " << std::left << std::setw(10)
                  << (level.possible ? "possible" : "no") << std::right;
              std::ostringstream share;
              if (level.n_design > 0)
                share << std::setprecision(3) << level.feasible_fraction()
                      << " (" << level.n_design_feasible << "/"
                      << level.n_design << ")";
              else
                share << (level.n_vertices_feasible == level.n_vertices
                            ? "1 (a point)"
                            : "0 (a point)");
              out << std::left << std::setw(25) << share.str() << std::right;
              std::string where;
              for (const BoundaryCrossing &c : level.boundary)
                where += (where.empty() ? "" : "; ") +
                         values(r.parameters, c.point, c.parameter);
              out << where << "\n";
            }
          out << "  the bounds of every output are over the part of each box "
                 "with a static equilibrium; points without one were left "
                 "out (optimisation: "
              << sum(r.optimisation.n_infeasible) << " of "
              << sum(r.optimisation.n_points) << " points of the global stage";
          if (r.has_vertex)
            out << "; vertex method: " << sum(r.vertex.n_infeasible) << " of "
                << sum(r.vertex.n_points) << " vertices";
          if (r.has_reference)
            out << "; Extension Principle: " << sum(r.reference.n_infeasible)
                << " of " << sum(r.reference.n_points) << " samples";
          out << ", counted per level)\n";
        }
      evaluations_line(
        out,
        r.unanswered.at_limit,
        false,
        "at the limit of equilibrium (the loads need all but 1e-6 of the "
        "friction: the static answer is degenerate there, a body about to "
        "slide may slip any amount) failed in the contact solver and were "
        "counted as without equilibrium");
      j["n_at_limit"] = r.unanswered.at_limit;
      evaluations_line(
        out,
        r.unanswered.unsolved_near_limit,
        true,
        "near the limit of equilibrium (the loads need more than " +
          number(100 * (1 - FuzzyContactModel::near_limit_margin)) +
          " % of the friction) failed in the contact solver and were left "
          "out as if without equilibrium: the bounds next to the edge of "
          "equilibrium may miss them (doc/contact.md, section 1)");
      j["n_unsolved_near_limit"] = r.unanswered.unsolved_near_limit;
      evaluations_line(
        out,
        r.unanswered.beyond_small_sliding,
        false,
        "had contact forces within the friction cones only after the bodies "
        "slid farther than node-to-segment contact answers (the master face "
        "turned by more than 'sliding angle limit' under a closed node's "
        "slide, or a node slid off it, at the point's friction or with "
        "more: the bodies slide) and were counted as without equilibrium");
      j["n_beyond_small_sliding"] = r.unanswered.beyond_small_sliding;
      evaluations_line(
        out,
        r.unanswered.unsolved_below_sliding_limit,
        true,
        "failed in the contact solver below the friction that holds the "
        "bodies within small sliding (with their friction times up to " +
          number(r.unanswered.sliding_factor, 4) +
          " the solves answer within it; with less they fail, as they do "
          "where the cones hold the load only after gross sliding) and were "
          "left out as if without equilibrium: the bounds next to the edge "
          "of equilibrium may miss them (doc/contact.md, section 1)");
      j["n_unsolved_below_sliding_limit"] =
        r.unanswered.unsolved_below_sliding_limit;
      j["unsolved_sliding_factor"] = r.unanswered.sliding_factor;
      // What the failed points' verdicts cost (doc/contact.md, section 1).
      if (r.unanswered.probes > 0)
        out << "  the failed solves' verdicts took " << r.unanswered.probes
            << " probe(s) with more friction, " << r.unanswered.failed_probes
            << " of which failed too\n";
      j["n_sliding_probes"]        = r.unanswered.probes;
      j["n_failed_sliding_probes"] = r.unanswered.failed_probes;

      j["sliding_possible"] = {{"possible", e.possible},
                               {"membership", e.membership},
                               {"starts_at",
                                values_json(r.parameters, e.starts_at)},
                               {"vertices_decide", e.vertices_decide}};
      j["levels"]           = nlohmann::json::array();
      for (const LevelFeasibility &level : e.levels)
        {
          nlohmann::json l = {{"alpha", level.alpha},
                              {"sliding_possible", level.possible},
                              {"feasible_fraction", level.feasible_fraction()},
                              {"n_design", level.n_design},
                              {"n_design_feasible", level.n_design_feasible},
                              {"n_vertices", level.n_vertices},
                              {"n_vertices_feasible",
                               level.n_vertices_feasible}};
          l["boundary"]    = nlohmann::json::array();
          for (const BoundaryCrossing &c : level.boundary)
            l["boundary"].push_back(
              {{"parameter", r.parameters[c.parameter].quantity.name},
               {"value", c.point[c.parameter]},
               {"point", values_json(r.parameters, c.point)}});
          j["levels"].push_back(l);
        }
      j["excluded"]["optimisation"] = excluded_json(r.optimisation);
      if (r.has_vertex)
        j["excluded"]["vertex"] = excluded_json(r.vertex);
      if (r.has_reference)
        j["excluded"]["extension_principle"] = excluded_json(r.reference);
      j["evaluations"]           = e.n_evaluations;
      j["time_s"]                = e.wall_time;
      json["static_equilibrium"] = j;
      return out.str();
    }
  } // namespace FuzzyStudyReport
} // namespace FuzzyContact
