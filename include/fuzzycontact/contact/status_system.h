// The linear algebra of one iteration of the exact contact solver
// (active_set_solver.h): for fixed statuses of the slave nodes the contact
// conditions are linear, and this is that linear system.

#ifndef fuzzycontact_contact_status_system_h
#define fuzzycontact_contact_status_system_h

#include <fuzzycontact/contact/contact_problem.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace FuzzyContact
{
  /**
   * Solves A x = b (A square, general) by LU with partial pivoting; if
   * LAPACK's condition estimate says A is numerically singular, by the
   * pseudo-inverse (least squares, minimum norm) instead.
   */
  Vector<double>
  solve_dense(const FullMatrix<double> &A, const Vector<double> &b);

  /**
   * The linear system of fixed statuses: unknowns p_n of the closed nodes,
   * p_t of the sticking ones (a slipping node's p_t is mu s p_n), and the
   * amplitudes a of the free rigid-body motions, if any; equations g_n = 0
   * of the closed nodes, g_t = g_t,previous of the sticking ones, and the
   * equilibrium G^T p + lambda e = 0 along each free motion
   * (contact_problem.h). The amplitudes and the equilibrium rows are scaled
   * by the closed rows' mean flexibility, so that every block of A has the
   * units and size of W's.
   */
  struct StatusSystem
  {
    std::vector<unsigned int> closed, sticking, rows, columns;
    FullMatrix<double>        A;

    StatusSystem(FlexibilityOperator              &W,
                 const std::vector<ContactStatus> &status,
                 const std::vector<int>           &sign,
                 const std::vector<double>        &mu,
                 const RigidMotions               *rigid = nullptr);

    /**
     * The solution for the gap residuals @p gap_rhs (per entry of rows: the
     * value of W p + G a the equations ask for) and, with free motions, the
     * resultant @p load of the external load along them (lambda e): x,
     * solved by solve_dense().
     */
    Vector<double>
    solve(const Vector<double> &gap_rhs, const Vector<double> &load) const;

    /** The forces of a solution x. */
    Vector<double>
    forces(const Vector<double>             &x,
           const std::vector<ContactStatus> &status,
           const std::vector<int>           &sign,
           const std::vector<double>        &mu) const;

    /** The amplitudes of the free motions in a solution x. */
    Vector<double>
    amplitudes(const Vector<double> &x) const;

  private:
    unsigned int n_motions = 0;
    double       scale     = 1;
  };

  /**
   * g = g_free + W p (+ G a), using only the columns where p is not zero
   * (the entries of @p columns).
   */
  Vector<double>
  gaps_of(FlexibilityOperator             &W,
          const Vector<double>            &g_free,
          const Vector<double>            &p,
          const std::vector<unsigned int> &columns,
          const LoadStep                  *step = nullptr,
          const Vector<double>            &a    = Vector<double>());
} // namespace FuzzyContact

#endif
