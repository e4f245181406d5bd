#include <fuzzycontact/reanalysis/residual_check.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/sparse_matrix.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
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
} // namespace FuzzyContact
