// The discrete contact problem that every solver of FuzzyContact solves, and
// the result they all return.
//
// Whatever model the displacements come from (the full finite element
// systems, or component modes with or without static correction), with the
// contact forces p (two per slave node k: p_n = p[2k] >= 0 in compression
// and p_t = p[2k+1] along the tangent), the gaps are affine in p:
//
//     g(p) = g_initial + lambda g_load + W p,
//
// with W = C K^{-1} C^T the contact flexibility [m/N] (symmetric positive
// semi-definite), g_initial the gaps of the unloaded bodies (normal rows:
// g0, tangential rows: 0) and g_load the change of the gaps under the
// external load at load factor 1 without contact forces. The conditions
// at node k are Signorini and Coulomb's law:
//
//     g_n >= 0,  p_n >= 0,  g_n p_n = 0,
//     |p_t| <= mu p_n,  stick (dg_t = 0) where |p_t| < mu p_n,
//     slip where |p_t| = mu p_n, with dg_t p_t <= 0 (the friction force
//     opposes the slip).
//
// The load is applied proportionally in n_load_steps equal steps (lambda =
// 1/n, 2/n, ..., 1), or along a load history of stages: stage s ramps its
// own loads (gap change g_load,s) from 0 to full in its own n_s steps, on
// top of the earlier stages' loads held at full value,
//
//     g_free = g_initial + sum_{r < s} g_load,r + (i / n_s) g_load,s,
//
// (all of it times an overall load factor); the proportional load is the
// one-stage history. Friction depends on the path, so each step solves the
// incremental problem in which dg_t = g_t - g_t,previous is the tangential
// displacement since the converged previous step (g_t,previous = 0 before
// the first step); the state carries from stage to stage. All solvers solve
// exactly this discrete problem, so that their differences measure only the
// error of the model (W, g_load) and the error of the algorithm.
//
// The complementarity residual of a state is measured with the natural
// nonlinear complementarity functions (Hueber, Stadler and Wohlmuth 2008)
//
//     phi_n = p_n - max(0, p_n - c_n g_n),
//     phi_t = p_t - proj_[-mu a, mu a](p_t - c_t dg_t),  a = max(0, p_n - c_n
//     g_n),
//
// with c_n = 1 / W_nn and c_t = 1 / W_tt of the node (they turn a gap into
// the force that would close it), as max_k (|phi_n| + |phi_t|) divided by
// the force scale max(sum_k p_n, max_k c_n |g_free,n|). It is zero exactly at
// a solution, and independent of the units.
//
// Bodies held by contact alone (fe/component.h: their supports leave
// rigid-body motions free) add the amplitudes a of their free motions R as
// unknowns: the gaps are
//
//     g(p, a) = g_initial + lambda g_load + W p + G a,   G = sum_c C_c R_c,
//
// with W that of the pinned bodies, and each free motion adds the
// equilibrium of its body along it,
//
//     G^T p + lambda e = 0,   e = R^T f,
//
// (the contact forces balance the resultant of the external load). Its
// residual is measured per motion relative to sum_j |G_j p_j| + |lambda
// e|. A load no admissible contact forces can balance (p_n >= 0, |p_t| <=
// mu p_n: a block on a slope steeper than its friction angle) has no
// static solution; check_equilibrium() (static_equilibrium.h) says so (the
// exact solver calls it when its iterations fail).

