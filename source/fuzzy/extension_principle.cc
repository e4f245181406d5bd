#include <fuzzycontact/base/limits.h>
#include <fuzzycontact/fuzzy/extension_principle.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <string>

namespace FuzzyContact
{
  void
  ExtensionPrincipleSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Extension principle");
    prm.declare_entry("points per dimension",
                      "4",
                      Patterns::Integer(2, 100),
                      "Every alpha level's box is sampled on a grid of "
                      "this many equally spaced values per parameter "
                      "(both ends included).");
    prm.declare_entry("reuse factorisations",
                      "true",
                      Patterns::Bool(),
                      "false: every sample is an independent full-order "
                      "analysis (new factorisations, refined displacement "
                      "fields), the cost of a study without reduced "
                      "models. true: keep the nominal factorisations and "
                      "contact flexibility columns and reuse them where "
                      "exact (stiffness a multiple of the nominal one): "
                      "the same answers to about 1e-9, much cheaper.");
    prm.leave_subsection();
  }


  void
  ExtensionPrincipleSettings::check_size(const unsigned int n_alpha,
                                         const unsigned int n_parameters) const
  {
    Input::in_range(n_alpha *
                      std::pow(1.0 * points_per_dimension, n_parameters),
                    0,
                    1e5,
                    "Extension principle: points per dimension = " +
                      std::to_string(points_per_dimension) + " with " +
                      std::to_string(n_parameters) + " fuzzy parameters and " +
                      std::to_string(n_alpha) +
                      " alpha levels: the exact solves (about number of "
                      "alpha levels x points per dimension ^ parameters)",
                    "lower one of these keys");
  }


  void
  ExtensionPrincipleSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Extension principle");
    points_per_dimension = prm.get_integer("points per dimension");
    reuse_factorisations = prm.get_bool("reuse factorisations");
    prm.leave_subsection();
  }


  ExtensionPrinciple::ExtensionPrinciple(
    const unsigned int points_per_dimension)
      : points_per_dimension_(points_per_dimension)
  {
    AssertThrow(points_per_dimension >= 2,
                dealii::ExcMessage(
                  "Extension principle: points per dimension must be at "
                  "least 2 (the ends of every interval)."));
  }


  std::string
  ExtensionPrinciple::name() const
  {
    return "Extension Principle";
  }


  unsigned int
  ExtensionPrinciple::points_per_dimension() const
  {
    return points_per_dimension_;
  }


  std::vector<std::vector<double>>
  ExtensionPrinciple::points(const std::vector<FuzzyNumber> &parameters,
                             const std::vector<double>      &alpha) const
  {
    const unsigned int               r = points_per_dimension_;
    const unsigned int               n = parameters.size();
    std::vector<std::vector<double>> grid;
    for (const double a : alpha)
      {
        const std::vector<Interval> box = alpha_box(parameters, a);
        // values per parameter: r of them, or one for a point interval
        std::vector<std::vector<double>> values(n);
        unsigned long                    count = 1;
        for (unsigned int d = 0; d < n; ++d)
          {
            if (box[d].width() == 0)
              values[d] = {box[d].lower};
            else
              for (unsigned int i = 0; i < r; ++i)
                values[d].push_back(
                  i == 0       ? box[d].lower
                  : i == r - 1 ? box[d].upper
                               : box[d].lower + box[d].width() * i / (r - 1.));
            count *= values[d].size();
          }
        for (unsigned long i = 0; i < count; ++i)
          {
            std::vector<double> p(n);
            unsigned long       rest = i;
            for (unsigned int d = 0; d < n; ++d)
              {
                p[d] = values[d][rest % values[d].size()];
                rest /= values[d].size();
              }
            grid.push_back(p);
          }
      }
    return grid;
  }


  unsigned long
  extension_principle_size(const std::vector<FuzzyNumber> &parameters,
                           const std::vector<double>      &alpha,
                           const unsigned int              points_per_dimension)
  {
    return ExtensionPrinciple(points_per_dimension)
      .samples(parameters, alpha)
      .size();
  }
} // namespace FuzzyContact
