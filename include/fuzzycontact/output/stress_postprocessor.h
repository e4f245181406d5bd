// The stresses of a component's displacement field in its VTU files: a
// deal.II DataPostprocessor that gives, at every point DataOut writes, the
// stress of the field's gradient there (fe/stress_state.h) with the modulus
// and Poisson's ratio of the cell's zone: stress_xx, stress_yy, stress_xy,
// stress_zz, von_mises, principal_stress_1 and _2 (the larger first) and
// pressure, in Pa.
//
// Each cell gives its own values at its points (the gradient of its own
// shape functions, as DataOut writes every cell as a patch of its own):
// where cells meet, the VTU keeps both cells' values, so the jumps of the
// finite element stress stay visible instead of being averaged away.

#ifndef fuzzycontact_output_stress_postprocessor_h
#define fuzzycontact_output_stress_postprocessor_h

#include <fuzzycontact/fe/component.h>

#include <deal.II/numerics/data_postprocessor.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  class StressPostprocessor : public DataPostprocessor<2>
  {
  public:
    /**
     * For fields of @p component with the Young's modulus @p zone_moduli[z]
     * in zone z (a state's, which may differ from the scene's).
     */
    StressPostprocessor(const Component           &component,
                        const std::vector<double> &zone_moduli);

    void
    evaluate_vector_field(const DataPostprocessorInputs::Vector<2> &inputs,
                          std::vector<Vector<double>> &computed) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    PlaneModel          model;
    std::vector<double> moduli, poissons_ratios;
  };
} // namespace FuzzyContact

#endif
