// The report of a modal reanalysis study (step-2): for each case, what was
// prepared (nominal modes, clusters, offline times), and for each sample a
// table of every method at every order beside the exact re-solve, then the
// modes one by one. The text goes to the screen and report.txt, the figures
// to results.json, both written at the end of a successful run.

#ifndef fuzzycontact_output_reanalysis_report_h
#define fuzzycontact_output_reanalysis_report_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/modal/mode_comparison.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/reanalysis/order_selection.h>
#include <fuzzycontact/reanalysis/reanalysis_case.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/scene/scene.h>

#include <nlohmann/json.hpp>

#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace FuzzyContact
{
  /**
   * One answer to one sample: a reanalysis method at one order, set beside
   * the exact re-solve.
   */
  struct ReanalysisAnswer
  {
    std::string method;
    /** Whether the method has orders (ReanalysisMethod::has_order()). */
    bool             has_order = false;
    unsigned int     order     = 0;
    ReanalysisResult result;
    /** result against the exact modes (paired by MAC). */
    ModeComparison comparison;
    /** Largest relative and energy-norm residuals of the reported modes. */
    double residual        = std::numeric_limits<double>::quiet_NaN();
    double energy_residual = std::numeric_limits<double>::quiet_NaN();
    double time_online     = 0;
    double time_offline    = 0;
    /** The order rule's estimates of this order (methods with an order). */
    OrderEstimate estimate;
    /**
     * Whether this is the order shown mode by mode: the order the tolerance
     * asks for, or the only one of a method without orders.
     */
    bool selected = false;
    /** For a selected order of a method with orders: the tolerance is met. */
    bool tolerance_met = true;
  };

  /** One sample of a case: the exact re-solve and every answer. */
  struct ReanalysisSampleSummary
  {
    /** The parameters' changes [%]. */
    std::vector<double> changes_percent;
    /** The exact modes (a few more than reported, for the pairing). */
    const ModalBasis *exact      = nullptr;
    double            time_exact = 0;
    /** The reported exact modes against the nominal modes (by MAC). */
    ModeComparison                exact_from_nominal;
    std::vector<ReanalysisAnswer> answers;
  };

  /** "+5%/-10%/+8%": the label of a sample. */
  std::string
  changes_label(const std::vector<double> &changes_percent);

  class ReanalysisReport
  {
  public:
    /**
     * A report of the lowest @p n_modes modes, into @p output_directory,
     * for the reanalysis @p settings and meshes refined
     * @p mesh_refinements times.
     */
    ReanalysisReport(const std::string        &output_directory,
                     const ReanalysisSettings &settings,
                     const unsigned int        n_modes,
                     const unsigned int        mesh_refinements);

    /** The first line, for a study of @p n_cases cases. */
    void
    start(const unsigned int n_cases);

    /**
     * What case @p c (of the scene called @p scene_name) prepared: its
     * parameters, nominal modes (cluster-completed) and clusters, and the
     * offline time of each method.
     */
    void
    add_case(const ReanalysisCase                                 &c,
             const std::string                                    &scene_name,
             const ParameterModel                                 &model,
             const ModalBasis                                     &nominal,
             const std::vector<std::unique_ptr<ReanalysisMethod>> &methods,
             const std::vector<double> &offline_times);

    /**
     * The table of one sample of the case added last, and its modes one by
     * one.
     */
    void
    add_sample(const ReanalysisSampleSummary &sample);

    /** Writes report.txt and results.json, and says so. */
    void
    write();

  private:
    std::string
    answers_table(const ReanalysisSampleSummary &sample) const;
    std::string
    modes_table(const ReanalysisSampleSummary &sample) const;
    nlohmann::json
    answer_json(const ReanalysisSampleSummary &sample,
                const ReanalysisAnswer        &answer) const;
    /** Largest error and smallest MAC of the reported modes. */
    std::pair<double, double>
    measure(const ReanalysisAnswer &answer) const;

    ReanalysisSettings settings;
    unsigned int       n_modes;
    // The case added last: its name and its parameters' names.
    std::string              case_name;
    std::vector<std::string> parameter_names;
    unsigned int             mesh_refinements;
    Report                   report;
    OutputFiles              output;
    nlohmann::json           results;
  };
} // namespace FuzzyContact

#endif
