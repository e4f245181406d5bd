#include <fuzzycontact/reanalysis/combined_approximations.h>
#include <fuzzycontact/reanalysis/first_order_taylor.h>
#include <fuzzycontact/reanalysis/homotopy_perturbation.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>
#include <fuzzycontact/reanalysis/reanalysis_factory.h>

#include <deal.II/base/exceptions.h>

namespace FuzzyContact
{
  using namespace dealii;

  const std::vector<std::string> &
  reanalysis_method_names()
  {
    static const std::vector<std::string> names = {"taylor",
                                                   "ca",
                                                   "hptp",
                                                   "hptp-pi"};
    return names;
  }


  std::unique_ptr<ReanalysisMethod>
  create_reanalysis_method(const std::string        &name,
                           const ParameterModel     &model,
                           const ModalBasis         &nominal,
                           const ReanalysisSettings &settings)
  {
    if (name == "taylor")
      return std::make_unique<FirstOrderTaylor>(model,
                                                nominal,
                                                settings.cluster_gap,
                                                settings.derivative_solver);
    if (name == "ca")
      return std::make_unique<CombinedApproximations>(
        model,
        nominal,
        settings.truncation_tolerance);
    if (name == "hptp")
      return std::make_unique<HomotopyPerturbation>(
        model,
        nominal,
        settings.truncation_tolerance,
        settings.cluster_gap,
        settings.derivative_solver);
    if (name == "hptp-pi")
      {
        std::vector<std::string> parameter_names;
        for (const ReanalysisParameter &p : model.parameters())
          parameter_names.push_back(p.name);
        auto method = std::make_unique<ParameterIndependentReanalysis>();
        method->offline(model.component(),
                        nominal,
                        parameter_names,
                        settings.max_order,
                        settings.truncation_tolerance,
                        settings.cluster_gap,
                        nullptr,
                        settings.derivative_solver);
        return method;
      }
    std::string known;
    for (const std::string &n : reanalysis_method_names())
      known += (known.empty() ? "" : ", ") + n;
    AssertThrow(false,
                ExcMessage("There is no reanalysis method called <" + name +
                           ">; the methods are: " + known + "."));
    return nullptr;
  }
} // namespace FuzzyContact
