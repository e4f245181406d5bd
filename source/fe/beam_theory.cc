#include <fuzzycontact/fe/beam_theory.h>

#include <deal.II/base/exceptions.h>

#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <cstdint>

namespace FuzzyContact
{
  namespace BeamTheory
  {
    using namespace dealii;

    double
    Beam::effective_modulus() const
    {
      return plane_model == PlaneModel::plane_stress
               ? youngs_modulus
               : youngs_modulus / (1. - poissons_ratio * poissons_ratio);
    }

    double
    Beam::effective_poissons_ratio() const
    {
      return plane_model == PlaneModel::plane_stress
               ? poissons_ratio
               : poissons_ratio / (1. - poissons_ratio);
    }

    double
    Beam::shear_modulus() const
    {
      return youngs_modulus / (2. * (1. + poissons_ratio));
    }

    double
    Beam::area() const
    {
      return height * thickness;
    }

    double
    Beam::second_moment_of_area() const
    {
      return thickness * height * height * height / 12.;
    }

    Beam
    Beam::of(const ComponentDescription &component, const PlaneModel model)
    {
      const MaterialZone &first = component.zones.front();
      for (const MaterialZone &zone : component.zones)
        AssertThrow(zone.youngs_modulus == first.youngs_modulus &&
                      zone.poissons_ratio == first.poissons_ratio &&
                      zone.density == first.density,
                    ExcMessage("Component " + component.name +
                               ": beam theory needs a single material, but "
                               "its zones differ."));
      return Beam{component.length(),
                  component.height(),
                  component.thickness,
                  first.youngs_modulus,
                  first.poissons_ratio,
                  first.density,
                  model};
    }


    double
    shear_coefficient(const Beam &beam)
    {
      const double nu = beam.effective_poissons_ratio();
      return 10. * (1. + nu) / (12. + 11. * nu);
    }


    namespace
    {
      // Roots of the clamped-free condition 1 + cos(x) cosh(x) = 0, written
      // as cos(x) + 1/cosh(x) = 0 to stay bounded; the n-th lies in
      // ((n-1) pi, n pi).
      double
      cantilever_root(const unsigned int n)
      {
        const auto g = [](const double x) {
          return std::cos(x) + 1. / std::cosh(x);
        };
        std::uintmax_t max_iterations = 200;
        const auto     bracket        = boost::math::tools::toms748_solve(
          g,
          (n - 1.) * M_PI + (n == 1 ? 1e-3 : 0.),
          n * M_PI,
          boost::math::tools::eps_tolerance<double>(52),
          max_iterations);
        return 0.5 * (bracket.first + bracket.second);
      }

      // The clamped-free Timoshenko frequency determinant at omega.
      //
      // With w = W e^{kx}, psi = Psi e^{kx}, the equations
      //   kGA (w'' - psi') + rho A omega^2 w = 0,
      //   E'I psi'' + kGA (w' - psi) + rho I omega^2 psi = 0
      // give a quadratic in k^2 with one positive root k1^2 and (below the
      // second spectrum) one negative root -k2^2. Then
      //   w   = C1 cosh k1x + C2 sinh k1x + C3 cos k2x + C4 sin k2x,
      //   psi = r1 (C1 sinh + C2 cosh) + q2 (-C3 sin + C4 cos),
      // with r1 = (kG k1^2 + rho omega^2)/(kG k1),
      //      q2 = (kG k2^2 - rho omega^2)/(kG k2).
      // The clamp (w = psi = 0 at x = 0) gives C3 = -C1, C4 = -C2 r1/q2; the
      // free end (psi' = 0, w' - psi = 0 at x = L) leaves a 2x2 system. Its
      // rows are divided by cosh(k1 L) (to avoid overflow) and the shear row
      // by its common factor -rho omega^2 / kG (which would otherwise make it
      // a difference of nearly equal numbers for a slender beam). In the
      // Euler-Bernoulli limit (kG -> infinity, k1 = k2 = k) the determinant
      // becomes 2 k sech(kL) (sech(kL) + cos(kL)), whose roots are those of
      // 1 + cos(kL) cosh(kL) = 0.
      struct Determinant
      {
        double value;
        double q2;
      };

