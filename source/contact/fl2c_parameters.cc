// The keys of subsection FL2C (fl2c.h): declared, read and checked.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/fl2c.h>

#include <deal.II/base/exceptions.h>

#include <string>

namespace FuzzyContact
{
  void
  FL2CParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("FL2C");
    prm.declare_entry("calibration",
                      "automatic",
                      Patterns::Selection("automatic|prm"),
                      "Transition points of the regulators: calibrated "
                      "from the reduced contact flexibility (automatic) or "
                      "the points below (prm), as in the paper's Table 2.");
    prm.declare_entry("gap points",
                      "1e-3, 5e-3, 1e-2",
                      Patterns::Anything(),
                      "Normal regulator input a1 < a2 < a3 [m] (prm).");
    prm.declare_entry("force points",
                      "500, 5000, 15000",
                      Patterns::Anything(),
                      "Normal regulator output b1 < b2 < b3 [N] (prm).");
    prm.declare_entry("slip points",
                      "1e-3, 5e-3, 1e-2",
                      Patterns::Anything(),
                      "Tangential regulator input a1 < a2 < a3 [m] (prm).");
    prm.declare_entry("friction points",
                      "500, 5000, 15000",
                      Patterns::Anything(),
                      "Tangential regulator output b1 < b2 < b3 [N] (prm).");
    prm.declare_entry("coarse correction",
                      "active set",
                      Patterns::Selection("active set|none"),
                      "After each sweep of the regulators: the exact "
                      "reduced solver on the nodes the regulators work on, "
                      "warm-started from their statuses (active set: "
                      "converges on distributed contact in a few sweeps), "
                      "or nothing (none: the paper's regulators alone).");
    prm.declare_entry("coarse correction warm iterations",
                      "2",
                      Patterns::Integer(),
                      "Iterations of the coarse correction's exact solver "
                      "from the regulators' statuses; if it has not "
                      "converged then, it starts again cold (from its own "
                      "frictionless start).");
    prm.declare_entry("coarse correction max iterations",
                      "200",
                      Patterns::Integer(),
                      "Iterations of the coarse correction's exact solver "
                      "started cold, before it gives up with an error.");
    prm.declare_entry("tolerance",
                      "1e-4",
                      Patterns::Double(),
                      "Relative complementarity residual (Signorini and "
                      "Coulomb conditions, as the exact solver measures "
                      "it) at which the sweeps stop.");
    prm.declare_entry("max iterations",
                      "20000",
                      Patterns::Integer(),
                      "Regulator iterations per load step before FL2C "
                      "gives up with an error.");
    prm.leave_subsection();
  }


  void
  FL2CParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("FL2C");
    calibration       = prm.get("calibration") == "prm" ? Calibration::prm
                                                        : Calibration::automatic;
    const auto points = [&](const std::string &key) {
      const std::vector<double> v =
        Input::to_doubles(prm.get(key), "FL2C: " + key, 3);
      return std::array<double, 3>{{v[0], v[1], v[2]}};
    };
    coarse_correction = prm.get("coarse correction") == "none"
                          ? CoarseCorrection::none
                          : CoarseCorrection::active_set;
    gap_points        = points("gap points");
    force_points      = points("force points");
    slip_points       = points("slip points");
    friction_points   = points("friction points");
    tolerance = Input::positive(prm.get_double("tolerance"), "FL2C: tolerance");
    const long n = prm.get_integer("max iterations");
    AssertThrow(n >= 1,
                ExcMessage("FL2C: max iterations must be at least 1, got " +
                           std::to_string(n) + "."));
    max_iterations          = n;
    const auto at_least_one = [&](const std::string &key) {
      const long i = prm.get_integer(key);
      AssertThrow(i >= 1,
                  ExcMessage("FL2C: " + key + " must be at least 1, got " +
                             std::to_string(i) + "."));
      return static_cast<unsigned int>(i);
    };
    coarse_warm_iterations = at_least_one("coarse correction warm iterations");
    coarse_max_iterations  = at_least_one("coarse correction max iterations");
    prm.leave_subsection();
    check();
  }


  void
  FL2CParameters::check() const
  {
    MamdaniRegulator(gap_points,
                     force_points,
                     "FL2C: gap points / force points");
    MamdaniRegulator(slip_points,
                     friction_points,
                     "FL2C: slip points / friction points");
    AssertThrow(tolerance > 0 && tolerance < 1,
                ExcMessage("FL2C: tolerance must lie in (0, 1)."));
  }

} // namespace FuzzyContact
