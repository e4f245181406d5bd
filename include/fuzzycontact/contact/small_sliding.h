// The limit of node-to-segment contact's small sliding.
//
// The contact interface (contact_interface.h) is built once, in the
// reference configuration: each slave node keeps its master segment, its
// projection point, the normal and the tangent there, whatever the
// displacements. That holds while the master face keeps that normal
// under the node's slide. A node that slides farther along a curved face,
// or past a kink, lies under another normal, and one that slides off the
// master face over none: the answer of the linear problem is then not
// that of the bodies. It happens where
// the bodies cannot be held in small displacements at all: a pin in a bore
// whose friction cannot hold the torque of its load has, in the linear
// problem, an "equilibrium" in which it turns and shifts by metres against
// the frozen normals of the bore's sides, while in truth it spins in the
// bore (the static equilibrium test, static_equilibrium.h, balances the
// resultants only, and cannot see this).
//
// The measure (slide_profile.h): a slide along a flat master face changes
// nothing, whatever its length; what matters is how far the master face's
// normal turns under the slid node (a curved face, a kink between faces),
// and whether the node slides off the master face. For each closed slave
// node, its slip g_t (the relative tangential displacement since the
// unloaded state) is walked along the master face from its projection; the
// largest turn of the master normal met on the way, over the closed nodes,
// against a limit (the key `sliding angle limit`, default 5 degrees), says
// whether an answer is within small sliding; a node that slides off the
// master face (beyond a tenth of its last segment) is beyond any limit.
// Beyond, the bodies slide (gross sliding). The measure does not depend on
// the mesh: a finer mesh of the same curve turns by the same angle over the
// same slide.

#ifndef fuzzycontact_contact_small_sliding_h
#define fuzzycontact_contact_small_sliding_h

#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/contact_problem.h>

#include <deal.II/base/exceptions.h>

#include <string>

namespace FuzzyContact
{
  /** The largest slide of a solution's closed nodes (see the top). */
  struct SlidingExtent
  {
    /**
     * The largest turn of the master normal along the node's slide
     * [degrees]; INFINITY if it slides off the master face (0: no closed
     * node).
     */
    double angle = 0;
    /** The node and its slip [m] along the master's tangent. */
    unsigned int node = 0;
    double       slip = 0;
  };

  /** The largest slide of the closed nodes of @p solution on @p interface. */
  SlidingExtent
  largest_sliding(const ContactInterface &interface,
                  const ContactSolution  &solution);

  /**
   * An answer beyond small sliding: the master face turned by more than the
   * limit under a closed node's slide, or the node slid off it (the message
   * says which node, by how much, and names the key).
   */
  DeclException1(ExcBeyondSmallSliding, std::string, << arg1);

  /**
   * Throws ExcBeyondSmallSliding if the master normal turns by more than
   * @p limit degrees along a closed node's slide in @p solution, or the
   * node slides off the master face; @p what names the solve in the
   * message.
   */
  void
  check_small_sliding(const ContactInterface &interface,
                      const ContactSolution  &solution,
                      const double            limit,
                      const std::string      &what);

  /** The default limit [degrees]. */
  constexpr double default_sliding_limit = 5;
} // namespace FuzzyContact

#endif
