#include <fuzzycontact/base/input.h>
#include <fuzzycontact/reanalysis/modal_reanalysis.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace FuzzyContact
{
  void
  ReanalysisSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reanalysis");
    prm.declare_entry("maximum order",
                      "3",
                      Patterns::Integer(1, 3),
                      "Highest Taylor order n of HPTP (1 to 3); CA of order "
                      "n uses n + 1 terms per mode.");
    prm.declare_entry("order tolerance",
                      "1e-6",
                      Patterns::Double(),
                      "The order used is the lowest n whose estimated "
                      "relative frequency error max_j |f_j(n) - f_j(n+1)| / "
                      "f_j(n+1) is at most this.");
    prm.declare_entry("truncation tolerance",
                      "1e-6",
                      Patterns::Double(),
                      "A basis vector is dropped when its M-norm after "
                      "orthogonalisation is below this times max(its norm "
                      "before, 1).");
    prm.declare_entry("cluster gap",
                      "0.01",
                      Patterns::Double(),
                      "Nominal modes whose eigenvalues differ by at most this "
                      "relative gap are expanded together as a cluster.");
    prm.declare_entry("residual check",
                      "true",
                      Patterns::Bool(),
                      "Compute the relative residuals ||K phi - lambda M "
                      "phi|| / ||K phi|| of the reanalysed pairs on the "
                      "full matrices.");
    prm.leave_subsection();
  }


  void
  ReanalysisSettings::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Reanalysis");
    max_order       = prm.get_integer("maximum order");
    order_tolerance = Input::positive(prm.get_double("order tolerance"),
                                      "Reanalysis: order tolerance");
    truncation_tolerance =
      Input::positive(prm.get_double("truncation tolerance"),
                      "Reanalysis: truncation tolerance");
    AssertThrow(truncation_tolerance < 1e-2,
                ExcMessage("Reanalysis: truncation tolerance must be below "
                           "1e-2, got " +
                           std::to_string(truncation_tolerance) + "."));
    cluster_gap = Input::non_negative(prm.get_double("cluster gap"),
                                      "Reanalysis: cluster gap");
    AssertThrow(cluster_gap < 1,
                ExcMessage("Reanalysis: cluster gap must be below 1, got " +
                           std::to_string(cluster_gap) + "."));
    residual_check = prm.get_bool("residual check");
    prm.leave_subsection();
  }


  std::vector<double>
  ReanalysisResult::frequencies() const
  {
    std::vector<double> f;
    for (const double lambda : eigenvalues)
      f.push_back(std::sqrt(std::max(lambda, 0.)) / (2. * M_PI));
    return f;
  }


  std::vector<std::vector<unsigned int>>
  reanalysis_clusters(const ModalBasis &nominal, const double cluster_gap)
  {
    return nominal.clusters(std::max(cluster_gap, minimum_cluster_gap));
  }


  unsigned int
  modes_with_complete_clusters(const ModalBasis  &nominal,
                               const unsigned int n_wanted,
                               const double       cluster_gap)
  {
    AssertThrow(n_wanted >= 1 && n_wanted <= nominal.size(),
                ExcMessage("modal reanalysis: " + std::to_string(n_wanted) +
                           " modes wanted from a basis of " +
                           std::to_string(nominal.size()) + "."));
    for (const auto &cluster : reanalysis_clusters(nominal, cluster_gap))
      if (cluster.back() + 1 >= n_wanted)
        {
          AssertThrow(cluster.back() + 1 < nominal.size(),
                      ExcMessage("modal reanalysis: the cluster of close "
                                 "eigenvalues that holds mode " +
                                 std::to_string(n_wanted) + " (" +
                                 describe_modes(nominal, cluster) +
                                 ") reaches the highest computed nominal mode; "
                                 "its partners may lie above. Compute more "
                                 "nominal modes."));
          return cluster.back() + 1;
        }
    return n_wanted;
  }


  ModalBasis
  leading_modes(const ModalBasis &basis, const unsigned int n)
  {
    AssertThrow(n <= basis.size(), ExcMessage("leading_modes: too many"));
    ModalBasis result;
    result.eigenvalues.assign(basis.eigenvalues.begin(),
                              basis.eigenvalues.begin() + n);
    result.modes.assign(basis.modes.begin(), basis.modes.begin() + n);
    result.residuals.assign(basis.residuals.begin(),
                            basis.residuals.begin() + n);
    return result;
  }


  ReanalysisResult
  rayleigh_ritz(const SparseMatrix<double> &K,
                const SparseMatrix<double> &M,
                const ReducedBasis         &T,
                const unsigned int          n_modes)
  {
    const ReducedEigenpairs pairs =
      solve_reduced_eigenproblem(T.project(K), T.project(M), n_modes);
    ReanalysisResult result;
    result.eigenvalues = pairs.eigenvalues;
    result.modes       = T.expand(pairs.vectors);
    result.basis_size  = T.size();
    return result;
  }


  namespace
  {
    // Sorts eigenpairs by eigenvalue.
    void
    sort_pairs(ReanalysisResult &r)
    {
      std::vector<unsigned int> order(r.eigenvalues.size());
      std::iota(order.begin(), order.end(), 0);
      std::sort(order.begin(),
                order.end(),
                [&](unsigned int a, unsigned int b) {
                  return r.eigenvalues[a] < r.eigenvalues[b];
                });
      ReanalysisResult sorted = r;
      for (unsigned int i = 0; i < order.size(); ++i)
        {
          sorted.eigenvalues[i] = r.eigenvalues[order[i]];
          sorted.modes[i]       = r.modes[order[i]];
        }
      r = std::move(sorted);
    }

    std::vector<std::vector<double>>
    identity(const unsigned int n)
    {
      std::vector<std::vector<double>> I(n, std::vector<double>(n, 0.));
      for (unsigned int k = 0; k < n; ++k)
        I[k][k] = 1;
      return I;
    }
  } // namespace


  // ---------------------------------------------------------------------
  // ResidualCheck
  // ---------------------------------------------------------------------

  ResidualCheck::ResidualCheck(const ParameterModel &model)
      : model(model)
  {
    K0_inverse.initialize(model.nominal_stiffness());
  }


  ResidualCheck::Residuals
  ResidualCheck::check(const std::vector<double>         &t,
                       const std::vector<double>         &eigenvalues,
                       const std::vector<Vector<double>> &modes) const
  {
    AssertDimension(eigenvalues.size(), modes.size());
    SparseMatrix<double> K, M;
    model.matrices(t, K, M);
    Residuals      result;
    Vector<double> Kx(K.m()), r(K.m()), z(K.m());
    for (unsigned int j = 0; j < modes.size(); ++j)
      {
        K.vmult(Kx, modes[j]);
        M.vmult(r, modes[j]);
        r.sadd(-eigenvalues[j], 1., Kx);
        z = r;
        K0_inverse.solve(z);
        const double energy_norm = std::sqrt(std::max(modes[j] * Kx, 0.));
        result.relative.push_back(r.l2_norm() / Kx.l2_norm());
        result.energy.push_back(std::sqrt(std::max(r * z, 0.)) / energy_norm);
      }
    return result;
  }


  // ---------------------------------------------------------------------
  // ExactResolve
  // ---------------------------------------------------------------------

  ExactResolve::ExactResolve(const ParameterModel  &model,
                             const ModalParameters &modal_parameters)
      : model(model)
      , modal_parameters(modal_parameters)
  {
  }


  std::string
  ExactResolve::name() const
  {
    return "exact";
  }


  bool
  ExactResolve::has_order() const
  {
    return false;
  }


  ModalBasis
  ExactResolve::solve(const std::vector<double> &t) const
  {
    SparseMatrix<double> K, M;
    model.matrices(t, K, M);
    return ModalSolver(modal_parameters)
      .solve(K, M, "Component " + model.component().name());
  }


  ReanalysisResult
  ExactResolve::reanalyse(const std::vector<double> &t,
                          const unsigned int) const
  {
    ModalBasis       basis = solve(t);
    ReanalysisResult result;
    result.eigenvalues = std::move(basis.eigenvalues);
    result.modes       = std::move(basis.modes);
    return result;
  }


  // ---------------------------------------------------------------------
  // FirstOrderTaylor
  // ---------------------------------------------------------------------

  FirstOrderTaylor::FirstOrderTaylor(const ParameterModel &model,
                                     const ModalBasis     &nominal,
                                     const double          cluster_gap)
      : model(model)
      , nominal(nominal)
  {
    const unsigned int n_p = model.n_parameters();
    for (const auto &modes : reanalysis_clusters(nominal, cluster_gap))
      {
        const EigenDerivatives derivatives(model, nominal, modes, cluster_gap);
        Cluster                c;
        c.modes = modes;
        if (modes.size() == 1)
          c.derivatives = derivatives.derivatives(1);
        else
          {
            const EigenTaylorCoefficients taylor =
              derivatives.taylor_coefficients(identity(n_p), 1, false);
            const unsigned int m = modes.size();
            for (unsigned int k = 0; k < n_p; ++k)
              {
                std::vector<unsigned int> e(n_p, 0);
                e[k] = 1;
                c.X.push_back(taylor.vectors[taylor.indices.index(e)]);
                FullMatrix<double> PKP(m, m), PMP(m, m);
                Vector<double>     product;
                for (unsigned int j = 0; j < m; ++j)
                  {
                    const Vector<double> &phi_j = nominal.modes[modes[j]];
                    for (const bool stiffness : {true, false})
                      {
                        std::vector<double> direction(n_p, 0.);
                        direction[k] = 1;
                        const bool nonzero =
                          stiffness
                            ? model.stiffness_change(direction, phi_j, product)
                            : model.mass_change(direction, phi_j, product);
                        if (nonzero)
                          for (unsigned int i = 0; i < m; ++i)
                            (stiffness ? PKP : PMP)(i, j) =
                              nominal.modes[modes[i]] * product;
                      }
                  }
                c.PhiKPhi.push_back(PKP);
                c.PhiMPhi.push_back(PMP);
              }
          }
        clusters.push_back(std::move(c));
      }
  }


  std::string
  FirstOrderTaylor::name() const
  {
    return "taylor";
  }


  bool
  FirstOrderTaylor::has_order() const
  {
    return false;
  }


  ReanalysisResult
  FirstOrderTaylor::reanalyse(const std::vector<double> &t,
                              const unsigned int) const
  {
    const unsigned int n_p = model.n_parameters();
    AssertDimension(t.size(), n_p);
    ReanalysisResult result;
    result.order = 1;
    for (const Cluster &c : clusters)
      {
        if (c.modes.size() == 1)
          {
            double         lambda = nominal.eigenvalues[c.modes[0]];
            Vector<double> phi    = nominal.modes[c.modes[0]];
            for (unsigned int k = 0; k < n_p; ++k)
              {
                lambda += t[k] * c.derivatives.eigenvalue[k];
                phi.add(t[k], c.derivatives.mode_shape[k]);
              }
            result.eigenvalues.push_back(lambda);
            result.modes.push_back(std::move(phi));
            continue;
          }
        // A cluster: first-order degenerate perturbation.
        const unsigned int       m = c.modes.size();
        LAPACKFullMatrix<double> A(m, m), B(m, m);
        for (unsigned int i = 0; i < m; ++i)
          {
            A(i, i) = nominal.eigenvalues[c.modes[i]];
            B(i, i) = 1;
          }
        for (unsigned int k = 0; k < n_p; ++k)
          for (unsigned int i = 0; i < m; ++i)
            for (unsigned int j = 0; j < m; ++j)
              {
                A(i, j) += t[k] * c.PhiKPhi[k](i, j);
                B(i, j) += t[k] * c.PhiMPhi[k](i, j);
              }
        std::vector<Vector<double>> y(m, Vector<double>(m));
        A.compute_generalized_eigenvalues_symmetric(B, y);
        for (unsigned int s = 0; s < m; ++s)
          {
            result.eigenvalues.push_back(A.eigenvalue(s).real());
            Vector<double> phi(nominal.modes[0].size());
            for (unsigned int j = 0; j < m; ++j)
              {
                phi.add(y[s][j], nominal.modes[c.modes[j]]);
                for (unsigned int k = 0; k < n_p; ++k)
                  phi.add(t[k] * y[s][j], c.X[k][j]);
              }
            result.modes.push_back(std::move(phi));
          }
      }
    sort_pairs(result);
    return result;
  }


  // ---------------------------------------------------------------------
  // CombinedApproximations
  // ---------------------------------------------------------------------

  CombinedApproximations::CombinedApproximations(
    const ParameterModel &model,
    const ModalBasis     &nominal,
    const double          truncation_tolerance)
      : model(model)
      , nominal(nominal)
      , truncation_tolerance(truncation_tolerance)
  {
    K0_inverse.initialize(model.nominal_stiffness());
  }


  std::string
  CombinedApproximations::name() const
  {
    return "ca";
  }


  bool
  CombinedApproximations::has_order() const
  {
    return true;
  }


  ReanalysisResult
  CombinedApproximations::reanalyse(const std::vector<double> &t,
                                    const unsigned int         order) const
  {
    AssertThrow(order >= 1,
                ExcMessage("Combined Approximations: order must be >= 1."));
    SparseMatrix<double> K, M;
    model.matrices(t, K, M);
    const unsigned int          n_modes = nominal.size();
    const unsigned int          n       = K.m();
    ReducedBasis                T(M, truncation_tolerance);
    std::vector<Vector<double>> r(n_modes, Vector<double>(n));
    Vector<double>              tmp(n);
    // r_1 = K0^{-1} M(t) phi0 for every mode, then the series terms, added
    // term by term so that lower terms come first.
    for (unsigned int j = 0; j < n_modes; ++j)
      {
        M.vmult(r[j], nominal.modes[j]);
        K0_inverse.solve(r[j]);
        T.add(r[j], 0.);
      }
    for (unsigned int i = 2; i <= order + 1; ++i)
      for (unsigned int j = 0; j < n_modes; ++j)
        {
          // r <- -K0^{-1} Delta K r
          if (!model.stiffness_change(t, r[j], tmp))
            continue; // no stiffness change: the series stops at r_1
          tmp *= -1.;
          K0_inverse.solve(tmp);
          r[j] = tmp;
          T.add(r[j], 0.);
        }
    ReanalysisResult result = rayleigh_ritz(K, M, T, n_modes);
    result.order            = order;
    return result;
  }


  // ---------------------------------------------------------------------
  // HomotopyPerturbation
  // ---------------------------------------------------------------------

  HomotopyPerturbation::HomotopyPerturbation(const ParameterModel &model,
                                             const ModalBasis     &nominal,
                                             const double truncation_tolerance,
                                             const double cluster_gap)
      : model(model)
      , nominal(nominal)
      , truncation_tolerance(truncation_tolerance)
  {
    for (const auto &modes : reanalysis_clusters(nominal, cluster_gap))
      clusters.push_back(
        std::make_unique<EigenDerivatives>(model, nominal, modes, cluster_gap));
  }


  std::string
  HomotopyPerturbation::name() const
  {
    return "hptp";
  }


  bool
  HomotopyPerturbation::has_order() const
  {
    return true;
  }


  ReanalysisResult
  HomotopyPerturbation::reanalyse(const std::vector<double> &t,
                                  const unsigned int         order) const
  {
    AssertThrow(order >= 1, ExcMessage("HPTP: order must be >= 1."));
    AssertDimension(t.size(), model.n_parameters());
    std::vector<EigenTaylorCoefficients> terms;
    for (const auto &cluster : clusters)
      terms.push_back(cluster->taylor_coefficients({t}, order, false));

    SparseMatrix<double> K, M;
    model.matrices(t, K, M);
    // Nominal modes first, then the terms of order 1, 2, ...
    ReducedBasis T(model.nominal_mass(), truncation_tolerance);
    for (unsigned int i = 0; i <= order; ++i)
      for (const EigenTaylorCoefficients &c : terms)
        for (const Vector<double> &v : c.vectors[i])
          T.add(v);
    ReanalysisResult result = rayleigh_ritz(K, M, T, nominal.size());
    result.order            = order;
    return result;
  }
} // namespace FuzzyContact