      Determinant
      timoshenko_determinant(const Beam &beam, const double omega)
      {
        const double L   = beam.length;
        const double A   = beam.area();
        const double I   = beam.second_moment_of_area();
        const double E   = beam.effective_modulus();
        const double kG  = shear_coefficient(beam) * beam.shear_modulus();
        const double rho = beam.density;
        const double w2  = omega * omega;

        const double a4     = E * I * kG * A;
        const double b2     = E * I * rho * A * w2 + rho * I * w2 * kG * A;
        const double c0     = rho * A * w2 * (rho * I * w2 - kG * A);
        const double disc   = std::sqrt(b2 * b2 - 4. * a4 * c0);
        const double s_plus = (-b2 + disc) / (2. * a4);
        // The negative root, computed without cancellation.
        const double s_minus = c0 / (a4 * s_plus);
        const double k1      = std::sqrt(s_plus);
        const double k2      = std::sqrt(-s_minus);
        const double r1      = (kG * k1 * k1 + rho * w2) / (kG * k1);
        const double q2      = (kG * k2 * k2 - rho * w2) / (kG * k2);

        const double th   = std::tanh(k1 * L);
        const double sech = 1. / std::cosh(k1 * L);
        const double c    = std::cos(k2 * L) * sech;
        const double s    = std::sin(k2 * L) * sech;

        const double a11 = r1 * k1 + q2 * k2 * c;
        const double a12 = r1 * k1 * th + r1 * k2 * s;
        const double a21 = th / k1 - s / k2;
        const double a22 = 1. / k1 + r1 * c / (q2 * k2);
        return {a11 * a22 - a12 * a21, q2};
      }
    } // namespace


    double
    euler_bernoulli_frequency(const Beam &beam, const unsigned int n)
    {
      AssertThrow(n >= 1, ExcMessage("Mode numbers start at 1."));
      const double x = cantilever_root(n);
      const double L = beam.length;
      return x * x / (L * L) *
             std::sqrt(beam.effective_modulus() * beam.second_moment_of_area() /
                       (beam.density * beam.area())) /
             (2. * M_PI);
    }


    double
    timoshenko_frequency(const Beam &beam, const unsigned int n)
    {
      AssertThrow(n >= 1, ExcMessage("Mode numbers start at 1."));
      // omega = u^2 with u stepped so that the Euler-Bernoulli wavenumber
      // advances by pi/64 per step, fine enough to separate neighbouring
      // roots (about pi apart). Timoshenko frequencies lie below the
      // Euler-Bernoulli ones, so the scan ends shortly after the n-th of
      // those.
      const double omega_eb = 2. * M_PI * euler_bernoulli_frequency(beam, n);
      const double scale =
        beam.length *
        std::pow(beam.density * beam.area() /
                   (beam.effective_modulus() * beam.second_moment_of_area()),
                 0.25); // beta L = scale * sqrt(omega)
      const double du    = (M_PI / 64.) / scale;
      const double u_end = 1.05 * std::sqrt(omega_eb) + 4 * du;

      unsigned int found = 0;
      double       u0    = du;
      Determinant  d0    = timoshenko_determinant(beam, u0 * u0);
      for (double u1 = u0 + du; u1 <= u_end; u1 += du)
        {
          const Determinant d1 = timoshenko_determinant(beam, u1 * u1);
          if (std::signbit(d0.value) != std::signbit(d1.value) &&
              std::signbit(d0.q2) == std::signbit(d1.q2))
            {
              ++found;
              if (found == n)
                {
                  std::uintmax_t max_iterations = 200;
                  const auto     root = boost::math::tools::toms748_solve(
                    [&](const double u) {
                      return timoshenko_determinant(beam, u * u).value;
                    },
                    u0,
                    u1,
                    d0.value,
                    d1.value,
                    boost::math::tools::eps_tolerance<double>(50),
                    max_iterations);
                  const double u = 0.5 * (root.first + root.second);
                  return u * u / (2. * M_PI);
                }
            }
          u0 = u1;
          d0 = d1;
        }
      AssertThrow(false,
                  ExcMessage("Timoshenko frequency " + std::to_string(n) +
                             " not found below the Euler-Bernoulli value."));
      return 0;
    }


    double
    axial_frequency(const Beam &beam, const unsigned int n)
    {
      AssertThrow(n >= 1, ExcMessage("Mode numbers start at 1."));
      const double c = std::sqrt(beam.effective_modulus() / beam.density);
      return (2. * n - 1.) * c / (4. * beam.length);
    }


    double
    euler_bernoulli_tip_deflection(const Beam &beam, const double force)
    {
      return force * std::pow(beam.length, 3) /
             (3. * beam.effective_modulus() * beam.second_moment_of_area());
    }


    double
    timoshenko_tip_deflection(const Beam &beam, const double force)
    {
      return euler_bernoulli_tip_deflection(beam, force) +
             force * beam.length /
               (shear_coefficient(beam) * beam.shear_modulus() * beam.area());
    }
  } // namespace BeamTheory
} // namespace FuzzyContact
