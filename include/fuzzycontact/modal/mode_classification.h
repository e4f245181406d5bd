// What a mode of a slender component is, and what beam theory says of it.
//
// A mode of a slender beam is either a bending mode (mostly transverse
// motion) or an axial one (mostly longitudinal). With M-normalised modes,
// phi_y^T M phi_y is the share of the kinetic energy in the y direction;
// the mass matrix does not couple x and y, so the two shares add to 1, and
// a mode is a bending mode if its transverse share exceeds 1/2.
//
// Bending mode n of a clamped-free beam is then compared with the n-th
// Euler-Bernoulli and Timoshenko frequencies, axial mode n with the bar
// value (2n-1) c / (4L) (fe/beam_theory.h).

#ifndef fuzzycontact_modal_mode_classification_h
#define fuzzycontact_modal_mode_classification_h

#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/scene/scene.h>

#include <limits>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /** The kind of a mode: bending or axial, and its rank among its kind. */
  struct ModeKind
  {
    bool bending;
    /** 1 for the first bending (or axial) mode, ... */
    unsigned int order;
    /** Share of the kinetic energy in the transverse (y) direction. */
    double transverse_share;

    /** "bending 3", "axial 1". */
    std::string
    name() const;
  };

  /** The kind of every mode of @p basis, modes of @p component. */
  std::vector<ModeKind>
  classify_modes(const Component &component, const ModalBasis &basis);

  /** What beam theory says of one mode [Hz]; NaN where it says nothing. */
  struct BeamTheoryFrequency
  {
    double euler_bernoulli = std::numeric_limits<double>::quiet_NaN();
    double timoshenko      = std::numeric_limits<double>::quiet_NaN();
    double bar             = std::numeric_limits<double>::quiet_NaN();

    /** The value to compare with: Timoshenko for bending, bar for axial. */
    double
    reference() const;
  };

  /**
   * True if beam theory describes @p component: clamped at one end face
   * only (left or right), and made of a single material.
   */
  bool
  beam_theory_applies(const ComponentDescription &component);

  /**
   * The beam theory values of modes of the kinds @p kinds of @p component in
   * the 2D model @p plane_model; empty if !beam_theory_applies(component).
   */
  std::vector<BeamTheoryFrequency>
  beam_theory_frequencies(const ComponentDescription  &component,
                          const PlaneModel             plane_model,
                          const std::vector<ModeKind> &kinds);
} // namespace FuzzyContact

#endif
