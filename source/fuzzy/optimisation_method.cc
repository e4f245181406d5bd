// The optimisation method (optimisation_method.h): the chains of local
// optimisations (local_optimisation.h), the checks for a non-monotone
// response and the multi-start, and the gathering over MPI ranks.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fuzzy/local_optimisation.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/timer.h>
#include <deal.II/lac/vector.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace FuzzyContact
{
  void
  OptimisationSettings::declare_parameters(ParameterHandler &prm)
  {
    using Patterns::Tools::to_string;
    const OptimisationSettings defaults;
    prm.enter_subsection("Optimisation");
    prm.declare_entry("algorithm",
                      defaults.algorithm,
                      Patterns::Selection("spectral gradient|quasi-newton"),
                      "ROL's bound-constrained algorithm: projected spectral "
                      "gradient (Barzilai-Borwein steps) or a projected "
                      "quasi-Newton (L-BFGS) line search.");
    prm.declare_entry("gradient tolerance",
                      to_string(defaults.gradient_tolerance),
                      Patterns::Double(),
                      "ROL's tolerance on the projected gradient of the "
                      "scaled objective S / |S(nominal)|.");
    prm.declare_entry("step tolerance",
                      to_string(defaults.step_tolerance),
                      Patterns::Double(),
                      "ROL's tolerance on the step in normalised parameters.");
    prm.declare_entry("iteration limit",
                      to_string(defaults.max_iterations),
                      Patterns::Integer(),
                      "ROL iterations per output, bound and alpha level.");
    prm.declare_entry("finite difference step",
                      to_string(defaults.finite_difference_step),
                      Patterns::Double(),
                      "Step of the finite-difference sensitivities, relative "
                      "to the width of each parameter's support.");
    prm.declare_entry("interior tolerance",
                      to_string(defaults.interior_tolerance),
                      Patterns::Double(),
                      "An optimum further than this (relative to the "
                      "alpha-cut width) from both ends of a parameter's "
                      "interval counts as interior.");
    prm.declare_entry("response tolerance",
                      to_string(defaults.response_tolerance),
                      Patterns::Double(),
                      "Relative accuracy of the model's outputs (the FL2C "
                      "tolerance makes them accurate to about that much): "
                      "smaller differences are no evidence of a non-monotone "
                      "response. Keep the finite difference step well above "
                      "it.");
    prm.declare_entry("multi-start fallback",
                      to_string(defaults.fallback),
                      Patterns::Bool(),
                      "On a detected non-monotone response, restart the "
                      "local optimisation from every vertex and the centre.");
    prm.leave_subsection();
  }


  void
  OptimisationSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Optimisation");
    algorithm          = prm.get("algorithm");
    gradient_tolerance = Input::positive(prm.get_double("gradient tolerance"),
                                         "Optimisation: gradient tolerance");
    step_tolerance     = Input::positive(prm.get_double("step tolerance"),
                                     "Optimisation: step tolerance");
    const long iterations = prm.get_integer("iteration limit");
    AssertThrow(iterations >= 1,
                ExcMessage("Optimisation: iteration limit must be at least "
                           "1."));
    max_iterations = iterations;
    finite_difference_step =
      Input::positive(prm.get_double("finite difference step"),
                      "Optimisation: finite difference "
                      "step");
    AssertThrow(finite_difference_step < 0.1,
                ExcMessage("Optimisation: finite difference step must be "
                           "below 0.1 (it is relative to the support width)."));
    interior_tolerance = Input::positive(prm.get_double("interior tolerance"),
                                         "Optimisation: interior tolerance");
    response_tolerance = Input::positive(prm.get_double("response tolerance"),
                                         "Optimisation: response tolerance");
    AssertThrow(finite_difference_step > 10 * response_tolerance,
                ExcMessage("Optimisation: the finite difference step must be "
                           "well above the response tolerance (10 times at "
                           "least), or the sensitivities are noise."));
    fallback = prm.get_bool("multi-start fallback");
    prm.leave_subsection();
  }


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
      std::vector<std::string>         notes;

      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &value &argument &notes;
      }
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

      // The levels in @p order (from the core down), starting at @p centre.
      ChainResult
      run(const std::vector<double>       &alpha,
          const std::vector<unsigned int> &order,
          const VectorType                &centre) const;

    private:
      bool
      check_interval_ends(OutputObjective          &objective,
                          LocalOptimum             &best,
                          const VectorType         &lo,
                          const VectorType         &hi,
                          std::vector<std::string> &findings) const;
      bool
      vertex_is_better(OutputObjective    &objective,
                       const LocalOptimum &best,
                       const VectorType   &lo,
                       const VectorType   &hi) const;
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
                   const std::vector<std::string> &findings) const;
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
               const VectorType                &centre) const
    {
      ChainResult result;
      result.value.resize(alpha.size());
      result.argument.resize(alpha.size());
      VectorType              start = centre;
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
          LocalOptimum      best = minimise(objective, start, lo, hi, settings);
          const std::string level = what + ", alpha = " + format(alpha[l]);

          // Is the response monotone here? An interior optimum, or a vertex
          // better than the local optimum, says it is not.
          std::vector<std::string> findings;
          const bool               moved =
            check_interval_ends(objective, best, lo, hi, findings);
          if (vertex_is_better(objective, best, lo, hi))
            findings.push_back("a vertex of the box is better than the "
                               "local optimum");
          gradients.push_back(best.gradient);
          if (!findings.empty())
            result.notes.push_back(
              non_monotone(objective, best, lo, hi, level, findings));

          if (moved || !best.converged)
            result.notes.push_back(
              level + ": the local optimiser stopped short of the optimum (" +
              (best.converged ? "converged to its tolerances"
                              : "at its iteration limit") +
              "); the ends of the parameter intervals were better and the "
              "optimum was moved there");
          result.value[l]    = sign * best.value * scale;
          result.argument[l] = normalisation.parameters(best.x);
          start              = best.x;
        }
      check_sensitivity_signs(gradients, result);
      return result;
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


    // True if a vertex of the box (for fewer than 20 free parameters) is
    // better than @p best by more than the response tolerance.
    bool
    Chain::vertex_is_better(OutputObjective    &objective,
                            const LocalOptimum &best,
                            const VectorType   &lo,
                            const VectorType   &hi) const
    {
      const unsigned int n           = lo.size();
      double             best_vertex = std::numeric_limits<double>::infinity();
      if (n > 0 && n < 20)
        for (unsigned long corner = 0; corner < (1ul << n); ++corner)
          best_vertex =
            std::min(best_vertex, objective.at(vertex(corner, lo, hi)));
      return best_vertex < best.value - settings.response_tolerance *
                                          std::max(1., std::abs(best.value));
    }


    // The note on a non-monotone response at one level, and the answer to
    // it: the multi-start, unless the fallback is disabled.
    std::string
    Chain::non_monotone(OutputObjective                &objective,
                        LocalOptimum                   &best,
                        const VectorType               &lo,
                        const VectorType               &hi,
                        const std::string              &level,
                        const std::vector<std::string> &findings) const
    {
      std::string note = level + ": non-monotone response (";
      for (unsigned int f = 0; f < findings.size(); ++f)
        note += (f ? "; " : "") + findings[f];
      note += ")";
      if (settings.fallback)
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


    // The chains of all ranks on every rank, in chain order, with the
    // evaluations summed and the longest wall time over the ranks.
    std::vector<std::pair<unsigned int, ChainResult>>
    gather_chains(const std::vector<std::pair<unsigned int, ChainResult>> &mine,
                  const MPI_Comm                                           comm,
                  const bool     parallel,
                  unsigned long &n_evaluations,
                  double        &wall_time)
    {
      std::vector<std::pair<unsigned int, ChainResult>> all = mine;
      if (parallel)
        {
          all.clear();
          for (auto &part : Utilities::MPI::all_gather(comm, mine))
            for (auto &c : part)
              all.push_back(std::move(c));
          n_evaluations = Utilities::MPI::sum(n_evaluations, comm);
          wall_time     = Utilities::MPI::max(wall_time, comm);
        }
      std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) {
        return a.first < b.first;
      });
      return all;
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
      for (const auto &[chain, r] : chains)
        {
          const unsigned int k = chain / 2;
          for (unsigned int l = 0; l < alpha.size(); ++l)
            if (chain % 2)
              {
                result.bounds[k][l].upper = r.value[l];
                result.argmax[k][l]       = r.argument[l];
              }
            else
              {
                result.bounds[k][l].lower = r.value[l];
                result.argmin[k][l]       = r.argument[l];
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
    const unsigned int rank =
      parallel ? Utilities::MPI::this_mpi_process(comm) : 0;

    EvaluationCache                 cache(response);
    const Normalisation             normalisation(parameters);
    const std::vector<unsigned int> order = levels_from_the_core(alpha);
    const VectorType centre = centre_of_the_core(normalisation, parameters);
    const std::vector<double> nominal = cache(normalisation.parameters(centre));
    AssertThrow(nominal.size() == n_outputs,
                ExcMessage(
                  "The response returned " + std::to_string(nominal.size()) +
                  " outputs instead of " + std::to_string(n_outputs) + "."));

    // One chain per output and direction; chains are dealt to the ranks.
    std::vector<std::pair<unsigned int, ChainResult>> mine;
    for (unsigned int chain = rank; chain < 2 * n_outputs; chain += n_ranks)
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
        mine.emplace_back(chain, one.run(alpha, order, centre));
      }

    unsigned long n_evaluations = cache.n_evaluations();
    double        wall_time     = timer.wall_time();
    const auto    all =
      gather_chains(mine, comm, parallel, n_evaluations, wall_time);
    FuzzyOutputBounds result = bounds_of_chains(all, alpha, n_outputs);
    result.n_evaluations     = n_evaluations;
    result.wall_time         = wall_time;
    return result;
  }
} // namespace FuzzyContact
