#include <fuzzycontact/fe/patch_test.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  namespace PatchTest
  {
    double
    UniaxialCompression::axial_strain() const
    {
      return -shortening / height;
    }


    double
    UniaxialCompression::lateral_strain() const
    {
      const double nu = poissons_ratio;
      return (plane_model == PlaneModel::plane_stress ? -nu : -nu / (1 - nu)) *
             axial_strain();
    }


    double
    UniaxialCompression::pressure() const
    {
      const double nu      = poissons_ratio;
      const double E_plane = plane_model == PlaneModel::plane_stress
                               ? youngs_modulus
                               : youngs_modulus / (1 - nu * nu);
      return -E_plane * axial_strain();
    }


    Tensor<1, 2>
    UniaxialCompression::displacement(const Point<2> &x) const
    {
      Tensor<1, 2> u;
      u[0] = lateral_strain() * x[0];
      u[1] = axial_strain() * x[1];
      return u;
    }


    Vector<double>
    internal_forces(const Component &component, const Vector<double> &u)
    {
      const DoFHandler<2>               &dof_handler = component.dof_handler();
      const FiniteElement<2>            &fe          = dof_handler.get_fe();
      const QGauss<2>                    quadrature(fe.degree + 1);
      FEValues<2>                        fe_values(component.mapping(),
                            fe,
                            quadrature,
                            update_gradients | update_JxW_values);
      const FEValuesExtractors::Vector   displacement(0);
      const ComponentDescription        &description = component.description();
      std::vector<SymmetricTensor<4, 2>> C;
      for (unsigned int z = 0; z < description.zones.size(); ++z)
        C.push_back(elasticity_tensor(component.plane_model(),
                                      component.zone_moduli()[z],
                                      description.zones[z].poissons_ratio));
      std::vector<SymmetricTensor<2, 2>>   eps(quadrature.size());
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      Vector<double>                       forces(component.n_dofs());
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          fe_values.reinit(cell);
          fe_values[displacement].get_function_symmetric_gradients(u, eps);
          cell->get_dof_indices(dofs);
          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              const SymmetricTensor<2, 2> sigma =
                C[cell->material_id()] * eps[q];
              const double dx = fe_values.JxW(q) * description.thickness;
              for (unsigned int i = 0; i < dofs.size(); ++i)
                forces[dofs[i]] +=
                  sigma * fe_values[displacement].symmetric_gradient(i, q) * dx;
            }
        }
      return forces;
    }


    namespace
    {
      // The pressure errors of pair 0's slave nodes.
      void
      measure_pressure(const std::vector<const Component *> &components,
                       const ContactInterface               &interface,
                       const ContactSolution                &solution,
                       const UniaxialCompression            &exact,
                       Errors                               &errors)
      {
        const double p              = exact.pressure();
        double       sum_of_squares = 0;
        for (unsigned int k = 0; k < interface.n_nodes(); ++k)
          {
            const ContactNode &node = interface.node(k);
            if (node.pair != 0)
              continue;
            const double t =
              components[node.slave.component]->description().thickness;
            const double e =
              solution.p_n(k) / (node.tributary_length * t) / p - 1;
            ++errors.n_slave_nodes;
            errors.exact_force += p * node.tributary_length * t;
            if (solution.status[k] != ContactStatus::open)
              ++errors.n_closed;
            errors.max_pressure_error =
              std::max(errors.max_pressure_error, std::abs(e));
            sum_of_squares += e * e;
          }
        AssertThrow(errors.n_slave_nodes > 0,
                    ExcMessage("patch test: the pair has no slave node."));
        errors.rms_pressure_error =
          std::sqrt(sum_of_squares / errors.n_slave_nodes);
      }
    } // namespace


    Errors
    measure(const std::vector<const Component *> &components,
            const ContactInterface               &interface,
            const ContactSolution                &solution,
            const UniaxialCompression            &exact)
    {
      AssertThrow(solution.displacements.size() == components.size(),
                  ExcMessage("patch test: the solution has no displacements."));
      Errors errors{};
      measure_pressure(components, interface, solution, exact, errors);

      errors.contact_force = solution.normal_force;
      const std::vector<Vector<double>> contact =
        interface.nodal_forces(solution.p);
      double largest_u = 0, largest_error = 0;
      for (unsigned int c = 0; c < components.size(); ++c)
        {
          const Component      &component = *components[c];
          const Vector<double> &u         = solution.displacements[c];
          const auto           &points    = component.support_points();
          const auto           &direction = component.dof_directions();
          const Vector<double>  forces    = internal_forces(component, u);
          double                reaction  = 0;
          for (unsigned int i = 0; i < component.n_dofs(); ++i)
            {
              const double exact_u =
                exact.displacement(points[i])[direction[i]];
              largest_u     = std::max(largest_u, std::abs(exact_u));
              largest_error = std::max(largest_error, std::abs(u[i] - exact_u));
              const double residual = forces[i] - contact[c][i];
              if (!component.is_constrained(i))
                errors.equilibrium_residual =
                  std::max(errors.equilibrium_residual, std::abs(residual));
              else if (direction[i] == 1)
                reaction += residual;
            }
          errors.reactions.push_back(reaction);
          errors.reaction_balance =
            std::max(errors.reaction_balance,
                     std::abs(std::abs(reaction) - errors.contact_force));
        }
      errors.max_displacement_error = largest_error / largest_u;
      errors.reaction_balance /= errors.contact_force;
      errors.equilibrium_residual /= errors.contact_force;
      return errors;
    }
  } // namespace PatchTest
} // namespace FuzzyContact
