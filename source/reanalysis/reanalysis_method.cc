#include <fuzzycontact/base/input.h>
#include <fuzzycontact/reanalysis/eigen_derivatives.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>

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
    prm.declare_entry("derivative solver",
                      "deflated cg",
                      Patterns::Selection("deflated cg|direct"),
                      "How Lee's bordered systems are solved: 'deflated cg' "
                      "(conjugate gradients on the complement of the "
                      "nominal modes, preconditioned by the stiffness's "
                      "Cholesky factorisation; a system it does not solve "
                      "is factorised) or 'direct' (one LU factorisation of "
                      "the bordered matrix per mode).");
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
    residual_check    = prm.get_bool("residual check");
    derivative_solver = prm.get("derivative solver") == "direct"
                          ? DerivativeSolver::direct
                          : DerivativeSolver::deflated_cg;
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
} // namespace FuzzyContact
