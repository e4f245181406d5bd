#include <fuzzycontact/contact/face_geometry.h>

#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  Lagrange
  lagrange(const std::vector<double> &ts, const double t)
  {
    const unsigned int n = ts.size();
    Lagrange           l{std::vector<double>(n, 1.),
               std::vector<double>(n, 0.),
               std::vector<double>(n, 0.)};
    for (unsigned int k = 0; k < n; ++k)
      for (unsigned int a = 0; a < n; ++a)
        {
          if (a == k)
            continue;
          const double da = ts[k] - ts[a];
          l.value[k] *= (t - ts[a]) / da;
          double d1 = 1. / da;
          for (unsigned int b = 0; b < n; ++b)
            if (b != k && b != a)
              d1 *= (t - ts[b]) / (ts[k] - ts[b]);
          l.first[k] += d1;
          for (unsigned int b = 0; b < n; ++b)
            {
              if (b == k || b == a)
                continue;
              double d2 = 1. / (da * (ts[k] - ts[b]));
              for (unsigned int c = 0; c < n; ++c)
                if (c != k && c != a && c != b)
                  d2 *= (t - ts[c]) / (ts[k] - ts[c]);
              l.second[k] += d2;
            }
        }
    return l;
  }


  Point<2>
  FaceGeometry::point(const double t) const
  {
    const Lagrange l = lagrange(ts, t);
    Point<2>       x;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      x += l.value[i] * nodes[i].position;
    return x;
  }

  Tensor<1, 2>
  FaceGeometry::derivative(const double t, const unsigned int order) const
  {
    const Lagrange l = lagrange(ts, t);
    Tensor<1, 2>   d;
    for (unsigned int i = 0; i < nodes.size(); ++i)
      d += (order == 1 ? l.first[i] : l.second[i]) * nodes[i].position;
    return d;
  }

  Tensor<1, 2>
  FaceGeometry::normal(const double t) const
  {
    const Tensor<1, 2> d =
      straight ? nodes.back().position - nodes.front().position : derivative(t);
    Tensor<1, 2> n;
    n[0] = d[1];
    n[1] = -d[0];
    return orientation * n / n.norm();
  }

  // The same curve run the other way.
  void
  FaceGeometry::reverse()
  {
    std::reverse(nodes.begin(), nodes.end());
    std::reverse(ts.begin(), ts.end());
    for (double &t : ts)
      t = 1 - t;
    orientation = -orientation;
  }

  double
  FaceGeometry::closest_point(const Point<2> &x) const
  {
    const Tensor<1, 2> chord = nodes.back().position - nodes.front().position;
    double t = ((x - nodes.front().position) * chord) / chord.norm_square();
    // A straight face is parametrised linearly along its chord (its
    // Lagrange curve interpolates a linear function): the chord's
    // projection is the closest point.
    for (unsigned int it = 0; it < 30 && nodes.size() > 2 && !straight; ++it)
      {
        const Tensor<1, 2> r  = point(t) - x;
        const Tensor<1, 2> d1 = derivative(t, 1);
        const double       f  = r * d1;
        const double       df = d1.norm_square() + r * derivative(t, 2);
        if (df <= 0)
          break;
        const double step = f / df;
        t                 = std::clamp(t - step, -1., 2.);
        if (std::abs(step) < 1e-14)
          break;
      }
    return t;
  }


  double
  FaceGeometry::distance_lower_bound(const Point<2> &x) const
  {
    double distance_squared = 0;
    for (unsigned int d = 0; d < 2; ++d)
      {
        const double outside =
          std::max({box_lower[d] - x[d], x[d] - box_upper[d], 0.});
        distance_squared += outside * outside;
      }
    return std::sqrt(distance_squared);
  }


  // The box of the control points b_j of the curve's Bernstein form
  // x(t) = sum_j B_j(t) b_j, B_j(t) = binom(p, j) t^j (1 - t)^(p - j),
  // found from x(ts_i) = x_i; the curve on [0, 1] lies in their convex
  // hull. Widened by round-off of the face's size.
  void
  FaceGeometry::set_bounding_box()
  {
    const unsigned int    n = nodes.size();
    std::vector<Point<2>> b(n);
    if (n == 2)
      b = {nodes[0].position, nodes[1].position};
    else
      {
        FullMatrix<double> B(n, n);
        for (unsigned int i = 0; i < n; ++i)
          for (unsigned int j = 0; j < n; ++j)
            {
              double binomial = 1;
              for (unsigned int k = 0; k < j; ++k)
                binomial = binomial * (n - 1 - k) / (k + 1);
              B(i, j) =
                binomial * std::pow(ts[i], j) * std::pow(1 - ts[i], n - 1 - j);
            }
        B.gauss_jordan();
        for (unsigned int j = 0; j < n; ++j)
          for (unsigned int i = 0; i < n; ++i)
            b[j] += B(j, i) * nodes[i].position;
      }
    box_lower = box_upper = b[0];
    for (const Point<2> &p : b)
      for (unsigned int d = 0; d < 2; ++d)
        {
          box_lower[d] = std::min(box_lower[d], p[d]);
          box_upper[d] = std::max(box_upper[d], p[d]);
        }
    const double margin = 1e-10 * box_lower.distance(box_upper);
    for (unsigned int d = 0; d < 2; ++d)
      {
        box_lower[d] -= margin;
        box_upper[d] += margin;
      }
  }


  namespace
  {
    template <typename CellIterator, typename FaceIterator>
    FaceGeometry
    face_geometry(const Component    &component,
                  const unsigned int  c,
                  const CellIterator &cell,
                  const FaceIterator &face)
    {
      std::vector<types::global_dof_index> dofs(
        component.fe().n_dofs_per_face());
      face->get_dof_indices(dofs);
      const auto  &points    = component.support_points();
      const auto  &direction = component.dof_directions();
      const double size      = component.description().lower_left.distance(
        component.description().upper_right);
      FaceGeometry g;
      for (const types::global_dof_index dof : dofs)
        {
          bool found = false;
          for (FaceNode &node : g.nodes)
            if (node.position.distance(points[dof]) < 1e-12 * size)
              {
                node.dofs[direction[dof]] = dof;
                found                     = true;
              }
          if (!found)
            {
              FaceNode node{c, points[dof], {{0, 0}}};
              node.dofs[direction[dof]] = dof;
              g.nodes.push_back(node);
            }
        }
      const Point<2>     v0    = face->vertex(0);
      const Tensor<1, 2> chord = face->vertex(1) - v0;
      std::sort(g.nodes.begin(),
                g.nodes.end(),
                [&](const FaceNode &a, const FaceNode &b) {
                  return (a.position - v0) * chord < (b.position - v0) * chord;
                });
      const Tensor<1, 2> span =
        g.nodes.back().position - g.nodes.front().position;
      g.straight = true;
      for (const FaceNode &node : g.nodes)
        {
          const Tensor<1, 2> r = node.position - g.nodes.front().position;
          g.ts.push_back((r * span) / span.norm_square());
          g.straight =
            g.straight && std::abs(r[0] * span[1] - r[1] * span[0]) <=
                            1e-12 * span.norm_square();
        }
      g.orientation         = 1;
      const Point<2> middle = g.point(0.5);
      if (g.normal(0.5) * (middle - cell->center()) < 0)
        g.orientation = -1;
      g.set_bounding_box();
      return g;
    }

  } // namespace


  // Every boundary face with boundary id @p id of component @p c.
  std::vector<FaceGeometry>
  faces_of(const Component         &component,
           const unsigned int       c,
           const types::boundary_id id)
  {
    std::vector<FaceGeometry> faces;
    for (const auto &cell : component.dof_handler().active_cell_iterators())
      for (const unsigned int f : cell->face_indices())
        if (cell->face(f)->at_boundary() && cell->face(f)->boundary_id() == id)
          faces.push_back(face_geometry(component, c, cell, cell->face(f)));
    return faces;
  }

} // namespace FuzzyContact
