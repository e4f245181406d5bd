#include <fuzzycontact/base/rank_blocks.h>
#include <fuzzycontact/fuzzy/spot_checks.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <chrono>
#include <cmath>
#include <utility>

namespace FuzzyContact
{
  using namespace dealii;

  Response
  EvaluationRecord::recording(const Response &response)
  {
    return [this, response](const std::vector<double> &p) {
      // (std::chrono, not deal.II's Timer: making a Timer costs as much as
      // a small scene's solve.)
      const auto          start  = std::chrono::steady_clock::now();
      std::vector<double> values = response(p);
      list.push_back(
        {p,
         values,
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
           .count()});
      return values;
    };
  }


  void
  EvaluationRecord::clear()
  {
    list.clear();
  }


  const std::vector<RecordedEvaluation> &
  EvaluationRecord::evaluations() const
  {
    return list;
  }


  SpotChecks
  spot_check(const EvaluationRecord &record,
             const unsigned int      n,
             const Response         &exact,
             const MPI_Comm          comm)
  {
    const auto begin    = std::chrono::steady_clock::now();
    const bool parallel = Utilities::MPI::job_supports_mpi() &&
                          Utilities::MPI::n_mpi_processes(comm) > 1;

    // Every rank's evaluations, in rank order, then the sample: n of them
    // at even spacing (the middle of each of n equal parts).
    std::vector<RecordedEvaluation> all;
    if (!parallel)
      all = record.evaluations();
    else
      for (auto &part : Utilities::MPI::all_gather(comm, record.evaluations()))
        for (RecordedEvaluation &e : part)
          all.push_back(std::move(e));
    SpotChecks checks;
    checks.n_recorded             = all.size();
    const std::size_t        n_in = std::min<std::size_t>(n, all.size());
    std::vector<std::size_t> sample(n_in);
    for (std::size_t i = 0; i < n_in; ++i)
      sample[i] = (2 * i + 1) * all.size() / (2 * n_in);
    checks.n_checked = n_in;

    // The sample solved exactly and timed, in contiguous blocks on the
    // ranks.
    const std::vector<RecordedEvaluation> exact_values =
      in_rank_blocks<RecordedEvaluation>(
        n_in,
        [&](const std::size_t i) {
          const std::vector<double> &p     = all[sample[i]].point;
          const auto                 start = std::chrono::steady_clock::now();
          std::vector<double>        v     = exact(p);
          return RecordedEvaluation{p,
                                    std::move(v),
                                    std::chrono::duration<double>(
                                      std::chrono::steady_clock::now() - start)
                                      .count()};
        },
        comm);

    for (std::size_t i = 0; i < n_in; ++i)
      {
        const RecordedEvaluation &fast = all[sample[i]], &e = exact_values[i];
        checks.fast_seconds += fast.seconds;
        checks.exact_seconds += e.seconds;
        const bool fast_answered  = has_solution(fast.values),
                   exact_answered = has_solution(e.values);
        if (!fast_answered && !exact_answered)
          {
            ++checks.n_without_solution;
            continue;
          }
        if (fast_answered != exact_answered)
          {
            ++checks.n_disagreeing;
            checks.n_fast_without += !fast_answered;
            checks.disagreeing.push_back(fast.point);
            continue;
          }
        AssertThrow(fast.values.size() == e.values.size(),
                    ExcMessage("The exact response returned another number "
                               "of outputs than the fast one."));
        if (checks.largest_difference.empty())
          {
            checks.largest_difference.assign(e.values.size(), -1.);
            checks.argument.resize(e.values.size());
          }
        for (std::size_t k = 0; k < e.values.size(); ++k)
          {
            // (A NaN difference is the largest: it stays.)
            const double d       = std::abs(fast.values[k] - e.values[k]);
            double      &largest = checks.largest_difference[k];
            if (!std::isnan(largest) && (std::isnan(d) || d > largest))
              {
                largest            = d;
                checks.argument[k] = fast.point;
              }
          }
      }
    checks.wall_time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begin)
        .count();
    return checks;
  }
} // namespace FuzzyContact
