#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/contact_interface.h>

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
    Tensor<1, 2>
    outward_normal(const Face face)
    {
      Tensor<1, 2> n;
      switch (face)
        {
          case Face::left:
            n[0] = -1;
            break;
          case Face::right:
            n[0] = 1;
            break;
          case Face::bottom:
            n[1] = -1;
            break;
          case Face::top:
            n[1] = 1;
            break;
        }
      return n;
    }

    // tau = n turned clockwise by 90 degrees.
    Tensor<1, 2>
    tangent_of(const Tensor<1, 2> &n)
    {
      Tensor<1, 2> t;
      t[0] = n[1];
      t[1] = -n[0];
      return t;
    }

    // The nodes of one face (edge) of a cell: its DoFs grouped by support
    // point into (x, y) pairs, sorted along @p tau.
    template <typename FaceIterator>
    std::vector<FaceNode>
    nodes_of_face(const Component    &component,
                  const unsigned int  c,
                  const FaceIterator &face,
                  const Tensor<1, 2> &tau)
    {
      std::vector<types::global_dof_index> dofs(
        component.fe().n_dofs_per_face());
      face->get_dof_indices(dofs);
      const auto           &points    = component.support_points();
      const auto           &direction = component.dof_directions();
      std::vector<FaceNode> nodes;
      for (const types::global_dof_index dof : dofs)
        {
          bool found = false;
          for (FaceNode &node : nodes)
            if (node.position.distance(points[dof]) <
                1e-12 * component.description().length())
              {
                node.dofs[direction[dof]] = dof;
                found                     = true;
              }
          if (!found)
            {
              FaceNode node{c, points[dof], {{0, 0}}};
              node.dofs[direction[dof]] = dof;
              nodes.push_back(node);
            }
        }
      std::sort(nodes.begin(),
                nodes.end(),
                [&tau](const FaceNode &a, const FaceNode &b) {
                  return tau * a.position < tau * b.position;
                });
      return nodes;
    }

    // Values at t of the 1D Lagrange polynomials through the points ts.
    std::vector<double>
    lagrange_values(const std::vector<double> &ts, const double t)
    {
      std::vector<double> values(ts.size(), 1.);
      for (unsigned int k = 0; k < ts.size(); ++k)
        for (unsigned int l = 0; l < ts.size(); ++l)
          if (l != k)
            values[k] *= (t - ts[l]) / (ts[k] - ts[l]);
      return values;
    }

    // Local coordinates in [0, 1] of a segment's nodes along tau.
    std::vector<double>
    local_coordinates(const std::vector<FaceNode> &nodes,
                      const Tensor<1, 2>          &tau)
    {
      const double        s0 = tau * nodes.front().position;
      const double        s1 = tau * nodes.back().position;
      std::vector<double> ts;
      for (const FaceNode &node : nodes)
        ts.push_back((tau * node.position - s0) / (s1 - s0));
      return ts;
    }

    double
    face_length(const ComponentDescription &d, const Face face)
    {
      return (face == Face::left || face == Face::right) ? d.height()
                                                         : d.length();
    }

    std::string
    point_string(const Point<2> &p)
    {
      std::ostringstream s;
      s << "(" << p[0] << ", " << p[1] << ")";
      return s.str();
    }

    // The master segments of face @p face of component @p master (index
    // @p m), sorted along @p tau.
    std::vector<MasterSegment>
    master_segments_of(const Component    &master,
                       const unsigned int  m,
                       const Face          face,
                       const Tensor<1, 2> &tau)
    {
      std::vector<MasterSegment> segments;
      for (const auto &cell : master.dof_handler().active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == static_cast<unsigned int>(face))
            {
              MasterSegment segment;
              segment.nodes   = nodes_of_face(master, m, cell->face(f), tau);
              segment.s_begin = tau * segment.nodes.front().position;
              segment.s_end   = tau * segment.nodes.back().position;
              segments.push_back(segment);
            }
      std::sort(segments.begin(),
                segments.end(),
                [](const MasterSegment &a, const MasterSegment &b) {
                  return a.s_begin < b.s_begin;
                });
      Assert(!segments.empty(), ExcInternalError());
      return segments;
    }

    // The nodes of face @p face of component @p slave (index @p s), keyed by
    // their x DoF, with the length of face each stands for (the integral of
    // its shape function along the face); returns the extent of the face
    // along @p tau.
    std::pair<double, double>
    slave_nodes_of(const Component                             &slave,
                   const unsigned int                           s,
                   const Face                                   face,
                   const Tensor<1, 2>                          &tau,
                   std::map<types::global_dof_index, FaceNode> &nodes,
                   std::map<types::global_dof_index, double>   &tributary)
    {
      const QGauss<1> quadrature(slave.fe().degree + 1);
      double          begin = std::numeric_limits<double>::max();
      double          end   = -begin;
      for (const auto &cell : slave.dof_handler().active_cell_iterators())
        for (const unsigned int f : cell->face_indices())
          if (cell->face(f)->at_boundary() &&
              cell->face(f)->boundary_id() == static_cast<unsigned int>(face))
            {
              const std::vector<FaceNode> face_nodes =
                nodes_of_face(slave, s, cell->face(f), tau);
              const std::vector<double> ts = local_coordinates(face_nodes, tau);
              const double length = face_nodes.front().position.distance(
                face_nodes.back().position);
              for (unsigned int k = 0; k < face_nodes.size(); ++k)
                {
                  nodes[face_nodes[k].dofs[0]] = face_nodes[k];
                  double integral              = 0;
                  for (unsigned int q = 0; q < quadrature.size(); ++q)
                    integral += lagrange_values(ts, quadrature.point(q)[0])[k] *
                                quadrature.weight(q);
                  tributary[face_nodes[k].dofs[0]] += integral * length;
                }
              begin = std::min(begin, tau * face_nodes.front().position);
              end   = std::max(end, tau * face_nodes.back().position);
            }
      return {begin, end};
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
        penetration_tolerance_.push_back(
          penetration_tolerance *
          face_length(
            scene.components[scene.component_index(pair.master_component)],
            pair.master_face));
        add_pair(scene, components, p);
      }
    build_operators(components);
  }


  // Projects every node of the pair's slave face onto its master face.
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

    const Tensor<1, 2> n_master = outward_normal(pair.master_face);
    const Tensor<1, 2> n_slave  = outward_normal(pair.slave_face);
    const Tensor<1, 2> tau      = tangent_of(n_master);
    AssertThrow(n_master * n_slave < -0.5,
                ExcMessage(where + ": the slave face (" + pair.slave_component +
                           " " + to_string(pair.slave_face) +
                           ") and the master face (" + pair.master_component +
                           " " + to_string(pair.master_face) +
                           ") cannot touch: their outward normals are not "
                           "opposite."));

    const std::vector<MasterSegment> segments =
      master_segments_of(master, m, pair.master_face, tau);
    const double master_begin = segments.front().s_begin;
    const double master_end   = segments.back().s_end;
    const double s_tolerance  = 1e-10 * (master_end - master_begin);

    // Slave nodes with the length of slave face each stands for.
    std::map<types::global_dof_index, FaceNode> slave_nodes;
    std::map<types::global_dof_index, double>   tributary;
    const auto [slave_begin, slave_end] =
      slave_nodes_of(slave, s, pair.slave_face, tau, slave_nodes, tributary);
    slave_face_centre_.push_back(0.5 * (slave_begin + slave_end));

    const double tolerance = penetration_tolerance_[p];
    unsigned int n_added   = 0;
    for (const auto &[dof, slave_node] : slave_nodes)
      {
        const double s_slave = tau * slave_node.position;
        if (s_slave < master_begin - s_tolerance ||
            s_slave > master_end + s_tolerance)
          continue; // not opposite the master face
        const auto segment =
          std::find_if(segments.begin(),
                       segments.end(),
                       [&](const MasterSegment &seg) {
                         return s_slave >= seg.s_begin - s_tolerance &&
                                s_slave <= seg.s_end + s_tolerance;
                       });
        Assert(segment != segments.end(), ExcInternalError());

        ContactNode node;
        node.pair         = p;
        node.slave        = slave_node;
        node.master_nodes = segment->nodes;
        node.xi           = std::clamp((s_slave - segment->s_begin) /
                               (segment->s_end - segment->s_begin),
                             0.,
                             1.);
        node.shape_values =
          lagrange_values(local_coordinates(segment->nodes, tau), node.xi);
        node.projection = segment->nodes.front().position +
                          node.xi * (segment->nodes.back().position -
                                     segment->nodes.front().position);
        node.normal               = n_master;
        node.tangent              = tau;
        node.friction_coefficient = pair.friction_coefficient;
        node.tributary_length     = tributary[dof];

        const double geometric_gap =
          n_master * (slave_node.position - node.projection);
        node.initial_gap =
          pair.has_initial_gap ? pair.initial_gap : geometric_gap;
        if (node.initial_gap < -tolerance)
          {
            std::ostringstream message;
            message << where << ": initial penetration of " << -node.initial_gap
                    << " m at the slave node "
                    << point_string(slave_node.position) << " (";
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
        bool can_move = !slave.is_constrained(slave_node.dofs[0]) ||
                        !slave.is_constrained(slave_node.dofs[1]);
        for (unsigned int i = 0; i < node.master_nodes.size(); ++i)
          if (std::abs(node.shape_values[i]) > 1e-14)
            for (unsigned int d = 0; d < 2; ++d)
              can_move = can_move ||
                         !master.is_constrained(node.master_nodes[i].dofs[d]);
        if (!can_move)
          continue;

        nodes_.push_back(node);
        ++n_added;
      }
    AssertThrow(n_added > 0,
                ExcMessage(
                  where + ": no node of the slave face (" +
                  pair.slave_component + " " + to_string(pair.slave_face) +
                  ") lies opposite the master face (" + pair.master_component +
                  " " + to_string(pair.master_face) +
                  ") where it could move; the faces cannot touch."));
    segments_.push_back(std::move(segments));
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
    for (const Entry &e : entries)
      if (e.value != 0 && !constrained_[e.component][e.dof])
        operators_[e.component].add(e.row, e.dof, e.value);
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
    for (const ContactNode &node : nodes_)
      mu.push_back(node.friction_coefficient);
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
    for (const ContactNode &node : nodes_)
      mu.push_back(per_pair[node.pair]);
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
