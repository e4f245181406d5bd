#include <fuzzycontact/reanalysis/exact_resolve.h>

#include <deal.II/lac/sparse_matrix.h>

namespace FuzzyContact
{
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
} // namespace FuzzyContact
