// The model a fuzzy contact study evaluates: values of the fuzzy parameters
// in, the response of the report's slave node and the total contact forces
// out,
//
//     (P_1, ..., P_n)  ->  (u_x, u_y of the slave node, F_n, F_t),
//
// two ways:
//
//  - reduced(): the fast pipeline. Everything that does not depend on the
//    parameters is computed once: each component's mesh, matrices and modes
//    (ARPACK), its static correction modes, the contact interface, the
//    reduced contact flexibility of every component. Per evaluation:
//      * a modulus of a whole component, E_c = s_c E_c^0, scales its
//        stiffness exactly: the modes stay, the eigenvalues scale by s_c
//        (the reanalysis is exact, design.md section 1) and so does the
//        component's part of the contact flexibility, W = sum_c W_c / s_c;
//      * a density of a whole component scales the mass only: the modes
//        keep their span, so the static reduced model does not change;
//      * zone moduli and densities change the mode shapes: the modes are
//        re-analysed by the parameter-independent HPTP (modes T Y(p), with
//        the order chosen offline from a tolerance on the corners of the
//        parameter box). The static correction then enters one of two ways:
//        "residual flexibility" (the default) keeps the flexibility of the
//        static correction modes at its nominal value and adds it to that
//        of the re-analysed modes (MacNeal), O(rows^2 n_modes) per
//        evaluation; "galerkin" projects the stiffness onto the basis
//        [T Y(p), Psi] (zone projections precomputed offline), more accurate
//        but a dense factorisation of the whole reduced stiffness per
//        evaluation;
//      * the load scales the load term, mu and the gap enter the small
//        contact problem directly;
//    then the FL2C regulator solves the reduced contact problem.
//  - full_order(): the exact reference of the Extension Principle: the
//    full finite element systems with their exact contact solver, set to
//    the parameter values (components' zone materials, load factor,
//    friction, gap offset). By default every evaluation is an independent
//    full-order analysis, as one would run it without this project: new
//    factorisations, exact active set, refined displacement fields. With
//    set_reuse_factorisations(true) the factorisations of the nominal
//    stiffness and the columns of the contact flexibility are kept and
//    reused wherever that is exact (a stiffness that is a multiple of the
//    nominal one), and only the outputs are formed: the same answers to
//    about 1e-9, at a fraction of the cost.
//
// Both are pure functions of the parameters (no state carried from one
// evaluation to the next affects the result), so that the interval methods
// may evaluate them in any order and on any number of MPI ranks.

#ifndef fuzzycontact_study_fuzzy_contact_model_h
#define fuzzycontact_study_fuzzy_contact_model_h

#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/contact/full_order_contact.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/reduction/reduced_model.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  struct FuzzyContactModelSettings
  {
    /** Global refinements of every component mesh. */
    unsigned int mesh_refinements = 2;
    /** Static correction modes in the reduced model (else modes only). */
    bool static_correction = true;
    /** How the static correction enters for zone parameters (see above). */
    enum class ZoneCorrection
    {
      residual_flexibility,
      galerkin
    };
    ZoneCorrection     zone_correction = ZoneCorrection::residual_flexibility;
    ModalParameters    modal;
    ReanalysisSettings reanalysis;
    FL2CParameters     fl2c;

    /**
     * Declares "mesh refinements" and the subsections "Reduced models"
     * (static correction, zone correction), "Modal analysis", "Reanalysis" and
     * "FL2C".
     */
    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  class FuzzyContactModel
  {
  public:
    /**
     * Builds everything parameter-independent for @p scene and the fuzzy
     * parameters of @p fuzzy (bound to the same scene). Stages are timed in
     * @p timer if given. Throws if a parameter cannot be modelled (a fuzzy
     * load that is not the scene's only load, mu or gap of a scene with
     * several contact pairs).
     */
    FuzzyContactModel(const Scene                     &scene,
                      const FuzzyParameterSet         &fuzzy,
                      const FuzzyContactModelSettings &settings,
                      TimerOutput                     *timer = nullptr);

    /** "ux", "uy" (slave node [m]), "Fn", "Ft" (totals [N]). */
    static std::vector<std::string>
    output_names();

    /** The fast answer at @p values (one per fuzzy parameter). */
    std::vector<double>
    reduced(const std::vector<double> &values);

    /** The exact answer at @p values. */
    std::vector<double>
    full_order(const std::vector<double> &values);

    /** See the top of this file; default false. */
    void
    set_reuse_factorisations(const bool reuse);


    /** A few lines on what the model is: meshes, bases, report node. */
    std::string
    describe() const;

    /** DoFs of each component. */
    std::vector<unsigned int>
    n_dofs() const;

    /** HPTP order used for each component (0: exact scaling or none). */
    std::vector<unsigned int>
    reanalysis_orders() const;


  private:
    // How a component's parameters enter the reduced model.
    enum class Treatment
    {
      fixed,   // no E or rho parameter
      scaling, // whole-component E (and rho): exact scaling
      hptp     // zone parameters: parameter-independent HPTP
    };

    struct ComponentModel
    {
      Treatment treatment = Treatment::fixed;
      // Fuzzy parameter indices acting on this component's materials, and
      // their names for the reanalysis.
      std::vector<unsigned int> parameters;
      std::vector<std::string>  names;
      // Scaling: index of the whole-component modulus parameter (or -1).
      int modulus_parameter = -1;

      ModalBasis                        modes;
      std::unique_ptr<ReducedComponent> reduced;
      ReducedComponentMatrices          nominal_matrices;

      // HPTP: the reanalysis and the projections that turn Y(p) into the
      // component's reduced matrices.
      std::unique_ptr<ParameterIndependentReanalysis> reanalysis;
      std::vector<FullMatrix<double>> T_K_psi;    // T^T K_z Psi per zone
      std::vector<FullMatrix<double>> psi_K_psi;  // Psi^T K_z Psi per zone
      FullMatrix<double>              C_T, C_psi; // C T, C Psi
      FullMatrix<double>              O_T, O_psi; // rows at observed DoFs
      Vector<double>                  T_f, psi_f; // T^T f, Psi^T f
    };

    // The relative changes t of component c's reanalysis parameters.
    std::vector<double>
    relative_changes(const ComponentModel      &model,
                     const std::vector<double> &values) const;
    ReducedComponentMatrices
    reanalysed_matrices(const ComponentModel      &model,
                        const std::vector<double> &values) const;
    void
    check_values(const std::vector<double> &values) const;

    Scene                                             scene;
    const FuzzyParameterSet                          &fuzzy;
    FuzzyContactModelSettings                         settings;
    std::vector<std::unique_ptr<Component>>           components;
    std::vector<const Component *>                    component_pointers;
    std::unique_ptr<ContactInterface>                 interface;
    ReportNodes                                       report;
    std::vector<std::vector<types::global_dof_index>> observed;
    std::vector<ComponentModel>                       models;
    std::unique_ptr<ReducedContactModel>              reduced_model;
    // The reused exact solver (set_reuse_factorisations(true) only).
    std::unique_ptr<FullOrderContact> full;
    bool                              reuse = false;
    Vector<double>                    nominal_gaps;
    std::vector<double>               nominal_mu;
    double                            nominal_gap = 0;
    // Index of the fuzzy load, friction and gap parameters (-1: none).
    int    load_parameter = -1, friction_parameter = -1, gap_parameter = -1;
    double nominal_load = 0;
  };
} // namespace FuzzyContact

#endif
