// The report of a fuzzy study (step-4): the study and its model, one table
// per output with the alpha-cuts of every method and their differences from
// the Extension Principle, the non-monotone responses found, the cost, and
// the membership functions as a picture. Text goes to a Report
// (report.txt), numbers to results.json under the keys step-4 has always
// written (outputs[].name/unit/alpha/lower/upper/..., time_s, evaluations,
// speed_up, notes).

#ifndef fuzzycontact_output_fuzzy_report_h
#define fuzzycontact_output_fuzzy_report_h

#include <fuzzycontact/base/factor_preconditioned_cg.h>
#include <fuzzycontact/fuzzy/bound_proof.h>
#include <fuzzycontact/fuzzy/feasible_region.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/interval_method.h>
#include <fuzzycontact/fuzzy/proof_feedback.h>
#include <fuzzycontact/fuzzy/spot_checks.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>
#include <fuzzycontact/study/observations.h>

#include <nlohmann/json.hpp>

#include <sstream>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /** What a fuzzy study found, for its report. */
  struct FuzzyStudyResults
  {
    std::string                 scene;
    unsigned int                n_processes = 1;
    std::vector<unsigned int>   n_dofs;
    std::vector<FuzzyParameter> parameters;
    std::vector<Observation>    outputs;
    std::vector<double>         alpha;
    FuzzyOutputBounds           optimisation;
    /** Empty bounds if the method was not run. */
    FuzzyOutputBounds vertex, reference;
    bool              has_vertex    = false;
    bool              has_reference = false;
    /** The reference kept its factorisations (else independent analyses). */
    bool   reference_reuses = false;
    double offline_time     = 0;
    /** The exact value at the argument of every optimisation bound. */
    BoundProofs proofs;
    bool        has_proofs = false;
    /**
     * The rounds of search, proofs and enrichment (fuzzy/proof_feedback.h),
     * the bounds left beyond the tolerance, why the rounds stopped, the
     * settings, what the proofs' conjugate gradients did, and the model's
     * description after it was made richer (empty if it was not).
     */
    std::vector<ProofRound>    proof_rounds;
    std::vector<UnprovenBound> unproven;
    std::string                proof_stop;
    ProofSettings              proof_settings;
    IterativeSolveStatistics   proof_cg;
    std::string                model_after;
    /** Per parameter: why it cannot change the answer (empty: it can). */
    std::vector<std::string> inert;
    /** What each MPI rank assembled and factorised. */
    std::vector<RankWork> ranks;
    /**
     * Where the bodies held by contact alone (@p free_bodies) have a
     * static equilibrium; has_equilibrium: the check ran (some body is
     * held by contact alone).
     */
    FeasibleRegion equilibrium;
    bool           has_equilibrium = false;
    std::string    free_bodies;
    /** The evaluations left unanswered and the probes of failed points,
     * over all ranks (FuzzyContactModel::unanswered()). */
    FuzzyContactModel::UnansweredEvaluations unanswered;
    /** The optimisation's evaluations checked by the full-order model
     * (if proof_settings.spot_checks > 0). */
    SpotChecks spot_checks;

    /**
     * What the model built in @p offline_time [s] is: its DoFs and outputs.
     */
    void
    set_model(const FuzzyContactModel &model, const double offline_time);

    /**
     * The optimisation's bounds and everything about their proofs, from
     * @p p (FuzzyContactModel::proven_bounds()).
     */
    void
    set_proofs(const ModelProofs &p);
  };

  namespace FuzzyStudyReport
  {
    /** The study: scene, processes, fuzzy parameters, levels. */
    std::string
    study(const std::string                 &scene_name,
          const std::string                 &scene_file,
          const unsigned int                 n_processes,
          const std::vector<FuzzyParameter> &parameters,
          const unsigned int                 n_alpha);

    /** The model built in @p offline_time [s], as @p description says. */
    std::string
    model(const double offline_time, const std::string &description);

    /**
     * The line announcing the Extension Principle's @p n_samples exact
     * solves (@p points per parameter and level, factorisations reused or
     * independent analyses).
     */
    std::string
    extension_principle(const unsigned long n_samples,
                        const unsigned int  points,
                        const bool          reuse_factorisations);

    /**
     * The bound tables of every output, the non-monotone responses and the
     * cost, said in @p report and written into @p json.
     */
    void
    bounds(const FuzzyStudyResults &results,
           Report                  &report,
           nlohmann::json          &json);

    /**
     * The proof and the shape of every optimisation bound of output @p k
     * (fuzzy_report_bounds.cc): a table in @p out, arrays in @p entry.
     */
    void
    proofs(const FuzzyStudyResults &results,
           const unsigned int       k,
           std::ostringstream      &out,
           nlohmann::json          &entry);

    /**
     * Output @p k's optimisation bounds against the reference, told apart
     * by the proofs: short of it, beyond it at an exactly verified point
     * (the reference missed it), or beyond it by a reduction error only.
     */
    void
    comparison(const FuzzyStudyResults &results,
               const unsigned int       k,
               std::ostringstream      &out,
               nlohmann::json          &entry);

    /**
     * Where sliding is possible (fuzzy_report_equilibrium.cc): the fuzzy
     * output "sliding possible", the share of every box with a static
     * equilibrium and the points each method left out; the text for the
     * report (empty without bodies held by contact alone), and
     * json["static_equilibrium"].
     */
    std::string
    equilibrium(const FuzzyStudyResults &results, nlohmann::json &json);

    /**
     * The line saying that round @p round of the proofs left bounds beyond
     * @p tolerance and the model was made richer at @p n_points points by
     * @p added vectors.
     */
    std::string
    enrichment(const unsigned int round,
               const std::size_t  n_points,
               const unsigned int added,
               const double       tolerance);

    /**
     * The proofs' rounds and the unproven bounds (one `warning:` line
     * each), said in @p report and written into @p json ("proofs").
     */
    void
    proof_summary(const FuzzyStudyResults &results,
                  Report                  &report,
                  nlohmann::json          &json);

    /**
     * The spot checks (fuzzy/spot_checks.h), if they were made: the
     * largest |reduced - exact| of every output (a `warning:` line each
     * beyond the proofs' tolerance, and one for points where one model
     * has a solution and the other none) and both times at the same
     * points, said in @p report and written into @p json ("spot_checks").
     */
    void
    spot_checks(const FuzzyStudyResults &results,
                Report                  &report,
                nlohmann::json          &json);

    /** The parameters that cannot change the answer, if any. */
    std::string
    inert(const FuzzyStudyResults &results, nlohmann::json &json);

    /**
     * Queues the membership functions of every output (membership.png,
     * drawn by gnuplot from membership.dat/.gp) in @p files; says in
     * @p report why the picture is missing if gnuplot fails.
     */
    void
    plot(const FuzzyStudyResults &results, OutputFiles &files, Report &report);

    /**
     * Writes report.txt (the text of @p report), results.json (@p json) and
     * the membership plot (plot()) into @p directory, and says so on
     * standard output.
     */
    void
    write(const FuzzyStudyResults &results,
          Report                  &report,
          const nlohmann::json    &json,
          const std::string       &directory);

    /**
     * What a run some of whose bounds are not proven (results.unproven)
     * says on standard error: how many, and the @p exit_status it returns.
     */
    std::string
    unproven(const FuzzyStudyResults &results, const int exit_status);
  } // namespace FuzzyStudyReport
} // namespace FuzzyContact

#endif
