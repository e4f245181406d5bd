#include <fuzzycontact/base/rank_blocks.h>
#include <fuzzycontact/fuzzy/sampling_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <cmath>
#include <limits>
#include <set>

namespace FuzzyContact
{
  using namespace dealii;

  namespace
  {
    unsigned int
    n_ranks(const MPI_Comm comm)
    {
      return Utilities::MPI::job_supports_mpi()
               ? Utilities::MPI::n_mpi_processes(comm)
               : 1;
    }


    // Evaluates the points assigned to this rank (a contiguous block, so
    // that neighbouring samples, which often share their stiffness and
    // with it the exact solver's factorisation, stay on one rank) and
    // gives every rank the outputs of all points.
    std::vector<std::vector<double>>
    evaluate_distributed(const std::vector<std::vector<double>> &points,
                         const Response                         &response,
                         const MPI_Comm                          comm)
    {
      return in_rank_blocks<std::vector<double>>(
        points.size(),
        [&](const std::size_t i) {
          return response(points[i]);
        },
        comm);
    }

    // Min and max of each output over the points inside each box that
    // have a solution (the others are counted); NaN bounds at a level
    // without any.
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
      result.n_points.assign(alpha.size(), 0);
      result.n_infeasible.assign(alpha.size(), 0);
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
              ++result.n_points[l];
              if (!has_solution(outputs[i]))
                {
                  ++result.n_infeasible[l];
                  continue;
                }
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
          Assert(result.n_points[l] > 0, ExcInternalError());
          if (!any)
            for (unsigned int k = 0; k < n_outputs; ++k)
              result.bounds[k][l] = {std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::quiet_NaN()};
        }
      return result;
    }
  } // namespace


  std::vector<std::vector<double>>
  SamplingMethod::samples(const std::vector<FuzzyNumber> &parameters,
                          const std::vector<double>      &alpha) const
  {
    std::vector<std::vector<double>> distinct;
    std::set<std::vector<double>>    seen;
    for (std::vector<double> &p : points(parameters, alpha))
      if (seen.insert(p).second)
        distinct.push_back(std::move(p));
    return distinct;
  }


  FuzzyOutputBounds
  SamplingMethod::bounds(const std::vector<FuzzyNumber> &parameters,
                         const std::vector<double>      &alpha,
                         const Response                 &response,
                         const std::vector<std::string> &output_names,
                         const MPI_Comm                  comm) const
  {
    Timer                                  timer;
    const std::vector<std::vector<double>> points = samples(parameters, alpha);
    const auto        outputs = evaluate_distributed(points, response, comm);
    FuzzyOutputBounds result  = bounds_over_points(parameters,
                                                  alpha,
                                                  points,
                                                  outputs,
                                                  output_names.size());
    result.n_evaluations      = points.size();
    result.wall_time          = timer.wall_time();
    if (n_ranks(comm) > 1)
      result.wall_time = Utilities::MPI::max(result.wall_time, comm);
    return result;
  }
} // namespace FuzzyContact
