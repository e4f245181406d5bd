#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/contact_workspace.h>
#include <fuzzycontact/contact/static_equilibrium.h>
#include <fuzzycontact/contact/status_system.h>

#include <deal.II/base/exceptions.h>

#include "active_set_method.h"
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace FuzzyContact
{
  ActiveSetSolver::ActiveSetSolver(const ActiveSetParameters &parameters)
      : parameters_(parameters)
  {
  }

  const ActiveSetParameters &
  ActiveSetSolver::parameters() const
  {
    return parameters_;
  }


  ContactState
  ActiveSetSolver::solve(FlexibilityOperator       &W,
                         const LoadStep            &step,
                         const std::vector<double> &mu,
                         const std::string         &what) const
  {
    AssertDimension(W.size(), 2 * mu.size());
    AssertDimension(step.g_free.size(), 2 * mu.size());
    // A load no contact forces can balance (ExcNoStaticEquilibrium), or a
    // body whose position the contact does not determine
    // (ExcPositionNotDetermined), has no solution from any start: its
    // message is final.
    const bool held_with_friction =
      step.n_motions() > 0 && *std::max_element(mu.begin(), mu.end()) > 0;
    // The attempts, each under the same iteration limit, until one
    // converges:
    //  - from the warm start (another point's statuses,
    //    ContactWorkspace::start), if there is one;
    //  - from the previous load step's state, as without a workspace: a
    //    warm start can lead the iterations where the load path does not
    //    (a slip zone that spreads over the interface a few nodes per
    //    iteration, or a cycle);
    //  - with bodies held by contact alone and friction (and the last
    //    resorts allowed, ActiveSetParameters), from that state
    //    with slips allowed to reverse at once: near the limit of
    //    equilibrium (a body that almost slides, every node but a few
    //    slipping) a slip that reverses is a small change of the free
    //    motions, and a whole interface that sticks before it reverses
    //    (the rule that calms a rocking roller, ActiveSetMethod) starts the
    //    iterations over and over.
    LoadStep cold = step;
    cold.start    = nullptr;
    struct Attempt
    {
      const LoadStep *step;
      bool            stick_before_reversal;
    };
    std::vector<Attempt> attempts;
    if (step.start != nullptr)
      attempts.push_back({&step, true});
    attempts.push_back({&cold, true});
    if (held_with_friction && parameters_.last_resorts)
      attempts.push_back({&cold, false});
    // What the load path's attempt said, for the final message.
    std::string message;
    for (const Attempt &attempt : attempts)
      try
        {
          return ActiveSetMethod(W,
                                 *attempt.step,
                                 mu,
                                 parameters_,
                                 what,
                                 attempt.stick_before_reversal)
            .solve();
        }
      catch (const ExcNoStaticEquilibrium &)
        {
          throw;
        }
      catch (const ExcPositionNotDetermined &)
        {
          throw;
        }
      catch (const ExceptionBase &e)
        {
          // (Without a ramp to follow, the last attempt's message is the
          // answer.)
          if (!(held_with_friction && parameters_.last_resorts) &&
              &attempt == &attempts.back())
            throw;
          if (attempt.step == &cold && attempt.stick_before_reversal)
            message = Input::message_of(e);
        }

    // A body held by contact alone turns in answer to the friction forces
    // of all slipping nodes at once, which can keep the primal-dual
    // iterations from settling. The same step is solved again along a path
    // of friction coefficients s mu, each solve started from the previous
    // one's statuses:
    //  - if the bodies need friction to be held (s >= s_min > 0,
    //    least_friction_factor()), from s = s_min + 1 down to s = 1, the
    //    distance s - s_min to the limit of sliding at most halved per
    //    solve (a solve that fails is tried again closer to the last
    //    converged one, the distance's ratio square-rooted; at most
    //    max_path_solves solves, of which at most max_path_failures
    //    fail): far from the limit the iterations settle, and each solve
    //    then starts from statuses near its own (near the limit nearly
    //    every node slips, and the few that stick decide the free
    //    motions). A path that would need more solves than allowed even
    //    if each converged (a point at the very limit: 1 - s_min = 1e-12
    //    takes 41) is not taken. Where the path does not lead to an
    //    answer, its retries fail one after the other, each costing a
    //    whole cycling solve (a pin that would turn in its bore, the
    //    linear problem solvable only beyond small sliding: 32 solves,
    //    16 to 28 of them failed; the paths that converged in studies of
    //    the shipped scenes failed at most 4 times: doc/contact.md);
    //  - otherwise up from 0 in 8 solves.
    const std::vector<double> frictionless(mu.size(), 0.);
    Vector<double>            p0;
    LoadStep                  ramped = cold;
    std::vector<double>       m(mu.size());
    ContactState              state;
    unsigned int              iterations = 0, solves = 0, failures = 0;
    // The path as said in the final message: its first factor and the
    // last that converged (0: none); or, if it was not taken, the solves
    // it would have needed.
    double       first = 0, reached = 0;
    unsigned int needed = 0;
    // Whether the path halves the distance to the limit (its failed
    // solves are retried); the ramp up from 0 ends at its first failure.
    bool       halving  = false;
    const auto solve_at = [&](const double s) {
      for (unsigned int k = 0; k < mu.size(); ++k)
        m[k] = s == 1 ? mu[k] : s * mu[k];
      if (solves++ == 0)
        first = s;
      state = ActiveSetMethod(W, ramped, m, parameters_, what).solve();
      iterations += state.iterations;
      ramped.previous = state;
      reached         = s;
    };
    try
      {
        if (held_with_friction && !admissible_forces(step, frictionless, p0))
          {
            const double s_min = least_friction_factor(step, mu, 0, 1, 1e-3);
            const double final_margin = std::max(1 - s_min, 1e-12);
            // The solves of a path on which every one converges: at the
            // distance 1, then one per halving down to final_margin.
            unsigned int at_least = 1;
            for (double d = 1; d > final_margin; d /= 2)
              ++at_least;
            if (at_least > parameters_.max_path_solves)
              {
                needed = at_least;
                AssertThrow(false, ExcMessage("the path is too long"));
              }
            halving       = true;
            double margin = 1, next = 1;
            while (true)
              {
                next = std::max(next, final_margin);
                AssertThrow(solves < parameters_.max_path_solves,
                            ExcMessage("the path's limit of solves"));
                try
                  {
                    solve_at(next == final_margin ? 1. : s_min + next);
                    margin = next;
                    if (margin == final_margin)
                      break;
                    next = margin / 2;
                  }
                catch (const ExceptionBase &)
                  {
                    if (++failures > parameters_.max_path_failures ||
                        margin == next)
                      throw;
                    next = std::sqrt(margin * next);
                  }
              }
          }
        else
          for (unsigned int i = 1; i <= 8; ++i)
            solve_at(i / 8.);
      }
    catch (const ExceptionBase &)
      {
        std::ostringstream said;
        said << message
             << " (Solved again from the previous load step's state, with "
                "slips allowed to reverse at once";
        if (needed > 0)
          said << "; not along a path of friction coefficients down to the "
                  "given ones: so near the limit of sliding it would take "
                  "at least "
               << needed << " solves, more than the "
               << parameters_.max_path_solves
               << " of key 'Exact contact solver/max path solves'.)";
        else
          {
            said << ", and along a path of friction coefficients from " << first
                 << " times the given ones to them, " << solves
                 << " solve(s) of at most " << parameters_.max_path_solves
                 << " (key 'Exact contact solver/max path solves'), ";
            if (halving)
              said << failures << " failed (at most "
                   << parameters_.max_path_failures
                   << " may: key 'Exact contact solver/max path failures'), ";
            said << "each from the statuses of the last converged one: ";
            if (reached > 0)
              said << "the last converged at " << reached << " times them.)";
            else
              said << "none converged.)";
          }
        AssertThrow(false, ExcMessage(said.str()));
      }
    state.iterations = iterations;
    return state;
  }


  ContactState
  ActiveSetSolver::correction(FlexibilityOperator       &W,
                              const ContactState        &state,
                              const std::vector<double> &mu,
                              const Vector<double>      &violation,
                              const RigidMotions        *rigid,
                              const Vector<double>      &imbalance) const
  {
    const StatusSystem system(W, state.status, state.slip_sign, mu, rigid);
    Vector<double>     b(system.rows.size());
    for (unsigned int r = 0; r < b.size(); ++r)
      b[r] = -violation[system.rows[r]];
    const Vector<double> x = system.solve(b, imbalance);
    ContactState         change;
    change.p     = system.forces(x, state.status, state.slip_sign, mu);
    change.rigid = system.amplitudes(x);
    return change;
  }


  std::string
  ActiveSetSolver::name() const
  {
    return "reduced exact";
  }


  ContactState
  ActiveSetSolver::solve_step(const ContactProblem &problem,
                              const LoadStep       &step,
                              const std::string    &what) const
  {
    if (problem.flexibility != nullptr)
      return solve(*problem.flexibility, step, problem.mu, what);
    DenseFlexibility W(problem.W);
    return solve(W, step, problem.mu, what);
  }
} // namespace FuzzyContact
