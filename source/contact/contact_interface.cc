#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/face_geometry.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    // tau = n turned clockwise by 90 degrees.
    Tensor<1, 2>
    tangent_of(const Tensor<1, 2> &n)
    {
      Tensor<1, 2> t;
      t[0] = n[1];
      t[1] = -n[0];
      return t;
    }

    // The pair's tangent, from the master faces' mean outward normal; each
    // face is turned to run along it.
    Tensor<1, 2>
    orient_along_pair(std::vector<FaceGeometry> &master_faces)
    {
      Tensor<1, 2> mean_normal;
      for (const FaceGeometry &face : master_faces)
        mean_normal += face.normal(0.5) * face.nodes.front().position.distance(
                                            face.nodes.back().position);
      const Tensor<1, 2> tau = tangent_of(mean_normal / mean_normal.norm());
      for (FaceGeometry &face : master_faces)
        if (tau * (face.nodes.back().position - face.nodes.front().position) <
            0)
          face.reverse();
      return tau;
    }

    // The faces' indices sorted by their start along @p tau.
    std::vector<unsigned>
    order_along(const std::vector<FaceGeometry> &faces, const Tensor<1, 2> &tau)
    {
      std::vector<unsigned> order(faces.size());
      for (unsigned int i = 0; i < order.size(); ++i)
        order[i] = i;
      std::sort(order.begin(),
                order.end(),
                [&](const unsigned a, const unsigned b) {
                  return tau * faces[a].nodes.front().position <
                         tau * faces[b].nodes.front().position;
                });
      return order;
    }

    // The closest point to @p x over the faces (in @p order) whose curve
    // it falls on within round-off of the ends: the face (nullptr if none)
    // and the local coordinate there; the first face in @p order wins a
    // tie. The faces are tried by increasing lower bound of their distance
    // (FaceGeometry::distance_lower_bound()) until the bound exceeds the
    // best distance: the same answer as trying them all, at the cost of a
    // few Newton solves instead of one per face.
    std::pair<const FaceGeometry *, double>
    closest_point(const std::vector<FaceGeometry> &faces,
                  const std::vector<unsigned>     &order,
                  const Point<2>                  &x)
    {
      std::vector<std::pair<double, unsigned int>> candidates;
      candidates.reserve(order.size());
      for (unsigned int k = 0; k < order.size(); ++k)
        candidates.emplace_back(faces[order[k]].distance_lower_bound(x), k);
      std::sort(candidates.begin(), candidates.end());

      const FaceGeometry *best   = nullptr;
      double              best_t = 0, best_distance = 0;
      unsigned int        best_k = 0;
      for (const auto &[bound, k] : candidates)
        {
          if (best != nullptr && bound > best_distance)
            break; // no face left can be closer
          const FaceGeometry &face = faces[order[k]];
          const double        t    = face.closest_point(x);
          if (t < -1e-10 || t > 1 + 1e-10)
            continue;
          const double distance = face.point(std::clamp(t, 0., 1.)).distance(x);
          if (best == nullptr || distance < best_distance ||
              (distance == best_distance && k < best_k))
            {
              best          = &face;
              best_t        = std::clamp(t, 0., 1.);
              best_distance = distance;
              best_k        = k;
            }
        }
      return {best, best_t};
    }


    std::string
    point_string(const Point<2> &p)
    {
      std::ostringstream s;
      s << "(" << p[0] << ", " << p[1] << ")";
      return s.str();
    }

    // A slave node: the node, its outward normal (the mean over the slave
    // faces it lies on) and the length of face it stands for (the integral
    // of its shape function along the slave face).
    struct SlaveNode
    {
      FaceNode     node;
      Tensor<1, 2> normal;
      double       tributary = 0;
    };

    std::map<types::global_dof_index, SlaveNode>
    slave_nodes_of(const std::vector<FaceGeometry> &faces,
                   const unsigned int               degree)
    {
      const QGauss<1>                              quadrature(degree + 1);
      std::map<types::global_dof_index, SlaveNode> nodes;
      for (const FaceGeometry &face : faces)
        for (unsigned int k = 0; k < face.nodes.size(); ++k)
          {
            SlaveNode &node = nodes[face.nodes[k].dofs[0]];
            node.node       = face.nodes[k];
            node.normal += face.normal(face.ts[k]);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              {
                const double t = quadrature.point(q)[0];
                node.tributary += lagrange(face.ts, t).value[k] *
                                  face.derivative(t).norm() *
                                  quadrature.weight(q);
              }
          }
      for (auto &[dof, node] : nodes)
        node.normal /= node.normal.norm();
      return nodes;
    }
  } // namespace


  ContactInterface::ContactInterface(
    const Scene                          &scene,
    const std::vector<const Component *> &components,
    const double                          penetration_tolerance)
  {
    AssertThrow(components.size() == scene.components.size(),
                ExcMessage("ContactInterface: expected one component per "
                           "scene component."));
    AssertThrow(penetration_tolerance >= 0,
                ExcMessage("ContactInterface: the penetration tolerance must "
                           "not be negative."));
    offsets_.push_back(0);
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        Assert(components[c] != nullptr, ExcInternalError());
        AssertThrow(components[c]->name() == scene.components[c].name,
                    ExcMessage("ContactInterface: component " +
                               std::to_string(c) + " is " +
                               components[c]->name() + ", the scene says " +
                               scene.components[c].name + "."));
        offsets_.push_back(offsets_.back() + components[c]->n_dofs());
      }
    for (unsigned int p = 0; p < scene.contact_pairs.size(); ++p)
      {
        const ContactPairDescription &pair = scene.contact_pairs[p];
        pair_names_.push_back(pair.name);
        const unsigned int m = scene.component_index(pair.master_component);
        penetration_tolerance_.push_back(
          penetration_tolerance *
          components[m]->boundary_length(scene.components[m].boundary_id(
            pair.master_face,
            "Contact " + pair.name + ": master face")));
        add_pair(scene, components, p);
      }
    build_operators(components);
  }


  // Projects every node of the pair's slave face onto its master face: the
  // closest point on the master segments (curved ones included), with the
  // master's normal and tangent there.
  void
  ContactInterface::add_pair(const Scene                          &scene,
                             const std::vector<const Component *> &components,
                             const unsigned int                    p)
  {
    const ContactPairDescription &pair  = scene.contact_pairs[p];
    const std::string             where = "Contact " + pair.name;
    const unsigned int s      = scene.component_index(pair.slave_component);
    const unsigned int m      = scene.component_index(pair.master_component);
    const Component   &slave  = *components[s];
    const Component   &master = *components[m];
    const std::string  faces_named =
      "the slave face (" + pair.slave_component + " " + pair.slave_face +
      ") and the master face (" + pair.master_component + " " +
      pair.master_face + ")";

    std::vector<FaceGeometry> master_faces =
      faces_of(master,
               m,
               scene.components[m].boundary_id(pair.master_face,
                                               where + ": master face"));
    const std::vector<FaceGeometry> slave_faces =
      faces_of(slave,
               s,
               scene.components[s].boundary_id(pair.slave_face,
                                               where + ": slave face"));
    Assert(!master_faces.empty() && !slave_faces.empty(), ExcInternalError());

    // The pair's tangent (from the master's mean normal) orders the
    // segments and measures positions along the face for the reports.
    const Tensor<1, 2>          tau   = orient_along_pair(master_faces);
    const std::vector<unsigned> order = order_along(master_faces, tau);
    const SlideProfiles         profiles(master_faces);

    const std::map<types::global_dof_index, SlaveNode> slave_nodes =
      slave_nodes_of(slave_faces, slave.fe().degree);
    double slave_begin = std::numeric_limits<double>::max();
    double slave_end   = -slave_begin;
    bool   any_facing = false, any_opposite = false;
    for (const auto &[dof, node] : slave_nodes)
      {
        slave_begin = std::min(slave_begin, tau * node.node.position);
        slave_end   = std::max(slave_end, tau * node.node.position);
      }
    slave_face_centre_.push_back(0.5 * (slave_begin + slave_end));

    const double tolerance = penetration_tolerance_[p];
    unsigned int n_added   = 0;
    for (const auto &[dof, slave_node] : slave_nodes)
      {
        // The closest point over all master segments whose curve it falls
        // on (within round-off of the ends).
        const auto [best, best_t] =
          closest_point(master_faces, order, slave_node.node.position);
        if (best == nullptr)
          continue; // not opposite the master face
        any_opposite                = true;
        const Tensor<1, 2> n_master = best->normal(best_t);
        if (slave_node.normal * n_master < -0.5)
          any_facing = true;
        if (slave_node.normal * n_master >= 0)
          continue; // this part of the slave face looks away

        ContactNode node;
        node.pair                 = p;
        node.slave                = slave_node.node;
        node.master_nodes         = best->nodes;
        node.xi                   = best_t;
        node.shape_values         = lagrange(best->ts, best_t).value;
        node.projection           = best->point(best_t);
        node.normal               = n_master;
        node.tangent              = tangent_of(n_master);
        node.friction_coefficient = pair.friction_coefficient;
        node.tributary_length     = slave_node.tributary;

        const double geometric_gap =
          n_master * (slave_node.node.position - node.projection);
        node.initial_gap =
          pair.has_initial_gap ? pair.initial_gap : geometric_gap;
        if (node.initial_gap < -tolerance)
          {
            std::ostringstream message;
            message << where << ": initial penetration of " << -node.initial_gap
                    << " m at the slave node "
                    << point_string(slave_node.node.position) << " (";
            if (pair.has_initial_gap)
              message << "the declared initial gap is " << pair.initial_gap;
            else
              message << "from the geometry";
            message << "); at most " << tolerance
                    << " m is accepted as round-off. Move the bodies apart or "
                       "set a non-negative initial gap.";
            AssertThrow(false, ExcMessage(message.str()));
          }
        // A penetration within the tolerance is round-off of the geometry.
        node.initial_gap = std::max(node.initial_gap, 0.);

        // A node whose slave and master DoFs are all clamped cannot move
        // relative to the master: it is no candidate.
        bool can_move = !slave.is_constrained(node.slave.dofs[0]) ||
                        !slave.is_constrained(node.slave.dofs[1]);
        for (unsigned int i = 0; i < node.master_nodes.size(); ++i)
          if (std::abs(node.shape_values[i]) > 1e-14)
            for (unsigned int d = 0; d < 2; ++d)
              can_move = can_move ||
                         !master.is_constrained(node.master_nodes[i].dofs[d]);
        if (!can_move)
          continue;

        node.slide = profiles(best - master_faces.data(),
                              best_t,
                              node.normal,
                              node.tangent);
        nodes_.push_back(node);
        ++n_added;
      }
    AssertThrow(!any_opposite || any_facing || n_added > 0,
                ExcMessage(where + ": " + faces_named +
                           " cannot touch: their outward normals are not "
                           "opposite."));
    AssertThrow(n_added > 0,
                ExcMessage(where + ": no node of the slave face (" +
                           pair.slave_component + " " + pair.slave_face +
                           ") lies opposite the master face (" +
                           pair.master_component + " " + pair.master_face +
                           ") where it could move; the faces cannot touch."));
    std::vector<MasterSegment> sorted;
    for (const unsigned int i : order)
      sorted.push_back(
        MasterSegment{master_faces[i].nodes,
                      tau * master_faces[i].nodes.front().position,
                      tau * master_faces[i].nodes.back().position});
    segments_.push_back(std::move(sorted));
  }


  void
  ContactInterface::build_operators(
    const std::vector<const Component *> &components)
  {
    const unsigned int n_c = components.size();
    constrained_.resize(n_c);
    for (unsigned int c = 0; c < n_c; ++c)
      {
        constrained_[c].resize(components[c]->n_dofs());
        for (unsigned int i = 0; i < components[c]->n_dofs(); ++i)
          constrained_[c][i] = components[c]->is_constrained(i);
      }

    // The entries of C: (row, component, dof, value).
    struct Entry
    {
      unsigned int            row, component;
      types::global_dof_index dof;
      double                  value;
    };
    std::vector<Entry> entries;
    for (unsigned int k = 0; k < nodes_.size(); ++k)
      {
        const ContactNode &node = nodes_[k];
        for (unsigned int r = 0; r < 2; ++r)
          {
            const Tensor<1, 2> &direction =
              (r == 0 ? node.normal : node.tangent);
            for (unsigned int d = 0; d < 2; ++d)
              {
                entries.push_back({2 * k + r,
                                   node.slave.component,
                                   node.slave.dofs[d],
                                   direction[d]});
                for (unsigned int i = 0; i < node.master_nodes.size(); ++i)
                  entries.push_back({2 * k + r,
                                     node.master_nodes[i].component,
                                     node.master_nodes[i].dofs[d],
                                     -node.shape_values[i] * direction[d]});
              }
          }
      }

    patterns_.resize(n_c);
    operators_.resize(n_c);
    contact_dofs_.assign(n_c, {});
    for (unsigned int c = 0; c < n_c; ++c)
      {
        DynamicSparsityPattern dsp(n_rows(), components[c]->n_dofs());
        for (const Entry &e : entries)
          if (e.component == c && e.value != 0 && !constrained_[c][e.dof])
            {
              dsp.add(e.row, e.dof);
              contact_dofs_[c].push_back(e.dof);
            }
        patterns_[c].copy_from(dsp);
        operators_[c].reinit(patterns_[c]);
        std::sort(contact_dofs_[c].begin(), contact_dofs_[c].end());
        contact_dofs_[c].erase(std::unique(contact_dofs_[c].begin(),
                                           contact_dofs_[c].end()),
                               contact_dofs_[c].end());
      }
    tangentially_held_.assign(nodes_.size(), true);
    for (const Entry &e : entries)
      if (e.value != 0 && !constrained_[e.component][e.dof])
        {
          operators_[e.component].add(e.row, e.dof, e.value);
          if (e.row % 2 == 1)
            tangentially_held_[e.row / 2] = false;
        }
  }


  unsigned int
  ContactInterface::n_nodes() const
  {
    return nodes_.size();
  }

  unsigned int
  ContactInterface::n_rows() const
  {
    return 2 * nodes_.size();
  }

  const ContactNode &
  ContactInterface::node(const unsigned int k) const
  {
    AssertIndexRange(k, nodes_.size());
    return nodes_[k];
  }

  const std::vector<ContactNode> &
  ContactInterface::nodes() const
  {
    return nodes_;
  }

  unsigned int
  ContactInterface::n_components() const
  {
    return offsets_.size() - 1;
  }

  types::global_dof_index
  ContactInterface::dof_offset(const unsigned int c) const
  {
    AssertIndexRange(c, n_components());
    return offsets_[c];
  }

  types::global_dof_index
  ContactInterface::n_total_dofs() const
  {
    return offsets_.back();
  }

  const SparseMatrix<double> &
  ContactInterface::gap_operator(const unsigned int c) const
  {
    AssertIndexRange(c, n_components());
    return operators_[c];
  }

  const std::vector<types::global_dof_index> &
  ContactInterface::contact_dofs(const unsigned int c) const
  {
    AssertIndexRange(c, n_components());
    return contact_dofs_[c];
  }

  unsigned int
  ContactInterface::n_pairs() const
  {
    return pair_names_.size();
  }

  const std::string &
  ContactInterface::pair_name(const unsigned int pair) const
  {
    AssertIndexRange(pair, pair_names_.size());
    return pair_names_[pair];
  }

  Vector<double>
  ContactInterface::initial_gaps() const
  {
    return initial_gaps(std::vector<double>(n_pairs(), 0.));
  }

  Vector<double>
  ContactInterface::initial_gaps(const std::vector<double> &gap_offsets) const
  {
    AssertThrow(gap_offsets.size() == n_pairs(),
                ExcMessage("ContactInterface: one gap offset per contact pair "
                           "is expected."));
    Vector<double> g(n_rows());
    for (unsigned int k = 0; k < nodes_.size(); ++k)
      {
        const ContactNode &node   = nodes_[k];
        const double       offset = gap_offsets[node.pair];
        AssertThrow(std::isfinite(offset),
                    ExcMessage("Contact " + pair_names_[node.pair] +
                               ": the gap offset must be a finite number."));
        if (node.initial_gap + offset < -penetration_tolerance_[node.pair])
          {
            std::ostringstream message;
            message << "Contact " << pair_names_[node.pair]
                    << ": a gap offset of " << offset
                    << " m makes the initial gap of the slave node "
                    << point_string(node.slave.position) << " negative ("
                    << node.initial_gap + offset << " m).";
            AssertThrow(false, ExcMessage(message.str()));
          }
        g[2 * k] = node.initial_gap + offset;
      }
    return g;
  }

  std::vector<double>
  ContactInterface::friction_coefficients() const
  {
    std::vector<double> mu;
    for (unsigned int k = 0; k < nodes_.size(); ++k)
      mu.push_back(tangentially_held_[k] ? 0. : nodes_[k].friction_coefficient);
    return mu;
  }

  std::vector<double>
  ContactInterface::friction_coefficients(
    const std::vector<double> &per_pair) const
  {
    AssertThrow(per_pair.size() == n_pairs(),
                ExcMessage("ContactInterface: one friction coefficient per "
                           "contact pair is expected."));
    for (unsigned int p = 0; p < n_pairs(); ++p)
      Input::non_negative(per_pair[p],
                          "Contact " + pair_names_[p] +
                            ": friction coefficient");
    std::vector<double> mu;
    for (unsigned int k = 0; k < nodes_.size(); ++k)
      mu.push_back(tangentially_held_[k] ? 0. : per_pair[nodes_[k].pair]);
    return mu;
  }

  Vector<double>
  ContactInterface::gaps(const std::vector<Vector<double>> &u) const
  {
    AssertDimension(u.size(), n_components());
    Vector<double> g = initial_gaps();
    for (unsigned int c = 0; c < n_components(); ++c)
      operators_[c].vmult_add(g, u[c]);
    return g;
  }

  std::vector<Vector<double>>
  ContactInterface::nodal_forces(const Vector<double> &p) const
  {
    AssertDimension(p.size(), n_rows());
    std::vector<Vector<double>> forces;
    for (unsigned int c = 0; c < n_components(); ++c)
      forces.emplace_back(offsets_[c + 1] - offsets_[c]);
    for (unsigned int k = 0; k < nodes_.size(); ++k)
      {
        const ContactNode &node = nodes_[k];
        const Tensor<1, 2> force =
          p[2 * k] * node.normal + p[2 * k + 1] * node.tangent;
        for (unsigned int d = 0; d < 2; ++d)
          {
            forces[node.slave.component][node.slave.dofs[d]] += force[d];
            for (unsigned int i = 0; i < node.master_nodes.size(); ++i)
              forces[node.master_nodes[i].component]
                    [node.master_nodes[i].dofs[d]] -=
                node.shape_values[i] * force[d];
          }
      }
    return forces;
  }

  unsigned int
  ContactInterface::nearest_node(const Point<2> &point) const
  {
    AssertThrow(!nodes_.empty(), ExcMessage("There are no contact nodes."));
    unsigned int best = 0;
    for (unsigned int k = 1; k < nodes_.size(); ++k)
      if (nodes_[k].slave.position.distance(point) <
          nodes_[best].slave.position.distance(point))
        best = k;
    return best;
  }

  const std::vector<MasterSegment> &
  ContactInterface::master_segments(const unsigned int pair) const
  {
    AssertIndexRange(pair, segments_.size());
    return segments_[pair];
  }

  double
  ContactInterface::slave_face_centre(const unsigned int pair) const
  {
    AssertIndexRange(pair, slave_face_centre_.size());
    return slave_face_centre_[pair];
  }

  double
  ContactInterface::penetration_tolerance(const unsigned int pair) const
  {
    AssertIndexRange(pair, penetration_tolerance_.size());
    return penetration_tolerance_[pair];
  }
} // namespace FuzzyContact
