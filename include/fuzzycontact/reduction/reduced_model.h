// Component-mode reduction of the contact problem.
//
// Per component, the displacements are sought in a basis V:
//
//   V = [Phi]        the lowest modes (the paper's form), or
//   V = [Phi, Psi]   with static correction modes Psi for the contact DoFs
//                    and the loads.
//
// Psi starts from the attachment modes Psi_raw = K^{-1} E, where the
// columns of E are unit loads at every DoF that the contact operator C
// touches and the component's unit load vectors. They are made independent
// of the modes by K-orthogonal projection, Psi_res = Psi_raw - Phi
// Lambda^{-1} Phi^T E with Lambda = Phi^T K Phi (the residual flexibility
// of MacNeal and Craig-Chang), and K-orthonormalised through the
// eigenvectors of their Gram matrix S = Psi_res^T K Psi_res = E^T K^{-1} E -
// (Phi^T E)^T Lambda^{-1} Phi^T E, dropping directions whose eigenvalue is
// below rank_tolerance times the largest (linearly dependent attachment
// modes): Psi = Psi_res X with X = Q D^{-1/2}. Then
//
//   K_r = V^T K V = [Lambda, 0; 0, I],
//
// and any load in the span of E (every contact force C^T p and the
// external load) gives the exact static solution: with the correction the
// reduced contact flexibility W = C V K_r^{-1} V^T C^T equals the full one
// up to the accuracy of the back-substitutions. Without it, point contact
// forces converge slowly in the number of modes.
//
// The reduced contact problem is built from small matrices only
// (ReducedComponentMatrices: K_r, C_r = C_c V, f_r = V^T f_c and the rows of
// V at observed DoFs), so that a fuzzy study can rebuild it for reanalysed
// bases (V = T Y, K_r = Y^T (T^T K T) Y, ...) without any full-size matrix:
//
//   W = sum_c C_r,c K_r,c^{-1} C_r,c^T,   g_load = sum_c C_r,c K_r,c^{-1}
//   f_r,c.

#ifndef fuzzycontact_reduction_reduced_model_h
#define fuzzycontact_reduction_reduced_model_h

