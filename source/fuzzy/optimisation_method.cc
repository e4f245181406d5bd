// The optimisation method (optimisation_method.h): the chains of global
// stages and local optimisations of every output (optimisation_chain.h),
// on an evaluation cache shared by the MPI ranks, and the global stage's
// design. Its settings: optimisation_settings.cc.

#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/fuzzy/global_stage.h>
#include <fuzzycontact/fuzzy/local_optimisation.h>
#include <fuzzycontact/fuzzy/optimisation_chain.h>
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
