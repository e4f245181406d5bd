#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/lapack_errors.h>
#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/base/sparse_direct_solver.h>
#include <fuzzycontact/modal/modal_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/arpack_solver.h>
#include <deal.II/lac/solver_control.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numeric>
#include <sstream>

namespace FuzzyContact
{
  void
  ModalParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal analysis");
    prm.declare_entry("number of modes",
                      "9",
                      Patterns::Integer(),
                      "How many of the lowest modes to compute per component "
                      "(ignored when a cutoff frequency is set).");
    prm.declare_entry("cutoff frequency",
                      "0",
                      Patterns::Double(),
                      "If positive: compute every mode below this frequency "
                      "[Hz] instead of a fixed number.");
    prm.declare_entry("tolerance",
                      "1e-12",
                      Patterns::Double(),
                      "ARPACK's relative tolerance on the eigenvalues.");
    prm.declare_entry("shift",
                      "0",
                      Patterns::Double(),
                      "Spectral shift sigma [(rad/s)^2] of the shift-invert "
                      "transformation; the modes nearest sigma converge "
                      "first. Use a negative value for an unclamped body.");
    prm.declare_entry("max iterations",
                      "0",
                      Patterns::Integer(),
                      "ARPACK's iterations (restarts of the Lanczos process) "
                      "at most; 0: the number of DoFs of the component, at "
                      "least 300.");
    prm.leave_subsection();
  }


  void
  ModalParameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Modal analysis");
    const long n = prm.get_integer("number of modes");
    AssertThrow(n >= 1,
                ExcMessage("Modal analysis: number of modes must be at least "
                           "1, got " +
                           std::to_string(n) + "."));
    n_modes          = static_cast<unsigned int>(n);
    cutoff_frequency = Input::non_negative(prm.get_double("cutoff frequency"),
                                           "Modal analysis: cutoff frequency");
    tolerance =
      Input::positive(prm.get_double("tolerance"), "Modal analysis: tolerance");
    shift = Input::finite(prm.get_double("shift"), "Modal analysis: shift");
    const long iterations = prm.get_integer("max iterations");
    AssertThrow(iterations >= 0 && iterations <= 1000000,
                ExcMessage("Modal analysis: max iterations must be from 0 "
                           "(automatic) to 1000000, got " +
                           std::to_string(iterations) + "."));
    max_iterations = static_cast<unsigned int>(iterations);
    prm.leave_subsection();
  }


  unsigned int
  ModalBasis::size() const
  {
    return eigenvalues.size();
  }


  std::vector<double>
  ModalBasis::frequencies() const
  {
    std::vector<double> f;
    for (const double lambda : eigenvalues)
      f.push_back(std::sqrt(std::max(lambda, 0.)) / (2. * M_PI));
    return f;
  }


  double
  ModalBasis::max_residual() const
  {
    return residuals.empty()
             ? 0.
             : *std::max_element(residuals.begin(), residuals.end());
  }


  std::vector<std::vector<unsigned int>>
  ModalBasis::clusters(const double relative_gap) const
  {
    std::vector<std::vector<unsigned int>> groups;
    for (unsigned int j = 0; j < eigenvalues.size(); ++j)
      {
        if (!groups.empty())
          {
            const double previous = eigenvalues[groups.back().back()];
            if (std::abs(eigenvalues[j] - previous) <=
                relative_gap *
                  std::max(std::abs(eigenvalues[j]), std::abs(previous)))
              {
                groups.back().push_back(j);
                continue;
              }
          }
        groups.push_back({j});
      }
    return groups;
  }


  std::vector<double>
  relative_residuals(const SparseMatrix<double>        &K,
                     const SparseMatrix<double>        &M,
                     const std::vector<double>         &eigenvalues,
                     const std::vector<Vector<double>> &modes)
  {
    std::vector<double> residuals;
    Vector<double>      Kx(K.m()), Mx(M.m());
    for (unsigned int j = 0; j < modes.size(); ++j)
      {
        K.vmult(Kx, modes[j]);
        M.vmult(Mx, modes[j]);
        const double norm_Kx = Kx.l2_norm();
        Kx.add(-eigenvalues[j], Mx);
        residuals.push_back(norm_Kx > 0 ? Kx.l2_norm() / norm_Kx
                                        : Kx.l2_norm());
      }
    return residuals;
  }


  ModalSolver::ModalSolver(const ModalParameters &parameters)
      : parameters(parameters)
  {
  }


  namespace
  {
    // The message for a K - sigma M that cannot be factorised.
    std::string
    singular_message(const std::string &what, const double shift)
    {
      std::ostringstream message;
      message << what
              << ": K - sigma M is singular at the shift sigma = " << shift
              << ". An unclamped component has rigid-body modes at zero "
                 "frequency: clamp it, or set a negative 'shift' in "
                 "'Modal analysis'.";
      return message.str();
    }
  } // namespace


  template <class Inverse>
  ModalBasis
  ModalSolver::solve_for(const SparseMatrix<double> &K,
                         const SparseMatrix<double> &M,
                         const Inverse              &inverse,
                         const unsigned int          n_modes,
                         const std::string          &what) const
  {
    const unsigned int n = K.m();
    // ARPACK needs more than 2 nev + 1 Lanczos vectors, and fewer than n.
    const unsigned int n_lanczos = std::min(n - 1, 2 * n_modes + 10);
    AssertThrow(n_lanczos > 2 * n_modes + 1,
                ExcMessage(what + ": " + std::to_string(n_modes) +
                           " modes are too many for a model with only " +
                           std::to_string(n) + " degrees of freedom."));

    std::vector<std::complex<double>> lambda(n_modes);
    std::vector<Vector<double>>       x(n_modes, Vector<double>(n));
    const unsigned int           max_iterations = parameters.max_iterations > 0
                                                    ? parameters.max_iterations
                                                    : std::max(n, 300u);
    SolverControl                control(max_iterations,
                          parameters.tolerance,
                          /*log_history=*/false,
                          /*log_result=*/false);
    ArpackSolver::AdditionalData data(n_lanczos,
                                      ArpackSolver::largest_magnitude,
                                      /*symmetric=*/true);
    ArpackSolver                 arpack(control, data);
    if (parameters.shift != 0)
      arpack.set_shift(parameters.shift);
    try
      {
        arpack.solve(K, M, inverse, lambda, x, n_modes);
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        message << what << ": ARPACK did not converge to " << n_modes
                << " eigenpairs (tolerance " << parameters.tolerance << ", "
                << max_iterations
                << " iterations at most: key 'max iterations' of subsection "
                   "Modal analysis): "
                << Input::message_of(e);
        AssertThrow(false, ExcMessage(message.str()));
      }
    // ARPACK's LAPACK calls (e.g. DLASCL on overflowed values) report
    // illegal arguments through xerbla only.
    LapackErrors::check(what + ": the modal analysis (ARPACK)");
    // deal.II's ArpackSolver says that ARPACK ran out of iterations only by
    // a debug-mode assertion (its info = 1); in release mode the unconverged
    // Ritz pairs would come back as they are. The iterations taken tell.
    if (control.last_step() >= max_iterations)
      {
        std::ostringstream message;
        message << what << ": ARPACK did not converge to " << n_modes
                << " eigenpairs (tolerance " << parameters.tolerance << ") in "
                << max_iterations
                << " iterations (key 'max iterations' of subsection Modal "
                   "analysis).";
        AssertThrow(false, ExcMessage(message.str()));
      }

    std::vector<unsigned int> order(n_modes);
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](unsigned int a, unsigned int b) {
      return lambda[a].real() < lambda[b].real();
    });

    // A factorisation of a singular K can succeed (round-off leaves tiny
    // positive pivots), and the rigid-body modes then come out as
    // eigenvalues at the round-off level of the largest ones. Refuse those:
    // they are not vibration modes of a supported structure.
    if (parameters.shift == 0)
      {
        double lambda_scale = 0;
        for (unsigned int i = 0; i < n; ++i)
          if (M.diag_element(i) > 0)
            lambda_scale =
              std::max(lambda_scale, K.diag_element(i) / M.diag_element(i));
        const double zero =
          1e3 * std::numeric_limits<double>::epsilon() * lambda_scale;
        for (const unsigned int j : order)
          if (lambda[j].real() < zero)
            {
              std::ostringstream message;
              message << what << ": K - sigma M is singular at the shift "
                      << "sigma = 0: there are modes at zero frequency "
                      << "(lambda = " << lambda[j].real()
                      << "), the rigid-body motions of an unclamped "
                         "component. Clamp it, or set a negative 'shift' in "
                         "'Modal analysis'.";
              AssertThrow(false, ExcMessage(message.str()));
            }
      }

    ModalBasis     basis;
    Vector<double> Mx(n);
    for (const unsigned int j : order)
      {
        Vector<double> &phi = x[j];
        M.vmult(Mx, phi);
        const double mass = phi * Mx;
        AssertThrow(mass > 0 && std::isfinite(mass),
                    ExcMessage(what + ": ARPACK returned a mode with "
                                      "non-positive modal mass."));
        phi /= std::sqrt(mass);
        // Sign convention: the entry of largest magnitude is positive.
        unsigned int imax = 0;
        for (unsigned int i = 1; i < n; ++i)
          if (std::abs(phi[i]) > std::abs(phi[imax]))
            imax = i;
        if (phi[imax] < 0)
          phi *= -1.;
        basis.eigenvalues.push_back(lambda[j].real());
        basis.modes.push_back(std::move(phi));
      }
    basis.residuals = relative_residuals(K, M, basis.eigenvalues, basis.modes);
    return basis;
  }


  ModalBasis
  ModalSolver::solve(const SparseMatrix<double> &K,
                     const SparseMatrix<double> &M,
                     const std::string          &what) const
  {
    AssertThrow(K.m() == M.m() && K.m() > 0,
                ExcMessage(what + ": K and M must be square, non-empty and of "
                                  "the same size."));
    // Factorise K - sigma M once; every Lanczos step is one back-solve.
    SparseMatrix<double> shifted(K.get_sparsity_pattern());
    shifted.copy_from(K);
    if (parameters.shift != 0)
      shifted.add(-parameters.shift, M);
    if (parameters.shift > 0)
      {
        SparseDirectSolver inverse;
        try
          {
            inverse.factorize(shifted);
          }
        catch (const ExceptionBase &)
          {
            AssertThrow(false,
                        ExcMessage(singular_message(what, parameters.shift)));
          }
        return solve_with(K, M, inverse, what);
      }
    SparseCholesky inverse;
    try
      {
        inverse.factorize(shifted, {}, what);
      }
    catch (const ExceptionBase &)
      {
        AssertThrow(false,
                    ExcMessage(singular_message(what, parameters.shift)));
      }
    return solve_with(K, M, inverse, what);
  }


  ModalBasis
  ModalSolver::solve(const SparseMatrix<double> &K,
                     const SparseMatrix<double> &M,
                     const SparseCholesky       &K_factorisation,
                     const std::string          &what) const
  {
    AssertThrow(K.m() == M.m() && K.m() > 0 && K_factorisation.n() == K.m(),
                ExcMessage(what + ": K, M and the factorisation of K must be "
                                  "square, non-empty and of the same size."));
    AssertThrow(parameters.shift == 0,
                ExcMessage(what + ": a factorisation of K serves the modal "
                                  "analysis at shift 0 only."));
    return solve_with(K, M, K_factorisation, what);
  }


  template <class Inverse>
  ModalBasis
  ModalSolver::solve_with(const SparseMatrix<double> &K,
                          const SparseMatrix<double> &M,
                          const Inverse              &inverse,
                          const std::string          &what) const
  {
    if (parameters.cutoff_frequency <= 0)
      return solve_for(K, M, inverse, parameters.n_modes, what);

    // With a cutoff, ask for more modes until one lies above it.
    const double lambda_cut =
      std::pow(2. * M_PI * parameters.cutoff_frequency, 2);
    unsigned int n_wanted = std::max(parameters.n_modes, 6u);
    while (true)
      {
        ModalBasis basis = solve_for(K, M, inverse, n_wanted, what);
        if (basis.eigenvalues.back() > lambda_cut)
          {
            unsigned int keep = 0;
            while (keep < basis.size() && basis.eigenvalues[keep] <= lambda_cut)
              ++keep;
            AssertThrow(keep > 0,
                        ExcMessage(what + ": no mode lies below the cutoff "
                                          "frequency."));
            basis.eigenvalues.resize(keep);
            basis.modes.resize(keep);
            basis.residuals.resize(keep);
            return basis;
          }
        AssertThrow(2 * (2 * n_wanted) + 2 < K.m(),
                    ExcMessage(what + ": the model has too few degrees of "
                                      "freedom to reach the cutoff "
                                      "frequency."));
        n_wanted *= 2;
      }
  }
} // namespace FuzzyContact
