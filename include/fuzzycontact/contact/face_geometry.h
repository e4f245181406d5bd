// The geometry of a boundary face (an edge) of a 2D component's mesh, as
// the contact interface sees it: the face's nodes (DoFs grouped by support
// point) sorted along the chord between its vertices, their local
// coordinates, and the curve x(t) = sum_i N_i(t) x_i the element's Lagrange
// shape functions N_i draw through them (curved when the nodes lie on an
// arc). Closest points are found by Newton's method on that curve.

#ifndef fuzzycontact_contact_face_geometry_h
#define fuzzycontact_contact_face_geometry_h

#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/fe/component.h>

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  // Values and first and second derivatives at t of the 1D Lagrange
  // polynomials through the points ts.
  struct Lagrange
  {
    std::vector<double> value, first, second;
  };

  Lagrange
  lagrange(const std::vector<double> &ts, const double t);

  // The geometry of one boundary face (edge) of a cell: its nodes (DoFs
  // grouped by support point into (x, y) pairs) sorted along the chord
  // between its vertices, their local coordinates in [0, 1], and the
  // sign that turns (x'_y, -x'_x) into the outward normal.
  struct FaceGeometry
  {
    std::vector<FaceNode> nodes;
    std::vector<double>   ts;
    double                orientation;
    // True if every node lies on the chord (to round-off): the normal is
    // then that of the chord, exactly.
    bool straight;
    // A box that contains the curve for t in [0, 1]: that of the control
    // points of its Bernstein form (the convex hull property), widened by
    // round-off.
    Point<2> box_lower, box_upper;


    /** x(t). */
    Point<2>
    point(const double t) const;
    /** x'(t) (order 1) or x''(t) (order 2). */
    Tensor<1, 2>
    derivative(const double t, const unsigned int order = 1) const;
    /** Outward unit normal at t. */
    Tensor<1, 2>
    normal(const double t) const;
    /** The same curve run the other way. */
    void
    reverse();
    /**
     * Closest point of the curve to @p x: Newton on (x(t) - x) . x'(t) = 0
     * from the chord's projection (a straight face: that projection
     * itself); t may leave [0, 1] (the point is then beyond the face).
     */
    double
    closest_point(const Point<2> &x) const;

    /**
     * Sets the box from the nodes and their coordinates (faces_of() does).
     */
    void
    set_bounding_box();

    /**
     * A lower bound of the distance from @p x to any point of the curve
     * with t in [0, 1] (the distance to the box): a closest-point search
     * skips the faces whose bound exceeds the best distance found.
     */
    double
    distance_lower_bound(const Point<2> &x) const;
  };

  /** Every boundary face with boundary id @p id of component @p c. */
  std::vector<FaceGeometry>
  faces_of(const Component         &component,
           const unsigned int       c,
           const types::boundary_id id);
} // namespace FuzzyContact

#endif
