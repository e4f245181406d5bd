#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/scene/mesh_file.h>

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/fe/mapping_q1.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/numerics/vector_tools.h>

#include <cmath>
#include <memory>
#include <sstream>

namespace FuzzyContact
{
  SymmetricTensor<4, 2>
  elasticity_tensor(const PlaneModel model, const double E, const double nu)
  {
    const double mu = E / (2. * (1. + nu));
    // Plane stress eliminates sigma_zz = 0, plane strain eps_zz = 0; both
    // leave the same isotropic form in the plane with different lambda.
    const double          lambda = model == PlaneModel::plane_stress
                                     ? E * nu / (1. - nu * nu)
                                     : E * nu / ((1. + nu) * (1. - 2. * nu));
    SymmetricTensor<4, 2> C;
    for (unsigned int i = 0; i < 2; ++i)
      for (unsigned int j = 0; j < 2; ++j)
        for (unsigned int k = 0; k < 2; ++k)
          for (unsigned int l = 0; l < 2; ++l)
            C[i][j][k][l] = (i == j && k == l ? lambda : 0.) +
                            ((i == k && j == l) ? mu : 0.) +
                            ((i == l && j == k) ? mu : 0.);
    return C;
  }


  namespace
  {
    // Element loop shared by the zone-wise and the direct assembly: for the
    // cell of zone z, target(z) names the stiffness and mass matrices to add
    // into and the modulus and density to scale them with.
    struct AssemblyTarget
    {
      SparseMatrix<double> *stiffness;
      double                modulus;
      SparseMatrix<double> *mass;
      double                density;
    };

    // The cell matrix of zone z with unit modulus, for what else needs it.
    struct NoCellHook
    {
      void
      operator()(const unsigned int,
                 const FullMatrix<double> &,
                 const std::vector<types::global_dof_index> &) const
      {
      }
    };

