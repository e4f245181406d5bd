#include <fuzzycontact/base/factor_preconditioned_cg.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    // The preconditioner: x = K0^{-1} r by the factorisation.
    struct FactorPreconditioner
    {
      const SparseCholesky &factor;

      void
      vmult(Vector<double> &dst, const Vector<double> &src) const
      {
        dst = src;
        factor.solve(dst);
      }
    };
  } // namespace


  unsigned int
  cg_steps_bound(const double lower, const double upper, const double tolerance)
  {
    Assert(lower > 0 && upper >= lower && tolerance > 0, ExcInternalError());
    const double k = upper / lower;
    if (k <= 1 + 1e-14)
      return 1;
    const double rho = (std::sqrt(k) - 1) / (std::sqrt(k) + 1);
    return 1 + static_cast<unsigned int>(
                 std::ceil(std::log(tolerance / 2) / std::log(rho)));
  }


  FactorPreconditionedCG::FactorPreconditionedCG(
    const SparseMatrix<double>               &matrix_,
    std::shared_ptr<const SparseCholesky>     nominal,
    const double                              tolerance,
    const unsigned int                        max_iterations,
    const std::string                        &keys,
    const std::string                        &what,
    std::shared_ptr<IterativeSolveStatistics> statistics)
      : nominal(std::move(nominal))
      , tolerance(tolerance)
      , max_iterations(max_iterations)
      , keys(keys)
      , what(what)
      , statistics(std::move(statistics))
  {
    AssertThrow(this->nominal != nullptr && this->nominal->n() == matrix_.m() &&
                  matrix_.m() == matrix_.n(),
                ExcMessage(what + ": conjugate gradients need the "
                                  "factorisation of a matrix of the same "
                                  "size as their preconditioner."));
    AssertThrow(tolerance > 0 && max_iterations > 0,
                ExcMessage(what +
                           ": conjugate gradients need a positive "
                           "tolerance and iteration limit (" +
                           keys + ")."));
    matrix.reinit(matrix_.get_sparsity_pattern());
    matrix.copy_from(matrix_);
  }


  types::global_dof_index
  FactorPreconditionedCG::n() const
  {
    return matrix.m();
  }


  void
  FactorPreconditionedCG::solve(Vector<double> &b) const
  {
    AssertDimension(b.size(), matrix.m());
    const double norm = b.l2_norm();
    if (norm == 0)
      return;
    SolverControl control(max_iterations, tolerance * norm, false, false);
    SolverCG<Vector<double>> cg(control);
    Vector<double>           x(b.size());
    try
      {
        cg.solve(matrix, x, b, FactorPreconditioner{*nominal});
      }
    catch (const SolverControl::NoConvergence &e)
      {
        std::ostringstream message;
        message << what << ": conjugate gradients preconditioned by the "
                << "nominal factorisation did not reach the relative "
                << "residual " << tolerance
                << " in max_iterations = " << max_iterations
                << " steps (it reached " << e.last_residual / norm
                << "); raise or loosen them (" << keys << ").";
        AssertThrow(false, ExcMessage(message.str()));
      }
    if (statistics != nullptr)
      {
        ++statistics->solves;
        statistics->iterations += control.last_step();
        statistics->max_iterations =
          std::max(statistics->max_iterations, control.last_step());
      }
    b.swap(x);
  }
} // namespace FuzzyContact
