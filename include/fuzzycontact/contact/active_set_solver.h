// The exact solver of one load step of the contact problem (see
// contact_problem.h), in two phases.
//
// 1. Start (only when no node is closed yet, i.e. without a warm start):
//    the frictionless normal problem, which is the convex quadratic program
//    min 1/2 p_n^T W_nn p_n + g_free,n^T p_n subject to p_n >= 0, solved by
//    the primal active set method of Lawson and Hanson (NNLS): close the
//    most penetrating open node, solve on the closed set, step back to the
//    boundary and open nodes whose force would turn negative, repeat. It
//    terminates in finitely many steps whatever W (no cycling) and, when
//    few nodes end up closed, in few steps. It matters on the `stacked`
//    scene: there the free solution penetrates at every node while the
//    answer has two closed nodes, and the primal-dual method started from
//    "all penetrating nodes closed" peels them off a few per iteration.
//
// 2. The primal-dual active set method, i.e. the semismooth Newton method
//    of Hueber, Stadler and Wohlmuth (2008) for Signorini's conditions with
//    Coulomb friction, from the statuses of phase 1 (closed nodes stick) or
//    of a warm start. In 2D the tangential direction is a sign, so for a
//    fixed status of every node the conditions are linear:
//
//      open:  p_n = 0, p_t = 0;
//      stick: g_n = 0, g_t = g_t,previous;
//      slip:  g_n = 0, p_t = mu s p_n (s = +1 or -1).
//
//    Each iteration solves that linear system on the closed nodes only (a
//    dense LU factorisation of W restricted to the closed rows, slip
//    columns folded in), then predicts a new status from the complementarity
//    functions: closed if p_n - c_n g_n > 0, then stick if |p_t - c_t dg_t|
//    < mu (p_n - c_n g_n), else slip in the direction of p_t - c_t dg_t. A
//    node whose own residual is already below the tolerance keeps its
//    status: weakly complementary nodes (g_n = 0 and p_n = 0 at once, as
//    along the interface of `stacked`) then do not flip on round-off.
//
// The method stops when the relative complementarity residual is at most
// the tolerance (default 1e-10), and nowhere else: if a status repeats (a
// cycle), it switches to Murty's least-index rule, which changes only the
// violated node of least index per iteration and terminates for P-matrices
// (frictionless contact with W positive definite); if that cycles too, or
// max_iterations pass, it throws with the iteration count and the residual
// reached. A numerically singular active system (a reduced W of low rank)
// is solved in the least-squares sense with a pseudo-inverse.
//
// Bodies held by contact alone (contact_problem.h) add the amplitudes of
// their free motions to the unknowns of every linear system and their
// equilibrium to its equations (status_system.h), and the equilibrium's
// residual to the stopping test. Such a body has no position before its
// contact holds it, so phase 1 is replaced by the start "every node
// closed" (the primal-dual iterations then open the nodes in tension); and
// a load that no contact forces in the friction cones can balance is
// refused with that reason (check_equilibrium()) when the iterations fail
// (a converged state balances the load within the cones: the test is not
// repeated before every solve).

#ifndef fuzzycontact_contact_active_set_solver_h
#define fuzzycontact_contact_active_set_solver_h

#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/contact/contact_solver.h>

#include <deal.II/base/parameter_handler.h>

#include <string>

namespace FuzzyContact
{
  struct ActiveSetParameters
  {
    /** Relative complementarity residual at which the method stops. */
    double tolerance = 1e-10;
    /** Iterations per load step (both phases) before it gives up. */
    unsigned int max_iterations = 200;
    /**
     * The key that sets max_iterations, named in the message of a solve
     * that runs out of iterations.
     */
    std::string max_iterations_key = "Exact contact solver/max iterations";
    /**
     * Near the limit of sliding (bodies held by contact alone that need
     * friction), the solves on the path of friction coefficients
     * (active_set_solver.cc) before the step gives up. Each success at
     * least halves the distance to the limit, and a path that needs all
     * but 1e-6 of the friction takes 20 successful solves.
     */
    unsigned int max_path_solves = 32;
    /**
     * The failed solves on that path before the step gives up (each is
     * retried closer to the last converged one). Where the path leads to
     * an answer it fails a few times at most; where it does not, every
     * retry fails, each a whole cycling solve.
     */
    unsigned int max_path_failures = 4;
    /**
     * Whether a step of bodies held by contact alone with friction that
     * fails from its starts is tried again with slips allowed to reverse
     * at once, then along the path of friction coefficients (the last
     * resorts of active_set_solver.cc). Not a key: a fuzzy study's probes
     * of failed points go without them (study/fuzzy_contact_model.h).
     */
    bool last_resorts = true;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  class ActiveSetSolver : public ContactSolver
  {
  public:
    explicit ActiveSetSolver(const ActiveSetParameters &parameters = {});

    /** "reduced exact". */
    std::string
    name() const override;

    /** One load step of a dense problem (the method below on its W). */
    ContactState
    solve_step(const ContactProblem &problem,
               const LoadStep       &step,
               const std::string    &what) const override;

    using ContactSolver::solve;

    /**
     * Solves one load step with flexibility @p W, free gaps
     * @p step.g_free, previous gaps @p step.g_previous and friction
     * coefficients @p mu, starting from the statuses of @p step.previous
     * if any node is closed there (a warm start), else from phase 1.
     * @p what names the solver in messages.
     */
    ContactState
    solve(FlexibilityOperator       &W,
          const LoadStep            &step,
          const std::vector<double> &mu,
          const std::string         &what) const;

    /**
     * For the statuses of @p state, the change of the forces (and of the
     * free motions' amplitudes, with @p rigid) that removes the constraint
     * violations @p violation (per row: g_n of closed nodes, g_t -
     * g_t,previous of sticking nodes; other rows are ignored) and the
     * equilibrium defect @p imbalance (G^T p + lambda e, with @p rigid),
     * i.e. the solution of the same linear system as in an iteration with
     * the right-hand side -violation. Used to refine a solution whose gaps
     * were recomputed more accurately than W is known.
     */
    ContactState
    correction(FlexibilityOperator       &W,
               const ContactState        &state,
               const std::vector<double> &mu,
               const Vector<double>      &violation,
               const RigidMotions        *rigid     = nullptr,
               const Vector<double>      &imbalance = Vector<double>()) const;

    const ActiveSetParameters &
    parameters() const;

  private:
    ActiveSetParameters parameters_;
  };
} // namespace FuzzyContact

#endif
