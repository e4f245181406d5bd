// The Cholesky factor of the contact flexibility restricted to the
// constrained rows of an active set, kept up to date as the set changes.
//
// For fixed statuses the exact contact solver (active_set_solver.h) solves a
// linear system whose symmetric part is H = W_BB, W restricted to the rows
// B it constrains (the normal rows of the closed nodes and the tangential
// rows of the sticking ones; status_system.h). Between two iterations of
// the method, between two load steps and between two neighbouring points
// of a study, B changes by a few rows: refactorising H each time costs
// m^3/3 for m = |B| (8 Mflop at m = 290), a row added or removed only
// O(m^2):
//
//  - insert(r): H gains row and column r at the end, L gains the row
//    (l^T, d) with L l = W_Br and d = sqrt(W_rr - l^T l) (one forward
//    substitution);
//  - erase(r): row and column q of H are removed. Deleting row q and
//    column q of L leaves the factor of the smaller H once its trailing
//    block takes up the column l = L(q+1:m, q) that was removed:
//    L_22' L_22'^T = L_22 L_22^T + l l^T, a rank-one update by plane
//    rotations (LINPACK's dchud), O((m - q)^2);
//  - reset(): a new factorisation (LAPACK's dpotrf), when many rows change
//    at once or W itself changed.
//
// A row that W makes (numerically) dependent on those already in the
// factor (pivot d^2 below 1e-12 of W_rr: a reduced W of low rank, or two
// slave nodes at one point) is refused by insert(); the caller then solves
// otherwise (status_system.h falls back to a dense LU with a pseudo-inverse).
//
// The factor remembers the state of W it was made for
// (FlexibilityOperator::state()); after W changed it is still the exact
// factor of the old W_BB, a good preconditioner for the new one when the
// change is small (status_system.h decides).

#ifndef fuzzycontact_contact_closed_set_factor_h
#define fuzzycontact_contact_closed_set_factor_h

#include <fuzzycontact/contact/contact_problem.h>

#include <deal.II/lac/vector.h>

#include <vector>

namespace FuzzyContact
{
  class ClosedSetFactor
  {
  public:
    /** Rows of W in the factor, in the order of its rows. */
    const std::vector<unsigned int> &
    rows() const;
    unsigned int
    size() const;
    /** The position of row @p r of W in the factor, or -1. */
    int
    position(const unsigned int r) const;

    /** The state of W the factor was made for (see above). */
    unsigned long
    state() const;

    /** No rows. */
    void
    clear();

    /**
     * The factor of W_BB for @p rows, anew (LAPACK's dpotrf). False (and
     * the factor empty) if W_BB is not numerically positive definite.
     */
    bool
    reset(FlexibilityOperator &W, const std::vector<unsigned int> &rows);

    /**
     * Adds row and column @p r of W (of its current state, which must be
     * the factor's); false, and nothing changed, if the row is numerically
     * dependent on the rows already in the factor.
     */
    bool
    insert(FlexibilityOperator &W, const unsigned int r);

    /** Removes row and column @p r (which must be in the factor). */
    void
    erase(const unsigned int r);

    /**
     * x <- H^{-1} x, with x ordered as rows() (two triangular solves,
     * LAPACK's dtrtrs).
     */
    void
    solve(Vector<double> &x) const;

    /**
     * How often the factor was made anew, and how many rows were inserted
     * and erased by updates (for reports and benchmarks).
     */
    unsigned long n_resets = 0, n_inserts = 0, n_erases = 0;

  private:
    // Makes room for @p n rows (keeps the factor).
    void
    reserve(const unsigned int n);
    double &
    L(const unsigned int i, const unsigned int j)
    {
      return data[i + j * capacity];
    }
    double
    L(const unsigned int i, const unsigned int j) const
    {
      return data[i + j * capacity];
    }

    // Column-major, leading dimension capacity; lower triangle in use.
    std::vector<double>       data;
    unsigned int              capacity = 0;
    std::vector<unsigned int> rows_;
    std::vector<int>          positions;
    unsigned long             state_ = 0;
  };
} // namespace FuzzyContact

#endif
