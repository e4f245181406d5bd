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
  FuzzyContactModel::has_static_equilibrium(const std::vector<double> &values)
  {
    if (!can_lose_equilibrium())
      return true;
    bool feasible = true;
    at_point(values, "the equilibrium check", [&]() {
      reduced_model->set_state(state(values));
      feasible = FuzzyContact::has_static_equilibrium(reduced_model->problem());
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
      reduced_communicator());
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
  FuzzyContactModel::failure_counts_as_without_equilibrium()
  {
    if (!can_lose_equilibrium())
      return false;
    // At the limit the static answer is degenerate (a body about to slide
    // may slip any amount); near it, the point is left out with a warning.
    if (at_limit_of_equilibrium())
      ++n_limit_points;
    else if (at_limit_of_equilibrium(near_limit_margin))
      ++n_unsolved;
    else
      return false;
    return true;
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
      catch (const ExceptionBase &)
        {
          // At or near the limit of equilibrium a solver that fails
          // counts the point as without equilibrium
          // (n_unsolved_near_limit()).
          if (!failure_counts_as_without_equilibrium())
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
      catch (const ExceptionBase &)
        {
          // (As in reduced(), where the reduced problem is at hand.)
          if (!can_lose_equilibrium() || reduced_ranks == MPI_COMM_NULL)
            throw;
          reduced_model->set_state(state(values));
          if (!failure_counts_as_without_equilibrium())
            throw;
          return std::vector<double>();
        }
    });
  }


  unsigned long
  FuzzyContactModel::n_at_limit_of_equilibrium() const
  {
    return n_limit_points;
  }


  unsigned long
  FuzzyContactModel::n_unsolved_near_limit() const
  {
    return n_unsolved;
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
        std::ostringstream point;
        for (unsigned int i = 0; i < values.size(); ++i)
          point << (i > 0 ? ", " : "") << fuzzy.parameters()[i].quantity.name
                << " = " << values[i];
        std::string message = "At the parameter point " + point.str() + ", " +
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
