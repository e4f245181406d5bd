#include <fuzzycontact/fe/beam_theory.h>
#include <fuzzycontact/modal/mode_classification.h>

#include <deal.II/lac/vector.h>

#include <cmath>

namespace FuzzyContact
{
  std::string
  ModeKind::name() const
  {
    return (bending ? "bending " : "axial ") + std::to_string(order);
  }


  std::vector<ModeKind>
  classify_modes(const Component &component, const ModalBasis &basis)
  {
    std::vector<ModeKind> kinds;
    unsigned int          n_bending = 0, n_axial = 0;
    const auto           &direction = component.dof_directions();
    Vector<double>        phi_y(component.n_dofs());
    for (const Vector<double> &phi : basis.modes)
      {
        for (unsigned int i = 0; i < phi.size(); ++i)
          phi_y[i] = (direction[i] == 1 ? phi[i] : 0.);
        const double share = component.mass_matrix().matrix_norm_square(phi_y) /
                             component.mass_matrix().matrix_norm_square(phi);
        const bool bending = share > 0.5;
        kinds.push_back(
          ModeKind{bending, bending ? ++n_bending : ++n_axial, share});
      }
    return kinds;
  }


  double
  BeamTheoryFrequency::reference() const
  {
    return std::isnan(bar) ? timoshenko : bar;
  }


  bool
  beam_theory_applies(const ComponentDescription &component)
  {
    const bool cantilever = component.is_rectangle() &&
                            component.supports.empty() &&
                            component.clamped_faces.size() == 1 &&
                            (component.clamped_faces[0] == "left" ||
                             component.clamped_faces[0] == "right");
    bool single_material = true;
    for (const MaterialZone &z : component.zones)
      single_material = single_material &&
                        z.youngs_modulus == component.zones[0].youngs_modulus &&
                        z.poissons_ratio == component.zones[0].poissons_ratio &&
                        z.density == component.zones[0].density;
    return cantilever && single_material;
  }


  std::vector<BeamTheoryFrequency>
  beam_theory_frequencies(const ComponentDescription  &component,
                          const PlaneModel             plane_model,
                          const std::vector<ModeKind> &kinds)
  {
    std::vector<BeamTheoryFrequency> result;
    if (!beam_theory_applies(component))
      return result;
    const BeamTheory::Beam beam = BeamTheory::Beam::of(component, plane_model);
    for (const ModeKind &kind : kinds)
      {
        BeamTheoryFrequency f;
        if (kind.bending)
          {
            f.euler_bernoulli =
              BeamTheory::euler_bernoulli_frequency(beam, kind.order);
            f.timoshenko = BeamTheory::timoshenko_frequency(beam, kind.order);
          }
        else
          f.bar = BeamTheory::axial_frequency(beam, kind.order);
        result.push_back(f);
      }
    return result;
  }
} // namespace FuzzyContact
