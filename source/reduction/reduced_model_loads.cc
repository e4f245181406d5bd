// The loads of ReducedContactModel (reduction/reduced_model.h): the load
// forces, the stages of a load history, the bodies' weights at their zone
// densities, and what they give the contact problem: g_load and the
// resultants along the free motions of the bodies held by contact alone.

#include <fuzzycontact/reduction/reduced_model.h>

#include <deal.II/base/exceptions.h>

#include <cmath>

namespace FuzzyContact
{
  void
  ReducedContactModel::set_load_forces(
    const std::vector<std::vector<double>> &forces)
  {
    AssertThrow(forces.size() == variable.size(),
                ExcMessage("ReducedContactModel: one list of load forces per "
                           "component is expected."));
    for (unsigned int c = 0; c < forces.size(); ++c)
      {
        AssertThrow(forces[c].size() == load_forces[c].size(),
                    ExcMessage("ReducedContactModel: one force per load of "
                               "each component is expected."));
        for (const double f : forces[c])
          AssertThrow(std::isfinite(f),
                      ExcMessage("ReducedContactModel: load forces must be "
                                 "finite."));
      }
    if (forces == load_forces)
      return;
    load_forces = forces;
    assemble_load_gaps();
  }


  double
  ReducedContactModel::load_factor(const unsigned int c,
                                   const unsigned int l) const
  {
    // The reduced loads are those of the nominal stiffness; at K = s K_ref
    // the forces that impose a displacement are s times theirs.
    const ReducedComponentMatrices &r = variable[c].matrices;
    return (r.stiffness_proportional[l] ? scales[c] : 1.) * load_forces[c][l] /
           r.reference_forces[l];
  }


  Vector<double>
  ReducedContactModel::load_gaps(const LoadStage *stage) const
  {
    Vector<double> g(problem_.g_initial.size());
    for (unsigned int c = 0; c < variable.size(); ++c)
      for (const Part *part : {&variable[c], &fixed[c]})
        if (part->present)
          for (unsigned int l = 0; l < part->load_gaps.size(); ++l)
            {
              const double factor = load_factor(c, l);
              if (factor != 0 && (stage == nullptr || stage->ramps(c, l)))
                g.add(factor / scales[c], part->load_gaps[l]);
            }
    // The weights: sum_z rho_z C K^{-1} w_z (F / F_ref) / s.
    for (unsigned int c = 0; c < variable.size(); ++c)
      if (weight_in(c, stage))
        {
          const std::vector<double> a = weight_coefficients(c);
          for (const Part *part : {&variable[c], &fixed[c]})
            if (part->present)
              for (unsigned int z = 0; z < part->weight_gaps.size(); ++z)
                g.add(a[z], part->weight_gaps[z]);
        }
    return g;
  }


  bool
  ReducedContactModel::weight_in(const unsigned int c,
                                 const LoadStage   *stage) const
  {
    const int l = variable[c].matrices.weight_load;
    return l >= 0 && (stage == nullptr || stage->ramps(c, l));
  }


  std::vector<double>
  ReducedContactModel::weight_coefficients(const unsigned int c) const
  {
    AssertIndexRange(c, variable.size());
    const int l = variable[c].matrices.weight_load;
    if (l < 0)
      return {};
    std::vector<double> a = densities[c];
    for (double &x : a)
      x *= load_factor(c, l) / scales[c];
    return a;
  }


  void
  ReducedContactModel::set_zone_densities(
    const std::vector<std::vector<double>> &new_densities)
  {
    AssertThrow(new_densities.size() == variable.size(),
                ExcMessage("ReducedContactModel: one list of zone densities "
                           "per component is expected."));
    for (unsigned int c = 0; c < variable.size(); ++c)
      AssertThrow(new_densities[c].size() == densities[c].size(),
                  ExcMessage("ReducedContactModel: one density per zone of "
                             "each component is expected."));
    if (new_densities == densities)
      return;
    densities = new_densities;
    assemble_load_gaps();
  }


  Vector<double>
  ReducedContactModel::rigid_load(const LoadStage *stage) const
  {
    Vector<double> e(problem_.rigid.size());
    for (unsigned int c = 0; c < variable.size(); ++c)
      {
        const ReducedComponentMatrices &r = variable[c].matrices;
        for (unsigned int j = 0; j < r.rigid_gaps.n(); ++j)
          for (unsigned int l = 0; l < r.rigid_loads.size(); ++l)
            if (stage == nullptr || stage->ramps(c, l))
              e[first_motion[c] + j] +=
                load_forces[c][l] / r.reference_forces[l] * r.rigid_loads[l][j];
        // The weight's whole resultant (pins included): sum_z rho_z e_z.
        if (weight_in(c, stage))
          for (unsigned int z = 0; z < r.weight_rigid_loads.size(); ++z)
            for (unsigned int j = 0; j < r.rigid_gaps.n(); ++j)
              e[first_motion[c] + j] += densities[c][z] *
                                        load_factor(c, r.weight_load) *
                                        r.weight_rigid_loads[z][j];
      }
    return e;
  }


  void
  ReducedContactModel::assemble_load_gaps()
  {
    problem_.g_load     = load_gaps(nullptr);
    problem_.rigid_load = rigid_load(nullptr);
    problem_.stages.clear();
    for (const LoadStage &stage : load_stages)
      problem_.stages.push_back(GapLoadStage{load_gaps(&stage),
                                             stage.n_load_steps,
                                             rigid_load(&stage)});
    problem_.check();
  }


  void
  ReducedContactModel::set_load_stages(const std::vector<LoadStage> &stages)
  {
    for (const LoadStage &stage : stages)
      for (const auto &[c, l] : stage.loads)
        AssertThrow(c < load_forces.size() && l < load_forces[c].size(),
                    ExcMessage("ReducedContactModel: stage " + stage.name +
                               " names a load the components do not have."));
    load_stages = stages;
    assemble_load_gaps();
  }
} // namespace FuzzyContact
