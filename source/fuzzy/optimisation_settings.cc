// The settings of the optimisation method (optimisation_method.h) in a
// parameter file: subsection Optimisation.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/patterns.h>
#include <deal.II/base/utilities.h>

#include <string>

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
                      defaults.global_points_auto
                        ? std::string("auto")
                        : to_string(defaults.global_points),
                      Patterns::Anything(),
                      "Points of the space-filling design (a scrambled Sobol "
                      "sequence, fixed seed) evaluated over every alpha-box "
                      "before the local searches start from the best points "
                      "of its distinct basins: 'auto' (32 per fuzzy "
                      "parameter, rounded up to a power of two) or a number "
                      "from 0 (vertices and the level above's optima only) "
                      "to 65536.");
    prm.declare_entry("global time limit",
                      to_string(defaults.global_time_limit),
                      Patterns::Double(0, 1e6),
                      "Seconds the design may take over all alpha levels (0: "
                      "no limit); a longer one is cut to the largest power of "
                      "two of points per box that fits, timed on the "
                      "vertices' evaluations (the report says so).");
    prm.declare_entry("local starts",
                      to_string(defaults.local_starts),
                      Patterns::Integer(1, 100),
                      "Local searches per bound and level at most: from the "
                      "best point of the global stage and the best points of "
                      "other basins of the design.");
    prm.declare_entry("refinement step",
                      to_string(defaults.refinement_step),
                      Patterns::Double(),
                      "The pattern search that refines bounds with interior "
                      "coordinates (kinks) stops when its step falls below "
                      "this fraction of the interval widths.");
    prm.declare_entry("line scan points",
                      to_string(defaults.line_scan_points),
                      Patterns::Integer(0, 4097),
                      "Values of a parameter on each line scanned through a "
                      "bound, ends included (0 or 1: no scans): along the "
                      "parameters in which the search has met a kink or an "
                      "interior optimum, a better point of the line moves "
                      "the bound and it is refined again.");
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
    fallback                 = prm.get_bool("multi-start fallback");
    const std::string points = Utilities::trim(prm.get("global points"));
    global_points_auto       = points == "auto";
    if (!global_points_auto)
      {
        std::size_t end   = 0;
        long        value = -1;
        try
          {
            value = std::stol(points, &end);
          }
        catch (const std::exception &)
          {
            end = 0;
          }
        AssertThrow(end > 0 && end == points.size() && value >= 0 &&
                      value <= 65536,
                    ExcMessage("Optimisation: global points must be auto or "
                               "an integer from 0 to 65536, got <" +
                               points + ">."));
        global_points = value;
      }
    global_time_limit = prm.get_double("global time limit");
    local_starts      = prm.get_integer("local starts");
    line_scan_points  = prm.get_integer("line scan points");
    refinement_step   = Input::positive(prm.get_double("refinement step"),
                                      "Optimisation: refinement step");
    AssertThrow(refinement_step < 0.1,
                ExcMessage("Optimisation: refinement step must be below 0.1 "
                           "(it is relative to the interval widths)."));
    prm.leave_subsection();
  }
} // namespace FuzzyContact
