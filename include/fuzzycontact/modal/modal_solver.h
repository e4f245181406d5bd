// The lowest eigenpairs of K phi = lambda M phi (lambda = omega^2), by
// ARPACK's implicitly restarted Lanczos method in shift-invert mode: the
// operator (K - sigma M)^{-1} M is applied through one sparse LU
// factorisation (UMFPACK), so the eigenvalues nearest the shift sigma
// converge first.
//
// The modes are M-normalised (phi^T M phi = 1), sorted by frequency, signed
// so that their largest entry is positive, and each comes with its relative
// residual ||K phi - lambda M phi|| / ||K phi||. In double precision that
// residual cannot fall below about eps * lambda_max / lambda, where
// lambda_max ~ max_i K_ii / M_ii grows like h^-2 under mesh refinement: it is
// a floor of the arithmetic, not of the solver (see doc/modal-analysis.md).

#ifndef fuzzycontact_modal_modal_solver_h
#define fuzzycontact_modal_modal_solver_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <string>
#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  struct ModalParameters
  {
    /** Number of modes wanted (ignored if a cutoff frequency is set). */
    unsigned int n_modes = 9;
    /** If positive: every mode below this frequency [Hz], however many. */
    double cutoff_frequency = 0;
    /** ARPACK's relative convergence tolerance on the Ritz values. */
    double tolerance = 1e-12;
    /** Spectral shift sigma [(rad/s)^2]; must be negative for a free body. */
    double shift = 0;
    /**
     * ARPACK's iterations (restarts of the Lanczos process) at most; 0:
     * the number of DoFs, at least 300.
     */
    unsigned int max_iterations = 0;

    static void
    declare_parameters(ParameterHandler &prm);
    void
    parse_parameters(ParameterHandler &prm);
  };

  struct ModalBasis
  {
    /** lambda_j = omega_j^2 [(rad/s)^2], ascending. */
    std::vector<double> eigenvalues;
    /** M-normalised modes, zero at clamped DoFs. */
    std::vector<Vector<double>> modes;
    /** ||K phi - lambda M phi|| / ||K phi|| of each mode. */
    std::vector<double> residuals;

    unsigned int
    size() const;
    /** f_j = sqrt(lambda_j) / (2 pi) [Hz]. */
    std::vector<double>
    frequencies() const;
    double
    max_residual() const;
    /**
     * Groups of consecutive modes whose eigenvalues lie within a relative
     * distance @p relative_gap of each other: the close or repeated
     * eigenvalues for which a single mode is not well defined. Singletons
     * are included, so the groups partition 0..size()-1.
     */
    std::vector<std::vector<unsigned int>>
    clusters(const double relative_gap) const;
  };

  /**
   * Relative residuals ||K x - lambda M x|| / ||K x|| of given pairs.
   */
  std::vector<double>
  relative_residuals(const SparseMatrix<double>        &K,
                     const SparseMatrix<double>        &M,
                     const std::vector<double>         &eigenvalues,
                     const std::vector<Vector<double>> &modes);

  class SparseCholesky;

  class ModalSolver
  {
  public:
    explicit ModalSolver(const ModalParameters &parameters);

    /**
     * Lowest modes of (K, M), by ARPACK in shift-invert mode on a
     * factorisation of K - sigma M: a sparse Cholesky (CHOLMOD) for
     * sigma <= 0, where K - sigma M is positive definite for a supported
     * structure, a sparse LU (UMFPACK) above. Every Lanczos step is one
     * plain back-substitution. @p what names the structure in messages.
     * Throws with a clear message if ARPACK fails or the problem is
     * singular at the chosen shift (for instance a free body with
     * shift 0).
     */
    ModalBasis
    solve(const SparseMatrix<double> &K,
          const SparseMatrix<double> &M,
          const std::string          &what) const;

    /**
     * The same with a factorisation of K that the caller already has (the
     * one its static correction uses): the shift must be 0.
     */
    ModalBasis
    solve(const SparseMatrix<double> &K,
          const SparseMatrix<double> &M,
          const SparseCholesky       &K_factorisation,
          const std::string          &what) const;

  private:
    // The modes with the inverse operator (K - sigma M)^{-1} of @p inverse,
    // n_modes of them or, with a cutoff, every one below it.
    template <class Inverse>
    ModalBasis
    solve_with(const SparseMatrix<double> &K,
               const SparseMatrix<double> &M,
               const Inverse              &inverse,
               const std::string          &what) const;
    template <class Inverse>
    ModalBasis
    solve_for(const SparseMatrix<double> &K,
              const SparseMatrix<double> &M,
              const Inverse              &inverse,
              const unsigned int          n_modes,
              const std::string          &what) const;

    ModalParameters parameters;
  };
} // namespace FuzzyContact

#endif
