#include <fuzzycontact/study/sliding_probes.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  std::vector<double>
  sliding_probe_factors(const unsigned int n_fine, const double largest)
  {
    std::vector<double> factors;
    for (int k = int(n_fine) - 1; k >= 0; --k)
      factors.push_back(1 + std::ldexp(1., -k));
    factors.push_back(4);
    factors.push_back(largest);
    return factors;
  }


  SlidingVerdict
  probe_sliding(const std::vector<double>        &factors,
                const std::function<int(double)> &answer)
  {
    Assert(std::is_sorted(factors.begin(), factors.end()),
           dealii::ExcMessage("The factors must increase."));
    // The order: the first factor, then 2 (if there is a 2), then the
    // others upwards.
    std::vector<unsigned int> order;
    for (unsigned int i = 0; i < factors.size(); ++i)
      order.push_back(i);
    const auto twice = std::find(factors.begin(), factors.end(), 2.);
    if (twice != factors.end() && twice != factors.begin())
      std::rotate(order.begin() + 1,
                  order.begin() + (twice - factors.begin()),
                  order.begin() + (twice - factors.begin()) + 1);

    SlidingVerdict   verdict;
    std::vector<int> answered(factors.size(), 2); // 2: not probed
    for (const unsigned int i : order)
      {
        answered[i] = answer(factors[i]);
        ++verdict.probes;
        verdict.failed += answered[i] == 0;
        if (answered[i] < 0)
          {
            verdict.kind = SlidingVerdict::beyond;
            return verdict;
          }
        // The first answer upwards, if the probes made so far fix it.
        unsigned int j = 0;
        while (j < factors.size() && answered[j] == 0)
          ++j;
        if (j < factors.size() && answered[j] == 1)
          {
            verdict.kind   = SlidingVerdict::within_with_more;
            verdict.factor = factors[j];
            return verdict;
          }
      }
    return verdict;
  }
} // namespace FuzzyContact
