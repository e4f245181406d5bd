#include <fuzzycontact/reanalysis/first_order_taylor.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <algorithm>
#include <numeric>

namespace FuzzyContact
{
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


  FirstOrderTaylor::FirstOrderTaylor(const ParameterModel  &model,
                                     const ModalBasis      &nominal,
                                     const double           cluster_gap,
                                     const DerivativeSolver method)
      : model(model)
      , nominal(nominal)
  {
    const unsigned int n_p = model.n_parameters();
    std::shared_ptr<const SparseDirectSolver::Analysis> analysis;
    std::shared_ptr<const DeflatedBorderedSolver>       deflated;
    if (method == DerivativeSolver::deflated_cg)
      deflated =
        std::make_shared<DeflatedBorderedSolver>(model, nominal, nullptr);
    for (const auto &modes : reanalysis_clusters(nominal, cluster_gap))
      {
        const EigenDerivatives derivatives(model,
                                           nominal,
                                           modes,
                                           cluster_gap,
                                           analysis,
                                           deflated);
        analysis = derivatives.analysis();
        Cluster c;
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
} // namespace FuzzyContact
