// FuzzyContactModel's proofs of a study's bounds (fuzzy_contact_model.h):
// the exact solves at the bounds' arguments on the factorisations of the
// offline build, and the rounds of enrichment and new search where a bound
// is not proven (fuzzy/proof_feedback.h).

#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/base/timer_section.h>
#include <fuzzycontact/fuzzy/bound_proof.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>

#include <limits>

namespace FuzzyContact
{
  ModelProofs
  FuzzyContactModel::proven_bounds(
    const std::function<FuzzyOutputBounds()>      &search,
    const ProofSettings                           &settings,
    const std::function<void(unsigned int round,
                             std::size_t  n_points,
                             unsigned int added)> &enriched,
    TimerOutput                                   *timer)
  {
    // Every bound's proof: its argument once more, exactly, on the
    // factorisations of the offline build (shared by the ranks, in the
    // proofs' time; a changed zone modulus by conjugate gradients on
    // them).
    const ProofSettings &ps     = settings;
    const double         shared = share_factorisations(timer);
    set_reuse_factorisations(true);
    set_iterative_solves(ps.solver == ProofSettings::Solver::cg
                           ? FullOrderModel::ChangedStiffness::cg
                         : ps.solver == ProofSettings::Solver::factorisation
                           ? FullOrderModel::ChangedStiffness::factorisation
                           : FullOrderModel::ChangedStiffness::automatic,
                         ps.cg_tolerance,
                         ps.cg_max_iterations,
                         "keys 'cg tolerance' and 'cg max "
                         "iterations' of subsection Proofs");
    const unsigned int n_outputs = observations().size();
    const Response     proved    = [&](const std::vector<double> &p) {
      std::vector<double> values;
      if (!p.empty())
        values = full_order(p);
      if (!has_solution(values))
        values.assign(n_outputs, std::numeric_limits<double>::quiet_NaN());
      return values;
    };
    unsigned int round = 0;
    ModelProofs  result;
    result.proven = prove_and_correct(
      search,
      [&](const FuzzyOutputBounds &b) {
        auto scope = timer_section(timer, "proofs (full order at the bounds)");
        return prove_bounds(b, proved, comm);
      },
      [&](const std::vector<std::vector<double>> &points) {
        ++round;
        const unsigned int added = enrich(points, timer);
        enriched(round, points.size(), added);
        return added;
      },
      ps);
    set_iterative_solves(FullOrderModel::ChangedStiffness::factorisation);

    // The cost of all rounds.
    FuzzyOutputBounds &bounds = result.proven.bounds;
    BoundProofs       &proofs = result.proven.proofs;
    bounds.wall_time          = 0;
    bounds.n_evaluations      = 0;
    bounds.evaluation_time    = 0;
    proofs.wall_time          = shared;
    proofs.n_evaluations      = 0;
    for (const ProofRound &r : result.proven.rounds)
      {
        bounds.wall_time += r.search_time;
        bounds.n_evaluations += r.evaluations;
        bounds.evaluation_time += r.evaluation_time;
        proofs.wall_time += r.proof_time + r.enrichment_time;
        proofs.n_evaluations += r.proofs;
      }
    result.settings    = ps;
    result.cg          = iterative_statistics();
    result.model_after = round > 0 ? describe() : "";
    return result;
  }


  SpotChecks
  FuzzyContactModel::spot_checks(const EvaluationRecord &record,
                                 const unsigned int      n)
  {
    set_reuse_factorisations(true);
    const unsigned int  n_ranks   = Utilities::MPI::n_mpi_processes(comm);
    const unsigned long n_checked = std::min<unsigned long>(
      n,
      Utilities::MPI::sum<unsigned long>(record.evaluations().size(), comm));
    Progress progress("spot checks, full-order solves" +
                        std::string(n_ranks > 1 ? " of the first rank" : ""),
                      (n_checked + n_ranks - 1) / n_ranks);
    return spot_check(
      record,
      n,
      [&](const std::vector<double> &p) {
        std::vector<double> values = full_order(p);
        progress.advance();
        return values;
      },
      comm);
  }
} // namespace FuzzyContact
