// FuzzyContactModel's evaluations (fuzzy_contact_model.h): the reduced and
// the exact model at a point, each reduced solve started from the nearest
// evaluated point's contact states, and the points without a static
// equilibrium (a result of the point, not an error) and where in every box
// they lie.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/static_equilibrium.h>
#include <fuzzycontact/fuzzy/global_stage.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace FuzzyContact
{
  bool
  FuzzyContactModel::can_lose_equilibrium() const
  {
    return !bodies_held_by_contact().empty();
  }


  std::string
  FuzzyContactModel::bodies_held_by_contact() const
  {
    return held_by_contact;
  }


  bool
  FuzzyContactModel::has_static_equilibrium(const std::vector<double> &values,
                                            const bool within_small_sliding)
  {
    if (!can_lose_equilibrium())
      return true;
    bool feasible = true;
    at_point(values, "the equilibrium check", [&]() {
      reduced_model->set_state(state(values));
      feasible = FuzzyContact::has_static_equilibrium(reduced_model->problem());
      if (feasible && within_small_sliding)
        try
          {
            // The contact solve (its state then starts the neighbours'),
            // for the slip it leads to.
            reduced_from_neighbour(values, [&]() {
              return reduced_model->solve();
            });
          }
        catch (const ExcBeyondSmallSliding &)
          {
            feasible = false;
          }
        catch (const ExceptionBase &)
          {
            // A solve that fails at or near the limit is the evaluations'
            // to count or report; farther from it, the probes with more
            // friction decide as for an evaluation: an answer beyond small
            // sliding, or one within it where the point's own failed (the
            // evaluations leave such a point out), makes it infeasible.
            if (!at_limit_of_equilibrium(near_limit_margin))
              feasible =
                sliding_with_more_friction(values).kind == SlidingVerdict::none;
          }
      return std::vector<double>();
    });
    return feasible;
  }


  FeasibleRegion
  FuzzyContactModel::equilibrium_region(const std::vector<FuzzyNumber> &numbers,
                                        const std::vector<double>      &alpha)
  {
    const unsigned int n_free = [&]() {
      unsigned int n = 0;
      for (const FuzzyNumber &f : numbers)
        n += f.alpha_cut(0).width() > 0;
      return n;
    }();
    return feasible_region_on_ranks(
      numbers,
      alpha,
      [&](const std::vector<double> &p) {
        return has_static_equilibrium(p);
      },
      LocalOptimisation::default_design_points(n_free),
      comm,
      reduced_communicator(),
      [&](const std::vector<double> &p) {
        return has_static_equilibrium(p, false);
      });
  }


  std::vector<double>
  FuzzyContactModel::reduced(const std::vector<double> &values)
  {
    return reduced(values, nullptr);
  }


  std::vector<double>
  FuzzyContactModel::reduced(const std::vector<double> &values,
                             const ContactSolver       &solver)
  {
    return reduced(values, &solver);
  }


  bool
  FuzzyContactModel::at_limit_of_equilibrium(const double margin)
  {
    // The reduced problem of the current state with every friction
    // coefficient lowered by the margin.
    ContactProblem problem = reduced_model->problem();
    for (double &mu : problem.mu)
      mu *= 1 - margin;
    return !FuzzyContact::has_static_equilibrium(problem);
  }


  bool
  FuzzyContactModel::failure_counts_as_without_equilibrium(
    const std::vector<double> &values)
  {
    if (!can_lose_equilibrium())
      return false;
    // At the limit the static answer is degenerate (a body about to slide
    // may slip any amount); near it, the point is left out with a warning.
    if (at_limit_of_equilibrium())
      ++unanswered_.at_limit;
    else if (at_limit_of_equilibrium(near_limit_margin))
      ++unanswered_.unsolved_near_limit;
    else
      {
        const SlidingVerdict verdict = sliding_with_more_friction(values);
        if (verdict.kind == SlidingVerdict::beyond)
          ++unanswered_.beyond_small_sliding;
        else if (verdict.kind == SlidingVerdict::within_with_more)
          {
            ++unanswered_.unsolved_below_sliding_limit;
            unanswered_.sliding_factor =
              std::max(unanswered_.sliding_factor, verdict.factor);
          }
        else
          return false;
      }
    return true;
  }


  SlidingVerdict
  FuzzyContactModel::sliding_with_more_friction(
    const std::vector<double> &values)
  {
    // The probes (sliding_probes.h) by the quick probe solver; if none
    // answers (the failure would be an error), again with the last
    // resorts (one solve on the path of friction coefficients).
    const SceneState at = state(values);
    const auto answer = [&](const ContactSolver &solver, const double factor) {
      SceneState more = at;
      for (double &mu : more.friction_coefficients)
        mu *= factor;
      reduced_model->set_state(more);
      try
        {
          reduced_model->solve(solver);
          return 1;
        }
      catch (const ExcBeyondSmallSliding &)
        {
          return -1;
        }
      catch (const ExceptionBase &)
        {
          return 0;
        }
    };
    static const std::vector<double> factors =
      sliding_probe_factors(sliding_probes, max_sliding_probe);
    const auto probe = [&](const ContactSolver &solver) {
      const SlidingVerdict verdict =
        probe_sliding(factors, [&](const double factor) {
          return answer(solver, factor);
        });
      unanswered_.probes += verdict.probes;
      unanswered_.failed_probes += verdict.failed;
      return verdict;
    };
    SlidingVerdict verdict = probe(*probe_solvers[0]);
    if (verdict.kind == SlidingVerdict::none)
      verdict = probe(*probe_solvers[1]);
    reduced_model->set_state(at);
    return verdict;
  }


  std::vector<double>
  FuzzyContactModel::reduced(const std::vector<double> &values,
                             const ContactSolver       *solver)
  {
    const std::string name = solver != nullptr       ? solver->name()
                             : solver_name == "fl2c" ? std::string("FL2C")
                                                     : solver_name;
    return at_point(values, "the reduced model (" + name + ")", [&]() {
      reduced_model->set_state(state(values));
      // No static equilibrium: no outputs (a result of this point).
      if (can_lose_equilibrium() &&
          !FuzzyContact::has_static_equilibrium(reduced_model->problem()))
        return std::vector<double>();
      try
        {
          return reduced_from_neighbour(values, [&]() {
            return solver != nullptr ? reduced_model->solve(*solver)
                                     : reduced_model->solve();
          });
        }
      catch (const ExcBeyondSmallSliding &)
        {
          // The bodies slide: no static equilibrium within small sliding
          // (an error where every body is supported).
          if (!can_lose_equilibrium())
            throw;
          ++unanswered_.beyond_small_sliding;
          return std::vector<double>();
        }
      catch (const ExceptionBase &)
        {
          // At or near the limit of equilibrium a solver that fails
          // counts the point as without equilibrium
          // (UnansweredEvaluations).
          if (!failure_counts_as_without_equilibrium(values))
            throw;
          return std::vector<double>();
        }
    });
  }


  std::vector<double>
  FuzzyContactModel::reduced_from_neighbour(
    const std::vector<double>              &values,
    const std::function<ContactSolution()> &solve)
  {
    ContactWorkspace                &workspace = reduced_model->workspace();
    const std::vector<ContactState> *neighbour = warm_starts.nearest(values);
    if (neighbour != nullptr)
      workspace.start = *neighbour;
    else
      workspace.start.clear();
    const ContactSolution solution = solve();
    warm_starts.add(values, workspace.converged);
    return outputs->values(solution);
  }


  std::vector<double>
  FuzzyContactModel::full_order(const std::vector<double> &values)
  {
    return at_point(values, "the exact full-order reference", [&]() {
      full_model->set_state(state(values));
      try
        {
          return outputs->values(full_model->solve());
        }
      catch (const ExcNoStaticEquilibrium &)
        {
          // A result of this point: the exact solver found no contact
          // forces in the friction cones that balance the load.
          return std::vector<double>();
        }
      catch (const ExcBeyondSmallSliding &)
        {
          // (As in reduced().)
          if (!can_lose_equilibrium())
            throw;
          ++unanswered_.beyond_small_sliding;
          return std::vector<double>();
        }
      catch (const ExceptionBase &)
        {
          // (As in reduced(), where the reduced problem is at hand.)
          if (!can_lose_equilibrium() || reduced_ranks == MPI_COMM_NULL)
            throw;
          reduced_model->set_state(state(values));
          if (!failure_counts_as_without_equilibrium(values))
            throw;
          return std::vector<double>();
        }
    });
  }


  const FuzzyContactModel::UnansweredEvaluations &
  FuzzyContactModel::unanswered() const
  {
    return unanswered_;
  }


  FuzzyContactModel::UnansweredEvaluations
  FuzzyContactModel::UnansweredEvaluations::summed_over(
    const MPI_Comm comm) const
  {
    // (One reduction for the six counts.)
    const std::vector<unsigned long> counts = {at_limit,
                                               unsolved_near_limit,
                                               beyond_small_sliding,
                                               unsolved_below_sliding_limit,
                                               probes,
                                               failed_probes};
    std::vector<unsigned long>       sums(counts.size());
    Utilities::MPI::sum(counts, comm, sums);
    UnansweredEvaluations sum;
    sum.at_limit                     = sums[0];
    sum.unsolved_near_limit          = sums[1];
    sum.beyond_small_sliding         = sums[2];
    sum.unsolved_below_sliding_limit = sums[3];
    sum.probes                       = sums[4];
    sum.failed_probes                = sums[5];
    sum.sliding_factor = Utilities::MPI::max(sliding_factor, comm);
    return sum;
  }


  std::vector<double>
  FuzzyContactModel::at_point(
    const std::vector<double>                  &values,
    const std::string                          &model,
    const std::function<std::vector<double>()> &evaluate) const
  {
    try
      {
        return evaluate();
      }
    catch (const ExceptionBase &e)
      {
        // Which point of the study failed, and which keys control the
        // solver that failed.
        std::string message = "At the parameter point " +
                              point_text(fuzzy.parameters(), values) + ", " +
                              model + ": " + Input::message_of(e);
        if (model.find("FL2C") != std::string::npos)
          message += " FL2C is set by the keys of subsection FL2C "
                     "(tolerance, max iterations, calibration, gap/force/"
                     "slip/friction points); a friction coefficient, "
                     "modulus or load at the edge of its fuzzy support can "
                     "also prevent its convergence.";
        AssertThrow(false, ExcMessage(message));
      }
    return {};
  }
} // namespace FuzzyContact
