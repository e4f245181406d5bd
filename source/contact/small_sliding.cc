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
        const double slip = solution.g[2 * k + 1];
        // (A NaN slip counts as beyond any limit.)
        const double angle =
          std::isnan(slip) ? INFINITY
                           : interface.node(k).slide.turn_at(slip) * 180 / M_PI;
        if (!(angle <= largest.angle))
          largest = {angle, k, slip};
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
    if (largest.angle <= limit)
      return;
    const ContactNode &node = interface.node(largest.node);
    std::ostringstream message;
    message.precision(4);
    message << what << ": the answer is beyond small sliding: slave node ("
            << node.slave.position[0] << ", " << node.slave.position[1]
            << ") of contact pair '" << interface.pair_name(node.pair)
            << "' slides " << std::abs(largest.slip)
            << " m along the master face";
    if (std::isinf(largest.angle))
      message << ", off its end (the master face ends "
              << node.slide.face_end[largest.slip >= 0 ? 1 : 0]
              << " m from the node's projection, with a tenth of its last "
                 "segment)";
    else
      message << ", where the master face's normal has turned by "
              << largest.angle << " degrees (the key 'sliding angle limit' "
              << "allows " << limit << ")";
    message << ". Node-to-segment contact keeps each node's projection, "
               "normal and tangent of the unloaded bodies, so this is not "
               "the bodies' answer: ";
    if (std::isinf(largest.angle))
      message << "either they slide (gross sliding: the friction cannot hold "
                 "them), or the slave face overhangs the master face's end "
                 "(make the longer face the master).";
    else
      message << "they slide (gross sliding), the friction cannot hold them "
                 "in small displacements.";
    AssertThrow(false, ExcBeyondSmallSliding(message.str()));
  }
} // namespace FuzzyContact
