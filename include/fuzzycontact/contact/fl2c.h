// FL2C (Fuzzy Logic to Contact, Cazier et al. 2012, Massa et al. 2013):
// the contact forces are driven to Signorini's and Coulomb's conditions by
// two Mamdani regulators (fuzzy_regulator.h) instead of being solved for.
// Each iteration (a sweep) of a load step
//
//   1. reduced solve: the gaps of the current forces, g = g_free + W p;
//   2. regulators, node by node over the nodes that carry a force or
//      penetrate, most penetrating first:
//        normal:      p_n <- max(0, p_n + R_n(g_n)),
//        tangential:  p_t <- clamp(p_t + R_t(dg_t), -mu p_n, mu p_n),
//      with dg_t = g_t - g_t,previous the slip of the load step (no
//      tangential regulator when mu = 0). Each regulator sees the gaps left
//      by the force changes before it: the reduced solve is incremental, a
//      change dp_j moving all gaps by the column W e_j dp_j (a nonlinear
//      Gauss-Seidel sweep; regulating all nodes from the same gaps at once
//      overshoots as soon as several coupled nodes penetrate);
//   3. status check: open where p_n = 0, slip where |p_t| = mu p_n, stick
//      elsewhere;
//
// until the gaps satisfy the conditions within gap_tolerance = tolerance x
// the largest free penetration (|g_n| on closed nodes, -g_n on open ones,
// |dg_t| on sticking ones, the slip against the friction force on slipping
// ones) and the largest force change of the last sweep is below tolerance x
// the total normal force. A regulator that has not converged after
// max_iterations sweeps throws, with the sweeps and the residual reached.
//
// Transition points. From the parameter file (calibration = prm): the same
// absolute points for every node, as in the paper's Table 2 (gap [m] ->
// force [N]). Automatic calibration (the default) derives them from the
// reduced contact flexibility W:
//   - the shape is fixed: evenly spaced terms, a = g_ref (1, 2, 3) and
//     b = h (1, 2, 3), whose centroid curve is close to linear (R(x) = -x
//     at every half step from a1/2 to a3, within 5.3 % in between; slope
//     -1.5 h / g_ref at 0) and saturates at b3 beyond a3;
//   - the input scale g_ref is a third of the largest free penetration, so
//     that the first sweep works at the edge of the unsaturated range;
//   - the output scale of node k makes the secant gain of its normal
//     regulator at the saturation point, |R(a3) / a3|, equal to 1 / W_nn,k
//     (of its tangential one 1 / W_tt,k): for gaps up to a3 the regulator
//     then makes between 0.947 and 1.5 times the Newton step of its own
//     node (exactly 1 at the half steps, 1.5 near zero), and beyond a3 it
//     saturates. Each update is thus a Gauss-Seidel step relaxed by
//     0.947 <= omega <= 1.5 < 2, which lowers the energy of the
//     frictionless contact problem: the sweeps converge there (projected
//     SOR).
//   The paper's own points (gap 1, 5, 10 mm -> force 500, 5000, 15000 N)
//   have a small-signal gain (b2^2 - b1^2) / (2 a1 b1) = 2.5e7 N/m, eight
//   times the inverse flexibility of the overlap scene's tip (3e6 N/m):
//   there they oscillate and do not converge (see doc/contact.md).

#ifndef fuzzycontact_contact_fl2c_h
#define fuzzycontact_contact_fl2c_h

#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/contact/contact_solver.h>
#include <fuzzycontact/contact/fuzzy_regulator.h>

#include <deal.II/base/parameter_handler.h>

#include <array>
#include <string>

namespace FuzzyContact
{
  struct FL2CParameters
  {
    enum class Calibration
    {
      automatic,
      prm
    };
    Calibration calibration = Calibration::automatic;
    /** Normal regulator: gap [m] and force [N] transition points (prm). */
    std::array<double, 3> gap_points{{1e-3, 5e-3, 1e-2}};
    std::array<double, 3> force_points{{500, 5000, 15000}};
    /** Tangential regulator: slip [m] and force [N] points (prm). */
    std::array<double, 3> slip_points{{1e-3, 5e-3, 1e-2}};
    std::array<double, 3> friction_points{{500, 5000, 15000}};
    /** Relative gap and force-change tolerance. */
    double tolerance = 1e-4;
    /** Iterations per load step before FL2C gives up. */
    unsigned int max_iterations = 20000;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
    /** Throws unless the points are in order and positive. */
    void
    check() const;
  };

  class FL2CSolver : public ContactSolver
  {
  public:
    explicit FL2CSolver(const FL2CParameters &parameters = {});

    /** "fl2c". */
    std::string
    name() const override;

    /** One load step (see LoadStep), from the previous step's forces. */
    ContactState
    solve_step(const ContactProblem &problem,
               const LoadStep       &step,
               const std::string    &what) const override;

    /**
     * The largest secant gain sup_x |R(x) / x| of @p regulator, from the
     * slope at 0, (b2^2 - b1^2) / (2 a1 b1), and the exact centroid on a
     * fine logarithmic grid of inputs (to judge given transition points
     * against 2 / W_kk, the stability limit of a Gauss-Seidel step).
     */
    static double
    largest_secant_gain(const MamdaniRegulator &regulator);

    const FL2CParameters &
    parameters() const;

  private:
    FL2CParameters   parameters_;
    MamdaniRegulator shape;
    double           shape_gain;
  };
} // namespace FuzzyContact

#endif
