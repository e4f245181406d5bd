// Spot checks: a fast response against the exact one at points where an
// interval method evaluated it.
//
// The proofs (bound_proof.h) solve exactly at the arguments of the bounds,
// which says how accurate the bounds are, not how accurate the fast model
// is elsewhere in the box, nor what one of its evaluations saves against
// an exact one at the same points: the Extension Principle's samples, on a
// grid, are solved from scratch far from one another, while most of an
// optimisation's points lie next to one it evaluated before (warm starts,
// kept factors). A spot check takes an evenly spread sample of the
// evaluations an EvaluationRecord kept (in the order they were made),
// solves each exactly once more, and gives
//
//  - the largest |fast - exact| of every output over the sample, and where;
//  - the points where one side has a solution and the other none;
//  - both times at the same points: the fast one as the method spent it
//    (in its order, from its neighbours), the exact one by the exact
//    response (each point alone).
//
// With several ranks, every rank's record is gathered, the sample is the
// same on all of them, dealt in contiguous blocks to the ranks, and the
// exact values gathered back (as the proofs do).

#ifndef fuzzycontact_fuzzy_spot_checks_h
#define fuzzycontact_fuzzy_spot_checks_h

#include <fuzzycontact/fuzzy/interval_method.h>

#include <deal.II/base/mpi.h>

#include <vector>

namespace FuzzyContact
{
  /** One evaluation of a response: where, what it gave, in how long. */
  struct RecordedEvaluation
  {
    std::vector<double> point, values;
    double              seconds = 0;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &point &values &seconds;
    }
  };

  /** The evaluations of a response, kept as it is called. */
  class EvaluationRecord
  {
  public:
    /**
     * @p response, timed (steady clock) and kept in this record at every
     * call. The record must outlive the returned response.
     */
    Response
    recording(const Response &response);

    /** Forgets the evaluations kept so far. */
    void
    clear();

    const std::vector<RecordedEvaluation> &
    evaluations() const;

  private:
    std::vector<RecordedEvaluation> list;
  };

  struct SpotChecks
  {
    /** The evaluations recorded (over the ranks) and the points checked. */
    unsigned long n_recorded = 0, n_checked = 0;
    /** Checked points where neither side has a solution, and where one
     * has and the other none (of them, where the fast one has none). */
    unsigned long n_without_solution = 0, n_disagreeing = 0, n_fast_without = 0;
    /** The fast response's time at the checked points, as recorded, and
     * the exact one's there [s]. */
    double fast_seconds = 0, exact_seconds = 0;
    /** The spot checks' wall time [s] (the exact solves and gathering). */
    double wall_time = 0;
    /** Per output: the largest |fast - exact| over the points where both
     * have a solution, and the point of it (empty if there is none). */
    std::vector<double>              largest_difference;
    std::vector<std::vector<double>> argument;
    /** The points where one side has a solution and the other none. */
    std::vector<std::vector<double>> disagreeing;
  };

  /**
   * Checks @p n evaluations of @p record (this rank's; gathered over @p
   * comm), evenly spread over them in their order, against @p exact
   * (called on every rank for its block of the sample; collective over
   * @p comm). All of them if @p n is larger.
   */
  SpotChecks
  spot_check(const EvaluationRecord &record,
             const unsigned int      n,
             const Response         &exact,
             const MPI_Comm          comm);
} // namespace FuzzyContact

#endif
