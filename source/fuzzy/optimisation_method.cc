// The optimisation method (optimisation_method.h): the chains of global
// stages (global_stage.h) and local optimisations (local_optimisation.h),
// the checks for a non-monotone response and the multi-start, on an
// evaluation cache shared by the MPI ranks. Its settings:
// optimisation_settings.cc.

#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/fuzzy/global_stage.h>
#include <fuzzycontact/fuzzy/local_optimisation.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <set>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    using namespace LocalOptimisation;

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

    // The result of one chain: one output, one direction, all levels.
    struct ChainResult
    {
      std::vector<double>              value;    // per level, unscaled
      std::vector<std::vector<double>> argument; // per level, all parameters
      std::vector<BoundQuality>        quality;  // per level
      std::vector<std::string>         notes;
    };

    // One chain: the lower (or upper) bound of one output at every level,
    // from the core down, each level started at the optimum of the level
    // above, with the checks for a non-monotone response.
    class Chain
    {
    public:
      Chain(EvaluationCache                &cache,
            const Normalisation            &normalisation,
            const std::vector<FuzzyNumber> &parameters,
            const OptimisationSettings     &settings,
            const unsigned int              output,
            const bool                      upper,
            const double                    nominal,
            const std::string              &output_name)
          : cache(cache)
          , normalisation(normalisation)
          , parameters(parameters)
          , settings(settings)
          , output(output)
          , sign(upper ? -1. : 1.)
          , scale(std::abs(nominal) > 0 ? std::abs(nominal) : 1.)
          , what(output_name + (upper ? " (upper bound)" : " (lower bound)"))
      {
      }

      // The levels in @p order (from the core down), starting at @p centre,
      // with the global stage's @p design (in the unit box).
      ChainResult
      run(const std::vector<double>       &alpha,
          const std::vector<unsigned int> &order,
          const VectorType                &centre,
          const std::vector<VectorType>   &design,
          Progress                        *progress) const;

    private:
      std::vector<LocalOptimum>
      local_stage(OutputObjective  &objective,
                  const Starts     &starts,
                  const VectorType &lo,
                  const VectorType &hi) const;
      void
      compare_basins(OutputObjective                 &objective,
                     const std::vector<LocalOptimum> &optima,
                     const unsigned int               winner,
                     LocalOptimum                    &best,
                     const VectorType                &lo,
                     const VectorType                &hi,
                     const double                     range,
                     BoundQuality                    &quality,
                     const std::string               &level,
                     ChainResult                     &result) const;
      bool
      check_interval_ends(OutputObjective          &objective,
                          LocalOptimum             &best,
                          const VectorType         &lo,
                          const VectorType         &hi,
                          std::vector<std::string> &findings) const;
      void
      refine(OutputObjective  &objective,
             LocalOptimum     &best,
             const VectorType &lo,
             const VectorType &hi,
             const double      range,
             BoundQuality     &quality) const;
      std::string
      iteration_limit_note(const std::string  &level,
                           const BoundQuality &quality) const;
      std::string
      multi_start(OutputObjective  &objective,
                  LocalOptimum     &best,
                  const VectorType &lo,
                  const VectorType &hi) const;
      std::string
      non_monotone(OutputObjective                &objective,
                   LocalOptimum                   &best,
                   const VectorType               &lo,
                   const VectorType               &hi,
                   const std::string              &level,
                   const std::vector<std::string> &findings,
                   const bool                      missed,
                   const unsigned int              n_starts,
                   const unsigned int              n_design) const;
      void
      check_sensitivity_signs(const std::vector<VectorType> &gradients,
                              ChainResult                   &result) const;

      EvaluationCache                &cache;
      const Normalisation            &normalisation;
      const std::vector<FuzzyNumber> &parameters;
      const OptimisationSettings     &settings;
      const unsigned int              output;
      const double                    sign;
      const double                    scale;
      const std::string               what;
    };


    ChainResult
    Chain::run(const std::vector<double>       &alpha,
               const std::vector<unsigned int> &order,
               const VectorType                &centre,
               const std::vector<VectorType>   &design,
               Progress                        *progress) const
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

          // Local searches from the best points of distinct basins.
          const Starts starts     = basin_starts(objective,
                                             pool,
                                             lo,
                                             hi,
                                             settings.local_starts,
                                             noise0);
          quality.n_roots         = starts.n_roots;
          quality.n_starts        = starts.points.size();
          quality.basins_searched = starts.all_roots_tested;
          const std::vector<LocalOptimum> optima =
            local_stage(objective, starts, lo, hi);
          unsigned int winner = 0;
          for (unsigned int s = 1; s < optima.size(); ++s)
            if (optima[s].value < optima[winner].value)
              winner = s;
          LocalOptimum best       = optima[winner];
          quality.iteration_limit = !best.converged;

          // Is the response monotone here? An interior optimum, or a point
          // of the global stage better than the local optimum, says not.
          std::vector<std::string> findings;
          const bool               moved =
            check_interval_ends(objective, best, lo, hi, findings);
          const double noise =
            settings.response_tolerance * std::max(1., std::abs(best.value));
          const bool missed = pool.front().value < best.value - noise;
          if (missed)
            findings.push_back(std::string(pool.front().vertex
                                             ? "a vertex of the box"
                                             : "a point of the global stage") +
                               " is better than the local optimum");
          if (!findings.empty())
            result.notes.push_back(non_monotone(objective,
                                                best,
                                                lo,
                                                hi,
                                                level,
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
          refine(objective, best, lo, hi, range, quality);
          compare_basins(objective,
                         optima,
                         winner,
                         best,
                         lo,
                         hi,
                         range,
                         quality,
                         level,
                         result);
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
    Chain::local_stage(OutputObjective  &objective,
                       const Starts     &starts,
                       const VectorType &lo,
                       const VectorType &hi) const
    {
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
    Chain::compare_basins(OutputObjective                 &objective,
                          const std::vector<LocalOptimum> &optima,
                          const unsigned int               winner,
                          LocalOptimum                    &best,
                          const VectorType                &lo,
                          const VectorType                &hi,
                          const double                     range,
                          BoundQuality                    &quality,
                          const std::string               &level,
                          ChainResult                     &result) const
    {
      const double noise =
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
              check_interval_ends(objective, o, lo, hi, ignored);
              objective.gradient_at(o.gradient, o.x);
              BoundQuality scratch;
              refine(objective, o, lo, hi, range, scratch);
            }
          if (o.value < best.value - tolerance)
            {
              // Another basin's search went further: it is the bound.
              result.notes.push_back(
                level +
                ": the local search from another basin found a better point "
                "than the best start's (by " +
                format((best.value - o.value) / (range > 0 ? range : 1.)) +
                " of the range); it is the bound");
              other          = std::min(other, best.value);
              best           = o;
              BoundQuality q = quality;
              refine(objective, best, lo, hi, range, q);
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
    Chain::refine(OutputObjective  &objective,
                  LocalOptimum     &best,
                  const VectorType &lo,
                  const VectorType &hi,
                  const double      range,
                  BoundQuality     &quality) const
    {
      const double noise =
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
    Chain::check_interval_ends(OutputObjective          &objective,
                               LocalOptimum             &best,
                               const VectorType         &lo,
                               const VectorType         &hi,
                               std::vector<std::string> &findings) const
    {
      const double noise =
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
    Chain::non_monotone(OutputObjective                &objective,
                        LocalOptimum                   &best,
                        const VectorType               &lo,
                        const VectorType               &hi,
                        const std::string              &level,
                        const std::vector<std::string> &findings,
                        const bool                      missed,
                        const unsigned int              n_starts,
                        const unsigned int              n_design) const
    {
      std::string note = level + ": non-monotone response (";
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
        note += multi_start(objective, best, lo, hi);
      else
        note += "; no fallback (disabled)";
      return note;
    }


    // The fallback: a local minimisation from every vertex (for fewer than
    // 20 free parameters) and the centre of the box; @p best becomes the
    // best of them if it is better. Returns what it did, for the note.
    std::string
    Chain::multi_start(OutputObjective  &objective,
                       LocalOptimum     &best,
                       const VectorType &lo,
                       const VectorType &hi) const
    {
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


    // The levels from the core (alpha = 1) down to the support.
    std::vector<unsigned int>
    levels_from_the_core(const std::vector<double> &alpha)
    {
      std::vector<unsigned int> order(alpha.size());
      for (unsigned int l = 0; l < alpha.size(); ++l)
        order[l] = l;
      std::sort(order.begin(),
                order.end(),
                [&](unsigned int a, unsigned int b) {
                  return alpha[a] > alpha[b];
                });
      return order;
    }


    // The nominal point: the centre of the core, in normalised coordinates.
    VectorType
    centre_of_the_core(const Normalisation            &normalisation,
                       const std::vector<FuzzyNumber> &parameters)
    {
      const unsigned int n = normalisation.n_free();
      const auto [lo, hi]  = normalisation.box(parameters, 1.0);
      VectorType centre(n);
      for (unsigned int i = 0; i < n; ++i)
        centre[i] = 0.5 * (lo[i] + hi[i]);
      return centre;
    }


    // The points every chain's global stage evaluates whatever its seeds
    // (the vertices and the design of every level's box), after the
    // nominal point @p centre.
    std::vector<std::vector<double>>
    fixed_points_of_all_levels(const Normalisation             &normalisation,
                               const std::vector<FuzzyNumber>  &parameters,
                               const std::vector<double>       &alpha,
                               const std::vector<unsigned int> &order,
                               const VectorType                &centre,
                               const std::vector<VectorType>   &design)
    {
      std::vector<std::vector<double>> points{normalisation.parameters(centre)};
      for (const unsigned int l : order)
        {
          const auto [lo, hi] = normalisation.box(parameters, alpha[l]);
          for (const VectorType &x : fixed_points(design, lo, hi))
            points.push_back(normalisation.parameters(x));
        }
      return points;
    }


    // The bounds of the chains (chain 2k: the lower bound of output k,
    // chain 2k + 1: its upper bound) and their notes, in chain order.
    FuzzyOutputBounds
    bounds_of_chains(
      const std::vector<std::pair<unsigned int, ChainResult>> &chains,
      const std::vector<double>                               &alpha,
      const unsigned int                                       n_outputs)
    {
      FuzzyOutputBounds result;
      result.alpha = alpha;
      result.bounds.assign(n_outputs, std::vector<Interval>(alpha.size()));
      result.argmin.assign(n_outputs,
                           std::vector<std::vector<double>>(alpha.size()));
      result.argmax = result.argmin;
      result.lower_quality.assign(n_outputs,
                                  std::vector<BoundQuality>(alpha.size()));
      result.upper_quality = result.lower_quality;
      for (const auto &[chain, r] : chains)
        {
          const unsigned int k = chain / 2;
          for (unsigned int l = 0; l < alpha.size(); ++l)
            if (chain % 2)
              {
                result.bounds[k][l].upper  = r.value[l];
                result.argmax[k][l]        = r.argument[l];
                result.upper_quality[k][l] = r.quality[l];
              }
            else
              {
                result.bounds[k][l].lower  = r.value[l];
                result.argmin[k][l]        = r.argument[l];
                result.lower_quality[k][l] = r.quality[l];
              }
          for (const std::string &note : r.notes)
            result.notes.push_back(note);
        }
      return result;
    }
  } // namespace


  OptimisationMethod::OptimisationMethod(const OptimisationSettings &settings)
      : settings_(settings)
  {
  }


  std::string
  OptimisationMethod::name() const
  {
    return "optimisation";
  }


  const OptimisationSettings &
  OptimisationMethod::settings() const
  {
    return settings_;
  }


  FuzzyOutputBounds
  OptimisationMethod::bounds(const std::vector<FuzzyNumber> &parameters,
                             const std::vector<double>      &alpha,
                             const Response                 &response,
                             const std::vector<std::string> &output_names,
                             const MPI_Comm                  comm) const
  {
    Timer              timer;
    const unsigned int n_outputs = output_names.size();
    const bool         parallel  = Utilities::MPI::job_supports_mpi() &&
                          Utilities::MPI::n_mpi_processes(comm) > 1;
    const unsigned int n_ranks =
      parallel ? Utilities::MPI::n_mpi_processes(comm) : 1;

    // Every rank runs every chain on one cache shared by the ranks: each
    // distinct point is evaluated once, by one rank, as with one process.
    // The points every chain needs (the global stage's vertices and designs
    // of every level) are evaluated first, spread over the ranks; the
    // design's evaluations are counted for the progress lines.
    std::unique_ptr<Progress> design_progress;
    const Response            counted = [&](const std::vector<double> &p) {
      std::vector<double> values = response(p);
      if (design_progress)
        design_progress->advance();
      return values;
    };
    EvaluationCache                 cache(counted, comm);
    const Normalisation             normalisation(parameters);
    const unsigned int              n_free = normalisation.n_free();
    const std::vector<unsigned int> order  = levels_from_the_core(alpha);
    const VectorType centre = centre_of_the_core(normalisation, parameters);

    // The nominal point and every level's vertices first; they time an
    // evaluation for the global time limit (the slowest rank's time, the
    // same number on every rank).
    Timer vertices;
    cache.prefetch(fixed_points_of_all_levels(normalisation,
                                              parameters,
                                              alpha,
                                              order,
                                              centre,
                                              {}));
    double per_evaluation = cache.n_evaluated_here() > 0
                              ? vertices.wall_time() / cache.n_evaluated_here()
                              : 0.;
    if (parallel)
      per_evaluation = Utilities::MPI::max(per_evaluation, comm);
    unsigned int n_boxes = 0; // levels whose box is not a point
    for (const double a : alpha)
      {
        const auto [lo, hi] = normalisation.box(parameters, a);
        bool point          = true;
        for (unsigned int i = 0; i < n_free; ++i)
          point = point && hi[i] <= lo[i];
        n_boxes += !point;
      }
    const unsigned int wanted   = settings_.global_points_auto
                                    ? default_design_points(n_free)
                                    : settings_.global_points;
    unsigned int       n_design = n_free > 0 ? wanted : 0;
    bool               cut      = false;
    if (settings_.global_time_limit > 0 && per_evaluation > 0 && n_boxes > 0)
      {
        // The largest power of two that fits (a Sobol net), or none.
        const double fits =
          settings_.global_time_limit / (per_evaluation * n_boxes);
        unsigned int allowed = fits >= 1 ? 1 : 0;
        while (allowed > 0 && 2. * allowed <= fits && 2 * allowed <= n_design)
          allowed *= 2;
        if (allowed < n_design)
          {
            n_design = allowed;
            cut      = true;
          }
      }
    const std::vector<VectorType> design =
      scrambled_sobol(n_design, n_free, 20261124);
    {
      const std::vector<std::vector<double>> points =
        fixed_points_of_all_levels(normalisation,
                                   parameters,
                                   alpha,
                                   order,
                                   centre,
                                   design);
      design_progress = std::make_unique<Progress>(
        "optimisation, global stage (" + std::to_string(n_design) +
          " design points per alpha-box)" +
          std::string(n_ranks > 1 ? ", evaluations of the first rank" : ""),
        (points.size() + n_ranks - 1) / n_ranks);
      cache.prefetch(points);
      design_progress.reset();
    }

    // The points of each level's global stage without a solution.
    std::vector<unsigned long> n_points(alpha.size()),
      n_infeasible(alpha.size());
    for (unsigned int l = 0; l < alpha.size(); ++l)
      {
        const auto [lo, hi] = normalisation.box(parameters, alpha[l]);
        std::set<std::vector<double>> distinct;
        for (const VectorType &x : fixed_points(design, lo, hi))
          distinct.insert(normalisation.parameters(x));
        n_points[l] = distinct.size();
        for (const std::vector<double> &p : distinct)
          n_infeasible[l] += !has_solution(cache(p));
      }

    // The objectives are scaled by the outputs at the nominal point, or,
    // if it has no solution, at the first point with one.
    std::vector<double> nominal = cache(normalisation.parameters(centre));
    if (!has_solution(nominal))
      for (const unsigned int l : order)
        {
          const auto [lo, hi] = normalisation.box(parameters, alpha[l]);
          for (const VectorType &x : fixed_points(design, lo, hi))
            if (nominal.empty())
              nominal = cache(normalisation.parameters(x));
        }
    if (!has_solution(nominal))
      nominal.assign(n_outputs, 1.);
    AssertThrow(nominal.size() == n_outputs,
                ExcMessage(
                  "The response returned " + std::to_string(nominal.size()) +
                  " outputs instead of " + std::to_string(n_outputs) + "."));

    // One chain per output and direction.
    Progress chains_progress("optimisation: bounds (output x side x level)",
                             2 * n_outputs * alpha.size(),
                             3.,
                             [&]() {
                               return std::to_string(cache.n_evaluations()) +
                                      " evaluations";
                             });
    std::vector<std::pair<unsigned int, ChainResult>> all;
    for (unsigned int chain = 0; chain < 2 * n_outputs; ++chain)
      {
        const unsigned int k = chain / 2;
        const Chain        one(cache,
                        normalisation,
                        parameters,
                        settings_,
                        k,
                        chain % 2,
                        nominal[k],
                        output_names[k]);
        all.emplace_back(
          chain,
          one.run(alpha, order, centre, design, &chains_progress));
      }

    FuzzyOutputBounds result = bounds_of_chains(all, alpha, n_outputs);
    result.n_points          = n_points;
    result.n_infeasible      = n_infeasible;
    result.design_points     = n_design;
    result.design_cut        = cut;
    result.design_wanted     = wanted;
    // (Evaluations made over all ranks: each distinct point once.)
    result.n_evaluations =
      parallel ? Utilities::MPI::sum(cache.n_evaluated_here(), comm)
               : cache.n_evaluated_here();
    result.wall_time = parallel ? Utilities::MPI::max(timer.wall_time(), comm)
                                : timer.wall_time();
    return result;
  }
} // namespace FuzzyContact
