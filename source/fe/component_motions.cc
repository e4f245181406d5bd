// The rigid-body motions of a Component (fe/component.h): the three
// motions of a 2D body, those its clamps and supports leave free, and the
// pins that hold a free body for the solvers (a body held by contact
// alone).

#include <fuzzycontact/fe/component.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    // The size of the body: its bounding box's diagonal.
    double
    size_of(const ComponentDescription &d)
    {
      return d.lower_left.distance(d.upper_right);
    }

    Point<2>
    centre_of(const ComponentDescription &d)
    {
      return 0.5 * (d.lower_left + d.upper_right);
    }

    // The combinations v (x translation, y translation, rotation about the
    // centre times 1/size) that move no DoF with held[i] set: the
    // eigenvectors of the smallest eigenvalues of R_h^T R_h, one column of
    // the result each.
    FullMatrix<double>
    free_combinations(const std::vector<Vector<double>> &motions,
                      const std::vector<bool>           &held,
                      const double                       size)
    {
      LAPACKFullMatrix<double> G(3, 3);
      for (unsigned int i = 0; i < held.size(); ++i)
        if (held[i])
          for (unsigned int a = 0; a < 3; ++a)
            for (unsigned int b = 0; b < 3; ++b)
              G(a, b) += motions[a][i] * motions[b][i] /
                         ((a == 2 ? size : 1.) * (b == 2 ? size : 1.));
      const double       scale = std::max(1., G.frobenius_norm());
      Vector<double>     eigenvalues;
      FullMatrix<double> eigenvectors;
      G.compute_eigenvalues_symmetric(-1.,
                                      1e-10 * scale,
                                      1e-14 * scale,
                                      eigenvalues,
                                      eigenvectors);
      if (eigenvalues.size() == 3)
        return IdentityMatrix(3); // nothing held: the motions themselves
      return eigenvectors;
    }

    // A combination in words: a translation, or a rotation about its pole.
    std::string
    describe(const double                tx,
             const double                ty,
             const double                r,
             const ComponentDescription &d)
    {
      // (The sign is arbitrary: x first, then y, positive.)
      const double sign =
        (tx < -1e-12 || (std::abs(tx) <= 1e-12 && ty < 0)) ? -1. : 1.;
      std::ostringstream out;
      if (std::abs(r) > 1e-6)
        {
          // Translation (tx, ty) plus rotation r / size about the centre is
          // a rotation about centre + size (-ty, tx) / r.
          const double   size = size_of(d);
          const Point<2> pole(centre_of(d)[0] - size * ty / r,
                              centre_of(d)[1] + size * tx / r);
          out << "rotation about (" << pole[0] << ", " << pole[1] << ")";
        }
      else
        out << "translation along (" << (std::abs(tx) < 1e-12 ? 0. : sign * tx)
            << ", " << (std::abs(ty) < 1e-12 ? 0. : sign * ty) << ")";
      return out.str();
    }
  } // namespace


  std::vector<Vector<double>>
  Component::rigid_body_motions() const
  {
    const Point<2>              centre = centre_of(description_);
    std::vector<Vector<double>> motions(3, Vector<double>(n_dofs()));
    for (unsigned int i = 0; i < n_dofs(); ++i)
      {
        const unsigned int c = dof_directions_[i];
        const Point<2>    &x = support_points_[i];
        motions[0][i]        = (c == 0 ? 1. : 0.);
        motions[1][i]        = (c == 1 ? 1. : 0.);
        motions[2][i] = (c == 0 ? -(x[1] - centre[1]) : (x[0] - centre[0]));
      }
    return motions;
  }


  // The held DoFs' rows of the three rigid-body motions (the rotation
  // scaled by the body's size) span all three unless a motion moves no held
  // DoF: the eigenvector of the smallest eigenvalue of R_h^T R_h is then
  // that motion.
  std::string
  Component::free_rigid_motion() const
  {
    if (!free_motion_names_.empty())
      {
        std::string free = free_motion_names_[0];
        if (free_motion_names_.size() > 1)
          free +=
            " (and " + std::to_string(free_motion_names_.size() - 1) + " more)";
        return free;
      }
    std::vector<bool> held(n_dofs());
    for (unsigned int i = 0; i < n_dofs(); ++i)
      held[i] = is_constrained(i);
    const FullMatrix<double> v =
      free_combinations(rigid_body_motions(), held, size_of(description_));
    if (v.n() == 0)
      return "";
    std::string free = describe(v(0, 0), v(1, 0), v(2, 0), description_);
    if (v.n() > 1)
      free += " (and " + std::to_string(v.n() - 1) + " more)";
    return free;
  }


  // The motions the supports leave free, and one pin per motion: greedily,
  // the candidate DoF whose row of the free motions, less its part along
  // the rows already chosen, is longest (so that the pins' rows are well
  // conditioned), among the DoFs no support holds that lie on none of the
  // faces in avoid (the contact faces) and carry no load.
  void
  Component::pin_free_motions(const std::vector<std::string> &avoid)
  {
    std::vector<bool> held(n_dofs());
    for (unsigned int i = 0; i < n_dofs(); ++i)
      held[i] = constraints_.is_constrained(i);
    const double                      size    = size_of(description_);
    const std::vector<Vector<double>> motions = rigid_body_motions();
    const FullMatrix<double> v = free_combinations(motions, held, size);
    const unsigned int       r = v.n();
    if (r == 0)
      return;

    // The free motions, of unit size (a rotation of 1/size radians), zero
    // on the held DoFs.
    for (unsigned int j = 0; j < r; ++j)
      {
        Vector<double> field(n_dofs());
        for (unsigned int a = 0; a < 3; ++a)
          field.add(v(a, j) / (a == 2 ? size : 1.), motions[a]);
        for (unsigned int i = 0; i < n_dofs(); ++i)
          if (held[i])
            field[i] = 0;
        free_motions_.push_back(std::move(field));
        free_motion_names_.push_back(
          describe(v(0, j), v(1, j), v(2, j), description_));
        free_motion_angles_.push_back(std::abs(v(2, j)) > 1e-6 ? v(2, j) / size
                                                               : 0.);
      }

    // DoFs the pins must avoid: those of the contact faces and the loads.
    std::set<types::boundary_id> faces;
    for (const std::string &face : avoid)
      faces.insert(
        description_.boundary_id(face, "Component " + name() + ": face"));
    for (const EdgeLoad &load : description_.loads)
      if (!load.is_displacement && !load.is_weight) // (the weight: no face)
        faces.insert(description_.boundary_id(load.face,
                                              "Component " + name() +
                                                ", load " + load.name));
    std::vector<bool>                    excluded = held;
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_face());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && faces.count(face->boundary_id()) > 0)
          {
            face->get_dof_indices(dofs);
            for (const types::global_dof_index d : dofs)
              excluded[d] = true;
          }

    // rows[i]: DoF i's row of the free motions, projected as pins are
    // chosen (modified Gram-Schmidt on the chosen rows).
    std::vector<std::vector<double>> rows(n_dofs(), std::vector<double>(r));
    for (unsigned int i = 0; i < n_dofs(); ++i)
      for (unsigned int j = 0; j < r; ++j)
        rows[i][j] = free_motions_[j][i];
    const auto norm = [&](const std::vector<double> &x) {
      double s = 0;
      for (const double e : x)
        s += e * e;
      return std::sqrt(s);
    };
    for (unsigned int j = 0; j < r; ++j)
      {
        int best = -1;
        for (unsigned int i = 0; i < n_dofs(); ++i)
          if (!excluded[i] && (best < 0 || norm(rows[i]) > norm(rows[best])))
            best = i;
        AssertThrow(best >= 0 && norm(rows[best]) > 1e-8,
                    ExcMessage("Component " + name() +
                               ": it is held by contact alone (" +
                               free_motion_names_[j] +
                               " is free), but it has no node off its "
                               "contact and loaded faces to fix that motion "
                               "for the solvers. Refine its mesh, or hold it "
                               "by a support."));
        pinned_dofs_.push_back(best);
        excluded[best]               = true;
        const std::vector<double> q  = rows[best];
        const double              qq = norm(q) * norm(q);
        for (unsigned int i = 0; i < n_dofs(); ++i)
          {
            double dot = 0;
            for (unsigned int k = 0; k < r; ++k)
              dot += rows[i][k] * q[k];
            for (unsigned int k = 0; k < r; ++k)
              rows[i][k] -= dot / qq * q[k];
          }
      }
    for (const types::global_dof_index d : pinned_dofs_)
      constraints_.add_line(d);
  }


  const std::vector<Vector<double>> &
  Component::free_motions() const
  {
    return free_motions_;
  }


  const std::vector<std::string> &
  Component::free_motion_names() const
  {
    return free_motion_names_;
  }


  const std::vector<double> &
  Component::free_motion_angles() const
  {
    return free_motion_angles_;
  }


  Vector<double>
  Component::rigid_part(const Vector<double> &u) const
  {
    const unsigned int       r = free_motions_.size();
    LAPACKFullMatrix<double> normal(r, r);
    Vector<double>           a(r);
    for (unsigned int i = 0; i < r; ++i)
      {
        a[i] = free_motions_[i] * u;
        for (unsigned int j = 0; j < r; ++j)
          normal(i, j) = free_motions_[i] * free_motions_[j];
      }
    if (r > 0)
      {
        normal.compute_lu_factorization();
        normal.solve(a);
      }
    return a;
  }


  const std::vector<types::global_dof_index> &
  Component::pinned_dofs() const
  {
    return pinned_dofs_;
  }


  Vector<double>
  Component::rigid_load(const unsigned int l) const
  {
    // The pins lie off the loaded faces and the supports' DoFs do not move
    // in a free motion, so the condensed load vector has the whole
    // resultant along each free motion. The forces that impose a
    // displacement have none (R^T K = 0 and R vanishes where the support
    // holds), and need no assembly to say so.
    Vector<double> e(free_motions_.size());
    if (e.size() == 0 || description_.loads[l].is_displacement)
      return e;
    // The weight acts on every DoF, the pins too: its resultant comes from
    // its zone forces in full (weight_zone_resultants()).
    if (description_.loads[l].is_weight)
      {
        for (unsigned int z = 0; z < n_zones(); ++z)
          e.add(zone_densities_[z] * reference_load_force(l),
                weight_zone_resultants()[z]);
        return e;
      }
    const Vector<double> f = reference_load_vector(l);
    for (unsigned int j = 0; j < free_motions_.size(); ++j)
      e[j] = free_motions_[j] * f;
    return e;
  }
} // namespace FuzzyContact
