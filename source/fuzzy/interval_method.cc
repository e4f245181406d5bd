#include <fuzzycontact/fuzzy/interval_method.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  EvaluationCache::EvaluationCache(const Response &response)
      : response(response)
  {
  }

  const std::vector<double> &
  EvaluationCache::operator()(const std::vector<double> &parameters)
  {
    const auto found = values.find(parameters);
    if (found != values.end())
      return found->second;
    return values.emplace(parameters, response(parameters)).first->second;
  }

  unsigned long
  EvaluationCache::n_evaluations() const
  {
    return values.size();
  }


  std::vector<Interval>
  alpha_box(const std::vector<FuzzyNumber> &parameters, const double alpha)
  {
    std::vector<Interval> box;
    for (const FuzzyNumber &p : parameters)
      box.push_back(p.alpha_cut(alpha));
    return box;
  }


  double
  max_relative_difference(const std::vector<Interval> &bounds,
                          const std::vector<Interval> &reference,
                          const double                 floor)
  {
    AssertThrow(bounds.size() == reference.size(),
                dealii::ExcMessage(
                  "Bounds to compare must have the same levels."));
    double worst = 0;
    for (unsigned int l = 0; l < bounds.size(); ++l)
      for (const auto &[b, r] :
           {std::make_pair(bounds[l].lower, reference[l].lower),
            std::make_pair(bounds[l].upper, reference[l].upper)})
        worst = std::max(worst, std::abs(b - r) / std::max(std::abs(r), floor));
    return worst;
  }
} // namespace FuzzyContact
