#include <fuzzycontact/base/input.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/scene/scene_state.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  Scene
  component_scene(const ComponentDescription &component)
  {
    Scene scene;
    scene.name       = component.name;
    scene.components = {component};
    return scene;
  }


  namespace
  {
    // What a reanalysis of @p component may vary, for messages.
    std::string
    reanalysis_parameters_of(const ComponentDescription &component)
    {
      const std::string &c = component.name;
      std::string        zones;
      for (const MaterialZone &zone : component.zones)
        zones += (zones.empty() ? "" : ", ") + zone.name;
      return " A reanalysis parameter of component " + c + " is " + c + ".E, " +
             c + ".rho, " + c + ".<zone>.E or " + c +
             ".<zone>.rho (its zones: " + zones + ").";
    }
  } // namespace


  ReanalysisParameter
  ReanalysisParameter::parse(const std::string &name,
                             const Scene       &scene,
                             const std::string &component)
  {
    const unsigned int          c           = scene.component_index(component);
    const ComponentDescription &description = scene.components[c];
    SceneQuantity               q;
    try
      {
        q = SceneQuantity::parse(name, scene);
      }
    catch (const ExceptionBase &e)
      {
        AssertThrow(false,
                    ExcMessage(Input::message_of(e) +
                               reanalysis_parameters_of(description)));
      }
    AssertThrow(q.is_material(),
                ExcMessage("reanalysis parameter <" + q.name +
                           ">: a reanalysis changes Young's moduli (E) and "
                           "densities (rho) only." +
                           reanalysis_parameters_of(description)));
    AssertThrow(q.component == c,
                ExcMessage("reanalysis parameter <" + q.name +
                           "> does not belong to component " +
                           description.name + "." +
                           reanalysis_parameters_of(description)));

    ReanalysisParameter p;
    p.name      = q.name;
    p.component = description.name;
    p.zone      = q.zone >= 0 ? description.zones[q.zone].name : "";
    p.property  = q.kind == SceneQuantity::Kind::youngs_modulus
                    ? MaterialProperty::youngs_modulus
                    : MaterialProperty::density;
    p.zones     = q.zones(scene);
    // The same quantity, on the scene of the component alone.
    p.quantity           = q;
    p.quantity.component = 0;
    return p;
  }


  ReanalysisParameter
  ReanalysisParameter::parse(const std::string          &name,
                             const ComponentDescription &component)
  {
    return parse(name, component_scene(component), component.name);
  }


  void
  check_distinct(const std::vector<ReanalysisParameter> &parameters,
                 const ComponentDescription             &component)
  {
    const Scene scene = component_scene(component);
    for (unsigned int k = 0; k < parameters.size(); ++k)
      for (unsigned int l = 0; l < k; ++l)
        AssertThrow(!(parameters[k].quantity.overlaps(parameters[l].quantity,
                                                      scene) &&
                      parameters[k].zones == parameters[l].zones),
                    ExcMessage("reanalysis parameters <" + parameters[l].name +
                               "> and <" + parameters[k].name +
                               "> change the same property of the same "
                               "zones; declare only one of them."));
  }


  std::pair<std::vector<double>, std::vector<double>>
  perturbed_zone_materials(const ComponentDescription             &component,
                           const std::vector<ReanalysisParameter> &parameters,
                           const std::vector<double> &nominal_moduli,
                           const std::vector<double> &nominal_densities,
                           const std::vector<double> &t)
  {
    AssertThrow(t.size() == parameters.size(),
                ExcMessage("Component " + component.name + ": " +
                           std::to_string(t.size()) +
                           " parameter values given for " +
                           std::to_string(parameters.size()) +
                           " reanalysis parameters."));
    const unsigned int n_zones = component.zones.size();
    AssertDimension(nominal_moduli.size(), n_zones);
    AssertDimension(nominal_densities.size(), n_zones);
    // Cheap on the good path (this is called for every online sample);
    // the names for a message are only gathered when something is wrong.
    std::vector<double> factor_E(n_zones, 1.), factor_rho(n_zones, 1.);
    for (unsigned int k = 0; k < parameters.size(); ++k)
      {
        AssertThrow(std::isfinite(t[k]),
                    ExcMessage("reanalysis parameter <" + parameters[k].name +
                               ">: its change must be a finite number."));
        for (const unsigned int z : parameters[k].zones)
          (parameters[k].property == MaterialProperty::youngs_modulus
             ? factor_E
             : factor_rho)[z] += t[k];
      }
    std::pair<std::vector<double>, std::vector<double>> result;
    result.first.resize(n_zones);
    result.second.resize(n_zones);
    for (unsigned int z = 0; z < n_zones; ++z)
      {
        for (const bool modulus : {true, false})
          {
            const double factor = modulus ? factor_E[z] : factor_rho[z];
            if (!(factor > 0))
              {
                const MaterialProperty property =
                  modulus ? MaterialProperty::youngs_modulus
                          : MaterialProperty::density;
                std::string names;
                for (const ReanalysisParameter &p : parameters)
                  if (p.property == property &&
                      std::find(p.zones.begin(), p.zones.end(), z) !=
                        p.zones.end())
                    names += (names.empty() ? "" : ", ") + p.name;
                std::ostringstream message;
                message << "reanalysis parameter"
                        << (names.find(',') != std::string::npos ? "s " : " ")
                        << names << ": the change of " << std::showpos
                        << 100. * (factor - 1.) << std::noshowpos
                        << " % makes the "
                        << (modulus ? "Young's modulus" : "density")
                        << " of zone " << component.zones[z].name
                        << " of component " << component.name
                        << " non-positive.";
                AssertThrow(false, ExcMessage(message.str()));
              }
          }
        result.first[z]  = nominal_moduli[z] * factor_E[z];
        result.second[z] = nominal_densities[z] * factor_rho[z];
      }
    return result;
  }


  ParameterModel::ParameterModel(
    const Component                &component,
    const std::vector<std::string> &parameter_names)
      : component_(component)
      , nominal_moduli_(component.zone_moduli())
      , nominal_densities_(component.zone_densities())
  {
    const ComponentDescription &description = component.description();
    for (const std::string &name : parameter_names)
      parameters_.push_back(ReanalysisParameter::parse(name, description));

    check_distinct(parameters_, description);

    K0_.reinit(component.sparsity_pattern());
    M0_.reinit(component.sparsity_pattern());
    K0_.copy_from(component.stiffness_matrix());
    M0_.copy_from(component.mass_matrix());

    // The nominal state: the component's zone materials as they are now.
    const Scene scene = component_scene(description);
    SceneState  nominal_state(scene);
    nominal_state.zone_moduli[0]    = nominal_moduli_;
    nominal_state.zone_densities[0] = nominal_densities_;

    K_.resize(parameters_.size());
    M_.resize(parameters_.size());
    for (unsigned int k = 0; k < parameters_.size(); ++k)
      {
        const ReanalysisParameter &p = parameters_[k];
        const bool modulus = p.property == MaterialProperty::youngs_modulus;
        SparseMatrix<double> &target = modulus ? K_[k] : M_[k];
        target.reinit(component.sparsity_pattern());
        for (const unsigned int z : p.zones)
          target.add(modulus ? nominal_moduli_[z] : nominal_densities_[z],
                     modulus ? component.zone_stiffness_matrix(z)
                             : component.zone_mass_matrix(z));
        nominal_values_.push_back(p.quantity.value(nominal_state, scene));
      }
  }


  const Component &
  ParameterModel::component() const
  {
    return component_;
  }


  unsigned int
  ParameterModel::n_parameters() const
  {
    return parameters_.size();
  }


  const ReanalysisParameter &
  ParameterModel::parameter(const unsigned int k) const
  {
    AssertIndexRange(k, parameters_.size());
    return parameters_[k];
  }


  const std::vector<ReanalysisParameter> &
  ParameterModel::parameters() const
  {
    return parameters_;
  }


  double
  ParameterModel::nominal_value(const unsigned int k) const
  {
    AssertIndexRange(k, parameters_.size());
    return nominal_values_[k];
  }


  std::vector<double>
  ParameterModel::relative_changes(const std::vector<double> &values) const
  {
    AssertThrow(values.size() == parameters_.size(),
                ExcMessage("expected " + std::to_string(parameters_.size()) +
                           " parameter values, got " +
                           std::to_string(values.size()) + "."));
    std::vector<double> t(values.size());
    for (unsigned int k = 0; k < values.size(); ++k)
      t[k] = values[k] / nominal_values_[k] - 1.;
    return t;
  }


  bool
  ParameterModel::affects_stiffness(const unsigned int k) const
  {
    return parameter(k).property == MaterialProperty::youngs_modulus;
  }


  bool
  ParameterModel::affects_mass(const unsigned int k) const
  {
    return parameter(k).property == MaterialProperty::density;
  }


  const SparseMatrix<double> &
  ParameterModel::stiffness_derivative(const unsigned int k) const
  {
    AssertIndexRange(k, parameters_.size());
    return K_[k];
  }


  const SparseMatrix<double> &
  ParameterModel::mass_derivative(const unsigned int k) const
  {
    AssertIndexRange(k, parameters_.size());
    return M_[k];
  }


  const SparseMatrix<double> &
  ParameterModel::nominal_stiffness() const
  {
    return K0_;
  }


  const SparseMatrix<double> &
  ParameterModel::nominal_mass() const
  {
    return M0_;
  }


  const std::vector<double> &
  ParameterModel::nominal_zone_moduli() const
  {
    return nominal_moduli_;
  }


  const std::vector<double> &
  ParameterModel::nominal_zone_densities() const
  {
    return nominal_densities_;
  }


  std::pair<std::vector<double>, std::vector<double>>
  ParameterModel::zone_materials(const std::vector<double> &t) const
  {
    return perturbed_zone_materials(component_.description(),
                                    parameters_,
                                    nominal_moduli_,
                                    nominal_densities_,
                                    t);
  }


  void
  ParameterModel::matrices(const std::vector<double> &t,
                           SparseMatrix<double>      &K,
                           SparseMatrix<double>      &M) const
  {
    const auto materials = zone_materials(t);
    K.reinit(component_.sparsity_pattern());
    M.reinit(component_.sparsity_pattern());
    for (unsigned int z = 0; z < component_.n_zones(); ++z)
      {
        K.add(materials.first[z], component_.zone_stiffness_matrix(z));
        M.add(materials.second[z], component_.zone_mass_matrix(z));
      }
  }


  bool
  ParameterModel::change(const std::vector<SparseMatrix<double>> &matrices,
                         const std::vector<double>               &c,
                         const Vector<double>                    &x,
                         Vector<double>                          &dst,
                         const MaterialProperty property) const
  {
    AssertDimension(c.size(), parameters_.size());
    dst.reinit(x.size());
    bool           any = false;
    Vector<double> tmp;
    for (unsigned int k = 0; k < parameters_.size(); ++k)
      if (c[k] != 0 && parameters_[k].property == property)
        {
          if (c[k] == 1)
            matrices[k].vmult_add(dst, x);
          else
            {
              tmp.reinit(x.size(), /*omit_zeroing_entries=*/true);
              matrices[k].vmult(tmp, x);
              dst.add(c[k], tmp);
            }
          any = true;
        }
    return any;
  }


  bool
  ParameterModel::stiffness_change(const std::vector<double> &c,
                                   const Vector<double>      &x,
                                   Vector<double>            &dst) const
  {
    return change(K_, c, x, dst, MaterialProperty::youngs_modulus);
  }


  bool
  ParameterModel::mass_change(const std::vector<double> &c,
                              const Vector<double>      &x,
                              Vector<double>            &dst) const
  {
    return change(M_, c, x, dst, MaterialProperty::density);
  }
} // namespace FuzzyContact
