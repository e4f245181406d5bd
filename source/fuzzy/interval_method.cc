#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/mpi_wait.h>
#include <fuzzycontact/fuzzy/interval_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

namespace FuzzyContact
{
  namespace
  {
    // The response at @p p, or the message of its failure.
    std::pair<std::string, std::vector<double>>
    evaluate(const Response &response, const std::vector<double> &p)
    {
      try
        {
          return {"", response(p)};
        }
      catch (const dealii::ExceptionBase &e)
        {
          return {Input::message_of(e), {}};
        }
      catch (const std::exception &e)
        {
          return {std::string("the evaluation failed: ") + e.what(), {}};
        }
    }

    // Adds the wall time of its life to @p seconds (also when the response
    // throws).
    struct StopWatch
    {
      explicit StopWatch(double &seconds)
          : seconds(seconds)
          , start(std::chrono::steady_clock::now())
      {
      }
      ~StopWatch()
      {
        seconds += std::chrono::duration<double>(
                     std::chrono::steady_clock::now() - start)
                     .count();
      }
      double                               &seconds;
      std::chrono::steady_clock::time_point start;
    };

    // Rethrows a failure of evaluate() (on every rank, when shared).
    void
    rethrow(const std::string &message)
    {
      AssertThrow(message.empty(), dealii::ExcMessage(message));
    }
  } // namespace


  EvaluationCache::EvaluationCache(const Response &response,
                                   const MPI_Comm  comm)
      : response(response)
      , comm(comm)
  {
    if (dealii::Utilities::MPI::job_supports_mpi())
      {
        n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
        rank    = dealii::Utilities::MPI::this_mpi_process(comm);
      }
  }

  const std::vector<double> &
  EvaluationCache::operator()(const std::vector<double> &parameters)
  {
    const auto found = values.find(parameters);
    if (found != values.end())
      return found->second;
    if (n_ranks == 1)
      {
        ++n_here;
        return values.emplace(parameters, response(parameters)).first->second;
      }
    // Made by the ranks in turn, sent to all.
    const unsigned int                          owner = n_alone++ % n_ranks;
    std::pair<std::string, std::vector<double>> result;
    if (rank == owner)
      {
        ++n_here;
        result = evaluate(response, parameters);
      }
    result = dealii::Utilities::MPI::broadcast(comm, result, owner);
    rethrow(result.first);
    return values.emplace(parameters, std::move(result.second)).first->second;
  }


  void
  EvaluationCache::prefetch(const std::vector<std::vector<double>> &points)
  {
    std::vector<const std::vector<double> *> missing;
    std::set<std::vector<double>>            seen;
    for (const std::vector<double> &p : points)
      if (values.count(p) == 0 && seen.insert(p).second)
        missing.push_back(&p);
    // (Every rank knows the same points: nothing to do on all of them.)
    if (missing.empty())
      return;
    if (n_ranks == 1)
      {
        for (const std::vector<double> *p : missing)
          values.emplace(*p, response(*p));
        n_here += missing.size();
        return;
      }
    // Round robin; the first failure (in the order of @p points) is
    // thrown on every rank.
    std::vector<std::pair<std::string, std::vector<double>>> mine;
    for (unsigned long i = rank; i < missing.size(); i += n_ranks)
      mine.push_back(evaluate(response, *missing[i]));
    n_here += mine.size();
    auto all = dealii::Utilities::MPI::all_gather(comm, mine);
    for (unsigned long i = 0; i < missing.size(); ++i)
      rethrow(all[i % n_ranks][i / n_ranks].first);
    for (unsigned long i = 0; i < missing.size(); ++i)
      values.emplace(*missing[i],
                     std::move(all[i % n_ranks][i / n_ranks].second));
  }

  unsigned long
  EvaluationCache::n_evaluations() const
  {
    return values.size();
  }


  unsigned long
  EvaluationCache::n_evaluated_here() const
  {
    return n_here;
  }


  FuzzyOutputBounds
  bounds_on_ranks(const IntervalMethod           &method,
                  const std::vector<FuzzyNumber> &parameters,
                  const std::vector<double>      &alpha,
                  const Response                 &response,
                  const std::vector<std::string> &output_names,
                  const MPI_Comm                  comm,
                  const MPI_Comm                  solving)
  {
    // The time inside the response, apart from the method's own work.
    double         inside = 0;
    const Response timed  = [&](const std::vector<double> &p) {
      const StopWatch watch(inside);
      return response(p);
    };
    // The bounds on @p on, with the time inside the response of its ranks.
    const auto on_ranks = [&](const MPI_Comm on) {
      FuzzyOutputBounds result =
        method.bounds(parameters, alpha, timed, output_names, on);
      result.evaluation_time = dealii::Utilities::MPI::job_supports_mpi()
                                 ? dealii::Utilities::MPI::sum(inside, on)
                                 : inside;
      return result;
    };
    if (solving == comm)
      return on_ranks(comm);
    // The lowest rank of @p comm among the solving ones sends the bounds.
    const unsigned int n_ranks = dealii::Utilities::MPI::n_mpi_processes(comm);
    const unsigned int rank    = dealii::Utilities::MPI::this_mpi_process(comm);
    const unsigned int root =
      dealii::Utilities::MPI::min(solving != MPI_COMM_NULL ? rank : n_ranks,
                                  comm);
    AssertThrow(root < n_ranks,
                dealii::ExcMessage("No MPI rank can evaluate the response."));
    FuzzyOutputBounds result;
    if (solving != MPI_COMM_NULL)
      result = on_ranks(solving);
    wait_for_all_ranks(comm); // (the others, without spinning)
    return dealii::Utilities::MPI::broadcast(comm, result, root);
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
                dealii::ExcMessage(
                  "Bounds to compare must have the same levels."));
    double worst = 0;
    for (unsigned int l = 0; l < bounds.size(); ++l)
      for (const auto &[b, r] :
           {std::make_pair(bounds[l].lower, reference[l].lower),
            std::make_pair(bounds[l].upper, reference[l].upper)})
        if (!std::isnan(b) && !std::isnan(r)) // (NaN: no bound there)
          worst =
            std::max(worst, std::abs(b - r) / std::max(std::abs(r), floor));
    return worst;
  }
} // namespace FuzzyContact
