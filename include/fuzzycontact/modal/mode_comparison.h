// Comparing approximate eigenpairs with exact ones: the modal assurance
// criterion (MAC) in the mass inner product, a one-to-one matching of modes
// by MAC (modes change order when eigenvalues cross), and the relative
// frequency error of each matched pair.

#ifndef fuzzycontact_modal_mode_comparison_h
#define fuzzycontact_modal_mode_comparison_h

#include <fuzzycontact/modal/modal_solver.h>

#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <vector>

namespace FuzzyContact
{
  using namespace dealii;

  /**
   * MAC(a, b) = (a^T M b)^2 / ((a^T M a)(b^T M b)): 1 for parallel modes, 0
   * for M-orthogonal ones.
   */
  double
  modal_assurance_criterion(const Vector<double>       &a,
                            const Vector<double>       &b,
                            const SparseMatrix<double> &M);

  struct ModeComparison
  {
    /** match[j]: index of the exact mode paired with approximate mode j. */
    std::vector<unsigned int> match;
    /** MAC of each pair. */
    std::vector<double> mac;
    /** |f_j - f_exact| / f_exact of each pair. */
    std::vector<double> relative_error;
    double              max_relative_error = 0;
    double              min_mac            = 1;
    /** True if some approximate mode j is paired with exact mode i != j. */
    bool reordered = false;
  };

  /**
   * Pairs each approximate mode with one exact mode (greedily, by
   * decreasing MAC, each exact mode used once) and measures the pairs. The
   * exact basis should hold a few more modes than the approximation, so
   * that a mode which moved up the spectrum still finds its partner.
   */
  ModeComparison
  compare_modes(const std::vector<double>         &eigenvalues,
                const std::vector<Vector<double>> &modes,
                const ModalBasis                  &exact,
                const SparseMatrix<double>        &M);
} // namespace FuzzyContact

#endif
