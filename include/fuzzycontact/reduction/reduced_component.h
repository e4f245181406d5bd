// The reduction basis of one component (see reduced_model.h for the
// method): its modes Phi, with or without static correction modes Psi.
//
// Everything the reduced contact problem needs lives on a few DoFs B: the
// contact DoFs, the DoFs the loads act on, and (mostly) the observed ones.
// The component's stiffness is factorised once, by a sparse Cholesky with B
// ordered last (base/sparse_cholesky.h), whose trailing block gives
// G = (K^{-1})_BB without a single solve. The attachment modes are
// Psi_raw = K^{-1} E with the columns of E supported on B, so their rows at
// B are G E_B, and the whole static correction is formed from m x m and
// m x n_e matrices (m = |B|):
//
//   R = Lambda^{-1} Phi_B^T E_B,
//   S = E_B^T G E_B - (Phi_B^T E_B)^T R  (the Gram matrix of Psi_res),
//   P^T S P = L L^T (pivoted Cholesky, stopping at pivots below
//                    rank_tolerance times the largest diagonal entry:
//                    linearly dependent attachment modes),
//   X = P_r L_r^{-T},  Psi = Psi_res X,  so Psi^T K Psi = X^T S X = I,
//
// and V_B = [Phi_B, (G E_B - Phi_B R) X], the basis at B. No full-length
// correction vector is kept: rows of V outside B, projections of vectors
// not supported on B and the expansion V q each cost one back-substitution
// with the factorisation, and only the Galerkin zone correction (which
// needs V^T K_z V of a multi-zone component) forms all of V, transiently.
//
// A body's weight acts on every DoF: it has no column in E (B would be
// every DoF). Its exact static response K^{-1} w_z per zone, one
// back-substitution each, is carried beside the basis instead
// (ReducedComponentMatrices::weight_gaps): the contact forces' part of the
// displacement, V K_r^{-1} C_r^T p, stays exact by the static correction,
// and so does the whole.

#ifndef fuzzycontact_reduction_reduced_component_h
#define fuzzycontact_reduction_reduced_component_h