    template <typename TargetFunction, typename CellHook = NoCellHook>
    void
    assemble_elasticity(const Mapping<2>                &mapping,
                        const DoFHandler<2>             &dof_handler,
                        const AffineConstraints<double> &constraints,
                        const ComponentDescription      &description,
                        const PlaneModel                 model,
                        const TargetFunction            &target,
                        const CellHook                  &cell_hook = CellHook())
    {
      const FiniteElement<2>              &fe = dof_handler.get_fe();
      const QGauss<2>                      quadrature(fe.degree + 1);
      FEValues<2>                          fe_values(mapping,
                            fe,
                            quadrature,
                            update_values | update_gradients |
                              update_JxW_values);
      const FEValuesExtractors::Vector     displacement(0);
      const unsigned int                   n = fe.n_dofs_per_cell();
      FullMatrix<double>                   cell_k(n, n), cell_m(n, n);
      std::vector<types::global_dof_index> dofs(n);
      std::vector<SymmetricTensor<2, 2>>   eps(n);
      std::vector<Tensor<1, 2>>            phi(n);
      const double                         t = description.thickness;

      std::vector<SymmetricTensor<4, 2>> C;
      for (const MaterialZone &zone : description.zones)
        C.push_back(elasticity_tensor(model, 1.0, zone.poissons_ratio));

      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          const unsigned int   z  = cell->material_id();
          const AssemblyTarget to = target(z);
          fe_values.reinit(cell);
          cell_k = 0;
          cell_m = 0;
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              for (unsigned int i = 0; i < n; ++i)
                {
                  eps[i] = fe_values[displacement].symmetric_gradient(i, q);
                  phi[i] = fe_values[displacement].value(i, q);
                }
              const double dx = fe_values.JxW(q) * t;
              for (unsigned int i = 0; i < n; ++i)
                {
                  const SymmetricTensor<2, 2> sigma_i = C[z] * eps[i];
                  for (unsigned int j = 0; j <= i; ++j)
                    {
                      cell_k(i, j) += (sigma_i * eps[j]) * dx;
                      cell_m(i, j) += (phi[i] * phi[j]) * dx;
                    }
                }
            }
          for (unsigned int i = 0; i < n; ++i)
            for (unsigned int j = i + 1; j < n; ++j)
              {
                cell_k(i, j) = cell_k(j, i);
                cell_m(i, j) = cell_m(j, i);
              }
          cell->get_dof_indices(dofs);
          cell_hook(z, cell_k, dofs);
          cell_k *= to.modulus;
          cell_m *= to.density;
          constraints.distribute_local_to_global(cell_k, dofs, *to.stiffness);
          constraints.distribute_local_to_global(cell_m, dofs, *to.mass);
        }
    }

    // Clamped DoFs carry no mass (see the class documentation).
    void
    remove_constrained_mass(const AffineConstraints<double> &constraints,
                            SparseMatrix<double>            &M)
    {
      for (const auto &line : constraints.get_lines())
        M.set(line.index, line.index, 0.);
    }
  } // namespace


  Component::Component(const ComponentDescription &description,
                       const PlaneModel            plane_model,
                       const unsigned int          n_refinements,
                       TimerOutput                *timer)
      : Component(description, plane_model, n_refinements, timer, {})
  {
  }


  Component::Component(const ComponentDescription     &description,
                       const PlaneModel                plane_model,
                       const unsigned int              n_refinements,
                       TimerOutput                    *timer,
                       const std::vector<std::string> &contact_faces,
                       const bool                      assemble)
      : description_(description)
      , plane_model_(plane_model)
      , fe_(FE_Q<2>(description.fe_degree), 2)
      , dof_handler_(triangulation_)
  {
    // Curved boundaries need a mapping of the element's degree to put the
    // nodes and quadrature points on the arcs; straight ones are exact
    // with the bilinear mapping.
    if (description_.mesh.arcs.empty())
      mapping_ = std::make_unique<MappingQ1<2>>();
    else
      mapping_ = std::make_unique<MappingQ<2>>(description_.fe_degree);
    AssertThrow(description_.zones.size() <= 255,
                ExcMessage("Component " + name() +
                           ": at most 255 material zones are supported."));
    for (const MaterialZone &zone : description_.zones)
      {
        zone_moduli_.push_back(zone.youngs_modulus);
        zone_densities_.push_back(zone.density);
      }
    for (unsigned int l = 0; l < description_.loads.size(); ++l)
      if (description_.loads[l].is_weight)
        weight_load_ = l;
    {
      std::unique_ptr<TimerOutput::Scope> scope;
      if (timer != nullptr)
        scope = std::make_unique<TimerOutput::Scope>(*timer, "mesh and DoFs");
      make_mesh(n_refinements);
      setup_dofs(contact_faces);
    }
    if (assemble)
      {
        std::unique_ptr<TimerOutput::Scope> scope;
        if (timer != nullptr)
          scope = std::make_unique<TimerOutput::Scope>(*timer, "assembly");
        ensure_matrices();
        ensure_loads();
        form_global_matrices();
      }
  }


  bool
  Component::is_assembled() const
  {
    return assembled_;
  }


  void
  Component::ensure_matrices() const
  {
    if (assembled_)
      return;
    DynamicSparsityPattern dsp(dof_handler_.n_dofs());
    DoFTools::make_sparsity_pattern(dof_handler_,
                                    dsp,
                                    constraints_,
                                    /*keep_constrained_dofs=*/false);
    sparsity_pattern_.copy_from(dsp);
    assemble_zone_matrices();
    assembled_ = true;
  }


  void
  Component::ensure_loads() const
  {
    if (loads_assembled_)
      return;
    // The loads of prescribed displacements come from the cell matrices.
    if (!displacement_fields_.empty() && !displacement_loads_formed_)
      ensure_matrices();
    assemble_loads();
    loads_assembled_ = true;
  }


  // A mesh file's cells take the index of the zone of their physical
  // surface as material id (every cell the implicit zone 0).
  void
  Component::make_mesh_from_file()
  {
    const ComponentDescription &d     = description_;
    const std::string           where = "Component " + name() + ": mesh file";
    create_mesh(d.mesh, d.scale, triangulation_, where);
    std::map<types::material_id, unsigned int> zone_of;
    for (unsigned int z = 0; z < d.zones.size(); ++z)
      zone_of[d.zones[z].material_id] = z;
    for (const auto &cell : triangulation_.active_cell_iterators())
      {
        if (d.implicit_zone)
          {
            cell->set_material_id(0);
            continue;
          }
        const auto z = zone_of.find(cell->material_id());
        if (z == zone_of.end())
          {
            std::ostringstream message;
            message << "Component " << name() << ": the cell centred at ("
                    << cell->center()[0] << ", " << cell->center()[1]
                    << ") of <" << d.mesh_file
                    << "> lies in no zone the component lists ("
                    << d.mesh.zone_kind() << " id " << cell->material_id()
                    << (d.mesh.abaqus ? ", 0: in no element set" : "")
                    << "); list every " << d.mesh.zone_kind()
                    << " of the file in 'zones' (it has: "
                    << d.mesh.zone_names() << "), or none.";
            AssertThrow(false, ExcMessage(message.str()));
          }
        cell->set_material_id(z->second);
      }
  }


  // The rectangle, with boundary ids left = 0, right = 1, bottom = 2,
  // top = 3, and the zone index of each cell as its material id. A zone whose
  // edges do not follow mesh lines would silently be a different zone, so the
  // area each zone receives is compared with the area it declares.
  void
  Component::make_mesh(const unsigned int n_refinements)
  {
    const ComponentDescription &d = description_;
    if (!d.is_rectangle())
      {
        make_mesh_from_file();
        triangulation_.refine_global(n_refinements);
        return;
      }
    GridGenerator::subdivided_hyper_rectangle(
      triangulation_,
      std::vector<unsigned int>{d.subdivisions[0], d.subdivisions[1]},
      d.lower_left,
      d.upper_right,
      /*colorize=*/true);

    const unsigned int  n_zones = d.zones.size();
    std::vector<double> area(n_zones, 0.);
    for (const auto &cell : triangulation_.active_cell_iterators())
      {
        const Point<2> c = cell->center();
        int            z = -1;
        for (unsigned int k = 0; k < n_zones; ++k)
          {
            const MaterialZone &zone = d.zones[k];
            if (c[0] > zone.x_range[0] && c[0] < zone.x_range[1] &&
                c[1] > zone.y_range[0] && c[1] < zone.y_range[1])
              {
                AssertThrow(z < 0,
                            ExcMessage("Component " + name() + ": zones " +
                                       d.zones[z].name + " and " + zone.name +
                                       " overlap."));
                z = static_cast<int>(k);
              }
          }
        if (z < 0)
          {
            std::ostringstream message;
            message << "Component " << name() << ": the cell centred at ("
                    << c[0] << ", " << c[1]
                    << ") lies in no material zone; the zones must cover "
                       "the whole component.";
            AssertThrow(false, ExcMessage(message.str()));
          }
        cell->set_material_id(static_cast<types::material_id>(z));
        area[z] += cell->measure();
      }

    const double total = d.length() * d.height();
    for (unsigned int k = 0; k < n_zones; ++k)
      {
        const MaterialZone &zone = d.zones[k];
        const double        w    = std::min(zone.x_range[1], d.upper_right[0]) -
                         std::max(zone.x_range[0], d.lower_left[0]);
        const double h = std::min(zone.y_range[1], d.upper_right[1]) -
                         std::max(zone.y_range[0], d.lower_left[1]);
        const double declared = std::max(w, 0.) * std::max(h, 0.);
        if (std::abs(declared - area[k]) > 1e-9 * total)
          {
            std::ostringstream message;
            message << "Component " << name() << ", zone " << zone.name
                    << ": its edges do not lie on mesh lines (the cells whose "
                       "centres it contains cover "
                    << area[k] << " m^2 instead of the " << declared
                    << " m^2 it declares); choose subdivisions that fit the "
                       "zone, or a zone that fits the mesh.";
            AssertThrow(false, ExcMessage(message.str()));
          }
      }

    triangulation_.refine_global(n_refinements);
  }


  void
  Component::setup_dofs(const std::vector<std::string> &contact_faces)
  {
    dof_handler_.distribute_dofs(fe_);
    support_points_.resize(dof_handler_.n_dofs());
    DoFTools::map_dofs_to_support_points(*mapping_,
                                         dof_handler_,
                                         support_points_);

    dof_directions_.resize(dof_handler_.n_dofs());
    std::vector<types::global_dof_index> dofs(fe_.n_dofs_per_cell());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < dofs.size(); ++i)
          dof_directions_[dofs[i]] = fe_.system_to_component_index(i).first;
      }

    // The supports hold their DoFs in the order listed (a node shared by
    // two supports is held by the first). A prescribed displacement keeps
    // the constraint homogeneous: its value enters through the load of the
    // support (assemble_zone_matrices()), with the field of unit
    // magnitude along its direction kept in displacement_fields_.
    constraints_.clear();
    displacement_fields_.clear();
    prescribed_.assign(dof_handler_.n_dofs(), false);
    for (const Support &support : description_.all_supports())
      {
        const std::string where =
          "Component " + name() + ", support " + support.name;
        std::map<types::global_dof_index, double> held;
        VectorTools::interpolate_boundary_values(
          *mapping_,
          dof_handler_,
          description_.boundary_id(support.face, where + ": face"),
          Functions::ZeroFunction<2>(2),
          held,
          ComponentMask(std::vector<bool>{support.fixed[0], support.fixed[1]}));
        const double   magnitude = support.displacement.norm();
        Vector<double> field(magnitude > 0 ? dof_handler_.n_dofs() : 0);
        unsigned int   n_held = 0;
        for (const auto &[dof, value] : held)
          if (!constraints_.is_constrained(dof))
            {
              constraints_.add_line(dof);
              ++n_held;
              if (magnitude > 0)
                field[dof] =
                  support.displacement[dof_directions_[dof]] / magnitude;
            }
        // Sharing a few nodes (corners) is fine; a support that holds
        // nothing would be silently ignored (Scene::read refuses one whose
        // face and components earlier supports already fix).
        AssertThrow(n_held > 0,
                    ExcMessage(where + ": it holds no DoF of the face '" +
                               support.face +
                               "': the supports listed before it hold them "
                               "all."));
        if (magnitude > 0)
          {
            for (unsigned int i = 0; i < field.size(); ++i)
              prescribed_[i] = prescribed_[i] || field[i] != 0;
            displacement_fields_.push_back(std::move(field));
          }
      }
    if (!contact_faces.empty())
      pin_free_motions(contact_faces);
    constraints_.close();
  }


  void
  Component::assemble_zone_matrices() const
  {
    const unsigned int n_zones = description_.zones.size();
    zone_stiffness_.resize(n_zones);
    zone_mass_.resize(n_zones);
    for (unsigned int z = 0; z < n_zones; ++z)
      {
        zone_stiffness_[z].reinit(sparsity_pattern_);
        zone_mass_[z].reinit(sparsity_pattern_);
      }
    assemble_elasticity(
      *mapping_,
      dof_handler_,
      constraints_,
      description_,
      plane_model_,
      [this](const unsigned int z) {
        return AssemblyTarget{&zone_stiffness_[z], 1., &zone_mass_[z], 1.};
      },
      [this](const unsigned int                          z,
             const FullMatrix<double>                   &cell_k,
             const std::vector<types::global_dof_index> &dofs) {
        if (!displacement_loads_formed_)
          add_displacement_loads(z, cell_k, dofs);
      });
    for (SparseMatrix<double> &M : zone_mass_)
      remove_constrained_mass(constraints_, M);
    if (displacement_loads_formed_)
      return; // given (set_displacement_zone_loads())
    displacement_loads_formed_ = true;
    // On the held rows, K's diagonal times the displacement: the solution
    // there is the displacement itself.
    for (unsigned int s = 0; s < displacement_fields_.size(); ++s)
      for (unsigned int i = 0; i < displacement_fields_[s].size(); ++i)
        if (displacement_fields_[s][i] != 0)
          for (unsigned int z = 0; z < n_zones; ++z)
            displacement_zone_loads_[s][z][i] =
              zone_stiffness_[z].diag_element(i) * displacement_fields_[s][i];
  }


  void
  Component::assemble_directly(SparseMatrix<double> &K,
                               SparseMatrix<double> &M) const
  {
    ensure_matrices();
    K.reinit(sparsity_pattern_);
    M.reinit(sparsity_pattern_);
    assemble_elasticity(
      *mapping_,
      dof_handler_,
      constraints_,
      description_,
      plane_model_,
      [&](const unsigned int z) {
        return AssemblyTarget{&K, zone_moduli_[z], &M, zone_densities_[z]};
      });
    remove_constrained_mass(constraints_, M);
  }


  void
  Component::form_global_matrices() const
  {
    ensure_matrices();
    if (stiffness_.empty())
      {
        stiffness_.reinit(sparsity_pattern_);
        mass_.reinit(sparsity_pattern_);
      }
    stiffness_ = 0;
    mass_      = 0;
    for (unsigned int z = 0; z < zone_stiffness_.size(); ++z)
      {
        stiffness_.add(zone_moduli_[z], zone_stiffness_[z]);
        mass_.add(zone_densities_[z], zone_mass_[z]);
      }
    matrices_current_ = true;
  }


  void
  Component::set_zone_materials(const std::vector<double> &moduli,
                                const std::vector<double> &densities)
  {
    AssertThrow(moduli.size() == n_zones() && densities.size() == n_zones(),
                ExcMessage("Component " + name() + ": expected " +
                           std::to_string(n_zones()) +
                           " zone moduli and densities."));
    for (unsigned int z = 0; z < n_zones(); ++z)
      {
        const std::string where =
          "Component " + name() + ", zone " + description_.zones[z].name;
        Input::positive(moduli[z], where + ": E");
        Input::positive(densities[z], where + ": rho");
      }
    zone_moduli_      = moduli;
    zone_densities_   = densities;
    matrices_current_ = false;
    // (Loads not yet assembled are assembled at these materials.)
    if ((!displacement_fields_.empty() || weight_load_ >= 0) &&
        loads_assembled_)
      update_material_loads();
  }


  const Mapping<2> &
  Component::mapping() const
  {
    return *mapping_;
  }


  std::array<types::global_dof_index, 2>
  Component::vertex_dofs(const Point<2> &p) const
  {
    const double tolerance =
      1e-10 * std::max(description_.length(), description_.height());
    for (const auto &cell : dof_handler_.active_cell_iterators())
      for (const unsigned int v : cell->vertex_indices())
        if (cell->vertex(v).distance(p) < tolerance)
          return {{cell->vertex_dof_index(v, 0), cell->vertex_dof_index(v, 1)}};
    std::ostringstream message;
    message << "Component " << name() << " has no mesh vertex at (" << p[0]
            << ", " << p[1] << ").";
    AssertThrow(false, ExcMessage(message.str()));
    return {{0, 0}};
  }


  const std::string &
  Component::name() const
  {
    return description_.name;
  }

  const ComponentDescription &
  Component::description() const
  {
    return description_;
  }

  PlaneModel
  Component::plane_model() const
  {
    return plane_model_;
  }

  unsigned int
  Component::n_dofs() const
  {
    return dof_handler_.n_dofs();
  }

  const Triangulation<2> &
  Component::triangulation() const
  {
    return triangulation_;
  }

  const DoFHandler<2> &
  Component::dof_handler() const
  {
    return dof_handler_;
  }

  const FESystem<2> &
  Component::fe() const
  {
    return fe_;
  }

  const AffineConstraints<double> &
  Component::constraints() const
  {
    return constraints_;
  }

  bool
  Component::is_constrained(const types::global_dof_index dof) const
  {
    return constraints_.is_constrained(dof);
  }

  unsigned int
  Component::n_zones() const
  {
    return description_.zones.size();
  }

  const SparseMatrix<double> &
  Component::zone_stiffness_matrix(const unsigned int zone) const
  {
    AssertIndexRange(zone, n_zones());
    ensure_matrices();
    return zone_stiffness_[zone];
  }

  const SparseMatrix<double> &
  Component::zone_mass_matrix(const unsigned int zone) const
  {
    AssertIndexRange(zone, n_zones());
    ensure_matrices();
    return zone_mass_[zone];
  }

  const std::vector<double> &
  Component::zone_moduli() const
  {
    return zone_moduli_;
  }

  const std::vector<double> &
  Component::zone_densities() const
  {
    return zone_densities_;
  }

  const SparseMatrix<double> &
  Component::stiffness_matrix() const
  {
    if (!matrices_current_)
      form_global_matrices();
    return stiffness_;
  }

  const SparseMatrix<double> &
  Component::mass_matrix() const
  {
    if (!matrices_current_)
      form_global_matrices();
    return mass_;
  }

  const SparsityPattern &
  Component::sparsity_pattern() const
  {
    ensure_matrices();
    return sparsity_pattern_;
  }


  const std::vector<Point<2>> &
  Component::support_points() const
  {
    return support_points_;
  }

  const std::vector<unsigned char> &
  Component::dof_directions() const
  {
    return dof_directions_;
  }
} // namespace FuzzyContact
