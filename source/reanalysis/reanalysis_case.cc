#include <fuzzycontact/base/input.h>
#include <fuzzycontact/reanalysis/reanalysis_case.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <functional>

namespace FuzzyContact
{
  void
  ReanalysisCase::declare_parameters(ParameterHandler  &prm,
                                     const std::string &name)
  {
    prm.enter_subsection("Case " + name);
    prm.declare_entry("description",
                      "",
                      Patterns::Anything(),
                      "One line saying what the case shows.");
    prm.declare_entry("scene",
                      "cantilever-zones.prm",
                      Patterns::Anything(),
                      "Scene file, relative to this parameter file.");
    prm.declare_entry("component",
                      "",
                      Patterns::Anything(),
                      "The component whose modes are reanalysed.",
                      /*has_to_be_set=*/true);
    prm.declare_entry("parameters",
                      "",
                      Patterns::Anything(),
                      "The parameters declared variable: "
                      "<component>.<zone>.<E|rho> or "
                      "<component>.<E|rho>, comma-separated.",
                      /*has_to_be_set=*/true);
    prm.declare_entry("changes in percent",
                      "",
                      Patterns::Anything(),
                      "Samples separated by ';', each a comma-separated "
                      "list of relative changes [%], one per parameter.",
                      /*has_to_be_set=*/true);
    prm.leave_subsection();
  }


  void
  ReanalysisCase::parse_parameters(ParameterHandler  &prm,
                                   const std::string &case_name,
                                   const std::string &prm_file)
  {
    const std::string what = "Case " + case_name;
    prm.enter_subsection(what);
    name        = case_name;
    description = Utilities::trim(prm.get("description"));
    scene_file =
      Input::resolve_relative_to(Utilities::trim(prm.get("scene")), prm_file);
    component = Utilities::trim(prm.get("component"));
    AssertThrow(!component.empty(),
                ExcMessage(what + ": component must not be empty."));
    parameters = Utilities::split_string_list(prm.get("parameters"), ',');
    AssertThrow(!parameters.empty(),
                ExcMessage(what + ": no parameter is declared variable."));
    const std::vector<std::string> texts =
      Utilities::split_string_list(prm.get("changes in percent"), ';');
    AssertThrow(!texts.empty(),
                ExcMessage(what + ": 'changes in percent' lists no sample."));
    samples.clear();
    samples_percent.clear();
    for (unsigned int s = 0; s < texts.size(); ++s)
      {
        const std::string sample_what = what + ", sample " +
                                        std::to_string(s + 1) +
                                        " of 'changes in percent'";
        const std::vector<double> percent =
          Input::to_doubles(texts[s], sample_what);
        AssertThrow(percent.size() == parameters.size(),
                    ExcMessage(
                      sample_what + ": " + std::to_string(percent.size()) +
                      " changes given for " +
                      std::to_string(parameters.size()) + " parameters."));
        std::vector<double> relative;
        for (const double p : percent)
          relative.push_back(p / 100.);
        samples.push_back(relative);
        samples_percent.push_back(percent);
      }
    prm.leave_subsection();
  }


  void
  ReanalysisCase::check(const Scene &scene) const
  {
    // Runs @p check and puts @p what in front of the message it throws.
    const auto in_context = [](const std::string           &what,
                               const std::function<void()> &check) {
      try
        {
          check();
        }
      catch (const ExceptionBase &e)
        {
          AssertThrow(false, ExcMessage(what + ": " + Input::message_of(e)));
        }
    };
    std::vector<ReanalysisParameter> declared;
    std::vector<double>              moduli, densities;
    in_context("Case " + name, [&]() {
      const ComponentDescription &description =
        scene.components[scene.component_index(component)];
      for (const std::string &parameter : parameters)
        declared.push_back(
          ReanalysisParameter::parse(parameter, scene, component));
      check_distinct(declared, description);
      for (const MaterialZone &zone : description.zones)
        {
          moduli.push_back(zone.youngs_modulus);
          densities.push_back(zone.density);
        }
    });
    const ComponentDescription &description =
      scene.components[scene.component_index(component)];
    for (unsigned int s = 0; s < samples.size(); ++s)
      in_context("Case " + name + ", sample " + std::to_string(s + 1), [&]() {
        perturbed_zone_materials(description,
                                 declared,
                                 moduli,
                                 densities,
                                 samples[s]);
      });
  }
} // namespace FuzzyContact
