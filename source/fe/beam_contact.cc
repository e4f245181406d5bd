#include <fuzzycontact/fe/beam_contact.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace FuzzyContact
{
  namespace BeamTheory
  {
    namespace
    {
      // The x of the one end face at which @p c is clamped, if it is
      // clamped at exactly one of its left and right faces and nowhere else.
      std::optional<double>
      clamp_position(const ComponentDescription &c)
      {
        if (!c.is_rectangle() || c.clamped_faces.size() != 1 ||
            !c.supports.empty())
          return {};
        if (c.clamped_faces[0] == "left")
          return c.lower_left[0];
        if (c.clamped_faces[0] == "right")
          return c.upper_right[0];
        return {};
      }

      std::string
      sci(const double value)
      {
        std::ostringstream s;
        s << std::scientific << std::setprecision(3) << value;
        return s.str();
      }
    } // namespace


    double
    TwoBeamContact::tip_force(const double F) const
    {
      const double L = beam.length;
      return F * L * L * L / (L * L * L + lever * lever * lever);
    }


    double
    TwoBeamContact::shared_deflection(const double F) const
    {
      const double EI = beam.effective_modulus() * beam.second_moment_of_area();
      return F * std::pow(beam.length, 3) / (3 * EI * 2);
    }


    double
    TwoBeamContact::composite_deflection(const double F) const
    {
      const double EI = beam.effective_modulus() * beam.second_moment_of_area();
      return F * std::pow(beam.length, 3) / (3 * EI * 8);
    }


    std::string
    TwoBeamContact::compare(const double F,
                            const double normal_force,
                            const double slave_uy) const
    {
      std::ostringstream out;
      if (layout == Layout::stacked)
        out << "Euler-Bernoulli tip deflection: load shared equally (mu = 0) "
               "F L^3 / (3 E' 2I) = "
            << sci(shared_deflection(F))
            << " m, composite beam (full stick) F L^3 / (3 E' 8I) = "
            << sci(composite_deflection(F))
            << " m; full_order slave uy = " << sci(slave_uy) << " m";
      else
        out << "Euler-Bernoulli with contact at the slave's tip only: N = F "
               "L^3 / (L^3 + a^3) = "
            << std::fixed << std::setprecision(0) << tip_force(F)
            << " N (L = " << std::setprecision(3) << beam.length
            << " m, a = " << lever
            << " m); full_order F_n = " << std::setprecision(0) << normal_force
            << " N";
      return out.str();
    }


    std::optional<TwoBeamContact>
    two_beam_contact(const Scene &scene)
    {
      // (Beam theory here knows the end load only, not a body's weight.)
      if (scene.components.size() != 2 || scene.contact_pairs.size() != 1 ||
          scene.gravity.norm() > 0)
        return {};
      const ContactPairDescription &pair = scene.contact_pairs[0];
      const bool                    faces =
        (pair.slave_face == "bottom" && pair.master_face == "top") ||
        (pair.slave_face == "top" && pair.master_face == "bottom");
      if (!faces)
        return {};
      const ComponentDescription &slave =
        scene.components[scene.component_index(pair.slave_component)];
      const ComponentDescription &master =
        scene.components[scene.component_index(pair.master_component)];
      const auto slave_clamp  = clamp_position(slave);
      const auto master_clamp = clamp_position(master);
      if (!slave_clamp || !master_clamp)
        return {};
      std::optional<TwoBeamContact> result;
      try
        {
          const Beam s = Beam::of(slave, scene.plane_model);
          const Beam m = Beam::of(master, scene.plane_model);
          if (s.youngs_modulus != m.youngs_modulus ||
              s.poissons_ratio != m.poissons_ratio ||
              std::abs(s.height - m.height) > 1e-12 * s.height ||
              s.thickness != m.thickness)
            return {};
          const double tolerance = 1e-9 * s.length;
          const double tip       = *slave_clamp == slave.lower_left[0]
                                     ? slave.upper_right[0]
                                     : slave.lower_left[0];
          if (std::abs(*slave_clamp - *master_clamp) <= tolerance &&
              std::abs(slave.lower_left[0] - master.lower_left[0]) <=
                tolerance &&
              std::abs(slave.upper_right[0] - master.upper_right[0]) <=
                tolerance)
            result = TwoBeamContact{TwoBeamContact::Layout::stacked, s, 0};
          else if (tip > master.lower_left[0] + tolerance &&
                   tip < master.upper_right[0] - tolerance &&
                   (tip - *slave_clamp) * (*master_clamp - tip) > 0)
            result = TwoBeamContact{TwoBeamContact::Layout::tip_contact,
                                    s,
                                    std::abs(*master_clamp - tip)};
        }
      catch (const ExceptionBase &)
        {
          // zones of different materials: no beam reference
          return {};
        }
      return result;
    }
  } // namespace BeamTheory
} // namespace FuzzyContact
