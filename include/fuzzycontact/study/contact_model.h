// The models of a contact scene that a study evaluates, and how a scene
// quantity reaches them.
//
// A study varies named scene quantities (scene_quantity.h). Their values
// are bound to a SceneState once (SceneQuantity::apply(), or
// FuzzyParameterSet::state() for fuzzy parameters), and every model is set
// from that state by set_state() -- materials, loads, friction coefficients
// and gaps of every contact pair at once -- so that the full-order reference
// and the reduced model always see the same values:
//
//   values --(SceneQuantity::apply)--> SceneState --(set_state)--> model
//   model.solve() --> ContactSolution --(Observations::values)--> outputs
//
// Two models implement this interface:
//  - FullOrderModel (full_order_model.h): the full finite element systems
//    and the exact contact solver;
//  - ReducedOrderModel (reduced_order_model.h): component modes (re-analysed
//    by HPTP where zone materials vary) with static correction, solved by a
//    ContactSolver (FL2C or the exact active set).

#ifndef fuzzycontact_study_contact_model_h
#define fuzzycontact_study_contact_model_h

#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/scene/scene_state.h>

#include <string>

namespace FuzzyContact
{
  class ContactModel
  {
  public:
    virtual ~ContactModel() = default;

    /** The model's name in reports. */
    virtual std::string
    name() const = 0;

    /**
     * Sets every value of the scene from @p state: zone materials, load
     * forces, friction coefficients and initial gaps of every contact pair.
     * Throws if the model cannot represent the state (a reduced model
     * built without the reanalysis of a component whose zones change).
     */
    virtual void
    set_state(const SceneState &state) = 0;

    /**
     * Solves the contact problem at the current state. The solution holds
     * the displacements at the DoFs the model was asked to observe.
     */
    virtual ContactSolution
    solve() = 0;
  };
} // namespace FuzzyContact

#endif
