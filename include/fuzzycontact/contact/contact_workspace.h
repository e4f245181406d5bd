// What a contact solver carries from one solve to the next.
//
// The points of a fuzzy study are close to each other (an optimisation
// steps, differentiates by finite differences, polls around a point), and
// so are their contact states: the statuses of the slave nodes at each
// load step hardly change from one point to its neighbour. A solve given a
// ContactWorkspace
//  - starts each load step from the statuses in start (the converged
//    states of the same load step at a neighbouring point, set by whoever
//    knows the neighbours: study/fuzzy_contact_model.h), where there are
//    any, and from the previous load step's otherwise;
//  - keeps, per load step, the factors of its linear systems
//    (status_solver.h) from iteration to iteration and from solve to
//    solve: the next solve's same load step, with nearly the same statuses
//    and W, updates them or uses them to precondition;
//  - leaves the converged state of every load step in converged, for the
//    next solve's start.
// The answer does not depend on the start (every solver stops at the same
// complementarity residual); only the work does.

#ifndef fuzzycontact_contact_contact_workspace_h
#define fuzzycontact_contact_contact_workspace_h

#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/contact/status_solver.h>

#include <memory>
#include <vector>

namespace FuzzyContact
{
  class ContactWorkspace
  {
  public:
    /** The start of each load step (empty: no warm start). */
    std::vector<ContactState> start;
    /** The converged state of each load step of the last solve. */
    std::vector<ContactState> converged;
    /** The linear solves of load step @p step (1, 2, ...). */
    StatusSolver &
    linear(const unsigned int step)
    {
      if (solvers.size() < step)
        {
          solvers.resize(step);
          for (StatusSolver &s : solvers)
            s.set_siblings(&solvers);
        }
      return solvers[step - 1];
    }
    /** What the linear solves of all load steps did so far. */
    StatusSolver::Counts
    counts() const
    {
      StatusSolver::Counts sum;
      for (const StatusSolver &s : solvers)
        sum += s.counts();
      return sum;
    }
    /**
     * FL2C's coarse correction (fl2c.h) carries its own exact problem from
     * correction to correction and from solve to solve: the slave nodes it
     * is posed on (every node that any working set held, of any load step,
     * in the order they came, so that a node keeps its place and the
     * factors of W restricted to them stay factors of the next, larger
     * restriction) and that problem's workspace.
     */
    struct Coarse
    {
      std::vector<unsigned int> nodes;
      /** Per slave node, its place in nodes (-1: none). */
      std::vector<int>                  place;
      std::unique_ptr<ContactWorkspace> workspace;
    };

    /** The coarse correction's problem, for a problem of @p n_nodes slave
     * nodes (made anew for another number). */
    Coarse &
    coarse(const unsigned int n_nodes)
    {
      if (!coarse_ || coarse_->place.size() != n_nodes)
        {
          coarse_ = std::make_unique<Coarse>();
          coarse_->place.assign(n_nodes, -1);
          coarse_->workspace = std::make_unique<ContactWorkspace>();
        }
      return *coarse_;
    }

    /** Forgets every factor. */
    void
    clear()
    {
      solvers.clear();
      coarse_.reset();
    }

  private:
    std::vector<StatusSolver> solvers;
    std::unique_ptr<Coarse>   coarse_;
  };
} // namespace FuzzyContact

#endif
