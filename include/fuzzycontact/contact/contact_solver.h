// The interface of the solvers of a (small, dense) contact problem
// (contact_problem.h): given the contact flexibility W, the free gaps and
// the friction coefficients, find the contact forces that satisfy
// Signorini's and Coulomb's conditions, load step by load step.
//
// Two methods implement it, one file each:
//  - ActiveSetSolver (active_set_solver.h): the exact solver, a primal-dual
//    active set (semismooth Newton) method;
//  - FL2CSolver (fl2c.h): the fuzzy regulators of the 2013 paper.
// create_contact_solver() makes one by its name in a parameter file.
//
// To add a contact solver: derive from ContactSolver, implement name() and
// solve_step() (one load step from the previous step's state; the load
// stepping is done here), declare its parameters, and add its name to
// create_contact_solver() and contact_solver_names().

#ifndef fuzzycontact_contact_contact_solver_h
#define fuzzycontact_contact_contact_solver_h

#include <fuzzycontact/contact/contact_problem.h>

#include <memory>
#include <string>

namespace FuzzyContact
{
  struct ActiveSetParameters;
  struct FL2CParameters;

  class ContactSolver
  {
  public:
    virtual ~ContactSolver() = default;

    /** The name of the method in parameter files and reports. */
    virtual std::string
    name() const = 0;

    /**
     * One load step of @p problem (see LoadStep), from the state the
     * previous step converged to. @p what names the solve in messages.
     */
    virtual ContactState
    solve_step(const ContactProblem &problem,
               const LoadStep       &step,
               const std::string    &what) const = 0;

    /**
     * All @p n_load_steps proportional load steps up to @p load_factor, or,
     * if @p problem has load stages, the steps of its stages (each with its
     * own number of steps; @p n_load_steps is then not used); see
     * solve_in_load_steps(). With a @p workspace, the steps start where it
     * says and leave their states in it (contact_workspace.h).
     */
    ContactState
    solve(const ContactProblem &problem,
          const double          load_factor,
          const unsigned int    n_load_steps,
          const std::string    &what,
          ContactWorkspace     *workspace = nullptr) const;
  };

  /** The names create_contact_solver() knows, as "fl2c|reduced exact". */
  std::string
  contact_solver_names();

  /**
   * The solver called @p name: "fl2c" (FL2CSolver with @p fl2c) or
   * "reduced exact" (ActiveSetSolver with @p exact). Throws a message
   * listing the names otherwise.
   */
  std::unique_ptr<ContactSolver>
  create_contact_solver(const std::string         &name,
                        const ActiveSetParameters &exact,
                        const FL2CParameters      &fl2c);
} // namespace FuzzyContact

#endif
