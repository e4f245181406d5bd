// The model a fuzzy contact study evaluates: values of the fuzzy parameters
// in, the chosen outputs (observations.h) out,
//
//     (P_1, ..., P_n)  ->  (S_1, ..., S_m),
//
// two ways, from one binding of the values to the scene
// (FuzzyParameterSet::state(): every model is set from the same SceneState,
// contact_model.h):
//
//  - reduced(): the fast pipeline (ReducedOrderModel: component modes with
//    static correction, re-analysed by HPTP for zone materials, built once;
//    the contact solver of the settings per evaluation: FL2C, the paper's
//    fuzzy regulators, by default, or the exact reduced solver);
//  - full_order(): the exact reference of the Extension Principle
//    (FullOrderModel): by default every evaluation is an independent
//    full-order analysis, as one would run it without this project; with
//    set_reuse_factorisations(true) the factorisations are reused where
//    that is exact.
//
// Both are pure functions of the parameters (no state carried from one
// evaluation to the next affects the result), so that the interval methods
// may evaluate them in any order and on any number of MPI ranks.
//
// A body held by contact alone can slide: at parameter values (a low
// friction coefficient, a large push) where no contact forces in the
// friction cones balance its load, the problem has no static solution.
// That is a result of the point, not an error: both reduced() and
// full_order() then return no outputs (an empty vector, the interval
// methods' mark of a point without a solution, interval_method.h), and
// has_static_equilibrium() tells it (it depends on the loads, the
// friction coefficients and the geometry only: an NNLS problem on the
// friction cones' edges, contact_problem.h). The same holds where the
// cones balance the load but only after the bodies slid beyond what
// node-to-segment contact answers (a pin that spins in its bore:
// contact/small_sliding.h): the solve says so, and the point counts as
// without equilibrium too.

#ifndef fuzzycontact_study_fuzzy_contact_model_h
#define fuzzycontact_study_fuzzy_contact_model_h

