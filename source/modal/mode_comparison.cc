#include <fuzzycontact/modal/mode_comparison.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <tuple>

namespace FuzzyContact
{
  double
  modal_assurance_criterion(const Vector<double>       &a,
                            const Vector<double>       &b,
                            const SparseMatrix<double> &M)
  {
    Vector<double> Mb(b.size());
    M.vmult(Mb, b);
    const double ab = a * Mb, bb = b * Mb, aa = M.matrix_norm_square(a);
    return (aa > 0 && bb > 0) ? ab * ab / (aa * bb) : 0.;
  }


  ModeComparison
  compare_modes(const std::vector<double>         &eigenvalues,
                const std::vector<Vector<double>> &modes,
                const ModalBasis                  &exact,
                const SparseMatrix<double>        &M)
  {
    const unsigned int n = modes.size(), n_exact = exact.size();
    AssertDimension(eigenvalues.size(), n);
    AssertThrow(n_exact >= n,
                ExcMessage("mode comparison: fewer exact modes (" +
                           std::to_string(n_exact) +
                           ") than approximate ones (" + std::to_string(n) +
                           ")."));
    // MAC matrix, from M times the exact modes.
    std::vector<Vector<double>> M_exact(n_exact, Vector<double>(M.m()));
    std::vector<double>         exact_norm(n_exact);
    for (unsigned int i = 0; i < n_exact; ++i)
      {
        M.vmult(M_exact[i], exact.modes[i]);
        exact_norm[i] = exact.modes[i] * M_exact[i];
      }
    std::vector<std::tuple<double, unsigned int, unsigned int>> pairs;
    for (unsigned int j = 0; j < n; ++j)
      {
        const double norm = M.matrix_norm_square(modes[j]);
        for (unsigned int i = 0; i < n_exact; ++i)
          {
            const double p = modes[j] * M_exact[i];
            pairs.emplace_back(norm > 0 ? p * p / (norm * exact_norm[i]) : 0.,
                               j,
                               i);
          }
      }
    // Largest MAC first; ties go to the pair nearest the diagonal.
    std::sort(pairs.begin(), pairs.end(), [](const auto &a, const auto &b) {
      if (std::get<0>(a) != std::get<0>(b))
        return std::get<0>(a) > std::get<0>(b);
      const int da = std::abs(int(std::get<1>(a)) - int(std::get<2>(a))),
                db = std::abs(int(std::get<1>(b)) - int(std::get<2>(b)));
      return da < db;
    });
    ModeComparison result;
    result.match.assign(n, numbers::invalid_unsigned_int);
    result.mac.assign(n, 0.);
    std::vector<bool> used(n_exact, false);
    for (const auto &[mac, j, i] : pairs)
      if (result.match[j] == numbers::invalid_unsigned_int && !used[i])
        {
          result.match[j] = i;
          result.mac[j]   = mac;
          used[i]         = true;
        }
    for (unsigned int j = 0; j < n; ++j)
      {
        const unsigned int i     = result.match[j];
        const double       f     = std::sqrt(std::max(eigenvalues[j], 0.));
        const double       f_ref = std::sqrt(exact.eigenvalues[i]);
        result.relative_error.push_back(std::abs(f - f_ref) / f_ref);
        result.max_relative_error =
          std::max(result.max_relative_error, result.relative_error.back());
        result.min_mac   = std::min(result.min_mac, result.mac[j]);
        result.reordered = result.reordered || i != j;
      }
    return result;
  }
} // namespace FuzzyContact
