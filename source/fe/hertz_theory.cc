#include <fuzzycontact/fe/hertz_theory.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  namespace HertzTheory
  {
    double
    contact_modulus(const double E1,
                    const double nu1,
                    const double E2,
                    const double nu2)
    {
      return 1. / ((1 - nu1 * nu1) / E1 + (1 - nu2 * nu2) / E2);
    }


    double
    Cylinder::half_width() const
    {
      return std::sqrt(4 * line_load * radius /
                       (numbers::PI * contact_modulus));
    }


    double
    Cylinder::peak_pressure() const
    {
      return 2 * line_load / (numbers::PI * half_width());
    }


    double
    Cylinder::pressure(const double x) const
    {
      const double a = half_width();
      return std::abs(x) < a ? peak_pressure() * std::sqrt(1 - x * x / (a * a))
                             : 0.;
    }


    std::vector<ProfilePoint>
    profile(const ContactInterface &interface,
            const ContactSolution  &solution,
            const unsigned int      pair,
            const Point<2>         &origin,
            const double            thickness)
    {
      std::vector<ProfilePoint> points;
      for (unsigned int k = 0; k < interface.n_nodes(); ++k)
        {
          const ContactNode &node = interface.node(k);
          if (node.pair != pair)
            continue;
          points.push_back(
            {node.tangent * (node.slave.position - origin),
             solution.p_n(k) / (node.tributary_length * thickness),
             solution.status[k] != ContactStatus::open});
        }
      std::sort(points.begin(),
                points.end(),
                [](const ProfilePoint &a, const ProfilePoint &b) {
                  return a.x < b.x;
                });
      return points;
    }


    ContactZone
    contact_zone(const std::vector<ProfilePoint> &profile)
    {
      ContactZone  zone{0, 0, 0};
      unsigned int first = profile.size(), last = 0;
      for (unsigned int i = 0; i < profile.size(); ++i)
        if (profile[i].closed)
          {
            first = std::min(first, i);
            last  = i;
            zone.peak_pressure =
              std::max(zone.peak_pressure, profile[i].pressure);
          }
      AssertThrow(first < profile.size(),
                  ExcMessage("Hertz: no slave node is in contact."));
      zone.half_width    = 0.5 * (profile[last].x - profile[first].x);
      const auto spacing = [&](const unsigned int i, const unsigned int j) {
        return j < profile.size() ? std::abs(profile[j].x - profile[i].x) : 0.;
      };
      zone.node_spacing = std::max(
        {first > 0 ? spacing(first - 1, first) : 0., spacing(last, last + 1)});
      return zone;
    }
  } // namespace HertzTheory
} // namespace FuzzyContact
