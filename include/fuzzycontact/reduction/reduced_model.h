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
// of MacNeal and Craig-Chang), and K-orthonormalised through a pivoted
// Cholesky factorisation of their Gram matrix S = Psi_res^T K Psi_res =
// E^T K^{-1} E - (Phi^T E)^T Lambda^{-1} Phi^T E, P^T S P = L L^T, stopping
// at pivots below rank_tolerance times the largest diagonal entry
// (linearly dependent attachment modes): Psi = Psi_res X with
// X = P_r L_r^{-T}. Then
//
//   K_r = V^T K V = [Lambda, 0; 0, I],
//
// and any load in the span of E (every contact force C^T p and the
// external load) gives the exact static solution: with the correction the
// reduced contact flexibility W = C V K_r^{-1} V^T C^T equals the full one
// up to the accuracy of the back-substitutions. Without it, point contact
// forces converge slowly in the number of modes.
//
// The basis is formed without full-length correction vectors, from one
// sparse Cholesky factorisation per component with the contact and load
// DoFs ordered last (reduced_component.h).
//
// The reduced contact problem is built from small matrices only
// (ReducedComponentMatrices: K_r, C_r = C_c V, f_r = V^T f_c and the rows of
// V at observed DoFs), so that a fuzzy study can rebuild it for reanalysed
// bases (V = T Y, K_r = Y^T (T^T K T) Y, ...) without any full-size matrix:
//
//   W = sum_c C_r,c K_r,c^{-1} C_r,c^T,   g_load = sum_c C_r,c K_r,c^{-1}
//   f_r,c.
//
// W is never assembled per state. Each part W_c is formed, checked and
// kept when it is built, densely or, when its rank k is below half its
// size m, as a factor U_c = C_r,c L_c^{-T} (K_r,c = L_c L_c^T, W_c = U_c
// U_c^T). A solver reads W through a FlexibilityOperator that combines a
// column of W = sum_c W_c / s_c the first time it asks for it in a state
// (O(m) per dense part, O(m k) per factored one) and keeps it, contiguous,
// until the state changes. A new state thus costs O(m) plus the columns the
// solver touches: a handful when few nodes close, not the O(m^2) of a
// dense W.

#ifndef fuzzycontact_reduction_reduced_model_h
#define fuzzycontact_reduction_reduced_model_h

