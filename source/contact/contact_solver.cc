#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/contact_solver.h>
#include <fuzzycontact/contact/fl2c.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

namespace FuzzyContact
{
  ContactState
  ContactSolver::solve(const ContactProblem &problem,
                       const double          load_factor,
                       const unsigned int    n_load_steps,
                       const std::string    &what,
                       ContactWorkspace     *workspace) const
  {
    problem.check();
    const auto step = [&](const LoadStep &load_step) {
      return solve_step(problem, load_step, what);
    };
    AssertThrow(n_load_steps >= 1,
                ExcMessage("The number of load steps must be at least 1."));
    const std::vector<GapLoadStage> one_stage = {
      GapLoadStage{problem.g_load, n_load_steps, problem.rigid_load}};
    return solve_in_load_steps(problem.g_initial,
                               problem.stages.empty() ? one_stage
                                                      : problem.stages,
                               load_factor,
                               step,
                               &problem.rigid,
                               workspace);
  }


  std::string
  contact_solver_names()
  {
    return "fl2c|reduced exact";
  }


  std::unique_ptr<ContactSolver>
  create_contact_solver(const std::string         &name,
                        const ActiveSetParameters &exact,
                        const FL2CParameters      &fl2c)
  {
    const std::string n = dealii::Utilities::trim(name);
    if (n == "fl2c")
      return std::make_unique<FL2CSolver>(fl2c);
    if (n == "reduced exact")
      return std::make_unique<ActiveSetSolver>(exact);
    AssertThrow(false,
                dealii::ExcMessage("contact solver: <" + n +
                                   "> is not a contact solver; use one of " +
                                   contact_solver_names() + "."));
    return nullptr;
  }
} // namespace FuzzyContact
