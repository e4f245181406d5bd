// Analytic references for a clamped-free rectangular beam of length L,
// height h and out-of-plane thickness t, used to judge the 2D finite element
// results: Euler-Bernoulli and Timoshenko bending frequencies, axial
// frequencies and static tip deflections.
//
// The 2D model enters through the effective in-plane constants: plane stress
// uses (E, nu) and plane strain the equivalent (E / (1 - nu^2), nu / (1 -
// nu)); the shear modulus is E / (2 (1 + nu)) in both.

#ifndef fuzzycontact_fe_beam_theory_h
#define fuzzycontact_fe_beam_theory_h

#include <fuzzycontact/scene/scene.h>

namespace FuzzyContact
{
  namespace BeamTheory
  {
    struct Beam
    {
      double     length;
      double     height;
      double     thickness;
      double     youngs_modulus;
      double     poissons_ratio;
      double     density;
      PlaneModel plane_model;

      /** E (plane stress) or E / (1 - nu^2) (plane strain). */
      double
      effective_modulus() const;
      /** nu (plane stress) or nu / (1 - nu) (plane strain). */
      double
      effective_poissons_ratio() const;
      double
      shear_modulus() const;
      double
      area() const;
      double
      second_moment_of_area() const;

      /**
       * The beam of a component made of a single material; throws if its
       * zones differ in E, nu or rho.
       */
      static Beam
      of(const ComponentDescription &component, const PlaneModel model);
    };

    /**
     * Cowper's shear coefficient of a rectangular section,
     * 10 (1 + nu) / (12 + 11 nu), with the effective Poisson's ratio.
     */
    double
    shear_coefficient(const Beam &beam);

    /** n-th (n = 1, 2, ...) Euler-Bernoulli bending frequency [Hz]. */
    double
    euler_bernoulli_frequency(const Beam &beam, const unsigned int n);

    /**
     * n-th Timoshenko bending frequency [Hz] (shear deformation and
     * rotary inertia): the n-th root of the clamped-free frequency
     * determinant, bracketed on a fine grid and refined by TOMS 748.
     */
    double
    timoshenko_frequency(const Beam &beam, const unsigned int n);

    /** n-th axial frequency (2n - 1) c / (4 L), c = sqrt(E' / rho) [Hz]. */
    double
    axial_frequency(const Beam &beam, const unsigned int n);

    /** Tip deflection P L^3 / (3 E' I) under a tip force P. */
    double
    euler_bernoulli_tip_deflection(const Beam &beam, const double force);

    /** Euler-Bernoulli plus the shear part P L / (kappa G A). */
    double
    timoshenko_tip_deflection(const Beam &beam, const double force);
  } // namespace BeamTheory
} // namespace FuzzyContact

#endif