#include <fuzzycontact/contact/contact_problem.h>
#include <fuzzycontact/reduction/reduced_component.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace FuzzyContact
{
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
     * The same, with the components' blocks formed on different MPI ranks:
     * component c's on rank @p owner[c] of @p comm from @p components[c]
     * (read there only), and sent to the other ranks (W_c or its factor,
     * its diagonal, load gaps and observation blocks; not its reduced
     * matrices, so that coordinates() of c is available on its owner only).
     * Every rank then solves with the same numbers. Collective.
     */
    ReducedContactModel(std::vector<ReducedComponentMatrices> components,
                        const Vector<double>                 &g_initial,
                        const std::vector<double>            &mu,
                        const std::vector<unsigned int>      &owner,
                        const MPI_Comm                        comm);
    // The problem's flexibility operator refers to this object.
    ReducedContactModel(const ReducedContactModel &) = delete;
    ReducedContactModel &
    operator=(const ReducedContactModel &) = delete;
    ~ReducedContactModel();

    /**
     * The total force of every load [N], load_forces[c][l] for load l of
     * component c: g_load becomes sum_c sum_l (F_l / F_ref,l) g_load,c,l.
     */
    void
    set_load_forces(const std::vector<std::vector<double>> &load_forces);

    /**
     * The load history (Scene::load_stages): the problem gets one
     * GapLoadStage per stage, the g_load of the stage's loads only, kept up
     * to date with the forces and stiffness scales. Empty (the default): one
     * proportional stage.
     */
    void
    set_load_stages(const std::vector<LoadStage> &stages);

    /**
     * The problem: W as an operator (ContactProblem::flexibility) that
     * combines its columns on demand, g_initial, g_load and mu.
     */
    const ContactProblem &
    problem() const;
    /** The problem, to change mu or shift the gaps. */
    ContactProblem &
    problem();
    /** W at the current state, assembled (for checks and reports). */
    FullMatrix<double>
    flexibility() const;
    /**
     * Component c's stiffness is now s_c times the one its reduced matrices
     * were built for (a change of E of every zone by one factor): W and
     * g_load become sums of W_c / s_c and g_load,c / s_c, and the recovered
     * displacements scale likewise. Exact, O(rows) per component.
     */
    void
    set_stiffness_scales(const std::vector<double> &scales);

    /**
     * The zone densities of every component (zone_densities[c][z]; at
     * first those its matrices were built at): a body's weight, carried by
     * its exact zone responses (ReducedComponentMatrices::weight_gaps),
     * becomes sum_z rho_z times them. Nothing else depends on them (the
     * problem is static). Exact, O(rows) per zone.
     */
    void
    set_zone_densities(const std::vector<std::vector<double>> &densities);

    /**
     * The factor of each of component @p c's zone responses to its weight
     * (ReducedComponentMatrices::weight_gaps) in its displacement at load
     * factor 1: rho_z (F / F_ref) / s_c; empty without a weight.
     */
    std::vector<double>
    weight_coefficients(const unsigned int c) const;

    /**
     * Replaces the reduced matrices of component @p c (for instance those
     * of a reanalysed basis) and rebuilds its blocks; the component's scale
     * is reset to 1.
     */
    void
    replace_component(const unsigned int c, ReducedComponentMatrices matrices);
    /**
     * The same for a component built on rank @p owner of @p comm (its
     * @p matrices read there only): its blocks are formed there and sent to
     * the other ranks. Collective.
     */
    void
    replace_component(const unsigned int       c,
                      ReducedComponentMatrices matrices,
                      const unsigned int       owner,
                      const MPI_Comm           comm);

    /**
     * Gives component @p c a second, fixed part: its reduced model becomes
     * the sum of the matrices set by replace_component() (the variable
     * part) and these, whose blocks are formed once here. This is how the
     * residual flexibility of static correction modes stays at its nominal
     * value while the modal part is re-analysed (MacNeal's residual
     * flexibility): a new modal part of n_modes vectors then costs
     * O(rows n_modes^2), not a factorisation of the whole reduced stiffness.
     */
    void
    set_fixed_part(const unsigned int c, ReducedComponentMatrices fixed);
    /** Removes the fixed part of component @p c (if any). */
    void
    clear_fixed_part(const unsigned int c);

    /** C_r,c K_r,c^{-1} C_r,c^T (both parts): W is their sum. */
    FullMatrix<double>
    component_flexibility(const unsigned int c) const;
    unsigned int
    n_components() const;

    /**
     * Modal coordinates q_c = K_r,c^{-1} (lambda f_r,c + C_r,c^T p); with a
     * fixed part, those of the variable part followed by those of the
     * fixed one. Empty for a component whose blocks were formed on another
     * MPI rank (see the constructor).
     */
    std::vector<Vector<double>>
    coordinates(const Vector<double> &p, const double load_factor) const;

    /**
     * The solution of a solver in reduced coordinates: forces, gaps
     * (g_free + W p), statuses, totals and the displacements at every
     * observed DoF, recovered as lambda O K_r^{-1} f_r + (O K_r^{-1} C_r^T) p
     * with matrices formed when the part is built (no reduced solve).
     */
    ContactSolution
    solution(const ContactState &state,
             const double        load_factor,
             const std::string  &solver) const;

  private:
    // The reduced matrices of (a part of) one component and what is formed
    // from them: the Cholesky factor L of K_r, W_c = C_r K_r^{-1} C_r^T
    // (dense, or its factor U = C_r L^{-T}) and its diagonal, g_load,c,l =
    // C_r K_r^{-1} f_r,l, and O K_r^{-1} C_r^T, O K_r^{-1} f_r,l, the
    // observed displacements straight from the forces.
    struct Part
    {
      ReducedComponentMatrices matrices;
      FullMatrix<double>       factor; // L (column-major: L^T row-major)
      // A diagonal K_r (ReducedComponentMatrices::stiffness_diagonal): L
      // is diag(root_diagonal) and factor is empty.
      Vector<double>              root_diagonal;
      bool                        low_rank = false;
      FullMatrix<double>          flexibility; // dense W_c
      FullMatrix<double>          U;           // W_c = U U^T
      Vector<double>              diagonal;
      std::vector<Vector<double>> load_gaps;
      FullMatrix<double>          observation_flexibility;
      std::vector<Vector<double>> observation_loads;
      // The weight's zone responses at the gaps and the observed DoFs
      // (ReducedComponentMatrices::weight_gaps, weight_observation).
      std::vector<Vector<double>> weight_gaps, weight_observation;
      bool                        present = false;
      // False for blocks formed on another MPI rank: matrices has its
      // reference forces and observed DoFs only, and factor is empty.
      bool has_matrices = false;

      // Adds a W_c(:, j) to @p w.
      void
      add_column(const unsigned int j, const double a, double *w) const;

      // What another rank needs to solve (the blocks, not the matrices).
      template <class Archive>
      void
      serialize(Archive &ar, const unsigned int)
      {
        ar &matrices.reference_forces &matrices.stiffness_proportional &matrices
          .observed_dofs &matrices.rigid_gaps &matrices.rigid_loads &matrices
          .rigid_observation &matrices.motion_names &matrices
          .weight_load &matrices.weight_rigid_loads &matrices
          .zone_densities &low_rank &flexibility &U &diagonal &load_gaps
            &observation_flexibility &observation_loads &weight_gaps
              &weight_observation &present;
      }
    };
    class Flexibility;

    // Checks and factorises a part's matrices, and forms its blocks (W_c
    // dense if @p dense, else as its factor U when its rank is low).
    void
    compute_blocks(Part &part, const bool dense = false) const;
    // Once every component's blocks are in variable: the reference load
    // forces and densities, the free motions of the bodies held by contact
    // alone (first_motion, the problem's RigidMotions), and W.
    void
    finish_construction();
    // The state of W changed: columns are combined afresh. If only the
    // stiffness scales changed (@p scales_only) and W had these scales
    // lately, it gets the state it had then back (what a solver kept from
    // it holds again: a study polls around a point, and most polls keep
    // the scales of the point); otherwise a new one.
    void
    flexibility_changed(const bool scales_only = false);
    // g_load = sum_c sum_l (F_l / F_ref,l) g_load,c,l / s_c, and that of
    // each load stage.
    void
    assemble_load_gaps();
    // The sum above over every load, or over the loads of @p stage only.
    Vector<double>
    load_gaps(const LoadStage *stage) const;
    // The loads' resultant along the free motions of the bodies held by
    // contact alone (of @p stage's loads only, if given), at load factor 1.
    Vector<double>
    rigid_load(const LoadStage *stage) const;
    // F_l / F_ref,l of load l of component c.
    double
    load_factor(const unsigned int c, const unsigned int l) const;
    // Whether @p stage ramps component c's weight (any stage: nullptr).
    bool
    weight_in(const unsigned int c, const LoadStage *stage) const;

    std::vector<Part> variable, fixed;
    // The first free motion of each component in the problem's.
    std::vector<unsigned int> first_motion;
    std::vector<double>       scales;
    // The last stiffness scales and the state W had at each (at most
    // max_known_scales, the latest last), since the parts last changed.
    std::vector<std::pair<std::vector<double>, unsigned long>> known_scales;
    static constexpr unsigned int    max_known_scales = 32;
    std::vector<std::vector<double>> densities;
    std::vector<std::vector<double>> load_forces;
    std::vector<LoadStage>           load_stages;
    std::shared_ptr<Flexibility>     flexibility_;
    ContactProblem                   problem_;
  };
} // namespace FuzzyContact

#endif