#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /**
   * The smallest number of modes of @p modes whose modal static solution of
   * the load @p f has a relative error in the energy norm of at most
   * @p tolerance: sqrt(1 - sum_j (phi_j^T f)^2 / lambda_j / (f^T K^{-1} f)),
   * where @p static_solution = K^{-1} f. Throws if all the modes together
   * do not reach it.
   */
  unsigned int
  modes_for_static_error(const ModalBasis     &modes,
                         const Vector<double> &f,
                         const Vector<double> &static_solution,
                         const double          tolerance,
                         const std::string    &what);

  /**
   * The small matrices of one reduced component, all that the reduced
   * contact problem needs.
   */
  struct ReducedComponentMatrices
  {
    /** K_r = V^T K V (k x k, symmetric positive definite). */
    FullMatrix<double> stiffness;
    /**
     * If not empty, K_r is diagonal, K_r = diag(stiffness_diagonal), and
     * stiffness is left empty (a basis that diagonalises it, see
     * zone_static_correction.h): no factorisation is needed.
     */
    Vector<double> stiffness_diagonal;
    /** C_r = C_c V (rows of the contact interface x k). */
    FullMatrix<double> gap_operator;
    /**
     * f_r,l = V^T f_l for every load l of the component, at its reference
     * force (Component::reference_load_force()).
     */
    std::vector<Vector<double>> loads;
    /** The reference force [N] of each load. */
    std::vector<double> reference_forces;
    /**
     * Per load: true if its forces are proportional to the stiffness (a
     * prescribed displacement's, EdgeLoad::is_displacement): when the
     * stiffness is scaled by s, so are they.
     */
    std::vector<bool> stiffness_proportional;
    /** DoFs whose displacements the solvers report, and V's rows there. */
    std::vector<types::global_dof_index> observed_dofs;
    FullMatrix<double>                   observation;
    /**
     * A body held by contact alone (fe/component.h): its free motions R as
     * the contact sees them (C_c R, rows of the interface x motions), the
     * resultant R^T f_l of each load at its reference force, R's rows at the
     * observed DoFs, and the motions' names. Exact (R does not depend on
     * the materials); no columns for a body its supports hold.
     */
    FullMatrix<double>          rigid_gaps;
    std::vector<Vector<double>> rigid_loads;
    FullMatrix<double>          rigid_observation;
    std::vector<std::string>    motion_names;
    /**
     * The body's weight (EdgeLoad::is_weight), load number weight_load
     * (-1: none). It acts on every DoF, so the basis does not carry it
     * (loads[weight_load] and rigid_loads[weight_load] are zero): its exact
     * static response does, per zone z at unit density and the load's
     * reference force: the gaps C_c K^{-1} w_z, the rows of K^{-1} w_z at
     * the observed DoFs, and the resultant of w_z along the free motions.
     * The response to the weight is sum_z rho_z times these, with the zone
     * densities rho_z (zone_densities: those the matrices were built at).
     */
    int                         weight_load = -1;
    std::vector<Vector<double>> weight_gaps;
    std::vector<Vector<double>> weight_observation;
    std::vector<Vector<double>> weight_rigid_loads;
    std::vector<double>         zone_densities;

    /**
     * These matrices without what depends on the basis V (stiffness,
     * gap_operator, loads and observation are left empty): the reference
     * forces, the observed DoFs, the free motions and the weight's
     * responses, which a part of the basis or a re-analysed basis shares.
     */
    ReducedComponentMatrices
    without_basis() const;

    /** For Utilities::MPI::broadcast and other serialisation. */
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &stiffness &stiffness_diagonal &gap_operator &loads
        &reference_forces &stiffness_proportional &observed_dofs &observation
          &rigid_gaps &rigid_loads &rigid_observation &motion_names &weight_load
            &weight_gaps &weight_observation &weight_rigid_loads
              &zone_densities;
    }
  };

  /**
   * The reduction basis V of one component, modes with or without static
   * correction (see the top of this file).
   */
  class ReducedComponent
  {
  public:
    /**
     * @p modes: M-normalised modes of @p component (all of them are used;
     * with the static correction there may be none);
     * @p factorisation: the Cholesky factorisation of the component's
     * current stiffness, with at least the @p attachment_dofs and the DoFs
     * of its loads ordered last (ContactScene::stiffness_factorisation());
     * @p attachment_dofs: the DoFs of the static correction (ignored
     * without it). The component's current stiffness is the nominal one.
     */
    ReducedComponent(
      const Component                            &component,
      const ModalBasis                           &modes,
      std::shared_ptr<const SparseCholesky>       factorisation,
      const std::vector<types::global_dof_index> &attachment_dofs,
      const bool                                  static_correction,
      const double                                rank_tolerance = 1e-12);

    unsigned int
    n_modes() const;
    unsigned int
    n_corrections() const;
    /** Vectors added by add_vectors() (after the corrections). */
    unsigned int
    n_added() const;
    /** k = n_modes() + n_corrections() + n_added(). */
    unsigned int
    size() const;

    /**
     * Enriches the basis with the vectors @p u (e.g. exact displacement
     * fields of the component where a reduced answer was found wrong):
     * each is made K-orthogonal to the basis (twice, at the nominal
     * stiffness; one back-substitution per pass) and K-normalised, so that
     * K_r stays diag(Lambda, I); a vector whose new part has a K-norm below
     * 1e-10 of its own is dropped (already in the span). Returns how many
     * were added. They are kept full-length.
     */
    unsigned int
    add_vectors(const std::vector<Vector<double>> &u);
    bool
    has_static_correction() const;

    /** K_r = V^T K V at the nominal stiffness. */
    const FullMatrix<double> &
    stiffness() const;
    /** The factorisation of the nominal stiffness the basis was built on. */
    const std::shared_ptr<const SparseCholesky> &
    stiffness_factorisation() const;
    /**
     * V^T K x at the nominal stiffness, without a back-substitution (the
     * static correction's part is X^T (E^T x - R^T Phi^T K x)).
     */
    Vector<double>
    stiffness_products(const Vector<double> &x) const;
    /**
     * The loads that make the static correction modes: without modes,
     * Psi = K^{-1} F with F zero outside B (the factorisation's trailing
     * DoFs, boundary_dofs()) and F_B = E_B X, returned here (|B| x
     * n_corrections(); with modes, Psi is that minus Phi R X).
     */
    FullMatrix<double>
    correction_loads() const;
    /** B, in the order of the rows of correction_loads(). */
    const std::vector<types::global_dof_index> &
    boundary_dofs() const;
    /**
     * V^T K_z V for every zone z of the component. For a single-zone
     * component K = E K_z, so this is K_r / E; otherwise it is computed
     * from the whole basis (one back-substitution per basis vector).
     */
    std::vector<FullMatrix<double>>
    zone_stiffnesses() const;
    /** V^T f. */
    Vector<double>
    project(const Vector<double> &f) const;
    /** C V for a sparse C acting on this component's DoFs. */
    FullMatrix<double>
    project_rows(const SparseMatrix<double> &C) const;
    /** The rows of V at @p dofs. */
    FullMatrix<double>
    rows(const std::vector<types::global_dof_index> &dofs) const;
    /** u = V q. */
    void
    expand(const Vector<double> &q, Vector<double> &u) const;

    /**
     * The exact static responses to the component's weight per zone,
     * K^{-1} w_z at unit density and the weight's reference force (empty
     * without gravity): back-substitutions with the shared factorisation,
     * made once.
     */
    const std::vector<Vector<double>> &
    weight_responses() const;

    /**
     * The reduced matrices of this component for the gap operator block
     * @p gap_operator (C_c of the contact interface), observing
     * @p observed_dofs.
     */
    ReducedComponentMatrices
    matrices(const SparseMatrix<double>                 &gap_operator,
             const std::vector<types::global_dof_index> &observed_dofs) const;

  private:
    // Forms the static correction on B: R, X and the correction columns of
    // V_B.
    void
    build_static_correction(
      const std::vector<types::global_dof_index> &attachment_dofs,
      const double                                rank_tolerance);
    // E^T x for a full-length x (E's columns are supported on B).
    Vector<double>
    attachment_loads(const Vector<double> &x) const;
    // The static correction part of a row of V, from its raw row
    // Psi_raw^T e_d = E^T K^{-1} e_d and its modal row.
    void
    correction_row(const Vector<double> &raw,
                   const Vector<double> &modal,
                   Vector<double>       &row) const;

    const Component                      &component;
    const ModalBasis                     &modes;
    std::shared_ptr<const SparseCholesky> factorisation;
    // B (the factorisation's trailing DoFs) and each DoF's place in it (-1
    // outside).
    std::vector<types::global_dof_index> boundary;
    std::vector<int>                     position;
    FullMatrix<double>                   lambda; // Phi^T K Phi
    // The static correction: E_B (unit columns at the attachment DoFs, then
    // the loads), R = Lambda^{-1} Phi^T E, X, and the basis at B.
    FullMatrix<double> E_B, R, X;
    FullMatrix<double> V_B;
    FullMatrix<double> K_r;
    // K^{-1} w_z per zone (see weight_responses()).
    std::vector<Vector<double>> weight_fields;
    // The nominal zone moduli (K = sum_z E_z K_z, whatever the component's
    // current materials), and the vectors of add_vectors().
    std::vector<double>         nominal_moduli;
    std::vector<Vector<double>> added;
  };
} // namespace FuzzyContact

#endif
