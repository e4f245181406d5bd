#include <fuzzycontact/fe/hertz_theory.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/numbers.h>
#include <deal.II/numerics/vector_tools.h>

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


    StressState
    Cylinder::stress_under_middle(const double z, const double nu) const
    {
      const double a = half_width(), p0 = peak_pressure(),
                   r = std::sqrt(a * a + z * z);
      StressState s;
      s.xx = -p0 * ((a * a + 2 * z * z) / r - 2 * z) / a;
      s.yy = -p0 * a / r;
      s.xy = 0;
      s.zz = nu * (s.xx + s.yy);
      return s;
    }


    SubsurfacePeaks
    subsurface_peaks(const Cylinder       &hertz,
                     const Component      &body,
                     const Vector<double> &u,
                     const Point<2>       &origin,
                     const double          E,
                     const double          nu,
                     const unsigned int    n)
    {
      const auto take = [](Peak &peak, const double value, const double z) {
        if (value > peak.value)
          peak = {value, z};
      };
      const auto shear = [](const StressState &s) {
        return (s.principal()[0] - s.principal()[1]) / 2;
      };
      SubsurfacePeaks           peaks;
      std::vector<Tensor<1, 2>> gradient(2);
      for (unsigned int k = 0; k <= n; ++k)
        {
          const double z = 3 * hertz.half_width() * k / n;
          VectorTools::point_gradient(body.mapping(),
                                      body.dof_handler(),
                                      u,
                                      Point<2>(origin[0], origin[1] - z),
                                      gradient);
          Tensor<2, 2> grad_u;
          grad_u[0] = gradient[0];
          grad_u[1] = gradient[1];
          const StressState fe =
            stress_state(grad_u, body.plane_model(), E, nu);
          const StressState form = hertz.stress_under_middle(z, nu);
          take(peaks.fe_von_mises, fe.von_mises(), z);
          take(peaks.fe_shear, shear(fe), z);
          take(peaks.von_mises, form.von_mises(), z);
          take(peaks.shear, shear(form), z);
        }
      return peaks;
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
             solution.status[k] != ContactStatus::open,
             node.tributary_length,
             solution.status[k] == ContactStatus::stick});
        }
      std::sort(points.begin(),
                points.end(),
                [](const ProfilePoint &a, const ProfilePoint &b) {
                  return a.x < b.x;
                });
      return points;
    }


    std::vector<double>
    averaged_pressures(const std::vector<ProfilePoint> &profile)
    {
      std::vector<double> averaged(profile.size());
      for (unsigned int i = 0; i < profile.size(); ++i)
        {
          double force = 0, length = 0;
          for (unsigned int j = (i > 0 ? i - 1 : 0);
               j <= std::min<unsigned int>(i + 1, profile.size() - 1);
               ++j)
            {
              force += profile[j].pressure * profile[j].tributary;
              length += profile[j].tributary;
            }
          averaged[i] = force / length;
        }
      return averaged;
    }


    ContactZone
    contact_zone(const std::vector<ProfilePoint> &profile)
    {
      const std::vector<double> averaged = averaged_pressures(profile);
      ContactZone               zone{0, 0, 0, 0};
      unsigned int              first = profile.size(), last = 0;
      for (unsigned int i = 0; i < profile.size(); ++i)
        if (profile[i].closed)
          {
            first = std::min(first, i);
            last  = i;
            zone.nodal_peak_pressure =
              std::max(zone.nodal_peak_pressure, profile[i].pressure);
            zone.peak_pressure = std::max(zone.peak_pressure, averaged[i]);
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


    double
    stick_half_width(const double half_width,
                     const double tangential_force,
                     const double mu,
                     const double normal_force)
    {
      const double ratio = std::abs(tangential_force) / (mu * normal_force);
      AssertThrow(ratio >= 0 && ratio <= 1,
                  ExcMessage("Cattaneo-Mindlin: the tangential force must lie "
                             "below mu P."));
      return half_width * std::sqrt(1 - ratio);
    }


    StickZone
    stick_zone(const std::vector<ProfilePoint> &profile)
    {
      unsigned int first = profile.size(), last = 0;
      for (unsigned int i = 0; i < profile.size(); ++i)
        if (profile[i].stick)
          {
            first = std::min(first, i);
            last  = i;
          }
      AssertThrow(first < profile.size(),
                  ExcMessage("Cattaneo-Mindlin: no slave node sticks."));
      const auto spacing = [&](const unsigned int i, const unsigned int j) {
        return j < profile.size() ? std::abs(profile[j].x - profile[i].x) : 0.;
      };
      return {0.5 * (profile[first].x + profile[last].x),
              0.5 * (profile[last].x - profile[first].x),
              std::max({first > 0 ? spacing(first - 1, first) : 0.,
                        spacing(last, last + 1)})};
    }
  } // namespace HertzTheory
} // namespace FuzzyContact
