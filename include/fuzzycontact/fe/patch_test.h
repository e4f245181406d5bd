// The contact patch test: two blocks of one material stacked on a
// frictionless contact whose meshes do not match, compressed by a
// prescribed displacement delta of the upper block's top face against the
// lower block's supported bottom face, their left faces symmetry lines
// (prm/patch-test.prm). The exact solution is a uniform uniaxial stress,
//
//     eps_yy = -delta / H,   sigma_yy = E' eps_yy,   sigma_xx = 0,
//     E' = E (plane stress),   E / (1 - nu^2) (plane strain),
//     eps_xx = -nu eps_yy (plane stress),   -nu / (1 - nu) eps_yy (strain),
//
// with H the height of the stack: the contact pressure is p = -sigma_yy
// everywhere and the displacement u = (eps_xx x, eps_yy y) is linear, which
// every Q_p element holds exactly. Whatever error the finite element
// solution has is the contact discretisation's (node-to-segment does not
// pass the patch test on non-matching meshes).

#ifndef fuzzycontact_fe_patch_test_h
#define fuzzycontact_fe_patch_test_h

#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/fe/component.h>

#include <vector>

namespace FuzzyContact
{
  namespace PatchTest
  {
    struct UniaxialCompression
    {
      PlaneModel plane_model;
      double     youngs_modulus;
      double     poissons_ratio;
      /** Height H of the stack and shortening delta > 0 [m]. */
      double height;
      double shortening;

      /** eps_yy (negative) and eps_xx. */
      double
      axial_strain() const;
      double
      lateral_strain() const;
      /** p = -sigma_yy [Pa]. */
      double
      pressure() const;
      /** The exact displacement at @p x (origin: the symmetry line x = 0
       * and the supported bottom face y = 0). */
      Tensor<1, 2>
      displacement(const Point<2> &x) const;
    };

    /**
     * The internal forces K u of component @p component at displacement
     * @p u, assembled cell by cell without the constraints (so that the
     * rows of held DoFs give the support reactions).
     */
    Vector<double>
    internal_forces(const Component &component, const Vector<double> &u);

    struct Errors
    {
      /** Slave nodes and how many of them are closed. */
      unsigned int n_slave_nodes, n_closed;
      /**
       * Nodal pressure p_n / (tributary length * thickness) against the
       * exact pressure: largest and root-mean-square relative error over
       * the slave nodes.
       */
      double max_pressure_error, rms_pressure_error;
      /**
       * Largest error of a nodal displacement component over both bodies,
       * relative to the largest exact displacement component.
       */
      double max_displacement_error;
      /**
       * Total normal contact force, and the exact one: p times the slave
       * face's area (its nodes' tributary lengths times thickness) [N].
       */
      double contact_force, exact_force;
      /**
       * The y reaction of each body's supports: the force they exert on it,
       * internal forces minus contact forces summed over its held y DoFs
       * [N].
       */
      std::vector<double> reactions;
      /**
       * Force balance, relative to the contact force: the largest of
       * |reaction| - contact force over the bodies, and the largest
       * residual K u - C^T p on a free DoF.
       */
      double reaction_balance, equilibrium_residual;
    };

    /**
     * Measures @p solution (with displacements) of contact pair 0 between
     * @p components against @p exact.
     */
    Errors
    measure(const std::vector<const Component *> &components,
            const ContactInterface               &interface,
            const ContactSolution                &solution,
            const UniaxialCompression            &exact);
  } // namespace PatchTest
} // namespace FuzzyContact

#endif
