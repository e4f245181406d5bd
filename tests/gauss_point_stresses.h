// A test helper: the stresses the VTU files carry (StressPostprocessor), at
// the Gauss points of every cell, for checks against closed forms.

#ifndef fuzzycontact_tests_gauss_point_stresses_h
#define fuzzycontact_tests_gauss_point_stresses_h

#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/output/stress_postprocessor.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/fe/fe_values.h>

#include <functional>
#include <vector>

namespace FuzzyContact
{
  namespace Testing
  {
    /**
     * Calls @p check(x, values) at every Gauss point x (3 x 3 per cell) of
     * @p component with the StressPostprocessor's values there (stress_xx,
     * _yy, _xy, _zz, von_mises, principal_stress_1, _2, pressure) for the
     * displacement @p u and the zone moduli @p moduli.
     */
    inline void
    for_each_gauss_point_stress(
      const Component           &component,
      const Vector<double>      &u,
      const std::vector<double> &moduli,
      const std::function<void(const Point<2> &, const Vector<double> &)>
        &check)
    {
      const StressPostprocessor          post(component, moduli);
      const QGauss<2>                    quadrature(3);
      FEValues<2>                        values(component.mapping(),
                         component.fe(),
                         quadrature,
                         update_gradients | update_quadrature_points);
      DataPostprocessorInputs::Vector<2> inputs;
      inputs.solution_gradients.assign(quadrature.size(),
                                       std::vector<Tensor<1, 2>>(2));
      std::vector<Vector<double>> computed(quadrature.size(),
                                           Vector<double>(
                                             post.get_names().size()));
      for (const auto &cell : component.dof_handler().active_cell_iterators())
        {
          values.reinit(cell);
          values.get_function_gradients(u, inputs.solution_gradients);
          inputs.template set_cell<2>(cell);
          post.evaluate_vector_field(inputs, computed);
          for (const unsigned int q : values.quadrature_point_indices())
            check(values.quadrature_point(q), computed[q]);
        }
    }
  } // namespace Testing
} // namespace FuzzyContact

#endif
