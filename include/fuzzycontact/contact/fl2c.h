// FL2C (Fuzzy Logic to Contact, Cazier et al. 2012, Massa et al. 2013):
// the contact forces are driven to Signorini's and Coulomb's conditions by
// two Mamdani regulators (fuzzy_regulator.h) instead of being solved for.
// Each iteration (a sweep) of a load step
//
//   1. regulators, node by node over the working set (the nodes that carry
//      a force or penetrate), most penetrating first:
//        normal:      p_n <- max(0, p_n + R_n(g_n)),
//        tangential:  p_t <- clamp(p_t + R_t(dg_t), -mu p_n, mu p_n),
//      with dg_t = g_t - g_t,previous the slip of the load step (no
//      tangential regulator when mu = 0). Each regulator sees the gaps left
//      by the force changes before it: the reduced solve is incremental, a
//      change dp_j moving the gaps by the column W e_j dp_j (a nonlinear
//      Gauss-Seidel sweep). Only the gaps of the working set are updated:
//      a sweep costs O(s^2) for s nodes in the working set, whatever the
//      number of contact rows m;
//   2. coarse correction (coarse correction = active set, the default): the
//      regulators' statuses (closed where p_n > 0, sticking where |p_t| <
//      mu p_n) are the warm start of the exact reduced solver
//      (ActiveSetSolver) on W restricted to the working set. When the
//      regulators found the right statuses this is one linear solve on the
//      closed and sticking rows (their Schur complement of W); otherwise
//      its primal-dual iterations fix them. Plain Gauss-Seidel sweeps crawl
//      where many closed nodes have nearly equal columns of W (`stacked`:
//      thousands of sweeps, growing with the mesh); the correction removes
//      that error at once, so that the number of sweeps does not grow with
//      the mesh. coarse correction = none keeps the paper's sweeps alone.
//      Given a ContactWorkspace (a study's reduced model), the correction
//      is posed on every node that a working set held (the workspace's
//      coarse nodes, which only grow: the open ones are solved as open),
//      so that its linear systems keep their factors from correction to
//      correction, load step to load step and point to point, as the
//      exact reduced solver's do; and where the step's start came from a
//      neighbouring point (or an earlier correction of the same step) the
//      correction starts from those exact statuses, with the exact
//      solver's full iteration limit, instead of the regulators' (which
//      leave a slipping node's friction a little inside the cone);
//   3. test: the complementarity residual (contact_problem.h) of the
//      working set; when it is at most the tolerance, the gaps of all m
//      rows are recomputed from the columns of the loaded nodes (O(m) per
//      loaded node), nodes that penetrate join the working set, and the
//      solve stops when the residual of every node is at most the
//      tolerance. Without correction the whole interface is also checked
//      every 16 sweeps.
//
// The stopping test is the residual of Signorini's and Coulomb's
// conditions (the same measure as the exact solver's), not a small change
// per sweep. A regulator that has not converged after max_iterations sweeps
// throws, with the sweeps and the residual reached.
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
#include <functional>
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
    /**
     * After each sweep: the exact reduced solver on the working set,
     * warm-started from the regulators' statuses (active_set), or nothing
     * (none: the paper's regulators alone).
     */
    enum class CoarseCorrection
    {
      active_set,
      none
    };
    CoarseCorrection coarse_correction = CoarseCorrection::active_set;
    /** Relative complementarity residual at which FL2C stops. */
    double tolerance = 1e-4;
    /** Iterations per load step before FL2C gives up. */
    unsigned int max_iterations = 20000;
    /**
     * Iterations of the coarse correction's exact solver from the
     * regulators' statuses, and started cold or from exact statuses (then
     * it gives up).
     */
    unsigned int coarse_warm_iterations = 2;
    unsigned int coarse_max_iterations  = 200;

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

    /**
     * Calls @p monitor(sweep, residual) before the first sweep (sweep 0)
     * and after every sweep (and its coarse correction) with the relative
     * complementarity residual of all nodes (for convergence plots; it costs
     * O(m) per sweep). Empty: none.
     */
    void
    set_monitor(std::function<void(unsigned int, double)> monitor);

  private:
    FL2CParameters                            parameters_;
    MamdaniRegulator                          shape;
    double                                    shape_gain;
    std::function<void(unsigned int, double)> monitor;
  };
} // namespace FuzzyContact

#endif
