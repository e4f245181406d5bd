// The full-order model of a study: the components' full finite element
// systems with the exact contact solver (FullOrderContact), set from a
// SceneState.
//
// Two ways of solving, both exact:
//  - independent analyses (the default): every solve is a new analysis, as
//    one would run it without this project: new factorisations, exact
//    active set, refined displacement fields;
//  - with set_reuse_factorisations(true), the factorisations of the nominal
//    stiffness (the scene's, ContactScene::stiffness_factorisation(), which
//    the reduced models were built from) and the columns of the contact
//    flexibility are kept and
//    reused wherever that is exact (a stiffness that is a multiple of the
//    nominal one), and only the observed outputs are formed: the same
//    answers to about 1e-9, at a fraction of the cost. The nominal stiffness
//    is factorised first, so that every MPI rank reuses the same
//    factorisations whatever the order of its samples.
// With set_iterative_solves() (and reused factorisations), a stiffness that
// is not the nominal one (a zone modulus moved) is not factorised either:
// it is solved by conjugate gradients preconditioned with the nominal
// factorisation (base/factor_preconditioned_cg.h), to the relative residual
// asked for. The proofs of a zone study use this.

#ifndef fuzzycontact_study_full_order_model_h
#define fuzzycontact_study_full_order_model_h

#include <fuzzycontact/base/factor_preconditioned_cg.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/full_order_contact.h>
#include <fuzzycontact/study/contact_model.h>
#include <fuzzycontact/study/contact_scene.h>

#include <memory>

namespace FuzzyContact
{
  class FullOrderModel : public ContactModel
  {
  public:
    /**
     * @p bodies must outlive the model (its components' materials are set
     * by set_state()); @p observed: the DoFs whose displacements solve()
     * reports.
     */
    FullOrderModel(ContactScene              &bodies,
                   const ObservedDofs        &observed,
                   const ActiveSetParameters &parameters = {});

    /** "full_order". */
    std::string
    name() const override;
    void
    set_state(const SceneState &state) override;
    ContactSolution
    solve() override;

    /** See the top of this file; default false. */
    void
    set_reuse_factorisations(const bool reuse);
    /** How a stiffness that is not the nominal one is solved. */
    enum class ChangedStiffness
    {
      /** A new factorisation (the default). */
      factorisation,
      /** Conjugate gradients on the nominal factorisation. */
      cg,
      /**
       * Conjugate gradients where they cost less than a new factorisation:
       * their steps, bounded by the ratios of the zone moduli to the
       * nominal ones (the preconditioned operator's eigenvalues lie between
       * the smallest and the largest: CG's classical bound), times the
       * solves the nominal exact solve needed, against the factorisation's
       * operations counted in solves (CHOLMOD's counts; a solve of the
       * factor is about 4 of its entries' worth, and the factorisation
       * runs about factor_to_solve_speed times faster per operation: its
       * supernodes are dense matrix products, a solve's matrix-vector
       * ones).
       */
      automatic
    };

    /**
     * With reused factorisations: solve a stiffness that is not the
     * nominal one by conjugate gradients preconditioned with the nominal
     * factorisation (to the relative residual @p tolerance in at most
     * @p max_iterations steps; @p keys names the keys that set them, for
     * messages) instead of factorising it, always or where it is cheaper
     * (@p mode).
     */
    void
    set_iterative_solves(const ChangedStiffness mode,
                         const double           tolerance      = 1e-12,
                         const unsigned int     max_iterations = 200,
                         const std::string     &keys           = "");
    /**
     * The per-operation speed ratio of the automatic choice (above), as
     * measured on the zone study's 20k-DoF bodies (doc/fuzzy-study.md: a
     * factorisation of 1.6e8 operations costs about 15 solves of its 1.1e6
     * entries).
     */
    static constexpr double factor_to_solve_speed = 2.5;
    /** What the conjugate gradient solves did so far. */
    const IterativeSolveStatistics &
    iterative_statistics() const;

    /**
     * solve() with the displacement fields of every component (in
     * ContactSolution::displacements), also when factorisations are
     * reused.
     */
    ContactSolution
    solve_with_fields();

    /** Proportional load steps up to the state's loads (default 1). */
    void
    set_n_load_steps(const unsigned int n_load_steps);

    /** The solver of the last solve (for its counters and W). */
    FullOrderContact &
    solver();

  private:
    // A solver set to the current state.
    std::unique_ptr<FullOrderContact>
    make_solver() const;

    ContactScene       &bodies;
    ObservedDofs        observed;
    ActiveSetParameters parameters;
    SceneState          state;
    // The state's gaps and friction coefficients, per slave node.
    Vector<double>      initial_gaps;
    std::vector<double> friction_coefficients;
    bool                reuse = false;
    // Conjugate gradients for changed stiffnesses (set_iterative_solves()),
    // on the nominal factorisations (kept from the first reusing solve).
    ChangedStiffness changed_stiffness = ChangedStiffness::factorisation;
    // Back-substitutions of the first (nominal) reusing solve.
    unsigned int                                       nominal_solves = 0;
    double                                             cg_tolerance   = 1e-12;
    unsigned int                                       cg_max_iterations = 200;
    std::string                                        cg_keys;
    std::vector<std::shared_ptr<const SparseCholesky>> nominal_factors;
    std::shared_ptr<IterativeSolveStatistics>          cg_statistics;
    unsigned int                                       n_load_steps = 1;
    std::unique_ptr<FullOrderContact>                  current;
  };
} // namespace FuzzyContact

#endif
