#include <fuzzycontact/reanalysis/combined_approximations.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/sparse_matrix.h>

namespace FuzzyContact
{
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
} // namespace FuzzyContact
