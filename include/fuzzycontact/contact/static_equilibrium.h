// Whether the bodies held by contact alone (contact_problem.h) can be held
// at all: contact forces within the friction cones (p_n >= 0, |p_t| <= mu
// p_n) that balance the load's resultant along their free motions. It
// depends on the friction coefficients, the loads and the geometry (the
// free motions' gaps G), not on the stiffness, and a bound-constrained
// least-squares problem (Lawson and Hanson's NNLS) on the cones' edges
// decides it. The exact solver refuses a load without such forces
// (check_equilibrium()) and follows a path of friction coefficients near
// the limit (least_friction_factor()); a fuzzy study tests each point
// (has_static_equilibrium()).

#ifndef fuzzycontact_contact_static_equilibrium_h
#define fuzzycontact_contact_static_equilibrium_h

#include <fuzzycontact/contact/contact_problem.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * Throws, naming @p what and the free motions, if no contact forces in
   * the friction cones (p_n >= 0, |p_t| <= mu p_n) of the nodes can balance
   * the step's load on the bodies held by contact alone: there is then no
   * static solution (the body slides or lifts off). Nothing to check
   * without such bodies. A bound-constrained least-squares problem
   * (Lawson and Hanson's NNLS) on the cones' edges decides it.
   */
  void
  check_equilibrium(const LoadStep            &step,
                    const std::vector<double> &mu,
                    const std::string         &what);

  /**
   * The least factor s in [@p low, @p high] such that the friction
   * coefficients s @p mu can hold the bodies held by contact alone
   * (admissible_forces()), by bisection (on a logarithmic scale if @p low
   * > 0) to a relative width of 1e-12, or, if @p distance_tolerance > 0,
   * until the width is at most @p distance_tolerance times the distance
   * 1 - s of the factor to 1 (all the path of friction coefficients
   * needs, active_set_solver.cc: far from the limit about a dozen tests
   * instead of about forty, by the bisection's arithmetic). The caller knows
   * that @p high can hold them and @p low cannot. Returns a factor that can
   * hold them.
   */
  double
  least_friction_factor(const LoadStep            &step,
                        const std::vector<double> &mu,
                        double                     low,
                        double                     high,
                        const double               distance_tolerance = 0);

  /**
   * What check_equilibrium() throws (its message says why and what
   * friction would hold the body). A study that varies loads or friction
   * coefficients takes it as a result of the point, not as a failure
   * (study/fuzzy_contact_model.h).
   */
  DeclException1(ExcNoStaticEquilibrium, std::string, << arg1);

  /**
   * Whether the problem's loads at @p load_factor have a static
   * equilibrium (check_equilibrium() without the throw): true without
   * bodies held by contact alone; else admissible_forces() at the end of
   * every load stage (the resultants an equilibrium can take form a convex
   * cone, so the stages' ends decide for every step between them). It
   * depends on the friction coefficients, the loads and the geometry (the
   * free motions' gaps G), not on the stiffness.
   */
  bool
  has_static_equilibrium(const ContactProblem &problem,
                         const double          load_factor = 1.);

  /**
   * Forces @p p in the friction cones of the nodes (coefficients @p mu)
   * that balance the step's load on the bodies held by contact alone, at
   * most one per free motion and cone edge (a basic solution of the NNLS
   * problem of check_equilibrium()); false if there are none, with the
   * unbalanced fraction of the load's resultant in @p unbalanced.
   */
  bool
  admissible_forces(const LoadStep            &step,
                    const std::vector<double> &mu,
                    Vector<double>            &p,
                    double                    *unbalanced = nullptr);
} // namespace FuzzyContact

#endif
