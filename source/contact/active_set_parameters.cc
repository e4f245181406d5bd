// The keys of subsection "Exact contact solver" (active_set_solver.h):
// declared, read and checked.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>

#include <deal.II/base/exceptions.h>

#include <string>

namespace FuzzyContact
{
  void
  ActiveSetParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact contact solver");
    prm.declare_entry("tolerance",
                      "1e-10",
                      Patterns::Double(),
                      "Relative complementarity residual at which the "
                      "primal-dual active set method stops.");
    prm.declare_entry("max iterations",
                      "200",
                      Patterns::Integer(),
                      "Active set iterations per load step before the "
                      "solver gives up with an error (its frictionless "
                      "start, which closes one node per iteration, may take "
                      "3 per slave node if that is more).");
    prm.declare_entry("max path solves",
                      "32",
                      Patterns::Integer(),
                      "Near the limit of sliding of bodies held by contact "
                      "alone, a step that does not settle is solved along "
                      "a path of friction coefficients down to the given "
                      "ones (each solve halves the distance to the limit, "
                      "a failed one is tried again closer to the last that "
                      "converged); at most this many solves.");
    prm.leave_subsection();
  }

  void
  ActiveSetParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Exact contact solver");
    tolerance    = Input::positive(prm.get_double("tolerance"),
                                "Exact contact solver: tolerance");
    const long n = prm.get_integer("max iterations");
    AssertThrow(n >= 1,
                ExcMessage("Exact contact solver: max iterations must be at "
                           "least 1, got " +
                           std::to_string(n) + "."));
    max_iterations    = n;
    const long solves = prm.get_integer("max path solves");
    AssertThrow(solves >= 1 && solves <= 10000,
                ExcMessage("Exact contact solver: max path solves must lie "
                           "between 1 and 10000, got " +
                           std::to_string(solves) + "."));
    max_path_solves = solves;
    prm.leave_subsection();
  }
} // namespace FuzzyContact
