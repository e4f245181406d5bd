// How far a slave node may slide along its master face before the frozen
// geometry of small sliding stops being the bodies' geometry.
//
// Node-to-segment contact keeps, for each slave node, the normal n0 and the
// tangent of the master face at its projection in the unloaded bodies
// (contact_interface.h). A slide along the master face changes nothing in
// the bodies' answer while the master face keeps that normal: on a flat face
// a node may slide across any number of segments. What makes the frozen
// answer wrong is the master face turning under the slid node (a curved
// face, a kink between faces: the gap, normal and friction directions are
// then those of another place), or the node sliding off the master face
// altogether.
//
// A SlideProfile says, for each direction along the tangent, how the master
// normal turns along the slide: walking along the master face from the
// projection (across faces that share an end node), the largest angle
// between n0 and the master's normal met up to each arc length, and the
// arc length at which the master face ends. It is built once, in the
// unloaded geometry; small_sliding.h reads it at a solution's slips.

#ifndef fuzzycontact_contact_slide_profile_h
#define fuzzycontact_contact_slide_profile_h

#include <deal.II/base/tensor.h>

#include <array>
#include <cmath>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  struct FaceGeometry;

  struct SlideProfile
  {
    /**
     * Per direction (0: against the tangent, 1: along it): arc lengths
     * along the master face [m] and the largest turn of the master normal
     * from n0 up to each [rad], both non-decreasing; between two entries
     * the turn is interpolated linearly (an upper bound of the largest turn
     * on a curved face between its samples).
     */
    std::array<std::vector<double>, 2> arc, turn;
    /**
     * Per direction: the arc length at which the slide leaves the master
     * face (INFINITY where the walk stopped because the normal had turned
     * by a right angle).
     */
    std::array<double, 2> face_end = {{INFINITY, INFINITY}};

    /**
     * The largest turn [rad] of the master normal along a slide of
     * @p slip [m] along the tangent (negative: against it); INFINITY if
     * the slide leaves the master face.
     */
    double
    turn_at(const double slip) const;
  };

  /**
   * The profiles of nodes projected onto one pair's master faces (its
   * master boundary). A face's neighbours are the faces that share one of
   * its end nodes. A walk stops where the normal has turned by a right
   * angle or the faces end; a slide may overhang the last face's end by a
   * tenth of that face's length (round-off of where the slave face ends,
   * as other codes extend their master faces).
   */
  class SlideProfiles
  {
  public:
    /** @p faces must outlive this object. */
    explicit SlideProfiles(const std::vector<FaceGeometry> &faces);

    /**
     * The profile of a node projected at @p t on face @p face, with the
     * master's normal @p normal and tangent @p tangent there.
     */
    SlideProfile
    operator()(const unsigned int  face,
               const double        t,
               const Tensor<1, 2> &normal,
               const Tensor<1, 2> &tangent) const;

  private:
    const std::vector<FaceGeometry> &faces_;
    // Per face and end (0: t = 0, 1: t = 1): the neighbouring face sharing
    // that end node and the neighbour's end there (-1: none).
    std::vector<std::array<std::array<int, 2>, 2>> neighbours_;
    // Per face: its normal and the arc length from t = 0 at t = i / 4
    // (i = 0, ..., 4), computed once for every node's walk.
    struct Samples
    {
      std::array<Tensor<1, 2>, 5> normal;
      std::array<double, 5>       arc;
    };
    std::vector<Samples> samples_;
  };
} // namespace FuzzyContact

#endif