#ifndef fuzzycontact_contact_contact_problem_h
#define fuzzycontact_contact_contact_problem_h

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  class ContactWorkspace;

  enum class ContactStatus
  {
    open,
    stick,
    slip
  };

  std::string
  to_string(ContactStatus status);

  /** Row of the normal and of the tangential gap of node k. */
  inline unsigned int
  normal_row(const unsigned int k)
  {
    return 2 * k;
  }
  inline unsigned int
  tangential_row(const unsigned int k)
  {
    return 2 * k + 1;
  }

  /**
   * Access to the contact flexibility W, which a solver may only need in
   * part: the full-order solver computes a column of W only when the
   * active set first needs it (two sparse back-substitutions), the reduced
   * models combine a column of W from their components' parts when a
   * solver first asks for it (ReducedContactModel), and a dense W is read
   * as it is (DenseFlexibility). W is symmetric, so a column is also a row:
   * column() returns it contiguously.
   */
  class FlexibilityOperator
  {
  public:
    virtual ~FlexibilityOperator() = default;
    /** Number of rows and columns (twice the number of slave nodes). */
    virtual unsigned int
    size() const = 0;
    /** Makes the given columns available (computing them if needed). */
    virtual void
    prepare(const std::vector<unsigned int> &columns) = 0;
    /** W(i, j); column j must have been prepared. */
    virtual double
    operator()(const unsigned int i, const unsigned int j) const = 0;
    /**
     * Column j of W, size() contiguous entries (prepares it if needed);
     * valid until the next call of column() or a change of the operator.
     */
    virtual const double *
    column(const unsigned int j) = 0;
    /** W(i, i), whether or not column i was prepared. */
    virtual double
    diagonal(const unsigned int i) = 0;
    /**
     * g += W(:, J) p(J), J = @p columns: the gaps of forces that are zero
     * outside J. Column by column here (BLAS axpy); an operator that keeps
     * its columns side by side does it by matrix-vector products.
     */
    virtual void
    add_columns(const std::vector<unsigned int> &columns,
                const Vector<double>            &p,
                Vector<double>                  &g);
    /**
     * A number that identifies the operator and the present value of its
     * W: unique to the operator when it is made, and new whenever W
     * changes (a new state of a reduced model, new stiffness scales), so
     * that what was computed from W (a factor of a part of it,
     * closed_set_factor.h) is known to be of another W when it differs.
     */
    unsigned long
    state() const;

  protected:
    FlexibilityOperator();
    /** To be called by a derived class whenever its W changes. */
    void
    changed();
    /**
     * To be called by a derived class whose W is back to exactly the value
     * it had when state() returned @p state (a reduced model back at
     * stiffness scales it had), so that what was computed from W then is
     * known to hold again.
     */
    void
    restored(const unsigned long state);

  private:
    unsigned long state_;
  };

  /** A FlexibilityOperator that holds W as a dense matrix. */
  class DenseFlexibility : public FlexibilityOperator
  {
  public:
    explicit DenseFlexibility(const FullMatrix<double> &W);
    unsigned int
    size() const override;
    void
    prepare(const std::vector<unsigned int> &columns) override;
    double
    operator()(const unsigned int i, const unsigned int j) const override;
    /** Column j of W, gathered from the rows. */
    const double *
    column(const unsigned int j) override;
    double
    diagonal(const unsigned int i) override;

  private:
    const FullMatrix<double> &W;
    std::vector<double>       gathered;
  };

  /**
   * The free rigid-body motions of the bodies held by contact alone (see
   * the top of this file).
   */
  struct RigidMotions
  {
    /**
     * G: the change of every gap row per unit amplitude of each free
     * motion [m/m] (n_rows x n_motions; no columns if every body is held by
     * its supports).
     */
    FullMatrix<double> gaps;
    /** Each motion in words, with its body ("Block: translation ..."). */
    std::vector<std::string> names;

    unsigned int
    size() const;
    /** The same motions seen by the rows @p rows only. */
    RigidMotions
    restricted(const std::vector<unsigned int> &rows) const;
  };

  /**
   * One stage of a load history as the gaps see it: the change of the
   * gaps under the stage's loads at full value (load factor 1), applied in
   * n_steps equal steps; and the resultant e of its loads along the free
   * rigid-body motions (empty if there are none).
   */
  struct GapLoadStage
  {
    Vector<double> g_load;
    unsigned int   n_steps = 1;
    Vector<double> rigid_load;
  };

  /**
   * A contact problem of small dense size: the reduced problem (or the full
   * one, once its W is known). It does not care how W and the gaps were
   * obtained.
   */
  struct ContactProblem
  {
    /**
     * Contact flexibility [m/N], n_rows x n_rows, symmetric; empty when
     * flexibility is set.
     */
    FullMatrix<double> W;
    /**
     * W as an operator, if it is not held in W (the reduced models combine
     * its columns on demand; they validate their parts when they build
     * them).
     */
    std::shared_ptr<FlexibilityOperator> flexibility;
    /** Gaps without load and contact forces (normal rows: g0). */
    Vector<double> g_initial;
    /** Change of the gaps under the external load at load factor 1. */
    Vector<double> g_load;
    /**
     * The load history, if the loads are applied in stages (their g_load
     * add up to g_load); empty: one proportional stage.
     */
    std::vector<GapLoadStage> stages;
    /** Friction coefficient of every node. */
    std::vector<double> mu;
    /**
     * The free motions of the bodies held by contact alone, and the
     * resultant e of the external load at load factor 1 along them.
     */
    RigidMotions   rigid;
    Vector<double> rigid_load;

    unsigned int
    n_nodes() const;
    unsigned int
    n_rows() const;
    /** g_initial + lambda g_load. */
    Vector<double>
    free_gaps(const double load_factor) const;
    /** Adds @p offset to every initial normal gap. */
    void
    shift_gaps(const double offset);
    /** The same coefficient for every node (>= 0). */
    void
    set_friction_coefficient(const double mu);
    /**
     * Throws if sizes disagree or an entry is not finite (of W only if W is
     * held densely: an operator's parts are checked where they are built).
     */
    void
    check() const;
  };

  /**
   * What one load step of a solver returns: forces, gaps and statuses, and
   * how the solver got there.
   */
  struct ContactState
  {
    Vector<double>             p;
    Vector<double>             g;
    std::vector<ContactStatus> status;
    /** +1 or -1: direction of the friction force of slipping nodes. */
    std::vector<int> slip_sign;
    /** Amplitudes of the free rigid-body motions (RigidMotions) [m]. */
    Vector<double> rigid;
    unsigned int   iterations = 0;
    double         residual   = 0;
  };

  /** Everything a load step needs to know. */
  struct LoadStep
  {
    /** 1, ..., total number of steps (counted over all stages). */
    unsigned int step;
    /** The stage (0, 1, ...) and the factor of its loads. */
    unsigned int stage = 0;
    double       load_factor;
    /** g_initial + the earlier stages' g_load + load_factor g_load. */
    Vector<double> g_free;
    /** Gaps at the end of the previous step (tangential rows: the
     * reference of the slip increment); zero before the first step. */
    Vector<double> g_previous;
    /** The converged state of the previous step (all open at first). */
    ContactState previous;
    /**
     * The free rigid-body motions (null if there are none) and the
     * resultant of this step's load along them, lambda e.
     */
    const RigidMotions *rigid = nullptr;
    Vector<double>      rigid_load;
    /**
     * What the solver may keep between solves (contact_workspace.h), and
     * the state this step should start from (the same step's at a
     * neighbouring point), if any; both may be null.
     */
    ContactWorkspace   *workspace = nullptr;
    const ContactState *start     = nullptr;

    /** The number of free rigid-body motions. */
    unsigned int
    n_motions() const;
  };

  /**
   * Applies the load history @p stages (each stage's loads in its own
   * steps, on top of the earlier stages' loads), all loads times
   * @p load_factor, calling @p solve_step for each step from the state the
   * previous one converged to; returns the last state with the iterations
   * summed over all steps and the largest residual. With a @p workspace,
   * each step gets it and the start it holds for that step (if any), and
   * its converged state is left there (contact_workspace.h).
   */
  ContactState
  solve_in_load_steps(
    const Vector<double>                                &g_initial,
    const std::vector<GapLoadStage>                     &stages,
    const double                                         load_factor,
    const std::function<ContactState(const LoadStep &)> &solve_step,
    const RigidMotions                                  *rigid     = nullptr,
    ContactWorkspace                                    *workspace = nullptr);

  /**
   * The one-stage history: the load in @p n_steps equal increments up to
   * @p load_factor.
   */
  ContactState
  solve_in_load_steps(
    const Vector<double>                                &g_initial,
    const Vector<double>                                &g_load,
    const double                                         load_factor,
    const unsigned int                                   n_steps,
    const std::function<ContactState(const LoadStep &)> &solve_step);

  /**
   * Per-node residuals |phi_n| + |phi_t| (see the top of this file) of the
   * forces @p p with gaps @p g at a load step whose previous gaps are
   * @p g_previous. @p c_n and @p c_t give the scaling of node k; they are
   * only called for nodes where they matter (closed or penetrating ones).
   */
  std::vector<double>
  complementarity_residuals(const Vector<double>      &p,
                            const Vector<double>      &g,
                            const Vector<double>      &g_previous,
                            const std::vector<double> &mu,
                            const std::function<double(unsigned int)> &c_n,
                            const std::function<double(unsigned int)> &c_t);

  /**
   * The residual |phi_n| + |phi_t| of node @p k alone (friction coefficient
   * @p mu), as complementarity_residuals() computes it for every node: a
   * solver that works on a few nodes tests them without visiting the rest.
   */
  double
  complementarity_residual(const unsigned int    k,
                           const Vector<double> &p,
                           const Vector<double> &g,
                           const Vector<double> &g_previous,
                           const double          mu,
                           const std::function<double(unsigned int)> &c_n,
                           const std::function<double(unsigned int)> &c_t);

  /** The force scale of the relative residual (see the top of this file). */
  double
  residual_scale(const Vector<double>                      &p,
                 const Vector<double>                      &g_free,
                 const std::function<double(unsigned int)> &c_n);

  /** g += G a: the gaps' change under the free motions' amplitudes. */
  void
  add_rigid_gaps(const LoadStep       &step,
                 const Vector<double> &a,
                 Vector<double>       &g);

  /**
   * The relative residual of the equilibrium G^T p + lambda e = 0 of the
   * bodies held by contact alone (see the top of this file); 0 if there
   * are none. With a @p force_scale [N] (the complementarity residual's,
   * residual_scale()), the residual of each motion is relative to at least
   * that force along it: forces at round-off where the answer is no force
   * do not count as an imbalance.
   */
  double
  equilibrium_residual(const LoadStep       &step,
                       const Vector<double> &p,
                       const double          force_scale = 0);

  /**
   * Throws, naming @p what and the motion, if neither the step's load nor
   * the contact forces @p p act along a free motion of a body held by
   * contact alone: its position is then not determined (any position that
   * does not penetrate solves the problem). Forces below 1e-12 of
   * @p force_scale count as none.
   */
  void
  check_motions_determined(const LoadStep       &step,
                           const Vector<double> &p,
                           const std::string    &what,
                           const double          force_scale = 0);

  /**
   * What check_motions_determined() throws: no start or method of a
   * solver changes it.
   */
  DeclException1(ExcPositionNotDetermined, std::string, << arg1);

  /**
   * DoFs whose displacements a solver reports, per component: the
   * observations of a study (study/observations.h) ask for them, and every
   * solver returns the displacements there, even when it computes no
   * displacement field.
   */
  using ObservedDofs = std::vector<std::vector<types::global_dof_index>>;

  /**
   * The result of a contact solver: per slave node the forces, gaps and
   * statuses; the total forces; the displacements at the observed DoFs;
   * and what it cost.
   */
  struct ContactSolution
  {
    std::string solver;
    /** Forces (2 per node), gaps g = g0 + C u (2 per node). */
    Vector<double>             p;
    Vector<double>             g;
    std::vector<ContactStatus> status;
    /** sum_k p_n and sum_k p_t [N]. */
    double normal_force     = 0;
    double tangential_force = 0;
    /**
     * Displacements [m] at the observed DoFs: observed[c][i] is that of the
     * i-th observed DoF of component c (see ObservedDofs).
     */
    std::vector<std::vector<double>> observed;
    /**
     * Amplitudes of the free rigid-body motions of the bodies held by
     * contact alone [m], in the order of the problem's RigidMotions.
     */
    Vector<double> rigid;
    unsigned int   iterations   = 0;
    unsigned int   n_load_steps = 1;
    /** Relative complementarity residual of the final state. */
    double residual = 0;
    /** Wall time of the solve [s] (see each solver for what it covers). */
    double time = 0;
    /** Displacements of every component, if the solver computed them. */
    std::vector<Vector<double>> displacements;

    double
    p_n(const unsigned int k) const;
    double
    p_t(const unsigned int k) const;
    unsigned int
    n_nodes() const;
    unsigned int
    count(const ContactStatus s) const;
    /** Fills status-derived totals from p. */
    void
    compute_totals();
  };
} // namespace FuzzyContact

#endif
