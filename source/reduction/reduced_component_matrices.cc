// The reduced matrices a ReducedComponent hands to the model that
// assembles the bodies (ReducedComponentMatrices, reduced_component.h):
// its reduced stiffness and loads, the contact gaps' and the observed
// displacements' rows, the free motions and the weight's responses.

#include <fuzzycontact/reduction/reduced_component.h>

namespace FuzzyContact
{
  ReducedComponentMatrices
  ReducedComponentMatrices::without_basis() const
  {
    ReducedComponentMatrices r;
    r.reference_forces       = reference_forces;
    r.stiffness_proportional = stiffness_proportional;
    r.observed_dofs          = observed_dofs;
    r.rigid_gaps             = rigid_gaps;
    r.rigid_loads            = rigid_loads;
    r.rigid_observation      = rigid_observation;
    r.motion_names           = motion_names;
    r.weight_load            = weight_load;
    r.weight_gaps            = weight_gaps;
    r.weight_observation     = weight_observation;
    r.weight_rigid_loads     = weight_rigid_loads;
    r.zone_densities         = zone_densities;
    return r;
  }


  ReducedComponentMatrices
  ReducedComponent::matrices(
    const SparseMatrix<double>                 &gap_operator,
    const std::vector<types::global_dof_index> &observed_dofs) const
  {
    ReducedComponentMatrices r;
    r.stiffness      = K_r;
    r.gap_operator   = project_rows(gap_operator);
    const int weight = component.weight_load();
    for (unsigned int l = 0; l < component.description().loads.size(); ++l)
      {
        // (The weight's response is carried whole, below.)
        r.loads.push_back(static_cast<int>(l) == weight
                            ? Vector<double>(size())
                            : project(component.reference_load_vector(l)));
        r.reference_forces.push_back(component.reference_load_force(l));
        r.stiffness_proportional.push_back(
          component.description().loads[l].is_displacement);
      }
    r.observed_dofs                      = observed_dofs;
    r.observation                        = rows(observed_dofs);
    const std::vector<Vector<double>> &R = component.free_motions();
    r.rigid_gaps.reinit(gap_operator.m(), R.size());
    r.rigid_observation.reinit(observed_dofs.size(), R.size());
    for (unsigned int j = 0; j < R.size(); ++j)
      {
        Vector<double> g(gap_operator.m());
        gap_operator.vmult(g, R[j]);
        for (unsigned int i = 0; i < g.size(); ++i)
          r.rigid_gaps(i, j) = g[i];
        for (unsigned int i = 0; i < observed_dofs.size(); ++i)
          r.rigid_observation(i, j) = R[j][observed_dofs[i]];
        r.motion_names.push_back(component.name() + ": " +
                                 component.free_motion_names()[j]);
      }
    for (unsigned int l = 0; l < component.description().loads.size(); ++l)
      r.rigid_loads.push_back(static_cast<int>(l) == weight
                                ? Vector<double>(R.size())
                                : component.rigid_load(l));
    r.zone_densities = component.zone_densities();
    r.weight_load    = weight;
    for (unsigned int z = 0; z < weight_fields.size(); ++z)
      {
        Vector<double> g(gap_operator.m()), u(observed_dofs.size());
        gap_operator.vmult(g, weight_fields[z]);
        for (unsigned int i = 0; i < observed_dofs.size(); ++i)
          u[i] = weight_fields[z][observed_dofs[i]];
        Vector<double> e = component.weight_zone_resultants()[z];
        if (e.size() > 0) // (a body held by contact alone)
          e *= component.reference_load_force(weight);
        r.weight_gaps.push_back(std::move(g));
        r.weight_observation.push_back(std::move(u));
        r.weight_rigid_loads.push_back(std::move(e));
      }
    return r;
  }
} // namespace FuzzyContact
