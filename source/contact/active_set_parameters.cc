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
    prm.declare_entry("max path failures",
                      "4",
                      Patterns::Integer(),
                      "Failed solves on that path (each is retried closer "
                      "to the last that converged) before the step gives "
                      "up: where the path leads to an answer it fails a "
                      "few times at most; where it does not, every retry "
                      "fails.");
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
    // An integer key of this subsection between @p low and 10000.
    const auto count = [&prm](const std::string &key, const long low) {
      const long value = prm.get_integer(key);
      AssertThrow(value >= low && value <= 10000,
                  ExcMessage("Exact contact solver: " + key +
                             " must lie between " + std::to_string(low) +
                             " and 10000, got " + std::to_string(value) + "."));
      return static_cast<unsigned int>(value);
    };
    max_path_solves   = count("max path solves", 1);
    max_path_failures = count("max path failures", 0);
    prm.leave_subsection();
  }
} // namespace FuzzyContact
