// Euler-Bernoulli references for two cantilevers in contact, recognised from
// the geometry of a scene (not from its name):
//
//  - tip contact: the slave beam's free end rests on a master cantilever
//    clamped at its far end (the `overlap` scene). With contact at the
//    slave's tip only, at distance a from the master's clamp, the tip
//    deflections agree: (F - N) L^3 / (3 E I) = N a^3 / (3 E I), so
//    N = F L^3 / (L^3 + a^3) (8F/9 for L = 0.2 m, a = 0.1 m);
//  - stacked: two equal cantilevers clamped at the same end, one on the
//    other (the `stacked` scene). The tip deflection lies between the
//    frictionless value, the load shared equally, F L^3 / (3 E' 2I), and
//    that of a composite beam of height 2h in full stick, F L^3 /
//    (3 E' 8I).
//
// Both need two single-material beams of the same modulus and height, each
// clamped at one end face, in contact through the slave's bottom (or top)
// face on the master's top (or bottom) face.

#ifndef fuzzycontact_fe_beam_contact_h
#define fuzzycontact_fe_beam_contact_h

#include <fuzzycontact/fe/beam_theory.h>
#include <fuzzycontact/scene/scene.h>

#include <optional>
#include <string>

namespace FuzzyContact
{
  namespace BeamTheory
  {
    struct TwoBeamContact
    {
      enum class Layout
      {
        tip_contact,
        stacked
      };
      Layout layout;
      /** The slave beam. */
      Beam beam;
      /** Distance from the master's clamp to the slave's tip (tip contact). */
      double lever = 0;

      /** N = F L^3 / (L^3 + a^3) for the tip contact. */
      double
      tip_force(const double load) const;
      /** F L^3 / (3 E' 2I) and F L^3 / (3 E' 8I) for the stacked beams. */
      double
      shared_deflection(const double load) const;
      double
      composite_deflection(const double load) const;

      /**
       * One line setting the reference beside the full-order answer
       * (normal force @p normal_force, slave deflection @p slave_uy) at
       * total load @p load.
       */
      std::string
      compare(const double load,
              const double normal_force,
              const double slave_uy) const;
    };

    /** The two-beam reference of @p scene, if its geometry is one. */
    std::optional<TwoBeamContact>
    two_beam_contact(const Scene &scene);
  } // namespace BeamTheory
} // namespace FuzzyContact

#endif
