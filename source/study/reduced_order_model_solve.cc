// ReducedOrderModel (study/reduced_order_model.h): the rank that builds
// each component, and the solves of the reduced contact problem.

#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <chrono>

namespace FuzzyContact
{
  std::vector<unsigned int>
  ReducedOrderModel::builders(const unsigned int                  n_components,
                              const std::vector<VaryingQuantity> &varying,
                              const MPI_Comm                      comm)
  {
    // (MPI_COMM_SELF, or a program that did not initialise MPI)
    const unsigned int n_ranks = Utilities::MPI::job_supports_mpi()
                                   ? Utilities::MPI::n_mpi_processes(comm)
                                   : 1;
    std::vector<bool>  reanalysed(n_components, false);
    for (const VaryingQuantity &v : varying)
      if (v.quantity.reshapes_stiffness())
        reanalysed[v.quantity.component] = true;
    const bool any =
      std::find(reanalysed.begin(), reanalysed.end(), true) != reanalysed.end();
    std::vector<unsigned int> owner(n_components, 0);
    unsigned int              next = 0;
    for (unsigned int c = 0; c < n_components && n_ranks > 1; ++c)
      if (!any)
        owner[c] = c % n_ranks;
      else if (!reanalysed[c])
        owner[c] = 1 + next++ % (n_ranks - 1);
    return owner;
  }


  std::string
  ReducedOrderModel::name() const
  {
    return "reduced (" + solver->name() + ")";
  }


  ContactSolution
  ReducedOrderModel::solve()
  {
    return solve(*solver, label);
  }


  ContactSolution
  ReducedOrderModel::solve(const ContactSolver &contact_solver,
                           const std::string   &what)
  {
    const std::string name = what.empty() ? contact_solver.name() : what;
    // (std::chrono, not deal.II's Timer: making a Timer costs as much as
    // a tenth of a small scene's solve.)
    const auto         start = std::chrono::steady_clock::now();
    const ContactState state = contact_solver.solve(reduced->problem(),
                                                    1.,
                                                    n_load_steps,
                                                    name,
                                                    &workspace_);
    ContactSolution    s     = reduced->solution(state, 1., name);
    s.n_load_steps           = n_load_steps;
    if (!reduced->problem().stages.empty())
      {
        s.n_load_steps = 0;
        for (const GapLoadStage &stage : reduced->problem().stages)
          s.n_load_steps += stage.n_steps;
      }
    s.time =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
        .count();
    check_small_sliding(bodies.interface(), s, bodies.sliding_limit(), name);
    return s;
  }


  ContactWorkspace &
  ReducedOrderModel::workspace()
  {
    return workspace_;
  }


  void
  ReducedOrderModel::set_contact_solver(std::unique_ptr<ContactSolver> s,
                                        const std::string             &what)
  {
    AssertThrow(s != nullptr, ExcMessage("ReducedOrderModel: no solver."));
    solver = std::move(s);
    label  = what;
  }


  void
  ReducedOrderModel::set_n_load_steps(const unsigned int n)
  {
    AssertThrow(n >= 1, ExcMessage("load steps must be at least 1."));
    n_load_steps = n;
  }


  const ContactProblem &
  ReducedOrderModel::problem() const
  {
    return reduced->problem();
  }
} // namespace FuzzyContact
