// The chains of the optimisation method (optimisation_chain.h): one
// output's lower or upper bound at every level, and the checks of each
// bound (interval ends, other basins, pattern search, non-monotone
// responses, the multi-start, the signs of the sensitivities).

#include <fuzzycontact/fuzzy/optimisation_chain.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace FuzzyContact
{
  namespace LocalOptimisation
  {
    namespace
    {
      std::string
      format(const double x)
      {
        std::ostringstream s;
        s.precision(6);
        s << x;
        return s.str();
      }

      // Corner number @p corner of the box [lower, upper]: bit i set means
      // the upper end of coordinate i.
      VectorType
      vertex(const unsigned long corner,
             const VectorType   &lower,
             const VectorType   &upper)
      {
        const unsigned int n = lower.size();
        VectorType         v(n);
        for (unsigned int i = 0; i < n; ++i)
          v[i] = (corner >> i) & 1 ? upper[i] : lower[i];
        return v;
      }
    } // namespace


    ChainResult
    Chain::run(const std::vector<double>       &alpha,
               const std::vector<unsigned int> &order,
               const VectorType                &centre,
               const std::vector<VectorType>   &design,
               Progress                        *progress) const
    {
      std::vector<bool> rough(normalisation.n_free(), false);
      ChainResult       result =
        levels(alpha, order, centre, design, progress, rough);
      if (!unscanned(alpha, order, rough, result))
        return result;
      // A kink met at some level was not known at the levels above it (the
      // first level below the core has none above to tell it): the chain
      // once more, scanning lines along those parameters from the start.
      // The cache answers the points evaluated before.
      result = levels(alpha, order, centre, design, nullptr, rough);
      result.notes.push_back(
        what + ": kinks met below the core; every level was searched again, "
               "scanning lines through its bound along the parameters with "
               "kinks from the first level on");
      return result;
    }


    // Levels whose bound was not scanned along a parameter of @p rough in
    // which its box has a width.
    bool
    Chain::unscanned(const std::vector<double>       &alpha,
                     const std::vector<unsigned int> &order,
                     const std::vector<bool>         &rough,
                     const ChainResult               &result) const
    {
      if (settings.line_scan_points < 2)
        return false;
      for (const unsigned int l : order)
        {
          const auto [lo, hi] = normalisation.box(parameters, alpha[l]);
          const std::vector<unsigned int> &done = result.quality[l].scanned;
          for (unsigned int j = 0; j < rough.size(); ++j)
            if (rough[j] && hi[j] > lo[j] &&
                std::find(done.begin(), done.end(), normalisation.free[j]) ==
                  done.end())
              return true;
        }
      return false;
    }


    ChainResult
    Chain::levels(const std::vector<double>       &alpha,
                  const std::vector<unsigned int> &order,
                  const VectorType                &centre,
                  const std::vector<VectorType>   &design,
                  Progress                        *progress,
                  std::vector<bool>               &rough) const
    {
      ChainResult result;
      result.value.resize(alpha.size());
      result.argument.resize(alpha.size());
      result.quality.resize(alpha.size());
      // The best points of the level above lie in this level's box: they
      // seed it, so a lower level's interval contains the upper's.
      std::vector<VectorType> seeds{centre};
      std::vector<VectorType> gradients;
      for (const unsigned int l : order)
        {
          const auto [lo, hi] = normalisation.box(parameters, alpha[l]);
          OutputObjective   objective(cache,
                                    normalisation,
                                    output,
                                    sign,
                                    scale,
                                    settings.finite_difference_step,
                                    lo,
                                    hi);
          const std::string level = what + ", alpha = " + format(alpha[l]);

          // The global stage: the points with a solution, best first.
          const GlobalStage stage =
            global_stage(objective, design, seeds, lo, hi);
          const std::vector<Candidate> &pool = stage.candidates;
          BoundQuality                  quality;
          quality.n_design = pool.size();
          if (pool.empty())
            {
              // No point of the box has a solution: no bound here.
              result.value[l] = std::numeric_limits<double>::quiet_NaN();
              result.argument[l].clear();
              quality.where     = "none";
              result.quality[l] = quality;
              result.notes.push_back(
                level + ": none of the " + std::to_string(stage.n_points) +
                " points of the global stage has a solution: no bound");
              if (progress)
                progress->advance();
              continue;
            }
          const double range  = pool.back().value - pool.front().value;
          const double noise0 = settings.response_tolerance *
                                std::max(1., std::abs(pool.front().value));
          const Level here{objective, lo, hi, range, level};

          // Local searches from the best points of distinct basins.
          const Starts starts                    = basin_starts(objective,
                                             pool,
                                             lo,
                                             hi,
                                             settings.local_starts,
                                             noise0);
          quality.n_roots                        = starts.n_roots;
          quality.n_starts                       = starts.points.size();
          quality.basins_searched                = starts.all_roots_tested;
          const std::vector<LocalOptimum> optima = local_stage(here, starts);
          unsigned int                    winner = 0;
          for (unsigned int s = 1; s < optima.size(); ++s)
            if (optima[s].value < optima[winner].value)
              winner = s;
          LocalOptimum best       = optima[winner];
          quality.iteration_limit = !best.converged;

          // Is the response monotone here? An interior optimum, or a point
          // of the global stage better than the local optimum, says not.
          std::vector<std::string> findings;
          const bool   moved = check_interval_ends(here, best, findings);
          const double noise =
            settings.response_tolerance * std::max(1., std::abs(best.value));
          const bool missed = pool.front().value < best.value - noise;
          if (missed)
            findings.push_back(std::string(pool.front().vertex
                                             ? "a vertex of the box"
                                             : "a point of the global stage") +
                               " is better than the local optimum");
          if (!findings.empty())
            result.notes.push_back(non_monotone(here,
                                                best,
                                                findings,
                                                missed,
                                                quality.n_starts,
                                                design.size()));
          quality.design_better = pool.front().value < best.value - noise;
          if (pool.front().value < best.value)
            {
              best.x     = pool.front().x;
              best.value = pool.front().value;
            }
          objective.gradient_at(best.gradient, best.x);
          refine(here, best, quality);
          compare_basins(here, optima, winner, best, quality, result);
          scan_lines(here, best, quality, rough, result);
          gradients.push_back(best.gradient);

          // Converged only with evidence (BoundQuality::converged).
          quality.converged =
            (quality.refined ? quality.search_converged
                             : quality.projected_gradient == 0) &&
            !quality.design_better &&
            (quality.basins_searched || quality.n_agree >= 2);

          if (moved)
            result.notes.push_back(
              level + ": the local optimiser stopped short of the optimum (" +
              (best.converged ? "converged to its tolerances"
                              : "at its iteration limit") +
              "); the ends of the parameter intervals were better and the "
              "optimum was moved there");
          else if (quality.iteration_limit)
            result.notes.push_back(iteration_limit_note(level, quality));
          result.value[l]    = sign * best.value * scale;
          result.argument[l] = normalisation.parameters(best.x);
          result.quality[l]  = quality;
          seeds              = {best.x};
          for (unsigned int c = 0; c < std::min<std::size_t>(2, pool.size());
               ++c)
            seeds.push_back(pool[c].x);
          if (progress)
            progress->advance();
        }
      check_sensitivity_signs(gradients, result);
      return result;
    }


    // A local optimisation from each start.
    std::vector<LocalOptimum>
    Chain::local_stage(const Level &level, const Starts &starts) const
    {
      OutputObjective          &objective = level.objective;
      const VectorType         &lo = level.lo, &hi = level.hi;
      std::vector<LocalOptimum> optima;
      for (const Candidate &s : starts.points)
        optima.push_back(minimise(objective, s.x, lo, hi, settings));
      return optima;
    }


    // The local searches from the other basins than the @p winner's,
    // against the bound @p best: those that did not reach it are refined
    // as the bound was (ends of the intervals, pattern search); how many
    // reach it is counted, how far the best of the others stays is kept,
    // and a better one (rare: its pattern search went further) becomes the
    // bound.
    void
    Chain::compare_basins(const Level                     &level,
                          const std::vector<LocalOptimum> &optima,
                          const unsigned int               winner,
                          LocalOptimum                    &best,
                          BoundQuality                    &quality,
                          ChainResult                     &result) const
    {
      OutputObjective &objective = level.objective;
      const double     range     = level.range;
      const double     noise =
        settings.response_tolerance * std::max(1., std::abs(best.value));
      const double tolerance = std::max(10 * noise, 1e-6 * range);
      quality.n_agree        = quality.design_better ? 0 : 1;
      double other           = std::numeric_limits<double>::infinity();
      for (unsigned int s = 0; s < optima.size(); ++s)
        {
          if (s == winner)
            continue;
          LocalOptimum o = optima[s];
          if (o.value > best.value + tolerance)
            {
              std::vector<std::string> ignored;
              check_interval_ends(level, o, ignored);
              objective.gradient_at(o.gradient, o.x);
              BoundQuality scratch;
              refine(level, o, scratch);
            }
          if (o.value < best.value - tolerance)
            {
              // Another basin's search went further: it is the bound.
              result.notes.push_back(
                level.name +
                ": the local search from another basin found a better point "
                "than the best start's (by " +
                format((best.value - o.value) / (range > 0 ? range : 1.)) +
                " of the range); it is the bound");
              other          = std::min(other, best.value);
              best           = o;
              BoundQuality q = quality;
              refine(level, best, q);
              q.n_agree = 1;
              quality   = q;
            }
          else if (o.value <= best.value + tolerance)
            ++quality.n_agree;
          else
            other = std::min(other, o.value);
        }
      quality.other_optimum =
        std::isfinite(other) ? (other - best.value) / (range > 0 ? range : 1.)
                             : 0.;
    }


    // The shape of the optimum, and the pattern search where it has
    // interior coordinates or a projected gradient (ROL stopped short).
    void
    Chain::refine(const Level  &level,
                  LocalOptimum &best,
                  BoundQuality &quality) const
    {
      OutputObjective  &objective = level.objective;
      const VectorType &lo = level.lo, &hi = level.hi;
      const double      range = level.range;
      const double      noise =
        settings.response_tolerance * std::max(1., std::abs(best.value));
      const auto shape = [&]() {
        shape_of_optimum(objective,
                         normalisation,
                         best.x,
                         best.value,
                         best.gradient,
                         lo,
                         hi,
                         settings.interior_tolerance,
                         range,
                         noise,
                         quality);
      };
      shape();
      if (quality.interior.empty() && quality.projected_gradient == 0)
        return;
      const VectorType    before = best.x;
      const PatternSearch search = pattern_search(objective,
                                                  best.x,
                                                  best.value,
                                                  lo,
                                                  hi,
                                                  1. / 16,
                                                  settings.refinement_step,
                                                  noise);
      quality.refined            = true;
      quality.last_change      = search.last_change / (range > 0 ? range : 1.);
      quality.final_step       = search.final_step;
      quality.search_converged = search.converged;
      if (best.x != before)
        {
          objective.gradient_at(best.gradient, best.x);
          shape();
        }
    }


    // Lines through the bound along the parameters in @p rough (a kink or
    // an interior optimum met at this level or one above; this bound's are
    // added): settings.line_scan_points values of each, evenly spaced over
    // the box, the other parameters kept. A better point moves the bound,
    // which is refined again (pattern search) and scanned again, at most
    // four times.
    void
    Chain::scan_lines(const Level       &level,
                      LocalOptimum      &best,
                      BoundQuality      &quality,
                      std::vector<bool> &rough,
                      ChainResult       &result) const
    {
      const unsigned int n_values = settings.line_scan_points;
      if (n_values < 2)
        return;
      OutputObjective  &objective = level.objective;
      const VectorType &lo = level.lo, &hi = level.hi;
      const auto        mark = [&]() {
        for (const std::vector<unsigned int> *set :
             {&quality.kinks, &quality.interior})
          for (const unsigned int p : *set)
            {
              const auto j = std::find(normalisation.free.begin(),
                                       normalisation.free.end(),
                                       p);
              Assert(j != normalisation.free.end(), ExcInternalError());
              rough[j - normalisation.free.begin()] = true;
            }
      };
      mark();
      const double start = best.value;
      for (unsigned int pass = 0; pass < 4; ++pass)
        {
          std::vector<VectorType> line;
          for (unsigned int j = 0; j < rough.size(); ++j)
            if (rough[j] && hi[j] > lo[j])
              {
                if (std::find(quality.scanned.begin(),
                              quality.scanned.end(),
                              normalisation.free[j]) == quality.scanned.end())
                  quality.scanned.push_back(normalisation.free[j]);
                for (unsigned int k = 0; k < n_values; ++k)
                  {
                    VectorType x = best.x;
                    x[j]         = k + 1 == n_values
                                     ? hi[j]
                                     : lo[j] + (hi[j] - lo[j]) * k / (n_values - 1);
                    line.push_back(x);
                  }
              }
          if (line.empty())
            return;
          objective.prefetch(line);
          const double noise =
            settings.response_tolerance * std::max(1., std::abs(best.value));
          double       value  = best.value - noise;
          unsigned int better = line.size();
          for (unsigned int i = 0; i < line.size(); ++i)
            {
              const double v = objective.at(line[i]);
              if (v < value)
                {
                  value  = v;
                  better = i;
                }
            }
          if (better == line.size())
            break;
          best.x     = line[better];
          best.value = value;
          objective.gradient_at(best.gradient, best.x);
          refine(level, best, quality);
          mark();
        }
      if (best.value < start)
        {
          const double range = level.range > 0 ? level.range : 1.;
          quality.scan_gain  = (start - best.value) / range;
          std::string along;
          for (const unsigned int p : quality.scanned)
            along +=
              (along.empty() ? "parameter " : ", ") + std::to_string(p + 1);
          result.notes.push_back(
            level.name + ": a line through the local searches' optimum along " +
            along + " found a better point (by " + format(quality.scan_gain) +
            " of the range): the searches had stopped at a kink; the bound "
            "moved there and was refined again");
        }
    }


    // What is true of a bound whose winning local optimisation stopped at
    // ROL's iteration limit.
    std::string
    Chain::iteration_limit_note(const std::string  &level,
                                const BoundQuality &quality) const
    {
      std::string note = level + ": ROL stopped at its iteration limit (" +
                         std::to_string(settings.max_iterations) +
                         " iterations); no end of a parameter interval was "
                         "better, ";
      if (quality.refined)
        note += "and the pattern search refined the point " +
                std::string(quality.search_converged
                              ? "until three halvings of its step in a row "
                                "improved nothing (final step " +
                                  format(quality.final_step) + " of the widths)"
                              : "but stopped at its limits: the bound changed "
                                "by " +
                                  format(quality.last_change) +
                                  " of the output's range over its last three "
                                  "refinements");
      else
        note += "and the bound lies at a vertex with a projected gradient of " +
                format(quality.projected_gradient);
      return note;
    }


    // Every coordinate of @p best strictly inside its interval, compared
    // with the two ends of the interval (the other coordinates kept):
    //  - both ends worse: an interior optimum (non-monotone response);
    //  - both ends better: an interior stationary point that is no optimum
    //    (non-monotone response); move to the better end;
    //  - one end better: the optimiser stopped short in a monotone
    //    direction; move there (returns true);
    //  - an end as good: the response is flat in that parameter (it does
    //    not depend on it there); move there.
    bool
    Chain::check_interval_ends(const Level              &level,
                               LocalOptimum             &best,
                               std::vector<std::string> &findings) const
    {
      OutputObjective  &objective = level.objective;
      const VectorType &lo = level.lo, &hi = level.hi;
      const double      noise =
        settings.response_tolerance * std::max(1., std::abs(best.value));
      bool moved = false;
      for (unsigned int i = 0; i < best.x.size(); ++i)
        {
          const double width = hi[i] - lo[i];
          if (width <= 0)
            continue;
          const double tol = settings.interior_tolerance * width;
          if (best.x[i] <= lo[i] + tol || best.x[i] >= hi[i] - tol)
            continue;
          VectorType at_end      = best.x;
          at_end[i]              = lo[i];
          const double f_lo      = objective.at(at_end);
          at_end[i]              = hi[i];
          const double      f_hi = objective.at(at_end);
          const std::string where =
            "parameter " + std::to_string(normalisation.free[i] + 1) + " (at " +
            format(normalisation.parameters(best.x)[normalisation.free[i]]) +
            ")";
          const bool lo_better = f_lo < best.value - noise;
          const bool hi_better = f_hi < best.value - noise;
          if (std::min(f_lo, f_hi) > best.value + noise)
            {
              findings.push_back("optimum inside the interval of " + where);
              continue;
            }
          if (lo_better && hi_better)
            findings.push_back("a stationary point inside the interval of " +
                               where + " that is no optimum");
          else
            moved = moved || lo_better || hi_better;
          best.x[i]  = f_lo <= f_hi ? lo[i] : hi[i];
          best.value = std::min(best.value, std::min(f_lo, f_hi));
        }
      return moved;
    }


    // The note on a non-monotone response at one level, and the answer to
    // it: without a global stage, or when the local optimum was @p missed
    // by it (a better point of the global stage), the multi-start, unless
    // the fallback is disabled; else what the global stage did.
    std::string
    Chain::non_monotone(const Level                    &level,
                        LocalOptimum                   &best,
                        const std::vector<std::string> &findings,
                        const bool                      missed,
                        const unsigned int              n_starts,
                        const unsigned int              n_design) const
    {
      std::string note = level.name + ": non-monotone response (";
      for (unsigned int f = 0; f < findings.size(); ++f)
        note += (f ? "; " : "") + findings[f];
      note += ")";
      if (n_design > 0 && !missed)
        note +=
          "; the global stage (" + std::to_string(n_design) + " design points" +
          (normalisation.n_free() < 20 ? ", the vertices" : "") +
          ", the optima of the level above) and " + std::to_string(n_starts) +
          " local start(s) found no better point";
      else if (settings.fallback)
        note += multi_start(level, best);
      else
        note += "; no fallback (disabled)";
      return note;
    }


    // The fallback: a local minimisation from every vertex (for fewer than
    // 20 free parameters) and the centre of the box; @p best becomes the
    // best of them if it is better. Returns what it did, for the note.
    std::string
    Chain::multi_start(const Level &level, LocalOptimum &best) const
    {
      OutputObjective        &objective = level.objective;
      const VectorType       &lo = level.lo, &hi = level.hi;
      const unsigned int      n = lo.size();
      std::vector<VectorType> starts;
      for (unsigned long corner = 0; n < 20 && corner < (1ul << n); ++corner)
        starts.push_back(vertex(corner, lo, hi));
      VectorType mid(n);
      for (unsigned int i = 0; i < n; ++i)
        mid[i] = 0.5 * (lo[i] + hi[i]);
      starts.push_back(mid);
      const double before = best.value;
      for (const VectorType &s : starts)
        {
          LocalOptimum candidate = minimise(objective, s, lo, hi, settings);
          if (candidate.value < best.value)
            best = candidate;
        }
      return "; fallback: multi-start from " + std::to_string(starts.size()) +
             " points (vertices and centre)" +
             (best.value < before ? ", which improved the bound to " +
                                      format(sign * best.value * scale)
                                  : ", which confirmed it");
    }


    // A sensitivity that changes sign between the optima of the levels.
    void
    Chain::check_sensitivity_signs(const std::vector<VectorType> &gradients,
                                   ChainResult                   &result) const
    {
      for (unsigned int i = 0; i < normalisation.n_free(); ++i)
        {
          bool positive = false, negative = false;
          for (const VectorType &g : gradients)
            {
              // A gradient below the noise of a finite difference of the
              // response carries no sign.
              const double noise = 10 * settings.response_tolerance /
                                   settings.finite_difference_step;
              positive = positive || g[i] > noise;
              negative = negative || g[i] < -noise;
            }
          if (positive && negative)
            result.notes.push_back(
              what + ": the sensitivity to parameter " +
              std::to_string(normalisation.free[i] + 1) +
              " changes sign between alpha levels (non-monotone response)");
        }
    }
  } // namespace LocalOptimisation
} // namespace FuzzyContact
