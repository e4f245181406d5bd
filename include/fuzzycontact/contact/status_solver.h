// The linear system of fixed statuses (status_system.h), solved the way the
// exact contact solver needs it on distributed contact: many times, for
// statuses that change by a few nodes from one solve to the next, and for
// contact flexibilities W that change little from one point of a study to
// its neighbour.
//
// For fixed statuses the contact conditions are linear: g_n = 0 at the
// closed nodes, g_t = g_t,previous at the sticking ones, p_t = mu s p_n at
// the slipping ones, and, for the free motions of bodies held by contact
// alone (amplitudes a), the equilibrium G^T p + lambda e = 0. A
// StatusSolver keeps what it factorised from one solve to the next and
// takes the cheapest exact way:
//
//  - no closed node with friction (a frictionless problem, the solver's
//    frictionless start): the system is symmetric, [W_BB, G_B; G_B^T, 0]
//    with B the closed nodes' normal rows. It is solved by block
//    elimination on a Cholesky factor of W_BB (closed_set_factor.h) kept
//    up to date by row updates, O(m^2) per node that opens or closes,
//    instead of a new factorisation, O(m^3) (the free motions through their
//    Schur complement G_B^T W_BB^{-1} G_B, pseudo-inverted where the closed
//    rows do not hold a motion: the minimum-norm answer of StatusSystem);
//  - friction: the unknowns are both forces of every closed node and the
//    amplitudes; each closed node has its normal equation (a row of W) and
//    a tangential one, a row of W if it sticks, the row W_tt (p_t - mu s
//    p_n) = 0 if it slips. The system is not symmetric; it is factorised
//    densely (LAPACK's LU with partial pivoting, from W's contiguous
//    columns) and the factors are kept. A node that turns from sticking to
//    slipping, or back, replaces one row: the kept factors take it by a
//    row update (RowUpdatedLU: the Sherman-Morrison-Woodbury formula, one
//    back-substitution per row ever changed, kept), exact, so the next
//    solve of the same W costs a back-substitution and O(r N) for r rows
//    replaced. Where W changed (a neighbouring point of a study) or the
//    friction coefficients did, every row changes a little: the updated
//    factors then precondition GMRES (deal.II's SolverGMRES, right
//    preconditioning, its solver object kept from solve to solve), which
//    converges in a few steps. A node that opens or closes changes the
//    unknowns: a new factorisation; so does GMRES taking more than
//    gmres_refresh_steps (or not converging within gmres_max_steps), and
//    so do more rows replaced than max_replaced_rows();
//  - a system LAPACK's condition estimate calls singular is solved by
//    StatusSystem's pseudo-inverse (least squares, minimum norm).
// Every path solves the same equations to round-off (GMRES to a residual
// of 1e-13 of the right-hand side), so the path changes the work, not the
// answer.

#ifndef fuzzycontact_contact_status_solver_h
#define fuzzycontact_contact_status_solver_h

#include <fuzzycontact/base/row_updated_lu.h>
#include <fuzzycontact/contact/closed_set_factor.h>
#include <fuzzycontact/contact/contact_problem.h>

