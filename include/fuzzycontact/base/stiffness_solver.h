// What the exact contact solver needs of a component's stiffness K: its
// size and x = K^{-1} b. A sparse Cholesky factorisation of K is one
// (base/sparse_cholesky.h); conjugate gradients on a changed stiffness,
// preconditioned by the factorisation of the nominal one, is another
// (base/factor_preconditioned_cg.h): a zone modulus that moved then costs
// a few back-substitutions per solve instead of a new factorisation.

#ifndef fuzzycontact_base_stiffness_solver_h
#define fuzzycontact_base_stiffness_solver_h

#include <deal.II/base/types.h>
#include <deal.II/lac/vector.h>

namespace FuzzyContact
{
  class StiffnessSolver
  {
  public:
    virtual ~StiffnessSolver() = default;

    /** Size of the matrix. */
    virtual dealii::types::global_dof_index
    n() const = 0;

    /** Overwrites @p b by K^{-1} b. */
    virtual void
    solve(dealii::Vector<double> &b) const = 0;
  };
} // namespace FuzzyContact

#endif
