#include <fuzzycontact/fuzzy/vertex_method.h>

namespace FuzzyContact
{
  std::string
  VertexMethod::name() const
  {
    return "vertex method";
  }


  std::vector<std::vector<double>>
  VertexMethod::points(const std::vector<FuzzyNumber> &parameters,
                       const std::vector<double>      &alpha) const
  {
    const unsigned int               n = parameters.size();
    std::vector<std::vector<double>> corners;
    for (const double a : alpha)
      {
        const std::vector<Interval> box = alpha_box(parameters, a);
        for (unsigned long corner = 0; corner < (1ul << n); ++corner)
          {
            std::vector<double> p(n);
            for (unsigned int d = 0; d < n; ++d)
              p[d] = (corner >> d) & 1 ? box[d].upper : box[d].lower;
            corners.push_back(p);
          }
      }
    return corners;
  }
} // namespace FuzzyContact
