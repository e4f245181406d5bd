#include <fuzzycontact/reanalysis/order_selection.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace FuzzyContact
{
  using namespace dealii;

  double
  relative_frequency_change(const std::vector<double> &a,
                            const std::vector<double> &b,
                            const unsigned int         n_modes)
  {
    AssertThrow(n_modes <= a.size() && n_modes <= b.size(),
                ExcMessage(
                  "relative_frequency_change: " + std::to_string(n_modes) +
                  " modes asked for, " + std::to_string(a.size()) + " and " +
                  std::to_string(b.size()) + " given."));
    double change = 0;
    for (unsigned int j = 0; j < n_modes; ++j)
      {
        const double fa = std::sqrt(std::max(a[j], 0.));
        const double fb = std::sqrt(std::max(b[j], 0.));
        change          = std::max(change, std::abs(fa - fb) / fb);
      }
    return change;
  }


  OrderSelection
  order_for_tolerance(
    const unsigned int                                      max_order,
    const double                                            tolerance,
    const unsigned int                                      n_modes,
    const std::function<std::vector<double>(unsigned int)> &eigenvalues,
    const std::function<double(unsigned int)> &largest_energy_residual,
    const bool                                 all_orders)
  {
    AssertThrow(max_order >= 1,
                ExcMessage("order selection: the highest order must be at "
                           "least 1."));
    OrderSelection      result;
    std::vector<double> current = eigenvalues(1);
    for (unsigned int n = 1; n <= max_order; ++n)
      {
        OrderEstimate       e;
        double              estimate = -1; // none yet
        std::vector<double> next;
        if (n < max_order)
          {
            next = eigenvalues(n + 1);
            e.change_to_next_order =
              relative_frequency_change(current, next, n_modes);
            estimate = e.change_to_next_order;
          }
        if (largest_energy_residual)
          {
            const double eta = largest_energy_residual(n);
            if (std::isfinite(eta))
              estimate = std::max(estimate, 0.5 * eta * eta);
          }
        if (estimate >= 0)
          e.estimate = estimate;
        result.estimates.push_back(e);

        if (result.order == 0 && estimate >= 0 && estimate <= tolerance)
          {
            result.order         = n;
            result.tolerance_met = true;
            if (!all_orders)
              return result;
          }
        current = std::move(next);
      }
    if (result.order == 0)
      {
        result.order         = max_order;
        result.tolerance_met = false;
      }
    return result;
  }
} // namespace FuzzyContact