#include <fuzzycontact/contact/contact_interface.h>
#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

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
    /** C_r = C_c V (rows of the contact interface x k). */
    FullMatrix<double> gap_operator;
    /**
     * f_r,l = V^T f_l for every load l of the component, at its reference
     * force (Component::reference_load_force()).
     */
    std::vector<Vector<double>> loads;
    /** The reference force [N] of each load. */
    std::vector<double> reference_forces;
    /** DoFs whose displacements the solvers report, and V's rows there. */
    std::vector<types::global_dof_index> observed_dofs;
    FullMatrix<double>                   observation;
  };

  /**
   * The reduction basis V of one component, modes with or without static
   * correction (see the top of this file).
   */
  class ReducedComponent
  {
  public:
    /**
     * @p modes: M-normalised modes of @p component (all of them are used);
     * @p attachment_dofs: the DoFs of the static correction (ignored
     * without it). The component's current stiffness is the nominal one.
     */
    ReducedComponent(
      const Component                            &component,
      const ModalBasis                           &modes,
      const std::vector<types::global_dof_index> &attachment_dofs,
      const bool                                  static_correction,
      const double                                rank_tolerance = 1e-12);

    unsigned int
    n_modes() const;
    unsigned int
    n_corrections() const;
    /** k = n_modes() + n_corrections(). */
    unsigned int
    size() const;
    bool
    has_static_correction() const;

    /** K_r = V^T K V at the nominal stiffness. */
    const FullMatrix<double> &
    stiffness() const;
    /**
     * V^T K_z V for zone z of the component. For a single-zone component
     * K = E K_z, so this is K_r / E; otherwise it is computed from the
     * basis vectors (O(n k^2)).
     */
    FullMatrix<double>
    zone_stiffness(const unsigned int zone) const;
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
     * The reduced matrices of this component for the gap operator block
     * @p gap_operator (C_c of the contact interface), observing
     * @p observed_dofs.
     */
    ReducedComponentMatrices
    matrices(const SparseMatrix<double>                 &gap_operator,
             const std::vector<types::global_dof_index> &observed_dofs) const;

  private:
    const Component   &component;
    const ModalBasis  &modes;
    FullMatrix<double> lambda;         // Phi^T K Phi
    FullMatrix<double> lambda_inverse; //
    // Static correction: Psi_raw = K^{-1} E, B = Phi^T E, X.
    std::vector<Vector<double>> psi_raw;
    FullMatrix<double>          B;
    FullMatrix<double>          X;
    FullMatrix<double>          K_r;
  };

  /**
   * The reduced contact problem of several components: W and g_load from
   * their small matrices, and the recovery of displacements.
   */
  class ReducedContactModel
  {
  public:
    /**
     * @p g_initial, @p mu: initial gaps and friction coefficients of the
     * slave nodes (the ContactInterface's, or those of a SceneState). The
     * loads are at their reference forces until set_load_forces().
     */
    ReducedContactModel(std::vector<ReducedComponentMatrices> components,
                        const Vector<double>                 &g_initial,
                        const std::vector<double>            &mu);

    /**
     * The total force of every load [N], load_forces[c][l] for load l of
     * component c: g_load becomes sum_c sum_l (F_l / F_ref,l) g_load,c,l.
     */
    void
    set_load_forces(const std::vector<std::vector<double>> &load_forces);

    const ContactProblem &
    problem() const;
    /** The problem, to change mu or shift the gaps. */
    ContactProblem &
    problem();
    /**
     * Component c's stiffness is now s_c times the one its reduced matrices
     * were built for (a change of E of every zone by one factor): W and
     * g_load become sums of W_c / s_c and g_load,c / s_c, and the recovered
     * displacements scale likewise. Exact, O(rows^2) per component.
     */
    void
    set_stiffness_scales(const std::vector<double> &scales);

    /**
     * Replaces the reduced matrices of component @p c (for instance those
     * of a reanalysed basis) and rebuilds W and g_load; the component's
     * scale is reset to 1.
     */
    void
    replace_component(const unsigned int c, ReducedComponentMatrices matrices);

    /**
     * Gives component @p c a second, fixed part: its reduced model becomes
     * the sum of the matrices set by replace_component() (the variable
     * part) and these, whose blocks are formed once here. This is how the
     * residual flexibility of static correction modes stays at its nominal
     * value while the modal part is re-analysed (MacNeal's residual
     * flexibility): a new modal part then costs O(rows^2 n_modes), not a
     * factorisation of the whole reduced stiffness.
     */
    void
    set_fixed_part(const unsigned int c, ReducedComponentMatrices fixed);

    /** C_r,c K_r,c^{-1} C_r,c^T (both parts): W is their sum. */
    FullMatrix<double>
    component_flexibility(const unsigned int c) const;
    unsigned int
    n_components() const;

    /**
     * Modal coordinates q_c = K_r,c^{-1} (lambda f_r,c + C_r,c^T p); with a
     * fixed part, those of the variable part followed by those of the
     * fixed one.
     */
    std::vector<Vector<double>>
    coordinates(const Vector<double> &p, const double load_factor) const;

    /**
     * The solution of a solver in reduced coordinates: forces, gaps
     * (g_free + W p), statuses, totals and the displacements at every
     * observed DoF, recovered as lambda O K_r^{-1} f_r + (O K_r^{-1} C_r^T) p
     * with matrices formed when the model is built (no reduced solve).
     */
    ContactSolution
    solution(const ContactState &state,
             const double        load_factor,
             const std::string  &solver) const;

  private:
    // The reduced matrices of (a part of) one component and what is formed
    // from them: the factorised K_r, W_c = C_r K_r^{-1} C_r^T, g_load,c,l =
    // C_r K_r^{-1} f_r,l, and O K_r^{-1} C_r^T, O K_r^{-1} f_r,l, the
    // observed displacements straight from the forces.
    struct Part
    {
      ReducedComponentMatrices                  matrices;
      std::unique_ptr<LAPACKFullMatrix<double>> factor;
      FullMatrix<double>                        flexibility;
      std::vector<Vector<double>>               load_gaps;
      FullMatrix<double>                        observation_flexibility;
      std::vector<Vector<double>>               observation_loads;
      bool                                      present = false;
    };
    // Checks and factorises a part's matrices, and forms its blocks.
    void
    compute_blocks(Part &part) const;
    // W = sum_c W_c / s_c, and g_load.
    void
    assemble_problem();
    // g_load = sum_c sum_l (F_l / F_ref,l) g_load,c,l / s_c.
    void
    assemble_load_gaps();
    // F_l / F_ref,l of load l of component c.
    double
    load_factor(const unsigned int c, const unsigned int l) const;

    std::vector<Part>                variable, fixed;
    std::vector<double>              scales;
    std::vector<std::vector<double>> load_forces;
    ContactProblem                   problem_;
  };
} // namespace FuzzyContact

#endif
