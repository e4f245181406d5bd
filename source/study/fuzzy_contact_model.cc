#include <fuzzycontact/base/input.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  void
  FuzzyContactModelSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("mesh refinements",
                      "2",
                      Patterns::Integer(0, 6),
                      "Global refinements of every component mesh (2: "
                      "about 20k DoFs per component in the default scenes).");
    prm.enter_subsection("Reduced models");
    prm.declare_entry("static correction",
                      "true",
                      Patterns::Bool(),
                      "Add static correction modes for the contact and load "
                      "DoFs to each component's modes (else modes only, "
                      "as in the paper).");
    prm.declare_entry("zone correction",
                      "residual flexibility",
                      Patterns::Selection("residual flexibility|galerkin"),
                      "For zone moduli and densities (re-analysed modes): "
                      "keep the static correction's flexibility at its "
                      "nominal value ('residual flexibility', cheap) or "
                      "project the stiffness onto [re-analysed modes, static "
                      "correction modes] ('galerkin', more accurate, a dense "
                      "factorisation per evaluation).");
    prm.leave_subsection();
    ModalParameters::declare_parameters(prm);
    ReanalysisSettings::declare_parameters(prm);
    FL2CParameters::declare_parameters(prm);
  }


  void
  FuzzyContactModelSettings::parse_parameters(ParameterHandler &prm)
  {
    mesh_refinements = prm.get_integer("mesh refinements");
    prm.enter_subsection("Reduced models");
    reduced.static_correction = prm.get_bool("static correction");
    reduced.zone_correction =
      prm.get("zone correction") == "galerkin"
        ? ReducedModelSettings::ZoneCorrection::galerkin
        : ReducedModelSettings::ZoneCorrection::residual_flexibility;
    prm.leave_subsection();
    modal.parse_parameters(prm);
    AssertThrow(modal.cutoff_frequency == 0,
                ExcMessage("Modal analysis: the fuzzy study needs a fixed "
                           "number of modes; set cutoff frequency = 0."));
    reduced.reanalysis.parse_parameters(prm);
    fl2c.parse_parameters(prm);
  }


  FuzzyContactModel::FuzzyContactModel(
    const Scene                     &scene_,
    const FuzzyParameterSet         &fuzzy,
    const std::vector<std::string>  &output_names,
    const FuzzyContactModelSettings &settings,
    TimerOutput                     *timer)
      : scene(scene_)
      , fuzzy(fuzzy)
  {
    AssertThrow(!scene.contact_pairs.empty(),
                ExcMessage("The fuzzy contact study needs a scene with a "
                           "contact pair."));
    Observations::check(output_names, scene);
    bodies  = std::make_unique<ContactScene>(scene,
                                            settings.mesh_refinements,
                                            1e-8,
                                            timer);
    outputs = std::make_unique<Observations>(output_names, *bodies);

    std::vector<VaryingQuantity> varying;
    for (const FuzzyParameter &p : fuzzy.parameters())
      varying.push_back({p.quantity, p.number.alpha_cut(0)});
    reduced_model = std::make_unique<ReducedOrderModel>(
      *bodies,
      component_modes(*bodies, settings.modal, timer),
      outputs->dofs(),
      varying,
      settings.reduced,
      timer);
    reduced_model->set_contact_solver(std::make_unique<FL2CSolver>(
                                        settings.fl2c),
                                      "FL2C");
    full_model = std::make_unique<FullOrderModel>(*bodies, outputs->dofs());
  }


  const Observations &
  FuzzyContactModel::observations() const
  {
    return *outputs;
  }


  SceneState
  FuzzyContactModel::state(const std::vector<double> &values) const
  {
    AssertThrow(values.size() == fuzzy.parameters().size(),
                ExcMessage("The model expects one value per fuzzy "
                           "parameter."));
    for (unsigned int i = 0; i < values.size(); ++i)
      AssertThrow(std::isfinite(values[i]),
                  ExcMessage("Fuzzy parameter " +
                             fuzzy.parameters()[i].quantity.name +
                             ": the value to evaluate is not finite."));
    return fuzzy.state(scene, values);
  }


  std::vector<double>
  FuzzyContactModel::reduced(const std::vector<double> &values)
  {
    reduced_model->set_state(state(values));
    return outputs->values(reduced_model->solve());
  }


  std::vector<double>
  FuzzyContactModel::full_order(const std::vector<double> &values)
  {
    full_model->set_state(state(values));
    return outputs->values(full_model->solve());
  }


  void
  FuzzyContactModel::set_reuse_factorisations(const bool reuse)
  {
    full_model->set_reuse_factorisations(reuse);
  }


  std::vector<unsigned int>
  FuzzyContactModel::n_dofs() const
  {
    return bodies->n_dofs();
  }


  std::vector<unsigned int>
  FuzzyContactModel::reanalysis_orders() const
  {
    return reduced_model->reanalysis_orders();
  }


  std::string
  FuzzyContactModel::describe() const
  {
    std::ostringstream out;
    out << reduced_model->describe()
        << "  contact: " << bodies->interface().n_nodes() << " slave nodes in "
        << bodies->interface().n_pairs() << " contact pair(s)\n"
        << "  outputs:";
    for (unsigned int i = 0; i < outputs->size(); ++i)
      {
        const Observation &o = (*outputs)[i];
        out << (i > 0 ? "," : "") << " " << o.name;
        if (o.kind == Observation::Kind::displacement)
          out << " (node (" << o.position[0] << ", " << o.position[1] << "))";
      }
    out << "\n";
    return out.str();
  }
} // namespace FuzzyContact
