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
    max_iterations = n;
    prm.leave_subsection();
  }
} // namespace FuzzyContact
