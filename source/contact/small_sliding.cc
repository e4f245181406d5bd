#include <fuzzycontact/contact/small_sliding.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  SlidingExtent
  largest_sliding(const ContactInterface &interface,
                  const ContactSolution  &solution)
  {
    AssertDimension(solution.status.size(), interface.n_nodes());
    AssertDimension(solution.g.size(), interface.n_rows());
    SlidingExtent largest;
    for (unsigned int k = 0; k < interface.n_nodes(); ++k)
      {
        if (solution.status[k] == ContactStatus::open)
          continue;
        const double length = interface.node(k).segment_length;
        const double slip   = std::abs(solution.g[2 * k + 1]);
        Assert(length > 0, ExcInternalError());
        const double ratio = slip / length;
        // (A NaN slip counts as beyond any limit.)
        if (!(ratio <= largest.ratio))
          largest = {std::isnan(ratio) ? INFINITY : ratio, k, slip, length};
      }
    return largest;
  }


  void
  check_small_sliding(const ContactInterface &interface,
                      const ContactSolution  &solution,
                      const double            limit,
                      const std::string      &what)
  {
    const SlidingExtent largest = largest_sliding(interface, solution);
    if (largest.ratio <= limit)
      return;
    const ContactNode &node = interface.node(largest.node);
    std::ostringstream message;
    message.precision(4);
    message << what << ": the answer is beyond small sliding: slave node ("
            << node.slave.position[0] << ", " << node.slave.position[1]
            << ") of contact pair '" << interface.pair_name(node.pair)
            << "' slides " << largest.slip << " m along the master face, "
            << largest.ratio << " times the length of its master segment ("
            << largest.length << " m; the key 'sliding limit' allows " << limit
            << "). Node-to-segment contact keeps each node's segment, normal "
               "and tangent of the unloaded bodies, so this is not the "
               "bodies' answer: they slide (gross sliding), the friction "
               "cannot hold them in small displacements.";
    AssertThrow(false, ExcBeyondSmallSliding(message.str()));
  }
} // namespace FuzzyContact
