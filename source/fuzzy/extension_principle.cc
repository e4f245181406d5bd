#include <fuzzycontact/fuzzy/extension_principle.h>

#include <deal.II/base/exceptions.h>

namespace FuzzyContact
{
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
