// Hertz's solution for a cylinder pressed onto an elastic body in plane
// strain, and the finite element pressure profile to set beside it.
//
// A line load P [N/m] (the contact force per unit thickness) on a cylinder
// of radius R against a half-space gives a contact half-width and a peak
// pressure
//
//     a = sqrt(4 P R / (pi E*)),   p0 = 2 P / (pi a),
//     p(x) = p0 sqrt(1 - x^2 / a^2)  for |x| < a,
//
// with 1 / E* = (1 - nu_1^2) / E_1 + (1 - nu_2^2) / E_2. The finite element
// pressure of a slave node is its normal force over its tributary area
// (tributary length times thickness), as step-3's max_pressure.

#ifndef fuzzycontact_fe_hertz_theory_h
#define fuzzycontact_fe_hertz_theory_h

#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/fe/stress_state.h>

#include <vector>

namespace FuzzyContact
{
  namespace HertzTheory
  {
    /** Plane-strain contact modulus E* of two materials. */
    double
    contact_modulus(const double E1,
                    const double nu1,
                    const double E2,
                    const double nu2);

    struct Cylinder
    {
      double radius;
      double contact_modulus;
      /** Contact force per unit thickness [N/m]. */
      double line_load;

      double
      half_width() const;
      double
      peak_pressure() const;
      /** p0 sqrt(1 - x^2 / a^2) inside the contact, 0 outside. */
      double
      pressure(const double x) const;
      /**
       * The stress in the body at depth @p z under the middle of the
       * contact (McEwen's closed form for the half-plane under Hertz's
       * pressure, plane strain, Poisson's ratio @p nu): along the surface
       * xx = -p0 ((a^2 + 2 z^2) / sqrt(a^2 + z^2) - 2 z) / a, along the
       * depth yy = -p0 a / sqrt(a^2 + z^2), xy = 0, zz = nu (xx + yy).
       * The in-plane components do not depend on nu: the largest shear
       * (xx - yy) / 2 is 0.300 p0 at z = 0.786 a; von Mises (with zz) is
       * largest at 0.5575 p0, z = 0.70 a, for nu = 0.3.
       */
      StressState
      stress_under_middle(const double z, const double nu) const;
    };

    /** The largest value of a stress measure along a line, and where. */
    struct Peak
    {
      double value = 0, depth = 0;
    };

    /** The largest von Mises stress and in-plane shear ((s1 - s2) / 2)
     * under the middle of the contact: of the finite element field and of
     * the closed form (Cylinder::stress_under_middle()). */
    struct SubsurfacePeaks
    {
      Peak fe_von_mises, fe_shear, von_mises, shear;
    };

    /**
     * The peaks from the surface point @p origin of @p body (the middle of
     * the contact) to 3a deep along its inward normal -y, sampled at @p n
     * + 1 points: the finite element stress of displacement @p u (its
     * gradient at each point, on the body's mapping) with modulus @p E and
     * Poisson's ratio @p nu, beside @p hertz's closed form for the same
     * depths.
     */
    SubsurfacePeaks
    subsurface_peaks(const Cylinder       &hertz,
                     const Component      &body,
                     const Vector<double> &u,
                     const Point<2>       &origin,
                     const double          E,
                     const double          nu,
                     const unsigned int    n = 60);

    /** One slave node of the profile. */
    struct ProfilePoint
    {
      /** Position along the master tangent, from the first contact point. */
      double x;
      double pressure;
      bool   closed;
      /** The length of slave face the node stands for [m]. */
      double tributary;
      /** Closed and sticking. */
      bool stick = false;
    };

    /**
     * The pressure of every slave node of pair @p pair in @p solution,
     * sorted by x = tangent . (slave position - @p origin); @p thickness is
     * the slave component's.
     */
    std::vector<ProfilePoint>
    profile(const ContactInterface &interface,
            const ContactSolution  &solution,
            const unsigned int      pair,
            const Point<2>         &origin,
            const double            thickness);

    /**
     * What the profile says about the contact zone. A node's own pressure
     * (force over tributary area) oscillates between the vertex and the
     * mid-side nodes of Q2 faces (node-to-segment contact does not give
     * consistent nodal forces); averaged over a node and its two
     * neighbours (their forces over their tributary areas: at least one
     * whole face) it does not.
     */
    struct ContactZone
    {
      /** Largest nodal pressure, largest averaged pressure. */
      double nodal_peak_pressure;
      double peak_pressure;
      /** Half of the closed zone's extent. */
      double half_width;
      /** Spacing of the slave nodes at the zone's edges (the larger). */
      double node_spacing;
    };

    ContactZone
    contact_zone(const std::vector<ProfilePoint> &profile);

    /** The averaged pressure of every node of @p profile (see ContactZone). */
    std::vector<double>
    averaged_pressures(const std::vector<ProfilePoint> &profile);

    /**
     * Cattaneo-Mindlin partial slip of the cylinder (both bodies of one
     * material, normal load P first, then a tangential load Q < mu P): the
     * stick zone in the middle of the contact has the half-width
     * c = a sqrt(1 - Q / (mu P)).
     */
    double
    stick_half_width(const double half_width,
                     const double tangential_force,
                     const double mu,
                     const double normal_force);

    /** The stick zone of a profile: its centre and half-width. */
    struct StickZone
    {
      double centre;
      double half_width;
      /** Spacing of the slave nodes at the zone's edges (the larger). */
      double node_spacing;
    };

    /** Throws if no node sticks. */
    StickZone
    stick_zone(const std::vector<ProfilePoint> &profile);
  } // namespace HertzTheory
} // namespace FuzzyContact

#endif
