// The full-order model of a study: the components' full finite element
// systems with the exact contact solver (FullOrderContact), set from a
// SceneState.
//
// Two ways of solving, both exact:
//  - independent analyses (the default): every solve is a new analysis, as
//    one would run it without this project: new factorisations, exact
//    active set, refined displacement fields;
//  - with set_reuse_factorisations(true), the factorisations of the nominal
//    stiffness (the scene's, ContactScene::stiffness_factorisation(), which
//    the reduced models were built from) and the columns of the contact
//    flexibility are kept and
//    reused wherever that is exact (a stiffness that is a multiple of the
//    nominal one), and only the observed outputs are formed: the same
//    answers to about 1e-9, at a fraction of the cost. The nominal stiffness
//    is factorised first, so that every MPI rank reuses the same
//    factorisations whatever the order of its samples.

#ifndef fuzzycontact_study_full_order_model_h
#define fuzzycontact_study_full_order_model_h

#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/full_order_contact.h>
#include <fuzzycontact/study/contact_model.h>
#include <fuzzycontact/study/contact_scene.h>

#include <memory>

namespace FuzzyContact
{
  class FullOrderModel : public ContactModel
  {
  public:
    /**
     * @p bodies must outlive the model (its components' materials are set
     * by set_state()); @p observed: the DoFs whose displacements solve()
     * reports.
     */
    FullOrderModel(ContactScene              &bodies,
                   const ObservedDofs        &observed,
                   const ActiveSetParameters &parameters = {});

    /** "full_order". */
    std::string
    name() const override;
    void
    set_state(const SceneState &state) override;
    ContactSolution
    solve() override;

    /** See the top of this file; default false. */
    void
    set_reuse_factorisations(const bool reuse);
    /** Proportional load steps up to the state's loads (default 1). */
    void
    set_n_load_steps(const unsigned int n_load_steps);

    /** The solver of the last solve (for its counters and W). */
    FullOrderContact &
    solver();

  private:
    // A solver set to the current state.
    std::unique_ptr<FullOrderContact>
    make_solver() const;

    ContactScene       &bodies;
    ObservedDofs        observed;
    ActiveSetParameters parameters;
    SceneState          state;
    // The state's gaps and friction coefficients, per slave node.
    Vector<double>                    initial_gaps;
    std::vector<double>               friction_coefficients;
    bool                              reuse        = false;
    unsigned int                      n_load_steps = 1;
    std::unique_ptr<FullOrderContact> current;
  };
} // namespace FuzzyContact

#endif
