// The limit of node-to-segment contact's small sliding.
//
// The contact interface (contact_interface.h) is built once, in the
// reference configuration: each slave node keeps its master segment, its
// projection point, the normal and the tangent there, whatever the
// displacements. That holds while a node slides along the master face by
// a small part of its segment. A node that slides farther would lie over
// another segment, and on a curved face under another normal: the answer
// of the linear problem is then not that of the bodies. It happens where
// the bodies cannot be held in small displacements at all: a pin in a bore
// whose friction cannot hold the torque of its load has, in the linear
// problem, an "equilibrium" in which it turns and shifts by metres against
// the frozen normals of the bore's sides, while in truth it spins in the
// bore (the static equilibrium test, static_equilibrium.h, balances the
// resultants only, and cannot see this).
//
// The measure: the slip of a closed slave node, |g_t|, the relative
// tangential displacement since the unloaded state, divided by the length
// of its master segment (the distance between the segment's end nodes).
// The largest over the closed nodes, against a limit (the key `sliding
// limit`, default 1: one master segment), says whether an answer is within
// small sliding; beyond it, the bodies slide (gross sliding).

#ifndef fuzzycontact_contact_small_sliding_h
#define fuzzycontact_contact_small_sliding_h

#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/contact_problem.h>

#include <deal.II/base/exceptions.h>

#include <string>

namespace FuzzyContact
{
  /** The largest slip of a solution's closed nodes (see the top). */
  struct SlidingExtent
  {
    /** |g_t| / master segment length of the node (0: no closed node). */
    double ratio = 0;
    /** The node, its slip [m] and its master segment's length [m]. */
    unsigned int node   = 0;
    double       slip   = 0;
    double       length = 0;
  };

  /** The largest slip of the closed nodes of @p solution on @p interface. */
  SlidingExtent
  largest_sliding(const ContactInterface &interface,
                  const ContactSolution  &solution);

  /**
   * An answer beyond small sliding: a closed node slid farther than the
   * limit (the message says which, by how much, and names the key).
   */
  DeclException1(ExcBeyondSmallSliding, std::string, << arg1);

  /**
   * Throws ExcBeyondSmallSliding if a closed node of @p solution slid
   * farther than @p limit times its master segment's length; @p what names
   * the solve in the message.
   */
  void
  check_small_sliding(const ContactInterface &interface,
                      const ContactSolution  &solution,
                      const double            limit,
                      const std::string      &what);

  /** The default limit, in master segment lengths. */
  constexpr double default_sliding_limit = 1;
} // namespace FuzzyContact

#endif
