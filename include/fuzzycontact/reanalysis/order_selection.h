// The order a tolerance asks for: the rule every reanalysis with an order
// (Combined Approximations, HPTP, the parameter-independent HPTP) uses to
// choose it a posteriori, without an exact re-solve.
//
// Two estimates of the relative frequency error of order n:
//
//  - the change to order n + 1, max_j |f_j(n) - f_j(n+1)| / f_j(n+1) over
//    the modes compared. Ritz values on nested bases decrease towards the
//    exact ones, so this is a lower estimate; the highest order has none;
//  - when the residuals are checked on the full matrices (residual_check.h),
//    eta^2 / 2 from the largest energy-norm residual eta of order n, which
//    also sees a method that stagnates, and covers the highest order.
//
// The estimate of order n is the larger of those available, and the order
// chosen is the lowest whose estimate is at most the tolerance; if none is,
// the highest order, and the tolerance is not met.

#ifndef fuzzycontact_reanalysis_order_selection_h
#define fuzzycontact_reanalysis_order_selection_h

#include <functional>
#include <limits>
#include <vector>

namespace FuzzyContact
{
  /** What the rule found for one order. */
  struct OrderEstimate
  {
    /**
     * max_j |f_j(n) - f_j(n+1)| / f_j(n+1); NaN for the highest order (no
     * next order).
     */
    double change_to_next_order = std::numeric_limits<double>::quiet_NaN();
    /**
     * The estimated relative frequency error of the order: the larger of
     * the change to the next order and eta^2 / 2 (where available); NaN if
     * neither is.
     */
    double estimate = std::numeric_limits<double>::quiet_NaN();
  };

  /** The order chosen, and the estimates it was chosen from. */
  struct OrderSelection
  {
    /** The order chosen, 1..max_order. */
    unsigned int order = 0;
    /** Whether its estimate meets the tolerance. */
    bool tolerance_met = false;
    /**
     * estimates[n - 1] for every order n looked at: 1..order if the rule
     * stopped at the order chosen, 1..max_order otherwise.
     */
    std::vector<OrderEstimate> estimates;
  };

  /**
   * max_j |f_j(a) - f_j(b)| / f_j(b) over the @p n_modes lowest of the
   * eigenvalues @p a and @p b (with f = sqrt(max(lambda, 0)); the 2 pi
   * cancels).
   */
  double
  relative_frequency_change(const std::vector<double> &a,
                            const std::vector<double> &b,
                            const unsigned int         n_modes);

  /**
   * The rule above for orders 1..@p max_order and a @p tolerance.
   * @p eigenvalues(n) gives the (ascending) eigenvalues of order n, of which
   * the lowest @p n_modes are compared; it is called at most once per order,
   * in increasing order. @p largest_energy_residual(n) gives eta of order n
   * (the largest energy-norm residual of the modes compared); leave it empty
   * when the residuals are not checked (a non-finite eta is ignored).
   *
   * With @p all_orders false the rule stops at the first order that meets
   * the tolerance (the orders above are not computed); with true every
   * order is estimated, for a report that shows them all. The order chosen
   * is the same.
   */
  OrderSelection
  order_for_tolerance(
    const unsigned int                                      max_order,
    const double                                            tolerance,
    const unsigned int                                      n_modes,
    const std::function<std::vector<double>(unsigned int)> &eigenvalues,
    const std::function<double(unsigned int)> &largest_energy_residual = {},
    const bool                                 all_orders              = false);
} // namespace FuzzyContact

#endif