#include <deal.II/lac/lapack_support.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace FuzzyContact
{
  class StatusSolver
  {
  public:
    StatusSolver();
    ~StatusSolver();
    StatusSolver(StatusSolver &&) noexcept;
    StatusSolver &
    operator=(StatusSolver &&) noexcept;

    /**
     * The forces @p p (2 per node) and the free motions' amplitudes @p a
     * for the statuses (@p status, @p sign, coefficients @p mu) such that
     * (W p + G a)_i = @p target[i] in every constrained row i (target has
     * one entry per row of W; the others are not read) and G^T p = -@p load
     * (lambda e) along the free motions @p rigid (if any).
     */
    void
    solve(FlexibilityOperator              &W,
          const std::vector<ContactStatus> &status,
          const std::vector<int>           &sign,
          const std::vector<double>        &mu,
          const RigidMotions               *rigid,
          const Vector<double>             &target,
          const Vector<double>             &load,
          Vector<double>                   &p,
          Vector<double>                   &a);

    /** Forgets every factor (the next solve factorises anew). */
    void
    clear();

    /**
     * The solvers of the other load steps of the same problem (a
     * ContactWorkspace's; @p siblings may hold this one too, and must
     * outlive it). Where this solver's factors are of another W and a
     * sibling's are of the present one, for the same unknowns and with at
     * most max_replaced_rows() equations other than this solve's, the
     * solve takes a copy of the sibling's and replaces those rows: at a
     * point far from the last one, the load steps share the closed set and
     * differ in which nodes stick or slip, so one LU serves them all.
     */
    void
    set_siblings(const std::vector<StatusSolver> *siblings);

    /** What the solves did (for reports and benchmarks). */
    struct Counts
    {
      /** Solves, of them by the pseudo-inverse. */
      unsigned long solves = 0, pseudo_inverse = 0;
      /** Dense LU factorisations; GMRES solves and their steps; solves
       * on factors with rows replaced. */
      unsigned long lu = 0, gmres = 0, gmres_steps = 0, row_updates = 0;
      /** Factors taken over from the solver of another load step. */
      unsigned long adopted = 0;
      Counts &
      operator+=(const Counts &other)
      {
        solves += other.solves;
        pseudo_inverse += other.pseudo_inverse;
        lu += other.lu;
        gmres += other.gmres;
        gmres_steps += other.gmres_steps;
        row_updates += other.row_updates;
        adopted += other.adopted;
        return *this;
      }
    };
    const Counts &
    counts() const;
    /** The Cholesky factor (its resets and row updates). */
    const ClosedSetFactor &
    factor() const;

    /** GMRES on a kept factor stops at this residual, relative to the
     * right-hand side, or gives up (a new factorisation) after so many
     * steps. */
    static constexpr double       gmres_tolerance = 1e-13;
    static constexpr unsigned int gmres_max_steps = 8;
    /** A GMRES solve of more steps has the factors made anew after it. */
    static constexpr unsigned int gmres_refresh_steps = 4;
    /** At most so many rows of a system of N unknowns are replaced in the
     * kept factors; more make new factors (N / 4: each row replaced costs
     * a back-substitution, O(N^2), once, and O(N) per solve; the new
     * factorisation O(N^3). On the punch's far points, N = 290, N / 4
     * made 44 LUs where N / 8 made 73 and N / 2 40, and cost 25 % less
     * than N / 8). */
    static unsigned int
    max_replaced_rows(const unsigned int N)
    {
      return std::max(8u, N / 4);
    }

    /**
     * The unknowns of the system with friction: the closed nodes (both
     * forces of each), and the free motions with their scale (the closed
     * normal rows' mean flexibility, as in StatusSystem). Its factors
     * precondition any system of the same unknowns.
     */
    struct Unknowns
    {
      std::vector<unsigned int> closed;
      unsigned int              n_motions = 0;
      bool
      operator==(const Unknowns &other) const
      {
        return closed == other.closed && n_motions == other.n_motions;
      }
      unsigned int
      size() const
      {
        return 2 * closed.size() + n_motions;
      }
    };

  private:
    // Without friction, on the Cholesky factor: the closed normal rows B.
    bool
    solve_symmetric(FlexibilityOperator             &W,
                    const std::vector<unsigned int> &B,
                    const RigidMotions              *rigid,
                    const double                     scale,
                    const Vector<double>            &b,
                    Vector<double>                  &x);
    // With friction, on kept LU factors (unknowns: see Unknowns; the
    // right-hand side @p b and the solution @p x in their order).
    bool
    solve_general(FlexibilityOperator              &W,
                  const Unknowns                   &unknowns,
                  const std::vector<ContactStatus> &status,
                  const std::vector<int>           &sign,
                  const std::vector<double>        &mu,
                  const RigidMotions               *rigid,
                  const double                      scale,
                  const Vector<double>             &b,
                  Vector<double>                   &x);

    // What a system with friction is made of: its unknowns, its equations
    // (key: per closed node its tangential one, infinity if the node
    // sticks, else mu s; then the scale) and W's state. Two systems of the
    // same unknowns, W and scale differ only in the tangential rows whose
    // key differs.
    struct Stamp
    {
      Unknowns            unknowns;
      std::vector<double> key;
      unsigned long       state = 0;
      bool
      same_unknowns_and_W(const Stamp &other) const
      {
        return !key.empty() && unknowns == other.unknowns &&
               state == other.state && key.back() == other.key.back();
      }
      /** The tangential rows (2i + 1) whose equation differs from @p
       * other's (same unknowns). */
      std::vector<unsigned int>
      rows_differing_from(const Stamp &other) const;
    };

    ClosedSetFactor factor_;
    // The dense LU factors of the system with friction (its rows replaced
    // as the statuses change), and what they were made for.
    Stamp        lu;
    RowUpdatedLU factors;
    // The last system with friction assembled, and what for: the next one
    // at the same unknowns and W changes only the rows whose equation
    // changed.
    std::vector<double>              matrix;
    Stamp                            assembled;
    Counts                           counts_;
    const std::vector<StatusSolver> *siblings = nullptr;
    // GMRES, made at its first use and kept.
    struct Krylov;
    std::unique_ptr<Krylov> krylov_;
    Krylov &
    krylov();
  };
} // namespace FuzzyContact

#endif
