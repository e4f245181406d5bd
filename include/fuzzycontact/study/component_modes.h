// The modes of the components of a ContactScene, for the reduced models:
// ARPACK on each body's shared stiffness factorisation, and their
// truncation to a static error tolerance.

#ifndef fuzzycontact_study_component_modes_h
#define fuzzycontact_study_component_modes_h

#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/study/contact_scene.h>

#include <deal.II/base/timer.h>

#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * The lowest modes of every component of @p bodies at their current
   * materials ("modes (ARPACK)" in @p timer), on the bodies' shared
   * stiffness factorisation at shift 0. If @p owned is not empty, only the
   * components it marks (the others need no modes, or are built on other
   * MPI ranks: their bases are left empty).
   */
  std::vector<ModalBasis>
  component_modes(const ContactScene      &bodies,
                  const ModalParameters   &parameters,
                  TimerOutput             *timer = nullptr,
                  const std::vector<bool> &owned = {});

  /**
   * Truncates each component's modes to the fewest whose modal static
   * response to a unit normal force at slave node @p node (its part of the
   * node's normal contact flexibility) has a relative energy error of at
   * most @p tolerance (modes_for_static_error()); components the node does
   * not touch keep theirs.
   */
  void
  truncate_to_static_error(std::vector<ModalBasis> &modes,
                           const ContactScene      &bodies,
                           const unsigned int       node,
                           const double             tolerance);
} // namespace FuzzyContact

#endif
