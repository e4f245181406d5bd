#include <fuzzycontact/base/limits.h>
#include <fuzzycontact/fuzzy/proof_feedback.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <utility>

namespace FuzzyContact
{
  void
  ProofSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Proofs");
    prm.declare_entry("tolerance",
                      "1e-4",
                      Patterns::Double(0),
                      "A bound is proven when |reduced - exact| at its "
                      "argument is at most this fraction of the output's "
                      "range; otherwise the model is made richer there and "
                      "the bounds are searched again.");
    prm.declare_entry("max rounds",
                      "3",
                      Patterns::Integer(0, 20),
                      "Rounds of enrichment and new search at most (0: the "
                      "bounds are proven, never corrected).");
    prm.declare_entry("accept unproven",
                      "false",
                      Patterns::Bool(),
                      "true: bounds left beyond the tolerance after the "
                      "last round still give exit status 0 (the warning and "
                      "the flag in results.json stay).");
    prm.declare_entry("solver",
                      "automatic",
                      Patterns::Selection("automatic|cg|factorisation"),
                      "How the proofs solve a stiffness whose zone moduli "
                      "moved: conjugate gradients preconditioned by the "
                      "nominal factorisation ('cg'), a new factorisation "
                      "('factorisation'), or CG where its steps (bounded by "
                      "the moduli's change) times the solves of an exact "
                      "solve cost less than a factorisation ('automatic').");
    prm.declare_entry("cg tolerance",
                      "1e-12",
                      Patterns::Double(0),
                      "cg: the relative residual ||b - K x|| / ||b|| of "
                      "every solve.");
    prm.declare_entry("cg max iterations",
                      "200",
                      Patterns::Integer(1, 100000),
                      "cg: steps of a solve at most.");
    prm.declare_entry("spot checks",
                      "0",
                      Patterns::Integer(0, 100000),
                      "Evaluations of the optimisation (of its last round), "
                      "evenly spread over them, solved by the exact "
                      "full-order model too: the reduced model's largest "
                      "error there, next to the time of one evaluation of "
                      "each model at the same points (0: none). A "
                      "difference beyond the tolerance is a warning.");
    prm.leave_subsection();
  }


  void
  ProofSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Proofs");
    tolerance              = Input::in_range(prm.get_double("tolerance"),
                                1e-14,
                                1,
                                "Proofs: tolerance",
                                "a fraction of the output's range");
    max_rounds             = prm.get_integer("max rounds");
    accept_unproven        = prm.get_bool("accept unproven");
    const std::string name = prm.get("solver");
    solver                 = name == "cg"              ? Solver::cg
                             : name == "factorisation" ? Solver::factorisation
                                                       : Solver::automatic;
    cg_tolerance           = Input::in_range(prm.get_double("cg tolerance"),
                                   1e-16,
                                   1e-4,
                                   "Proofs: cg tolerance",
                                   "a relative residual");
    cg_max_iterations      = prm.get_integer("cg max iterations");
    spot_checks            = prm.get_integer("spot checks");
    prm.leave_subsection();
  }


  namespace
  {
    // The smallest and the largest finite value among output k's bounds
    // and the exact values at their arguments (lo > hi if none).
    std::pair<double, double>
    extent(const FuzzyOutputBounds &bounds,
           const BoundProofs       &proofs,
           const unsigned int       k)
    {
      double     lo = std::numeric_limits<double>::infinity(), hi = -lo;
      const auto take = [&](const double x) {
        if (std::isfinite(x))
          {
            lo = std::min(lo, x);
            hi = std::max(hi, x);
          }
      };
      for (const Interval &i : bounds.bounds[k])
        {
          take(i.lower);
          take(i.upper);
        }
      for (const auto *side : {&proofs.lower, &proofs.upper})
        if (side->size() > k)
          for (const BoundProof &p : (*side)[k])
            take(p.exact);
      return {lo, hi};
    }
  } // namespace


  double
  proof_range(const FuzzyOutputBounds &bounds,
              const BoundProofs       &proofs,
              const unsigned int       k)
  {
    const auto [lo, hi] = extent(bounds, proofs, k);
    if (!(hi >= lo))
      return 0;
    const double magnitude = std::max(std::abs(lo), std::abs(hi));
    const double range     = hi - lo;
    return range > 1e-12 * magnitude ? range : magnitude;
  }


  double
  proof_magnitude(const FuzzyOutputBounds &bounds,
                  const BoundProofs       &proofs,
                  const unsigned int       k)
  {
    const auto [lo, hi] = extent(bounds, proofs, k);
    return hi >= lo ? std::max(std::abs(lo), std::abs(hi)) : 0.;
  }


  std::vector<UnprovenBound>
  unproven_bounds(const FuzzyOutputBounds &bounds,
                  const BoundProofs       &proofs,
                  const double             tolerance,
                  const double             accuracy)
  {
    std::vector<UnprovenBound> result;
    for (unsigned int k = 0; k < bounds.bounds.size(); ++k)
      {
        const double range = proof_range(bounds, proofs, k);
        const double floor = accuracy * proof_magnitude(bounds, proofs, k);
        for (unsigned int l = 0; l < bounds.bounds[k].size(); ++l)
          for (const bool upper : {false, true})
            {
              const std::vector<double> &argument =
                upper ? bounds.argmax[k][l] : bounds.argmin[k][l];
              // A level without any point with outputs has no bound (n/a:
              // no equilibrium, or every point left out near its limit),
              // and nothing to prove.
              if (argument.empty())
                continue;
              const BoundProof &p =
                upper ? proofs.upper[k][l] : proofs.lower[k][l];
              const double d = p.difference();
              // (A non-finite difference is never proven.)
              const double relative =
                range > 0
                  ? std::abs(d) / range
                  : (d == 0 ? 0. : std::numeric_limits<double>::infinity());
              if (!(relative <= tolerance) && !(std::abs(d) <= floor))
                result.push_back({k, l, upper, d, relative, argument});
            }
      }
    return result;
  }


  ProvenBounds
  prove_and_correct(
    const std::function<FuzzyOutputBounds()>                    &search,
    const std::function<BoundProofs(const FuzzyOutputBounds &)> &prove,
    const std::function<unsigned int(const std::vector<std::vector<double>> &)>
                        &enrich,
    const ProofSettings &settings)
  {
    ProvenBounds result;
    for (unsigned int round = 0;; ++round)
      {
        ProofRound this_round;
        Timer      clock;
        result.bounds              = search();
        this_round.search_time     = clock.wall_time();
        this_round.evaluations     = result.bounds.n_evaluations;
        this_round.evaluation_time = result.bounds.evaluation_time;
        clock.restart();
        result.proofs         = prove(result.bounds);
        this_round.proof_time = clock.wall_time();
        this_round.proofs     = result.proofs.n_evaluations;
        result.unproven       = unproven_bounds(result.bounds,
                                          result.proofs,
                                          settings.tolerance,
                                          settings.accuracy);
        this_round.n_unproven = result.unproven.size();
        // (n/a if a bound has no exact value to compare with.)
        for (const UnprovenBound &u : result.unproven)
          this_round.largest = std::isnan(u.relative)
                                 ? u.relative
                                 : std::max(this_round.largest, u.relative);
        if (result.unproven.empty())
          {
            result.rounds.push_back(this_round);
            result.stopped = "every bound proven";
            break;
          }
        if (round >= settings.max_rounds)
          {
            result.rounds.push_back(this_round);
            result.stopped = "the rounds ran out (Proofs: max rounds = " +
                             std::to_string(settings.max_rounds) + ")";
            break;
          }
        // The distinct arguments of the unproven bounds.
        std::set<std::vector<double>> points;
        for (const UnprovenBound &u : result.unproven)
          points.insert(u.argument);
        clock.restart();
        this_round.added           = enrich({points.begin(), points.end()});
        this_round.enrichment_time = clock.wall_time();
        result.rounds.push_back(this_round);
        if (this_round.added == 0)
          {
            result.stopped = "the exact solutions at the unproven bounds' "
                             "arguments add nothing to the model (its error "
                             "there is not a missing direction of the "
                             "reduced basis: the contact solver's tolerance, "
                             "or load stages)";
            break;
          }
      }
    return result;
  }
} // namespace FuzzyContact
