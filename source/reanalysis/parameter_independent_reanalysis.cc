#include <fuzzycontact/base/timer_section.h>
#include <fuzzycontact/reanalysis/order_selection.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace FuzzyContact
{
  std::vector<double>
  ReanalysedModes::frequencies() const
  {
    std::vector<double> f;
    for (const double lambda : eigenvalues)
      f.push_back(std::sqrt(std::max(lambda, 0.)) / (2. * M_PI));
    return f;
  }


  void
  ParameterIndependentReanalysis::offline(
    const Component                      &component,
    const ModalBasis                     &nominal,
    const std::vector<std::string>       &parameter_names,
    const unsigned int                    order,
    const double                          truncation_tolerance,
    const double                          cluster_gap,
    TimerOutput                          *timer,
    const DerivativeSolver                method,
    std::shared_ptr<const SparseCholesky> stiffness_factorisation)
  {
    AssertThrow(order >= 1 && order <= 3,
                ExcMessage("modal reanalysis: order must be 1, 2 or 3, got " +
                           std::to_string(order) + "."));
    AssertThrow(nominal.size() >= 1 &&
                  nominal.modes[0].size() == component.n_dofs(),
                ExcMessage("modal reanalysis: the nominal basis does not "
                           "belong to component " +
                           component.name() + "."));
    AssertThrow(!parameter_names.empty(),
                ExcMessage("modal reanalysis: no parameter is declared "
                           "variable."));
    const auto scope = [timer](const std::string &stage) {
      return timer_section(timer, stage);
    };

    residual_check_.reset();
    model_     = std::make_unique<ParameterModel>(component, parameter_names);
    nominal_   = nominal;
    clusters_  = reanalysis_clusters(nominal_, cluster_gap);
    max_order_ = order;
    order_     = order;
    basis_     = std::make_unique<ReducedBasis>(model_->nominal_mass(),
                                            truncation_tolerance);

    // Taylor coefficients of every cluster with respect to every parameter.
    const unsigned int               n_p = model_->n_parameters();
    std::vector<std::vector<double>> identity(n_p,
                                              std::vector<double>(n_p, 0.));
    for (unsigned int k = 0; k < n_p; ++k)
      identity[k][k] = 1;
    std::vector<EigenTaylorCoefficients> terms;
    {
      const auto s            = scope("reanalysis offline: Lee's derivatives");
      derivative_cost_        = DerivativeCost();
      derivative_cost_.method = method;
      std::shared_ptr<const DeflatedBorderedSolver> deflated;
      if (method == DerivativeSolver::deflated_cg)
        deflated =
          std::make_shared<DeflatedBorderedSolver>(*model_,
                                                   nominal_,
                                                   stiffness_factorisation);
      // The clusters' bordered matrices share one symbolic analysis (when
      // they are factorised), their systems one deflated solver.
      std::vector<std::unique_ptr<EigenDerivatives>> derivatives;
      std::vector<const EigenDerivatives *>          clusters;
      std::vector<bool>                              mass_normalise;
      for (const auto &cluster : clusters_)
        {
          derivatives.push_back(std::make_unique<EigenDerivatives>(
            *model_,
            nominal_,
            cluster,
            cluster_gap,
            derivatives.empty() ? nullptr : derivatives.back()->analysis(),
            deflated));
          clusters.push_back(derivatives.back().get());
          mass_normalise.push_back(cluster.size() == 1);
        }
      terms = EigenDerivatives::taylor_coefficients(clusters,
                                                    identity,
                                                    order,
                                                    mass_normalise);
      if (deflated)
        {
          const auto st                     = deflated->statistics();
          derivative_cost_.systems          = st.systems;
          derivative_cost_.cg_iterations    = st.iterations;
          derivative_cost_.not_solved_by_cg = st.not_solved;
        }
      for (const auto &d : derivatives)
        derivative_cost_.factorisations += d->n_factorisations();
    }

    {
      const auto s = scope("reanalysis offline: orthonormalisation");
      basis_sizes_.clear();
      for (unsigned int p = 0; p <= order; ++p)
        {
          for (const EigenTaylorCoefficients &c : terms)
            {
              const unsigned int first =
                p == 0 ? 0 : c.indices.n_up_to_order(p - 1);
              for (unsigned int a = first; a < c.indices.n_up_to_order(p); ++a)
                for (const Vector<double> &v : c.vectors[a])
                  basis_->add(v);
            }
          basis_sizes_.push_back(basis_->size());
        }
      terms.clear();
    }

    {
      const auto s = scope("reanalysis offline: projections");
      zone_K_.clear();
      zone_M_.clear();
      for (unsigned int z = 0; z < component.n_zones(); ++z)
        {
          zone_K_.push_back(
            basis_->project(component.zone_stiffness_matrix(z)));
          zone_M_.push_back(basis_->project(component.zone_mass_matrix(z)));
        }
    }
  }


  FullMatrix<double>
  ParameterIndependentReanalysis::combine(
    const std::vector<FullMatrix<double>> &zone_projections,
    const std::vector<double>             &zone_values,
    const unsigned int                     size) const
  {
    FullMatrix<double> result(size, size);
    for (unsigned int z = 0; z < zone_projections.size(); ++z)
      {
        const FullMatrix<double> &P = zone_projections[z];
        const double              v = zone_values[z];
        for (unsigned int i = 0; i < size; ++i)
          for (unsigned int j = 0; j < size; ++j)
            result(i, j) += v * P(i, j);
      }
    return result;
  }


  FullMatrix<double>
  ParameterIndependentReanalysis::reduced_stiffness(
    const std::vector<double> &t,
    const unsigned int         order) const
  {
    return combine(zone_K_, model_->zone_materials(t).first, basis_size(order));
  }


  FullMatrix<double>
  ParameterIndependentReanalysis::reduced_mass(const std::vector<double> &t,
                                               const unsigned int order) const
  {
    return combine(zone_M_,
                   model_->zone_materials(t).second,
                   basis_size(order));
  }


  ReanalysedModes
  ParameterIndependentReanalysis::online(const std::vector<double> &t) const
  {
    return online(t, order_);
  }


  ReanalysedModes
  ParameterIndependentReanalysis::online(const std::vector<double> &t,
                                         const unsigned int         order) const
  {
    AssertThrow(model_, ExcMessage("modal reanalysis: call offline() first."));
    AssertThrow(order >= 1 && order <= max_order_,
                ExcMessage("modal reanalysis: order " + std::to_string(order) +
                           " asked for, but the basis was built up to order " +
                           std::to_string(max_order_) + "."));
    const auto              materials = model_->zone_materials(t);
    const unsigned int      size      = basis_size(order);
    const ReducedEigenpairs pairs =
      solve_reduced_eigenproblem(combine(zone_K_, materials.first, size),
                                 combine(zone_M_, materials.second, size),
                                 nominal_.size());
    ReanalysedModes result;
    result.order       = order;
    result.basis_size  = size;
    result.eigenvalues = pairs.eigenvalues;
    result.Y           = pairs.vectors;
    return result;
  }


  ReanalysedModes
  ParameterIndependentReanalysis::online_to_tolerance(
    const std::vector<double> &t,
    const double               tolerance,
    const bool                 check_residuals) const
  {
    AssertThrow(model_, ExcMessage("modal reanalysis: call offline() first."));
    // The rule of order_selection.h, on the orders of this basis: each is
    // computed once, and the residuals only where the rule asks for them.
    std::vector<ReanalysedModes> by_order(max_order_ + 1);
    const auto                   eigenvalues = [&](const unsigned int n) {
      by_order[n] = online(t, n);
      return by_order[n].eigenvalues;
    };
    std::function<double(unsigned int)> largest_energy_residual;
    if (check_residuals)
      largest_energy_residual = [&](const unsigned int n) {
        const ResidualCheck::Residuals r = residuals(t, by_order[n]);
        return *std::max_element(r.energy.begin(), r.energy.end());
      };
    const OrderSelection selection =
      order_for_tolerance(max_order_,
                          tolerance,
                          nominal_.size(),
                          eigenvalues,
                          largest_energy_residual);
    ReanalysedModes result = std::move(by_order[selection.order]);
    result.estimated_error = selection.estimates[selection.order - 1].estimate;
    result.tolerance_met   = selection.tolerance_met;
    return result;
  }


  unsigned int
  ParameterIndependentReanalysis::select_order(
    const std::vector<std::vector<double>> &samples,
    const double                            tolerance,
    const bool                              check_residuals)
  {
    unsigned int chosen = 1;
    for (const auto &t : samples)
      chosen =
        std::max(chosen,
                 online_to_tolerance(t, tolerance, check_residuals).order);
    order_ = chosen;
    return chosen;
  }


  const ParameterIndependentReanalysis::DerivativeCost &
  ParameterIndependentReanalysis::derivative_cost() const
  {
    return derivative_cost_;
  }


  unsigned int
  ParameterIndependentReanalysis::order() const
  {
    return order_;
  }


  void
  ParameterIndependentReanalysis::set_order(const unsigned int order)
  {
    AssertThrow(order >= 1 && order <= max_order_,
                ExcMessage("modal reanalysis: order must lie in 1.." +
                           std::to_string(max_order_) + "."));
    order_ = order;
  }


  unsigned int
  ParameterIndependentReanalysis::max_order() const
  {
    return max_order_;
  }


  const ReducedBasis &
  ParameterIndependentReanalysis::basis() const
  {
    AssertThrow(basis_, ExcMessage("modal reanalysis: call offline() first."));
    return *basis_;
  }


  unsigned int
  ParameterIndependentReanalysis::basis_size(const unsigned int order) const
  {
    AssertIndexRange(order, basis_sizes_.size());
    return basis_sizes_[order];
  }


  const ParameterModel &
  ParameterIndependentReanalysis::model() const
  {
    AssertThrow(model_, ExcMessage("modal reanalysis: call offline() first."));
    return *model_;
  }


  const ModalBasis &
  ParameterIndependentReanalysis::nominal() const
  {
    return nominal_;
  }


  const std::vector<std::vector<unsigned int>> &
  ParameterIndependentReanalysis::clusters() const
  {
    return clusters_;
  }


  const FullMatrix<double> &
  ParameterIndependentReanalysis::zone_stiffness_projection(
    const unsigned int zone) const
  {
    AssertIndexRange(zone, zone_K_.size());
    return zone_K_[zone];
  }


  const FullMatrix<double> &
  ParameterIndependentReanalysis::zone_mass_projection(
    const unsigned int zone) const
  {
    AssertIndexRange(zone, zone_M_.size());
    return zone_M_[zone];
  }


  std::vector<Vector<double>>
  ParameterIndependentReanalysis::modes(const ReanalysedModes &modes) const
  {
    return basis().expand(modes.Y);
  }


  ResidualCheck::Residuals
  ParameterIndependentReanalysis::residuals(const std::vector<double> &t,
                                            const ReanalysedModes &modes) const
  {
    if (!residual_check_)
      residual_check_ = std::make_unique<ResidualCheck>(model());
    return residual_check_->check(t, modes.eigenvalues, this->modes(modes));
  }


  std::string
  ParameterIndependentReanalysis::name() const
  {
    return "hptp-pi";
  }


  bool
  ParameterIndependentReanalysis::has_order() const
  {
    return true;
  }


  ReanalysisResult
  ParameterIndependentReanalysis::reanalyse(const std::vector<double> &t,
                                            const unsigned int order) const
  {
    const ReanalysedModes r = online(t, order);
    ReanalysisResult      result;
    result.eigenvalues = r.eigenvalues;
    result.modes       = modes(r);
    result.order       = r.order;
    result.basis_size  = r.basis_size;
    return result;
  }
} // namespace FuzzyContact
