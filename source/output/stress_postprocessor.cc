#include <fuzzycontact/fe/stress_state.h>
#include <fuzzycontact/output/stress_postprocessor.h>

#include <deal.II/base/exceptions.h>

namespace FuzzyContact
{
  StressPostprocessor::StressPostprocessor(
    const Component           &component,
    const std::vector<double> &zone_moduli)
      : model(component.plane_model())
      , moduli(zone_moduli)
  {
    AssertDimension(zone_moduli.size(), component.n_zones());
    for (const MaterialZone &zone : component.description().zones)
      poissons_ratios.push_back(zone.poissons_ratio);
    AssertDimension(poissons_ratios.size(), moduli.size());
  }


  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<2> &inputs,
    std::vector<Vector<double>>              &computed) const
  {
    // The cell's zone (Component numbers the zones by material id).
    const unsigned int z = inputs.template get_cell<2>()->material_id();
    AssertIndexRange(z, moduli.size());
    for (unsigned int q = 0; q < computed.size(); ++q)
      {
        Tensor<2, 2> grad_u;
        for (unsigned int i = 0; i < 2; ++i)
          grad_u[i] = inputs.solution_gradients[q][i];
        const StressState s =
          stress_state(grad_u, model, moduli[z], poissons_ratios[z]);
        const std::array<double, 2> principal = s.principal();
        Vector<double>             &out       = computed[q];
        AssertDimension(out.size(), 8);
        out[0] = s.xx;
        out[1] = s.yy;
        out[2] = s.xy;
        out[3] = s.zz;
        out[4] = s.von_mises();
        out[5] = principal[0];
        out[6] = principal[1];
        out[7] = s.pressure();
      }
  }


  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    return {"stress_xx",
            "stress_yy",
            "stress_xy",
            "stress_zz",
            "von_mises",
            "principal_stress_1",
            "principal_stress_2",
            "pressure"};
  }


  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor::get_data_component_interpretation() const
  {
    return std::vector<
      DataComponentInterpretation::DataComponentInterpretation>(
      8,
      DataComponentInterpretation::component_is_scalar);
  }


  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    return update_gradients;
  }
} // namespace FuzzyContact
