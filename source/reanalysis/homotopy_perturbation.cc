#include <fuzzycontact/reanalysis/homotopy_perturbation.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/sparse_matrix.h>

namespace FuzzyContact
{
  HomotopyPerturbation::HomotopyPerturbation(const ParameterModel &model,
                                             const ModalBasis     &nominal,
                                             const double truncation_tolerance,
                                             const double cluster_gap,
                                             const DerivativeSolver method)
      : model(model)
      , nominal(nominal)
      , truncation_tolerance(truncation_tolerance)
  {
    std::shared_ptr<const DeflatedBorderedSolver> deflated;
    if (method == DerivativeSolver::deflated_cg)
      deflated =
        std::make_shared<DeflatedBorderedSolver>(model, nominal, nullptr);
    for (const auto &modes : reanalysis_clusters(nominal, cluster_gap))
      clusters.push_back(std::make_unique<EigenDerivatives>(
        model,
        nominal,
        modes,
        cluster_gap,
        clusters.empty() ? nullptr : clusters.back()->analysis(),
        deflated));
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
    std::vector<const EigenDerivatives *> all;
    for (const auto &cluster : clusters)
      all.push_back(cluster.get());
    const std::vector<EigenTaylorCoefficients> terms =
      EigenDerivatives::taylor_coefficients(all,
                                            {t},
                                            order,
                                            std::vector<bool>(all.size(),
                                                              false));

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
