#include <fuzzycontact/contact/fuzzy_regulator.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  MamdaniRegulator::MamdaniRegulator(const std::array<double, 3> &input_points,
                                     const std::array<double, 3> &output_points,
                                     const std::string           &what)
      : a(input_points)
      , b(output_points)
  {
    for (const auto &[points, name] :
         {std::make_pair(a, std::string("input")),
          std::make_pair(b, std::string("output"))})
      {
        std::ostringstream message;
        message << what << ": the " << name
                << " transition points must satisfy 0 < p1 < p2 < p3, got "
                << points[0] << ", " << points[1] << ", " << points[2] << ".";
        AssertThrow(std::isfinite(points[0]) && std::isfinite(points[1]) &&
                      std::isfinite(points[2]) && 0 < points[0] &&
                      points[0] < points[1] && points[1] < points[2],
                    ExcMessage(message.str()));
      }
    const double outer = 2 * b[2] - b[1];
    v = {{-outer, -b[2], -b[1], -b[0], 0., b[0], b[1], b[2], outer}};
  }


  MamdaniRegulator::Degrees
  MamdaniRegulator::fuzzify(const double x) const
  {
    // Positive half; the negative terms are its mirror image.
    const auto positive = [this](const double y) {
      std::array<double, 4> mu{{0, 0, 0, 0}}; // Z, PS, PM, PL
      if (y < a[0])
        {
          mu[0] = 1 - y / a[0];
          mu[1] = y / a[0];
        }
      else if (y < a[1])
        {
          mu[1] = (a[1] - y) / (a[1] - a[0]);
          mu[2] = (y - a[0]) / (a[1] - a[0]);
        }
      else if (y < a[2])
        {
          mu[2] = (a[2] - y) / (a[2] - a[1]);
          mu[3] = (y - a[1]) / (a[2] - a[1]);
        }
      else
        mu[3] = 1;
      return mu;
    };
    const std::array<double, 4> mu = positive(std::abs(x));
    Degrees                     d{{0, 0, 0, mu[0], 0, 0, 0}};
    for (unsigned int k = 1; k < 4; ++k)
      d[x >= 0 ? 3 + k : 3 - k] = mu[k];
    return d;
  }


  double
  MamdaniRegulator::output_membership(const unsigned int k,
                                      const double       y) const
  {
    AssertIndexRange(k, n_terms);
    const double left = v[k], centre = v[k + 1], right = v[k + 2];
    if (y <= left || y >= right)
      return 0;
    return y <= centre ? (y - left) / (centre - left)
                       : (right - y) / (right - centre);
  }


  double
  MamdaniRegulator::aggregated_membership(const Degrees &strengths,
                                          const double   y) const
  {
    double mu = 0;
    for (unsigned int k = 0; k < n_terms; ++k)
      mu = std::max(mu, std::min(strengths[k], output_membership(k, y)));
    return mu;
  }


  double
  MamdaniRegulator::centroid(const Degrees &strengths) const
  {
    // Between two neighbouring vertices v[i], v[i+1] at most two terms are
    // non-zero: term i-1 descending, D(t) = 1 - t, and term i ascending,
    // A(t) = t, with t = (y - v[i]) / (v[i+1] - v[i]). The aggregation
    // max(min(wD, 1 - t), min(wA, t)) is linear between the points where
    // one of its pieces changes: t = 1 - wD, wA, 1/2, 1 - wA, wD.
    double area = 0, moment = 0;
    for (unsigned int i = 0; i + 1 < v.size(); ++i)
      {
        const double wD = (i >= 1 ? strengths[i - 1] : 0.);
        const double wA = (i < n_terms ? strengths[i] : 0.);
        if (wD == 0 && wA == 0)
          continue;
        std::array<double, 7> ts = {{0., 1., 1 - wD, wA, 0.5, 1 - wA, wD}};
        std::sort(ts.begin(), ts.end());
        const auto f = [&](const double t) {
          return std::max(std::min(wD, 1 - t), std::min(wA, t));
        };
        const double y0 = v[i], h = v[i + 1] - v[i];
        for (unsigned int j = 0; j + 1 < ts.size(); ++j)
          {
            const double t0 = std::clamp(ts[j], 0., 1.);
            const double t1 = std::clamp(ts[j + 1], 0., 1.);
            if (t1 <= t0)
              continue;
            const double ya = y0 + t0 * h, yb = y0 + t1 * h;
            const double fa = f(t0), fb = f(t1);
            // Exact for a linear f on [ya, yb].
            area += 0.5 * (fa + fb) * (yb - ya);
            moment +=
              (yb - ya) / 6. * (fa * (2 * ya + yb) + fb * (ya + 2 * yb));
          }
      }
    Assert(area > 0, ExcInternalError());
    return moment / area;
  }


  MamdaniRegulator::Degrees
  MamdaniRegulator::rule_strengths(const double x) const
  {
    const Degrees input = fuzzify(x);
    Degrees       output;
    for (unsigned int k = 0; k < n_terms; ++k)
      output[n_terms - 1 - k] = input[k];
    return output;
  }


  double
  MamdaniRegulator::operator()(const double x) const
  {
    return centroid(rule_strengths(x));
  }

  const std::array<double, 3> &
  MamdaniRegulator::input_points() const
  {
    return a;
  }

  const std::array<double, 3> &
  MamdaniRegulator::output_points() const
  {
    return b;
  }

  double
  MamdaniRegulator::output_bound() const
  {
    return 2 * b[2] - b[1];
  }
} // namespace FuzzyContact