#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/fuzzy/feasible_region.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/interval_method.h>
#include <fuzzycontact/fuzzy/proof_feedback.h>
#include <fuzzycontact/fuzzy/spot_checks.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>
#include <fuzzycontact/study/observations.h>
#include <fuzzycontact/study/reduced_order_model.h>
#include <fuzzycontact/study/sliding_probes.h>
#include <fuzzycontact/study/warm_starts.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  struct FuzzyContactModelSettings
  {
    /** Global refinements of every component mesh. */
    unsigned int         mesh_refinements = 2;
    ReducedModelSettings reduced;
    ModalParameters      modal;
    /**
     * The reduced model's contact solver: "fl2c" (the paper's, default) or
     * "reduced exact" (ActiveSetSolver), see create_contact_solver().
     */
    std::string         contact_solver = "fl2c";
    FL2CParameters      fl2c;
    ActiveSetParameters exact;
    /**
     * Compute modes only when the study needs them (false: always, e.g. to
     * reproduce the paper's modal basis). They are not needed when the
     * static correction is on and every fuzzy parameter only scales a
     * body's stiffness or a load, or is a friction coefficient or a gap:
     * the static correction alone is then exact.
     */
    bool modes_when_needed = true;
    /**
     * The limit of small sliding [degrees] (contact/small_sliding.h): beyond it
     * a point counts as without static equilibrium (the bodies slide).
     */
    double sliding_limit = default_sliding_limit;

    /**
     * Declares "mesh refinements", "contact solver", "sliding angle limit" and
     * the subsections
     * "Reduced models" (static correction, zone correction, modes), "Modal
     * analysis", "Reanalysis", "FL2C" and "Exact contact solver".
     */
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  /** What one MPI rank did of the offline build, by component name. */
  struct RankWork
  {
    /** Components whose matrices this rank assembled. */
    std::vector<std::string> assembled;
    /** Components whose stiffness this rank factorised. */
    std::vector<std::string> factorised;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &assembled &factorised;
    }
  };

  /**
   * The bounds of a study proven on its model
   * (FuzzyContactModel::proven_bounds()): the rounds of prove_and_correct()
   * (fuzzy/proof_feedback.h), the last round's bounds and proofs with the
   * evaluations and wall times of all rounds (the proofs' with the
   * enrichment and the sharing of the factorisations), the settings they
   * were proven with, what the exact solves' conjugate gradients did, and
   * the model's description after it was made richer (empty if it was not).
   */
  struct ModelProofs
  {
    ProvenBounds             proven;
    ProofSettings            settings;
    IterativeSolveStatistics cg;
    std::string              model_after;
  };

  class FuzzyContactModel
  {
  public:
    /**
     * Builds everything parameter-independent for @p scene, the fuzzy
     * parameters of @p fuzzy (bound to the same scene) and the outputs
     * named in @p outputs. Stages are timed in @p timer if given.
     *
     * With several ranks in @p comm, each component is assembled,
     * factorised and reduced on one rank (ReducedOrderModel::builders():
     * component c on rank c mod n, or the re-analysed components on the
     * first rank and the others on the others), its reduced blocks sent to
     * all; the other ranks mesh it (for the contact interface and the
     * outputs) but do not assemble it.
     */
    FuzzyContactModel(const Scene                     &scene,
                      const FuzzyParameterSet         &fuzzy,
                      const std::vector<std::string>  &outputs,
                      const FuzzyContactModelSettings &settings,
                      TimerOutput                     *timer = nullptr,
                      const MPI_Comm                   comm  = MPI_COMM_SELF);

    ~FuzzyContactModel();

    /**
     * The ranks that can evaluate reduced(): the communicator of the
     * constructor, or, where components are re-analysed and several ranks
     * build them, one of the first rank alone (MPI_COMM_NULL on the
     * others, which must not call reduced()). Interval methods on the
     * reduced model run on it (bounds_on_ranks()).
     */
    MPI_Comm
    reduced_communicator() const;

    /** The outputs, in the order of the values returned. */
    const Observations &
    observations() const;

    /** The name of the reduced model's contact solver, e.g. "fl2c". */
    std::string
    contact_solver() const;

    /**
     * The fast answer at @p values (one per fuzzy parameter); empty where
     * the loads have no static equilibrium (see the top of this file).
     */
    std::vector<double>
    reduced(const std::vector<double> &values);

    /**
     * The reduced model's answer at @p values with @p solver instead of
     * FL2C (e.g. ActiveSetSolver, the exact reduced solution).
     */
    std::vector<double>
    reduced(const std::vector<double> &values, const ContactSolver &solver);

    /**
     * The exact answer at @p values; empty where the loads have no static
     * equilibrium (see the top of this file).
     */
    std::vector<double>
    full_order(const std::vector<double> &values);

    /**
     * True if some body is held by contact alone: then some values of the
     * loads and friction coefficients may have no static equilibrium.
     */
    bool
    can_lose_equilibrium() const;

    /** The names of the bodies held by contact alone, comma-separated. */
    std::string
    bodies_held_by_contact() const;

    /**
     * Whether the loads at @p values have a static equilibrium
     * (has_static_equilibrium() of contact/static_equilibrium.h on the reduced
     * problem, whose free motions and load resultants are exact: a few
     * microseconds to a millisecond) and, if @p within_small_sliding, the
     * reduced model's answer there stays within small sliding
     * (contact/small_sliding.h: one contact solve; a solve that fails
     * otherwise is left to the evaluations). Only on the ranks of
     * reduced_communicator().
     */
    bool
    has_static_equilibrium(const std::vector<double> &values,
                           const bool within_small_sliding = true);

    /**
     * Where in the box of every level of @p numbers (at the levels
     * @p alpha) the loads have a static equilibrium
     * (feasible_region_on_ranks(), fuzzy/feasible_region.h, on the ranks of
     * reduced_communicator(), from as many design points as the
     * optimisation's global stage evaluates). Collective over the
     * communicator of the constructor.
     */
    FeasibleRegion
    equilibrium_region(const std::vector<FuzzyNumber> &numbers,
                       const std::vector<double>      &alpha);

    /** The margin of the limit of equilibrium, relative to mu. */
    static constexpr double limit_margin = 1e-6;
    /** The margin of "near the limit of equilibrium", relative to mu. */
    static constexpr double near_limit_margin = 0.05;

    /**
     * The evaluations (reduced() and full_order(), on this rank so far)
     * that gave no outputs although the static equilibrium test passed,
     * by why, and the probes of failed points. The report says each
     * count (a warning for those left out) and results.json has them.
     */
    struct UnansweredEvaluations
    {
      /**
       * At the limit of equilibrium (the loads need all but limit_margin
       * of every friction coefficient) the static answer is degenerate: a
       * body about to slide may slip any amount, and the contact solvers
       * can fail there. Such a point whose solve failed counts as without
       * equilibrium instead of an error.
       */
      unsigned long at_limit = 0;
      /**
       * Near it (the loads need more than 1 - near_limit_margin of every
       * friction coefficient) the static answer is not degenerate, but
       * the exact solvers can still fail there (two stacked bodies held by
       * contact alone: doc/contact.md, section 1). Such a point whose solve
       * failed is left out as if it had no equilibrium instead of stopping
       * the study (the bounds next to the edge of equilibrium may miss
       * it). A solve that fails farther from the limit is an error, unless
       * the probes below say otherwise.
       */
      unsigned long unsolved_near_limit = 0;
      /**
       * The answer slid beyond small sliding (contact/small_sliding.h: the
       * key `sliding angle limit`), at the point's friction or, its solve
       * failed, at a probe's (sliding_probes.h): the bodies slide, and the
       * point counts as without static equilibrium. Where every body is
       * supported, such an answer is an error instead.
       */
      unsigned long beyond_small_sliding = 0;
      /**
       * The solve failed below the friction that holds the bodies within
       * small sliding: a probe with more friction (up to max_sliding_probe
       * times the point's) answers within small sliding, none slid beyond
       * it. Away from the limit of equilibrium, where the cones hold the
       * load only after gross sliding, the active set iterations cycle (a
       * pin in its bore whose friction cannot hold the torque of its
       * load). Left out as if without equilibrium; sliding_factor is the
       * largest factor of the friction that answered (1 if none).
       */
      unsigned long unsolved_below_sliding_limit = 0;
      double        sliding_factor               = 1;
      /** The probes made, and those of them that failed too. */
      unsigned long probes = 0, failed_probes = 0;

      /** The counts summed over the ranks of @p comm (sliding_factor:
       * the largest). */
      UnansweredEvaluations
      summed_over(const MPI_Comm comm) const;
    };

    /** What the evaluations on this rank left unanswered so far. */
    const UnansweredEvaluations &
    unanswered() const;

    /** The friction factors a failed point is solved again with
     * (sliding_probe_factors(sliding_probes, max_sliding_probe)). */
    static constexpr int    sliding_probes    = 11;
    static constexpr double max_sliding_probe = 8;

    /** See FullOrderModel; default false. */
    void
    set_reuse_factorisations(const bool reuse);

    /** See FullOrderModel::set_iterative_solves(); default: factorise. */
    void
    set_iterative_solves(const FullOrderModel::ChangedStiffness mode,
                         const double       tolerance      = 1e-12,
                         const unsigned int max_iterations = 200,
                         const std::string &keys           = "");
    /** What the exact solves' conjugate gradients did so far. */
    const IterativeSolveStatistics &
    iterative_statistics() const;

    /**
     * Makes the reduced model richer at the parameter points @p points
     * (where its answers were found wrong): the exact solution's
     * displacement fields there, without the free motions of the bodies
     * held by contact alone, join the components' bases
     * (ReducedOrderModel::add_snapshots()). Returns how many vectors were
     * added. Collective over the communicator of the constructor.
     */
    unsigned int
    enrich(const std::vector<std::vector<double>> &points,
           TimerOutput                            *timer = nullptr);

    /**
     * The bounds that @p search finds (an interval method on reduced()),
     * each proven by full_order() at its argument; where some are not
     * proven, the model is made richer there (enrich()) and they are
     * searched again, as @p settings say (prove_and_correct(),
     * fuzzy/proof_feedback.h). @p enriched(round, points, vectors added) is
     * told of every enrichment. The exact solves reuse the factorisations
     * of the offline build (shared by the ranks: share_factorisations()),
     * a changed zone modulus solved as the settings say
     * (set_iterative_solves(): afterwards factorised again); the proofs are
     * timed in @p timer. Collective over the communicator of the
     * constructor.
     */
    ModelProofs
    proven_bounds(const std::function<FuzzyOutputBounds()>      &search,
                  const ProofSettings                           &settings,
                  const std::function<void(unsigned int round,
                                           std::size_t  n_points,
                                           unsigned int added)> &enriched,
                  TimerOutput *timer = nullptr);

    /**
     * The spot checks of @p n of the reduced evaluations in @p record
     * (fuzzy/spot_checks.h): full_order() there on reused factorisations,
     * with progress lines. Best called last: the full-order model keeps
     * the contact flexibility's columns it computed where they stay
     * exact, so its solves here cost the least they can, and a reference
     * run after them would be timed on columns they computed. Collective
     * over the communicator of the constructor.
     */
    SpotChecks
    spot_checks(const EvaluationRecord &record, const unsigned int n);

    /** The reduced model (for its description and checks). */
    const ReducedOrderModel &
    reduced_order_model() const;

    /**
     * Where the components were built on different ranks: every rank gets
     * the stiffness factorisations made on the others (copies of their
     * factors, ContactScene::share_stiffness_factorisations()), so that the
     * exact solves that reuse them (full_order() with
     * set_reuse_factorisations(true)) factorise nothing again and give the
     * same numbers on every rank. Nothing to do otherwise. Collective over
     * the communicator of the constructor; returns its wall time [s] (the
     * longest over the ranks).
     */
    double
    share_factorisations(TimerOutput *timer = nullptr);

    /**
     * What every rank did of the build so far (collective; on every rank,
     * one entry per rank).
     */
    std::vector<RankWork>
    work_per_rank() const;

    /** A few lines on what the model is: meshes, bases, outputs. */
    std::string
    describe() const;

    /** DoFs of each component. */
    std::vector<unsigned int>
    n_dofs() const;

    /** HPTP order used for each component (0: exact scaling or none). */
    std::vector<unsigned int>
    reanalysis_orders() const;

    /**
     * What the model left out and why (empty if nothing), for the report.
     */
    const std::string &
    skipped() const;

    /**
     * For each fuzzy parameter, why it cannot change the answer, or empty
     * if it can. A density cannot unless the scene has gravity (it then
     * scales the weight of its zones): the contact problem is static (K u =
     * f, no mass). Both models evaluate such a parameter at its nominal value,
     * so the outputs do not depend on it even through the reduced basis
     * (a re-analysed zone density would otherwise move the reduced answer
     * by its reduction error).
     */
    const std::vector<std::string> &
    inert() const;

    /**
     * The fuzzy numbers to propagate: those of the parameters, the inert
     * ones made crisp (at the midpoint of their core), so that no interval
     * method varies them and the outputs are crisp in them.
     */
    std::vector<FuzzyNumber>
    effective_numbers() const;

  private:
    // The modes of every component, or empty bases when the study does not
    // need them (says why in skipped_stages).
    std::vector<ModalBasis>
    modes_for(const std::vector<VaryingQuantity> &varying,
              const FuzzyContactModelSettings    &settings,
              TimerOutput                        *timer,
              const MPI_Comm                      comm);

    // Whether the reduced problem of the current state is at the limit
    // of equilibrium (see UnansweredEvaluations::at_limit).
    bool
    at_limit_of_equilibrium(const double margin = limit_margin);

    // A solve at @p values (the reduced model's current state) failed:
    // whether the point counts as without equilibrium (at or near its
    // limit, or beyond small sliding; counted), or the failure is an error.
    bool
    failure_counts_as_without_equilibrium(const std::vector<double> &values);

    // What the reduced model answers at @p values with more friction, for
    // a point whose solve failed (sliding_probes.h; the probes counted).
    SlidingVerdict
    sliding_with_more_friction(const std::vector<double> &values);

    // The reduced model's answer with @p solver, or with the model's own
    // solver if null.
    std::vector<double>
    reduced(const std::vector<double> &values, const ContactSolver *solver);

    // @p evaluate(), its failure rethrown with the parameter point and the
    // @p model that failed.
    std::vector<double>
    at_point(const std::vector<double>                  &values,
             const std::string                          &model,
             const std::function<std::vector<double>()> &evaluate) const;

    // The state of the scene at @p values.
    SceneState
    state(const std::vector<double> &values) const;

    // The outputs of the reduced model's @p solve() at @p values, the
    // contact solver started from the states of the nearest point
    // evaluated before (warm_starts.h), and this point's states kept.
    std::vector<double>
    reduced_from_neighbour(const std::vector<double>              &values,
                           const std::function<ContactSolution()> &solve);

    Scene                              scene;
    const FuzzyParameterSet           &fuzzy;
    std::unique_ptr<ContactScene>      bodies;
    std::unique_ptr<Observations>      outputs;
    std::unique_ptr<ReducedOrderModel> reduced_model;
    std::unique_ptr<FullOrderModel>    full_model;
    // The reduced model's contact states at the points evaluated so far.
    WarmStarts               warm_starts;
    std::string              solver_name;
    std::string              skipped_stages;
    std::vector<std::string> inert_parameters;
    std::string              held_by_contact;
    UnansweredEvaluations    unanswered_;
    // The exact reduced solvers of sliding_with_more_friction(): the
    // study's settings with fewer iterations, without the last resorts
    // (a probe that does not converge quickly says nothing), then with
    // them and one path solve (if no probe answered).
    std::array<std::unique_ptr<ContactSolver>, 2> probe_solvers;
    MPI_Comm                                      comm;
    MPI_Comm                                      reduced_ranks = MPI_COMM_NULL;
    bool                                          own_reduced_ranks = false;
    std::vector<unsigned int> builder; // the rank of each component
    unsigned int              n_ranks_building = 1;
  };
} // namespace FuzzyContact

#endif
