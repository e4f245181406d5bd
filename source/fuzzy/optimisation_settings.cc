// The settings of the optimisation method (optimisation_method.h) in a
// parameter file: subsection Optimisation.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>

namespace FuzzyContact
{
  void
  OptimisationSettings::declare_parameters(ParameterHandler &prm)
  {
    using Patterns::Tools::to_string;
    const OptimisationSettings defaults;
    prm.enter_subsection("Optimisation");
    prm.declare_entry("algorithm",
                      defaults.algorithm,
                      Patterns::Selection("spectral gradient|quasi-newton"),
                      "ROL's bound-constrained algorithm: projected spectral "
                      "gradient (Barzilai-Borwein steps) or a projected "
                      "quasi-Newton (L-BFGS) line search.");
    prm.declare_entry("gradient tolerance",
                      to_string(defaults.gradient_tolerance),
                      Patterns::Double(),
                      "ROL's tolerance on the projected gradient of the "
                      "scaled objective S / |S(nominal)|.");
    prm.declare_entry("step tolerance",
                      to_string(defaults.step_tolerance),
                      Patterns::Double(),
                      "ROL's tolerance on the step in normalised parameters.");
    prm.declare_entry("iteration limit",
                      to_string(defaults.max_iterations),
                      Patterns::Integer(),
                      "ROL iterations per output, bound and alpha level.");
    prm.declare_entry("finite difference step",
                      to_string(defaults.finite_difference_step),
                      Patterns::Double(),
                      "Step of the finite-difference sensitivities, relative "
                      "to the width of each parameter's support.");
    prm.declare_entry("interior tolerance",
                      to_string(defaults.interior_tolerance),
                      Patterns::Double(),
                      "An optimum further than this (relative to the "
                      "alpha-cut width) from both ends of a parameter's "
                      "interval counts as interior.");
    prm.declare_entry("response tolerance",
                      to_string(defaults.response_tolerance),
                      Patterns::Double(),
                      "Relative accuracy of the model's outputs (the FL2C "
                      "tolerance makes them accurate to about that much): "
                      "smaller differences are no evidence of a non-monotone "
                      "response. Keep the finite difference step well above "
                      "it.");
    prm.declare_entry("multi-start fallback",
                      to_string(defaults.fallback),
                      Patterns::Bool(),
                      "On a detected non-monotone response, restart the "
                      "local optimisation from every vertex and the centre.");
    prm.declare_entry("global points",
                      to_string(defaults.global_points),
                      Patterns::Integer(0, 100000),
                      "Points of the space-filling design (a Latin hypercube, "
                      "fixed seed) evaluated over every alpha-box before the "
                      "local optimisation starts from the best points.");
    prm.declare_entry("local starts",
                      to_string(defaults.local_starts),
                      Patterns::Integer(1, 100),
                      "Local optimisations per bound and level when the best "
                      "point of the global stage lies inside the box (one "
                      "from the best point when it is a vertex).");
    prm.declare_entry("refinement step",
                      to_string(defaults.refinement_step),
                      Patterns::Double(),
                      "The pattern search that refines bounds with interior "
                      "coordinates (kinks) stops when its step falls below "
                      "this fraction of the interval widths.");
    prm.leave_subsection();
  }


  void
  OptimisationSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Optimisation");
    algorithm          = prm.get("algorithm");
    gradient_tolerance = Input::positive(prm.get_double("gradient tolerance"),
                                         "Optimisation: gradient tolerance");
    step_tolerance     = Input::positive(prm.get_double("step tolerance"),
                                     "Optimisation: step tolerance");
    const long iterations = prm.get_integer("iteration limit");
    AssertThrow(iterations >= 1,
                ExcMessage("Optimisation: iteration limit must be at least "
                           "1."));
    max_iterations = iterations;
    finite_difference_step =
      Input::positive(prm.get_double("finite difference step"),
                      "Optimisation: finite difference "
                      "step");
    AssertThrow(finite_difference_step < 0.1,
                ExcMessage("Optimisation: finite difference step must be "
                           "below 0.1 (it is relative to the support width)."));
    interior_tolerance = Input::positive(prm.get_double("interior tolerance"),
                                         "Optimisation: interior tolerance");
    response_tolerance = Input::positive(prm.get_double("response tolerance"),
                                         "Optimisation: response tolerance");
    AssertThrow(finite_difference_step > 10 * response_tolerance,
                ExcMessage("Optimisation: the finite difference step must be "
                           "well above the response tolerance (10 times at "
                           "least), or the sensitivities are noise."));
    fallback        = prm.get_bool("multi-start fallback");
    global_points   = prm.get_integer("global points");
    local_starts    = prm.get_integer("local starts");
    refinement_step = Input::positive(prm.get_double("refinement step"),
                                      "Optimisation: refinement step");
    AssertThrow(refinement_step < 0.1,
                ExcMessage("Optimisation: refinement step must be below 0.1 "
                           "(it is relative to the interval widths)."));
    prm.leave_subsection();
  }
} // namespace FuzzyContact
