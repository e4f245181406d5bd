// The loads of a Component (fe/component.h): edge loads and pressures on
// named faces, and the forces that impose a support's prescribed
// displacement.

#include <fuzzycontact/fe/component.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  // Adds -K_fp u_p of one cell (unit modulus, zone z) to the free rows of
  // each support displacement's load.
  void
  Component::add_displacement_loads(
    const unsigned int                          z,
    const FullMatrix<double>                   &cell_k,
    const std::vector<types::global_dof_index> &dofs) const
  {
    if (displacement_fields_.empty())
      return;
    if (displacement_zone_loads_.empty())
      displacement_zone_loads_.assign(
        displacement_fields_.size(),
        std::vector<Vector<double>>(description_.zones.size(),
                                    Vector<double>(dof_handler_.n_dofs())));
    for (unsigned int s = 0; s < displacement_fields_.size(); ++s)
      {
        const Vector<double> &field = displacement_fields_[s];
        for (unsigned int j = 0; j < dofs.size(); ++j)
          if (field[dofs[j]] != 0)
            for (unsigned int i = 0; i < dofs.size(); ++i)
              if (!constraints_.is_constrained(dofs[i]))
                displacement_zone_loads_[s][z][dofs[i]] -=
                  cell_k(i, j) * field[dofs[j]];
      }
  }

  // The load of each support displacement at the current zone moduli, and
  // the weight at the current densities.
  void
  Component::update_material_loads() const
  {
    unsigned int s = 0;
    load_.reinit(dof_handler_.n_dofs());
    for (unsigned int l = 0; l < description_.loads.size(); ++l)
      {
        if (description_.loads[l].is_displacement)
          {
            unit_loads_[l] = 0;
            for (unsigned int z = 0; z < n_zones(); ++z)
              unit_loads_[l].add(zone_moduli_[z],
                                 displacement_zone_loads_[s][z]);
            ++s;
          }
        if (description_.loads[l].is_weight)
          {
            unit_loads_[l] = 0;
            for (unsigned int z = 0; z < n_zones(); ++z)
              unit_loads_[l].add(zone_densities_[z], weight_zone_loads_[z]);
          }
        load_.add(description_.loads[l].total_force, unit_loads_[l]);
      }
  }


  // w_z = t int_z N^T d dx per zone, condensed (supports and pins left
  // out) and in full for its resultants along the free motions.
  void
  Component::assemble_weight() const
  {
    const Tensor<1, 2> d =
      description_.loads[weight_load_].direction * description_.thickness;
    const QGauss<2>                      quadrature(fe_.degree + 1);
    FEValues<2>                          fe_values(*mapping_,
                          fe_,
                          quadrature,
                          update_values | update_JxW_values);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n = fe_.n_dofs_per_cell();
    Vector<double>                       cell_f(n);
    std::vector<types::global_dof_index> dofs(n);
    weight_zone_loads_.assign(n_zones(), Vector<double>(n_dofs()));
    std::vector<Vector<double>> full(n_zones(), Vector<double>(n_dofs()));
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        fe_values.reinit(cell);
        cell_f = 0;
        for (const unsigned int q : fe_values.quadrature_point_indices())
          for (unsigned int i = 0; i < n; ++i)
            cell_f(i) +=
              fe_values[displacement].value(i, q) * d * fe_values.JxW(q);
        cell->get_dof_indices(dofs);
        const unsigned int z = cell->material_id();
        constraints_.distribute_local_to_global(cell_f,
                                                dofs,
                                                weight_zone_loads_[z]);
        full[z].add(dofs, cell_f);
      }
    weight_zone_resultants_.assign(n_zones(),
                                   Vector<double>(free_motions_.size()));
    for (unsigned int z = 0; z < n_zones(); ++z)
      for (unsigned int j = 0; j < free_motions_.size(); ++j)
        weight_zone_resultants_[z][j] = free_motions_[j] * full[z];
  }


  int
  Component::weight_load() const
  {
    return weight_load_;
  }


  const std::vector<Vector<double>> &
  Component::weight_zone_loads() const
  {
    ensure_loads();
    return weight_zone_loads_;
  }


  const std::vector<Vector<double>> &
  Component::weight_zone_resultants() const
  {
    ensure_loads();
    return weight_zone_resultants_;
  }

  const std::vector<std::vector<Vector<double>>> &
  Component::displacement_zone_loads() const
  {
    if (!displacement_loads_formed_)
      ensure_matrices();
    return displacement_zone_loads_;
  }

  void
  Component::set_displacement_zone_loads(
    const std::vector<std::vector<Vector<double>>> &loads)
  {
    bool fits = loads.size() == displacement_fields_.size();
    for (const auto &support : loads)
      {
        fits = fits && support.size() == n_zones();
        for (const Vector<double> &f : support)
          fits = fits && f.size() == n_dofs();
      }
    AssertThrow(fits,
                ExcMessage("Component " + name() +
                           ": the forces of its prescribed displacements "
                           "given do not fit its supports, zones and DoFs."));
    displacement_zone_loads_   = loads;
    displacement_loads_formed_ = true;
    if (loads_assembled_)
      update_material_loads();
  }

  bool
  Component::is_prescribed(const types::global_dof_index dof) const
  {
    AssertIndexRange(dof, prescribed_.size());
    return prescribed_[dof];
  }

  // Each load is a constant traction F d / (face length * t) on its face;
  // the unit vector holds the nodal forces for F = 1 N.
  void
  Component::assemble_loads() const
  {
    const QGauss<1>                      face_quadrature(fe_.degree + 1);
    FEFaceValues<2>                      fe_face_values(*mapping_,
                                   fe_,
                                   face_quadrature,
                                   update_values | update_JxW_values |
                                     update_normal_vectors);
    const FEValuesExtractors::Vector     displacement(0);
    const unsigned int                   n = fe_.n_dofs_per_cell();
    Vector<double>                       cell_f(n);
    std::vector<types::global_dof_index> dofs(n);

    unit_loads_.clear();
    load_.reinit(dof_handler_.n_dofs());
    for (const EdgeLoad &load : description_.loads)
      {
        if (load.is_displacement || load.is_weight)
          {
            unit_loads_.emplace_back(dof_handler_.n_dofs());
            continue; // update_material_loads() forms it
          }
        const types::boundary_id id =
          description_.boundary_id(load.face,
                                   "Component " + name() + ", load " +
                                     load.name);
        const double   length = boundary_length(id);
        Vector<double> f(dof_handler_.n_dofs());
        for (const auto &cell : dof_handler_.active_cell_iterators())
          for (const auto &face : cell->face_iterators())
            if (face->at_boundary() && face->boundary_id() == id)
              {
                fe_face_values.reinit(cell, face);
                cell_f = 0;
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  {
                    // Per unit length: F d / L for a total force, -p t n
                    // for a pressure (per Pa).
                    const Tensor<1, 2> traction_times_t =
                      load.is_pressure
                        ? Tensor<1, 2>(-description_.thickness *
                                       fe_face_values.normal_vector(q))
                        : load.direction / length;
                    for (unsigned int i = 0; i < n; ++i)
                      cell_f(i) += fe_face_values[displacement].value(i, q) *
                                   traction_times_t * fe_face_values.JxW(q);
                  }
                cell->get_dof_indices(dofs);
                constraints_.distribute_local_to_global(cell_f, dofs, f);
              }
        unit_loads_.push_back(std::move(f));
      }
    if (weight_load_ >= 0)
      assemble_weight();
    update_material_loads();
  }

  double
  Component::boundary_length(const types::boundary_id id) const
  {
    const QGauss<1> quadrature(fe_.degree + 1);
    FEFaceValues<2> values(*mapping_, fe_, quadrature, update_JxW_values);
    double          length = 0;
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const auto &face : cell->face_iterators())
        if (face->at_boundary() && face->boundary_id() == id)
          {
            values.reinit(cell, face);
            for (const unsigned int q : values.quadrature_point_indices())
              length += values.JxW(q);
          }
    return length;
  }

  const Vector<double> &
  Component::load_vector() const
  {
    ensure_loads();
    return load_;
  }

  const Vector<double> &
  Component::unit_load_vector(const unsigned int l) const
  {
    ensure_loads();
    AssertIndexRange(l, unit_loads_.size());
    return unit_loads_[l];
  }

  double
  Component::reference_load_force(const unsigned int l) const
  {
    AssertIndexRange(l, description_.loads.size());
    const double declared = description_.loads[l].total_force;
    return declared != 0 ? declared : 1.;
  }

  Vector<double>
  Component::reference_load_vector(const unsigned int l) const
  {
    Vector<double> f = unit_load_vector(l);
    f *= reference_load_force(l);
    return f;
  }

} // namespace FuzzyContact
