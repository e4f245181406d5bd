// The stress of a plane body at a point, from its displacement gradient, and
// what an engineer reads from it.
//
// Hooke's law gives the in-plane components from the strain eps = sym(grad
// u) with the body's elasticity tensor (elasticity_tensor(), component.h);
// the out-of-plane normal stress is 0 in plane stress and nu (sigma_xx +
// sigma_yy) in plane strain (eps_zz = 0). Von Mises and the pressure are
// those of the whole 3D state (sigma_zz included: in plane strain it is not
// zero), the principal stresses those of the plane.

#ifndef fuzzycontact_fe_stress_state_h
#define fuzzycontact_fe_stress_state_h

#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/tensor.h>

#include <array>

namespace FuzzyContact
{
  using namespace dealii;

  struct StressState
  {
    /** The in-plane components and the out-of-plane normal stress [Pa]. */
    double xx = 0, yy = 0, xy = 0, zz = 0;

    /** sqrt(((s1 - s2)^2 + (s2 - s3)^2 + (s3 - s1)^2) / 2) over the 3D
     * principal stresses. */
    double
    von_mises() const;
    /** The in-plane principal stresses, the larger first. */
    std::array<double, 2>
    principal() const;
    /** -(sigma_xx + sigma_yy + sigma_zz) / 3 (positive in compression). */
    double
    pressure() const;
  };

  /**
   * The stress of displacement gradient @p grad_u (grad_u[i][j] = du_i /
   * dx_j) in a body of modulus @p E and Poisson's ratio @p nu.
   */
  StressState
  stress_state(const Tensor<2, 2> &grad_u,
               const PlaneModel    model,
               const double        E,
               const double        nu);
} // namespace FuzzyContact

#endif
