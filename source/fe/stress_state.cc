#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/fe/stress_state.h>

#include <deal.II/base/symmetric_tensor.h>

#include <cmath>

namespace FuzzyContact
{
  StressState
  stress_state(const Tensor<2, 2> &grad_u,
               const PlaneModel    model,
               const double        E,
               const double        nu)
  {
    const SymmetricTensor<2, 2> sigma =
      elasticity_tensor(model, E, nu) * symmetrize(grad_u);
    StressState s;
    s.xx = sigma[0][0];
    s.yy = sigma[1][1];
    s.xy = sigma[0][1];
    s.zz = model == PlaneModel::plane_strain ? nu * (s.xx + s.yy) : 0.;
    return s;
  }


  std::array<double, 2>
  StressState::principal() const
  {
    const double mean = (xx + yy) / 2, radius = std::hypot((xx - yy) / 2, xy);
    return {{mean + radius, mean - radius}};
  }


  double
  StressState::von_mises() const
  {
    const std::array<double, 2> s = principal();
    return std::sqrt(((s[0] - s[1]) * (s[0] - s[1]) +
                      (s[1] - zz) * (s[1] - zz) + (zz - s[0]) * (zz - s[0])) /
                     2);
  }


  double
  StressState::pressure() const
  {
    return -(xx + yy + zz) / 3;
  }
} // namespace FuzzyContact
