#include <fuzzycontact/fuzzy/interval_analysis.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace FuzzyContact
{
  EvaluationCache::EvaluationCache(const Response &response)
      : response(response)
  {
  }

  const std::vector<double> &
  EvaluationCache::operator()(const std::vector<double> &parameters)
  {
    const auto found = values.find(parameters);
    if (found != values.end())
      return found->second;
    return values.emplace(parameters, response(parameters)).first->second;
  }

  unsigned long
  EvaluationCache::n_evaluations() const
  {
    return values.size();
  }


  std::vector<Interval>
  alpha_box(const std::vector<FuzzyNumber> &parameters, const double alpha)
  {
    std::vector<Interval> box;
    for (const FuzzyNumber &p : parameters)
      box.push_back(p.alpha_cut(alpha));
    return box;
  }


  double
  max_relative_difference(const std::vector<Interval> &bounds,
                          const std::vector<Interval> &reference,
                          const double                 floor)
  {
    AssertThrow(bounds.size() == reference.size(),
                ExcMessage("Bounds to compare must have the same levels."));
    double worst = 0;
    for (unsigned int l = 0; l < bounds.size(); ++l)
      for (const auto &[b, r] :
           {std::make_pair(bounds[l].lower, reference[l].lower),
            std::make_pair(bounds[l].upper, reference[l].upper)})
        worst = std::max(worst, std::abs(b - r) / std::max(std::abs(r), floor));
    return worst;
  }


  namespace
  {
    unsigned int
    n_ranks(const MPI_Comm comm)
    {
      return Utilities::MPI::job_supports_mpi()
               ? Utilities::MPI::n_mpi_processes(comm)
               : 1;
    }

    unsigned int
    this_rank(const MPI_Comm comm)
    {
      return Utilities::MPI::job_supports_mpi()
               ? Utilities::MPI::this_mpi_process(comm)
               : 0;
    }

    // Evaluates the points assigned to this rank (every n-th, round robin)
    // and gives every rank the outputs of all points.
    std::vector<std::vector<double>>
    evaluate_distributed(const std::vector<std::vector<double>> &points,
                         const Response                         &response,
                         const MPI_Comm                          comm)
    {
      const unsigned int size = n_ranks(comm), rank = this_rank(comm);
      std::vector<std::pair<unsigned long, std::vector<double>>> mine;
      for (unsigned long i = rank; i < points.size(); i += size)
        mine.emplace_back(i, response(points[i]));
      std::vector<std::vector<double>> outputs(points.size());
      if (size == 1)
        for (auto &[i, out] : mine)
          outputs[i] = std::move(out);
      else
        for (auto &part : Utilities::MPI::all_gather(comm, mine))
          for (auto &[i, out] : part)
            outputs[i] = std::move(out);
      return outputs;
    }

    // Min and max of each output over the points inside each box.
    FuzzyOutputBounds
    bounds_over_points(const std::vector<FuzzyNumber>         &parameters,
                       const std::vector<double>              &alpha,
                       const std::vector<std::vector<double>> &points,
                       const std::vector<std::vector<double>> &outputs,
                       const unsigned int                      n_outputs)
    {
      FuzzyOutputBounds result;
      result.alpha = alpha;
      result.bounds.assign(n_outputs, std::vector<Interval>(alpha.size()));
      result.argmin.assign(n_outputs,
                           std::vector<std::vector<double>>(alpha.size()));
      result.argmax = result.argmin;
      for (unsigned int l = 0; l < alpha.size(); ++l)
        {
          const std::vector<Interval> box = alpha_box(parameters, alpha[l]);
          for (unsigned int k = 0; k < n_outputs; ++k)
            result.bounds[k][l] = {std::numeric_limits<double>::infinity(),
                                   -std::numeric_limits<double>::infinity()};
          bool any = false;
          for (unsigned long i = 0; i < points.size(); ++i)
            {
              bool inside = true;
              for (unsigned int d = 0; d < box.size() && inside; ++d)
                inside = box[d].contains(points[i][d],
                                         1e-12 * (box[d].width() +
                                                  std::abs(box[d].lower)));
              if (!inside)
                continue;
              any = true;
              AssertThrow(outputs[i].size() == n_outputs,
                          ExcMessage("The response returned " +
                                     std::to_string(outputs[i].size()) +
                                     " outputs instead of " +
                                     std::to_string(n_outputs) + "."));
              for (unsigned int k = 0; k < n_outputs; ++k)
                {
                  const double v = outputs[i][k];
                  AssertThrow(std::isfinite(v),
                              ExcMessage("The response returned a non-finite "
                                         "value."));
                  if (v < result.bounds[k][l].lower)
                    {
                      result.bounds[k][l].lower = v;
                      result.argmin[k][l]       = points[i];
                    }
                  if (v > result.bounds[k][l].upper)
                    {
                      result.bounds[k][l].upper = v;
                      result.argmax[k][l]       = points[i];
                    }
                }
            }
          Assert(any, ExcInternalError());
          (void)any;
        }
      return result;
    }

    // The sampling methods' common end: evaluate the points on the ranks,
    // take the extremes per level, count and time.
    FuzzyOutputBounds
    bounds_by_sampling(const std::vector<FuzzyNumber>         &parameters,
                       const std::vector<double>              &alpha,
                       const std::vector<std::vector<double>> &points,
                       const Response                         &response,
                       const unsigned int                      n_outputs,
                       const MPI_Comm                          comm,
                       const Timer                            &timer)
    {
      const auto        outputs = evaluate_distributed(points, response, comm);
      FuzzyOutputBounds result =
        bounds_over_points(parameters, alpha, points, outputs, n_outputs);
      result.n_evaluations = points.size();
      result.wall_time     = timer.wall_time();
      if (n_ranks(comm) > 1)
        result.wall_time = Utilities::MPI::max(result.wall_time, comm);
      return result;
    }

    // Keeps each distinct point once, in the order first seen.
    void
    add_unique(std::vector<std::vector<double>> &points,
               std::set<std::vector<double>>    &seen,
               const std::vector<double>        &p)
    {
      if (seen.insert(p).second)
        points.push_back(p);
    }

    // The samples of the Extension Principle: every level's box on a grid
    // of @p r equally spaced values per parameter (both ends included), each
    // distinct point once.
    std::vector<std::vector<double>>
    sampling_points(const std::vector<FuzzyNumber> &parameters,
                    const std::vector<double>      &alpha,
                    const unsigned int              r)
    {
      AssertThrow(r >= 2,
                  ExcMessage("Extension principle: points per dimension must "
                             "be at least 2 (the ends of every interval)."));
      std::vector<std::vector<double>> points;
      std::set<std::vector<double>>    seen;
      const unsigned int               n = parameters.size();
      for (const double a : alpha)
        {
          const std::vector<Interval> box = alpha_box(parameters, a);
          // values per parameter: r of them, or one for a point interval
          std::vector<std::vector<double>> values(n);
          unsigned long                    count = 1;
          for (unsigned int d = 0; d < n; ++d)
            {
              if (box[d].width() == 0)
                values[d] = {box[d].lower};
              else
                for (unsigned int i = 0; i < r; ++i)
                  values[d].push_back(i == 0 ? box[d].lower
                                      : i == r - 1
                                        ? box[d].upper
                                        : box[d].lower +
                                            box[d].width() * i / (r - 1.));
              count *= values[d].size();
            }
          for (unsigned long i = 0; i < count; ++i)
            {
              std::vector<double> p(n);
              unsigned long       rest = i;
              for (unsigned int d = 0; d < n; ++d)
                {
                  p[d] = values[d][rest % values[d].size()];
                  rest /= values[d].size();
                }
              add_unique(points, seen, p);
            }
        }
      return points;
    }
  } // namespace


  FuzzyOutputBounds
  vertex_method(const std::vector<FuzzyNumber> &parameters,
                const std::vector<double>      &alpha,
                const Response                 &response,
                const unsigned int              n_outputs,
                const MPI_Comm                  comm)
  {
    Timer                            timer;
    const unsigned int               n = parameters.size();
    std::vector<std::vector<double>> points;
    std::set<std::vector<double>>    seen;
    for (const double a : alpha)
      {
        const std::vector<Interval> box = alpha_box(parameters, a);
        for (unsigned long corner = 0; corner < (1ul << n); ++corner)
          {
            std::vector<double> p(n);
            for (unsigned int d = 0; d < n; ++d)
              p[d] = (corner >> d) & 1 ? box[d].upper : box[d].lower;
            add_unique(points, seen, p);
          }
      }
    return bounds_by_sampling(parameters,
                              alpha,
                              points,
                              response,
                              n_outputs,
                              comm,
                              timer);
  }


  unsigned long
  extension_principle_size(const std::vector<FuzzyNumber> &parameters,
                           const std::vector<double>      &alpha,
                           const unsigned int              points_per_dimension)
  {
    return sampling_points(parameters, alpha, points_per_dimension).size();
  }


  FuzzyOutputBounds
  extension_principle(const std::vector<FuzzyNumber> &parameters,
                      const std::vector<double>      &alpha,
                      const Response                 &response,
                      const unsigned int              n_outputs,
                      const unsigned int              points_per_dimension,
                      const MPI_Comm                  comm)
  {
    Timer timer;
    return bounds_by_sampling(parameters,
                              alpha,
                              sampling_points(parameters,
                                              alpha,
                                              points_per_dimension),
                              response,
                              n_outputs,
                              comm,
                              timer);
  }
} // namespace FuzzyContact
