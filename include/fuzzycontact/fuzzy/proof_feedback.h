// The proofs of the bounds feed back into the model: a bound whose
// reduction error |reduced - exact| at its argument (bound_proof.h) exceeds
// a tolerance, relative to the output's range, makes the model richer there
// (the caller's enrich(): snapshots of the exact solution at those
// arguments) and the bounds are searched again, until every bound is
// proven within the tolerance or the rounds run out. A bound left unproven
// is reported as such (a warning line, a flag in results.json, and step-4's
// exit status; doc/fuzzy-study.md), unless the settings accept it.
//
// The output's range is the span of the bounds of every level and of the
// exact values at their arguments (the exact values keep a reduced model
// that is far off from shrinking its own yardstick); an output whose range
// is below 1e-12 of its magnitude (crisp) is measured against the
// magnitude. A bound is also proven when |reduced - exact| is within the
// accuracy the study asks of its outputs (the optimisation's response
// tolerance, relative to the output's magnitude): two solutions of the
// same contact problem on different floating-point paths (a reduced basis
// of hundreds of static correction modes against a sparse factorisation)
// agree only to that order where the output is a large reaction that the
// parameters barely move, and no basis enrichment can do better.

#ifndef fuzzycontact_fuzzy_proof_feedback_h
#define fuzzycontact_fuzzy_proof_feedback_h

#include <fuzzycontact/fuzzy/bound_proof.h>
#include <fuzzycontact/fuzzy/interval_method.h>

#include <deal.II/base/parameter_handler.h>

#include <functional>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /** The keys of subsection "Proofs" of a fuzzy study. */
  struct ProofSettings
  {
    /** |reduced - exact| at a bound, relative to the output's range. */
    double tolerance = 1e-4;
    /**
     * |reduced - exact| at a bound below this fraction of the output's
     * magnitude is proven too (not a key: the optimisation's response
     * tolerance, set by the study).
     */
    double accuracy = 0;
    /** Rounds of enrichment and new search at most (0: prove only). */
    unsigned int max_rounds = 3;
    /** Unproven bounds still give exit status 0 (the warning stays). */
    bool accept_unproven = false;
    /**
     * Exact solves of a changed stiffness (a zone modulus): by conjugate
     * gradients on the nominal factorisation, by new factorisations, or
     * by CG where it costs less (study/full_order_model.h); CG to this
     * relative residual in at most this many steps.
     */
    enum class Solver
    {
      automatic,
      cg,
      factorisation
    };
    Solver       solver            = Solver::automatic;
    double       cg_tolerance      = 1e-12;
    unsigned int cg_max_iterations = 200;
    /**
     * Evaluations of the optimisation solved exactly too, evenly spread
     * over them (fuzzy/spot_checks.h; 0: none).
     */
    unsigned int spot_checks = 0;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** A bound that its proof does not confirm within the tolerance. */
  struct UnprovenBound
  {
    unsigned int output = 0, level = 0;
    bool         upper = false;
    /** reduced - exact, and that relative to the output's range. */
    double              difference = 0, relative = 0;
    std::vector<double> argument;
  };

  /** The range of output @p k that the tolerance refers to (see above). */
  double
  proof_range(const FuzzyOutputBounds &bounds,
              const BoundProofs       &proofs,
              const unsigned int       k);

  /** The largest magnitude of output @p k's bounds and exact values. */
  double
  proof_magnitude(const FuzzyOutputBounds &bounds,
                  const BoundProofs       &proofs,
                  const unsigned int       k);

  /**
   * The bounds of @p bounds whose proofs @p proofs exceed both @p tolerance
   * of their output's range and @p accuracy of its magnitude, in the order
   * output, level, side. A bound without an argument (n/a: no point of its
   * level had outputs) is not one of them: there is nothing to prove.
   */
  std::vector<UnprovenBound>
  unproven_bounds(const FuzzyOutputBounds &bounds,
                  const BoundProofs       &proofs,
                  const double             tolerance,
                  const double             accuracy = 0);

  /** One round of search, proofs and (if needed) enrichment. */
  struct ProofRound
  {
    unsigned long evaluations = 0, proofs = 0;
    /** Bounds over the tolerance, and the largest relative error. */
    unsigned int n_unproven = 0;
    double       largest    = 0;
    /** Vectors the enrichment added after this round (0: none, or last). */
    unsigned int added = 0;
    /** Wall times [s]: search, proofs, enrichment. */
    double search_time = 0, proof_time = 0, enrichment_time = 0;
    /** Of the search's time, the time inside the response (all ranks). */
    double evaluation_time = 0;
  };

  /** What prove_and_correct() found. */
  struct ProvenBounds
  {
    /** The last round's bounds and their proofs. */
    FuzzyOutputBounds       bounds;
    BoundProofs             proofs;
    std::vector<ProofRound> rounds;
    /** The bounds still over the tolerance after the last round. */
    std::vector<UnprovenBound> unproven;
    /** Why the rounds stopped, for the report. */
    std::string stopped;
  };

  /**
   * Searches the bounds (@p search), proves them (@p prove) and, while some
   * exceed settings.tolerance and rounds are left, makes the model richer
   * at their distinct arguments (@p enrich, which returns how many vectors
   * it added: none stops the rounds) and searches again. The search must
   * not reuse evaluations of the model before its enrichment.
   */
  ProvenBounds
  prove_and_correct(
    const std::function<FuzzyOutputBounds()>                    &search,
    const std::function<BoundProofs(const FuzzyOutputBounds &)> &prove,
    const std::function<unsigned int(const std::vector<std::vector<double>> &)>
                        &enrich,
    const ProofSettings &settings);
} // namespace FuzzyContact

#endif
