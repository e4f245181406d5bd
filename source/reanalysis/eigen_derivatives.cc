#include <fuzzycontact/reanalysis/eigen_derivatives.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <sstream>

namespace FuzzyContact
{
  std::string
  describe_modes(const ModalBasis                &basis,
                 const std::vector<unsigned int> &modes)
  {
    const std::vector<double> f = basis.frequencies();
    std::ostringstream        numbers, frequencies;
    frequencies << std::setprecision(6);
    for (unsigned int i = 0; i < modes.size(); ++i)
      {
        const std::string separator =
          i == 0 ? "" : (i + 1 == modes.size() ? " and " : ", ");
        numbers << separator << modes[i] + 1;
        frequencies << separator << f[modes[i]];
      }
    return std::string(modes.size() > 1 ? "modes " : "mode ") + numbers.str() +
           " (" + frequencies.str() + " Hz)";
  }


  // ---------------------------------------------------------------------
  // EigenDerivatives
  // ---------------------------------------------------------------------

  EigenDerivatives::EigenDerivatives(
    const ParameterModel                                      &model,
    const ModalBasis                                          &nominal,
    const std::vector<unsigned int>                           &cluster,
    const double                                               cluster_gap,
    const std::shared_ptr<const SparseDirectSolver::Analysis> &same_pattern,
    std::shared_ptr<const DeflatedBorderedSolver>              deflated)
      : model(model)
      , nominal(nominal)
      , cluster_(cluster)
      , deflated(std::move(deflated))
      , same_pattern(same_pattern)
  {
    AssertThrow(!cluster.empty(), ExcMessage("empty cluster (internal)"));
    for (const unsigned int c : cluster)
      AssertThrow(c < nominal.size(),
                  ExcMessage("cluster mode out of range (internal)"));

    // An incomplete cluster has no well-defined expansion: refuse it.
    const double gap = std::max(cluster_gap, minimum_cluster_gap);
    for (const unsigned int c : cluster)
      for (unsigned int i = 0; i < nominal.size(); ++i)
        if (std::find(cluster.begin(), cluster.end(), i) == cluster.end())
          {
            const double a = nominal.eigenvalues[c], b = nominal.eigenvalues[i];
            if (std::abs(a - b) <= gap * std::max(a, b))
              {
                std::ostringstream message;
                message << "modal reanalysis: "
                        << describe_modes(nominal,
                                          {std::min(c, i), std::max(c, i)})
                        << " lie within a relative gap of "
                        << std::abs(a - b) / std::max(a, b) << " (cluster gap "
                        << gap
                        << ") but are not expanded together as a cluster; the "
                           "derivatives of the individual modes are not well "
                           "defined there.";
                AssertThrow(false, ExcMessage(message.str()));
              }
          }

    const SparseMatrix<double> &K0 = model.nominal_stiffness();
    const SparseMatrix<double> &M0 = model.nominal_mass();
    const unsigned int          n  = K0.m();

    double max_K_diagonal = 0;
    for (unsigned int i = 0; i < n; ++i)
      max_K_diagonal = std::max(max_K_diagonal, std::abs(K0.diag_element(i)));
    for (const unsigned int c : cluster)
      {
        Vector<double> b(n);
        M0.vmult(b, nominal.modes[c]);
        // The border column is scaled to the size of K's entries (see solve()).
        border_scale.push_back(max_K_diagonal / b.linfty_norm());
        M0_phi.push_back(std::move(b));
      }
    factorisations.resize(cluster.size());
    // The direct path factorises every bordered matrix now.
    if (this->deflated == nullptr)
      for (unsigned int j = 0; j < cluster.size(); ++j)
        factorisation(j);
  }


  EigenDerivatives::~EigenDerivatives() = default;


  const SparseDirectSolver &
  EigenDerivatives::factorisation(const unsigned int j) const
  {
    AssertIndexRange(j, factorisations.size());
    if (factorisations[j] != nullptr)
      return *factorisations[j];

    const SparseMatrix<double> &K0 = model.nominal_stiffness();
    const SparseMatrix<double> &M0 = model.nominal_mass();
    const unsigned int          n  = K0.m();
    const unsigned int          m  = cluster_.size();
    if (bordered_pattern == nullptr)
      {
        // K0's pattern, bordered by m dense rows and columns on the DoFs
        // that carry mass (clamped DoFs have zero rows in M0, hence in M0
        // Phi).
        DynamicSparsityPattern dsp(n + m, n + m);
        const SparsityPattern &pattern = K0.get_sparsity_pattern();
        for (unsigned int i = 0; i < n; ++i)
          for (auto it = pattern.begin(i); it != pattern.end(i); ++it)
            dsp.add(i, it->column());
        for (unsigned int i = 0; i < n; ++i)
          if (M0.diag_element(i) != 0)
            for (unsigned int c = 0; c < m; ++c)
              {
                dsp.add(i, n + c);
                dsp.add(n + c, i);
              }
        for (unsigned int c = 0; c < m; ++c)
          for (unsigned int d = 0; d < m; ++d)
            dsp.add(n + c, n + d);
        bordered_pattern = std::make_unique<SparsityPattern>();
        bordered_pattern->copy_from(dsp);
      }

    const double         lambda = nominal.eigenvalues[cluster_[j]];
    SparseMatrix<double> B(*bordered_pattern);
    for (unsigned int i = 0; i < n; ++i)
      {
        auto k  = K0.begin(i);
        auto mm = M0.begin(i);
        for (; k != K0.end(i); ++k, ++mm)
          {
            Assert(mm->column() == k->column(), ExcInternalError());
            B.set(i, k->column(), k->value() - lambda * mm->value());
          }
      }
    for (unsigned int c = 0; c < m; ++c)
      for (unsigned int i = 0; i < n; ++i)
        if (M0_phi[c][i] != 0)
          {
            const double v = -border_scale[c] * M0_phi[c][i];
            B.set(i, n + c, v);
            B.set(n + c, i, v);
          }
    auto solver = std::make_unique<SparseDirectSolver>();
    try
      {
        // Bordered matrices of one size have one pattern: a symbolic
        // analysis serves them all.
        solver->factorize(B, analysis());
      }
    catch (const ExceptionBase &)
      {
        AssertThrow(false,
                    ExcMessage("modal reanalysis: the bordered matrix of " +
                               describe_modes(nominal, {cluster_[j]}) +
                               " is singular; is its eigenvalue repeated "
                               "outside its cluster?"));
      }
    factorisations[j] = std::move(solver);
    return *factorisations[j];
  }


  std::shared_ptr<const SparseDirectSolver::Analysis>
  EigenDerivatives::analysis() const
  {
    for (const auto &f : factorisations)
      if (f != nullptr)
        return f->analysis();
    return same_pattern;
  }


  const std::vector<unsigned int> &
  EigenDerivatives::cluster() const
  {
    return cluster_;
  }


  unsigned int
  EigenDerivatives::n_factorisations() const
  {
    return std::count_if(factorisations.begin(),
                         factorisations.end(),
                         [](const auto &f) {
                           return f != nullptr;
                         });
  }


  void
  EigenDerivatives::solve_directly(BorderedSystem &system) const
  {
    const unsigned int n = system.r.size();
    const unsigned int m = cluster_.size();
    AssertDimension(system.c.size(), m);
    AssertIndexRange(system.j, m);
    // With mu = s nu, the system [A, -s B; -s B^T, 0] [x; nu] = [r; s c]
    // is symmetric and its border is of the size of K's entries.
    Vector<double> rhs(n + m);
    for (unsigned int i = 0; i < n; ++i)
      rhs[i] = system.r[i];
    for (unsigned int d = 0; d < m; ++d)
      rhs[n + d] = border_scale[d] * system.c[d];
    factorisation(system.j).solve(rhs);
    system.x.reinit(n, /*omit_zeroing_entries=*/true);
    for (unsigned int i = 0; i < n; ++i)
      system.x[i] = rhs[i];
    system.mu.resize(m);
    for (unsigned int d = 0; d < m; ++d)
      system.mu[d] = border_scale[d] * rhs[n + d];
    system.solved = true;
  }


  void
  EigenDerivatives::solve(const unsigned int         j,
                          const Vector<double>      &r,
                          const std::vector<double> &c,
                          Vector<double>            &x,
                          std::vector<double>       &mu) const
  {
    AssertIndexRange(j, cluster_.size());
    std::vector<BorderedSystem> system(1);
    system[0].cluster = cluster_;
    system[0].j       = j;
    system[0].r       = r;
    system[0].c       = c;
    if (deflated != nullptr)
      deflated->solve(system);
    if (!system[0].solved)
      solve_directly(system[0]);
    x  = std::move(system[0].x);
    mu = std::move(system[0].mu);
  }


  namespace
  {
    using IndexPairs = std::vector<std::pair<unsigned int, unsigned int>>;

    // The splittings of the multi-index alpha = I[a] that its right-hand
    // side needs: inner, the pairs (beta, gamma) with beta + gamma = alpha,
    // both nonzero; and for each direction d with alpha_d > 0, previous[d] =
    // alpha - e_d and outer[d], all splittings (beta, gamma) of it.
    struct Splittings
    {
      IndexPairs                inner;
      std::vector<IndexPairs>   outer;
      std::vector<unsigned int> previous;
    };

    // Appends (b, index of alpha - beta) for every beta = I[b], b in
    // [first, last], with beta <= alpha componentwise (and alpha - beta != 0
    // unless @p zero_allowed).
    void
    add_splittings(const MultiIndexSet             &I,
                   const std::vector<unsigned int> &alpha,
                   const unsigned int               first,
                   const unsigned int               last,
                   const bool                       zero_allowed,
                   IndexPairs                      &pairs)
    {
      for (unsigned int b = first; b <= last; ++b)
        {
          const std::vector<unsigned int> &beta = I[b];
          bool                             fits = true;
          std::vector<unsigned int>        gamma(alpha.size());
          for (unsigned int k = 0; k < alpha.size(); ++k)
            {
              fits     = fits && beta[k] <= alpha[k];
              gamma[k] = fits ? alpha[k] - beta[k] : 0;
            }
          if (fits)
            {
              const unsigned int g = I.index(gamma);
              if (zero_allowed || g != 0)
                pairs.emplace_back(b, g);
            }
        }
    }

    Splittings
    splittings_of(const MultiIndexSet &I, const unsigned int a)
    {
      const std::vector<unsigned int> &alpha = I[a];
      const unsigned int               q     = alpha.size();
      Splittings                       s;
      if (a > 1)
        add_splittings(I, alpha, 1, a - 1, false, s.inner);
      s.outer.resize(q);
      s.previous.assign(q, 0);
      for (unsigned int d = 0; d < q; ++d)
        if (alpha[d] > 0)
          {
            std::vector<unsigned int> reduced = alpha;
            --reduced[d];
            s.previous[d] = I.index(reduced);
            add_splittings(I, reduced, 0, s.previous[d], true, s.outer[d]);
          }
      return s;
    }


    // The products M0 X_alpha, and K_d X_alpha, M_d X_alpha per direction d
    // (an empty vector stands for a zero product), by multi-index: computed
    // once per multi-index and kept while they can still be needed.
    struct Products
    {
      Products(const unsigned int n_indices, const unsigned int q)
          : M0X(n_indices)
          , KdX(q, std::vector<std::vector<Vector<double>>>(n_indices))
          , MdX(KdX)
          , has_K(q, false)
          , has_M(q, false)
      {
      }

      std::vector<std::vector<Vector<double>>>              M0X;
      std::vector<std::vector<std::vector<Vector<double>>>> KdX, MdX;
      /** Whether any product with K_d (M_d) is not zero. */
      std::vector<bool> has_K, has_M;
    };


    // The products of the columns X of multi-index a; M0_phi: the products
    // of order 0, computed already.
    void
    compute_products(const ParameterModel                   &model,
                     const std::vector<Vector<double>>      &M0_phi,
                     const std::vector<std::vector<double>> &directions,
                     const unsigned int                      a,
                     const std::vector<Vector<double>>      &X,
                     Products                               &p)
    {
      const unsigned int m = X.size();
      const unsigned int q = directions.size();
      p.M0X[a].resize(m);
      for (unsigned int d = 0; d < q; ++d)
        {
          p.KdX[d][a].resize(m);
          p.MdX[d][a].resize(m);
        }
      for (unsigned int j = 0; j < m; ++j)
        {
          if (a == 0)
            p.M0X[a][j] = M0_phi[j];
          else
            {
              p.M0X[a][j].reinit(X[j].size());
              model.nominal_mass().vmult(p.M0X[a][j], X[j]);
            }
          for (unsigned int d = 0; d < q; ++d)
            {
              Vector<double> product;
              if (model.stiffness_change(directions[d], X[j], product))
                {
                  p.KdX[d][a][j] = std::move(product);
                  p.has_K[d]     = true;
                }
              if (model.mass_change(directions[d], X[j], product))
                {
                  p.MdX[d][a][j] = std::move(product);
                  p.has_M[d]     = true;
                }
            }
        }
    }


    // The right-hand side (r, c) of the bordered system of multi-index
    // alpha = I[a], column j, from the coefficients of lower order.
    void
    right_hand_side(const EigenTaylorCoefficients &result,
                    const unsigned int             a,
                    const Splittings              &s,
                    const Products                &p,
                    const unsigned int             j,
                    Vector<double>                &r,
                    std::vector<double>           &c)
    {
      const std::vector<unsigned int> &alpha = result.indices[a];
      const unsigned int               m     = result.modes.size();
      const unsigned int               q     = alpha.size();
      r                                      = 0;
      std::fill(c.begin(), c.end(), 0.);
      for (unsigned int d = 0; d < q; ++d)
        if (alpha[d] > 0 && p.has_K[d] && p.KdX[d][s.previous[d]][j].size() > 0)
          r.add(-1., p.KdX[d][s.previous[d]][j]);
      for (const auto &[b, g] : s.inner)
        for (unsigned int i = 0; i < m; ++i)
          if (result.eigenvalues[b](i, j) != 0)
            r.add(result.eigenvalues[b](i, j), p.M0X[g][i]);
      for (unsigned int d = 0; d < q; ++d)
        if (alpha[d] > 0 && p.has_M[d])
          for (const auto &[b, g] : s.outer[d])
            for (unsigned int i = 0; i < m; ++i)
              if (result.eigenvalues[b](i, j) != 0 && p.MdX[d][g][i].size() > 0)
                r.add(result.eigenvalues[b](i, j), p.MdX[d][g][i]);

      if (result.mass_normalised)
        {
          double sum = 0;
          for (const auto &[b, g] : s.inner)
            sum += result.vectors[b][0] * p.M0X[g][0];
          for (unsigned int d = 0; d < q; ++d)
            if (alpha[d] > 0 && p.has_M[d])
              for (const auto &[b, g] : s.outer[d])
                if (p.MdX[d][g][0].size() > 0)
                  sum += result.vectors[b][0] * p.MdX[d][g][0];
          c[0] = 0.5 * sum;
        }
    }
  } // namespace


  EigenTaylorCoefficients
  EigenDerivatives::taylor_coefficients(
    const std::vector<std::vector<double>> &directions,
    const unsigned int                      order,
    const bool                              mass_normalise) const
  {
    return std::move(
      taylor_coefficients({this}, directions, order, {mass_normalise})[0]);
  }


  // The recursion of the header, for the q directions of @p directions:
  // order 0 is each cluster itself, and every further multi-index, in
  // order, one bordered solve per mode of each cluster; the solves of one
  // multi-index are independent of each other and go together.
  std::vector<EigenTaylorCoefficients>
  EigenDerivatives::taylor_coefficients(
    const std::vector<const EigenDerivatives *> &clusters,
    const std::vector<std::vector<double>>      &directions,
    const unsigned int                           order,
    const std::vector<bool>                     &mass_normalise)
  {
    AssertThrow(!clusters.empty() && mass_normalise.size() == clusters.size(),
                ExcMessage("one normalisation per cluster (internal)"));
    const ParameterModel &model = clusters[0]->model;
    const unsigned int    q     = directions.size();
    const unsigned int    n     = model.nominal_mass().m();
    const MultiIndexSet   I(q, order);
    for (const auto &d : directions)
      AssertThrow(d.size() == model.n_parameters(),
                  ExcMessage("a direction needs one coefficient per "
                             "parameter (internal)"));

    std::vector<EigenTaylorCoefficients> results(clusters.size());
    std::vector<Products>                products;
    for (unsigned int k = 0; k < clusters.size(); ++k)
      {
        const EigenDerivatives &e = *clusters[k];
        const unsigned int      m = e.cluster_.size();
        AssertThrow(&e.model == &model && &e.nominal == &clusters[0]->nominal,
                    ExcMessage("clusters of one basis (internal)"));
        AssertThrow(!mass_normalise[k] || m == 1,
                    ExcMessage("modal reanalysis: Lee's M-normalised "
                               "derivatives exist for simple modes only, "
                               "but " +
                               describe_modes(e.nominal, e.cluster_) +
                               " form a cluster of close eigenvalues."));
        EigenTaylorCoefficients &result = results[k];
        result.modes                    = e.cluster_;
        result.mass_normalised          = mass_normalise[k];
        result.directions               = directions;
        result.indices                  = I;
        result.vectors.resize(I.size());
        result.eigenvalues.resize(I.size());
        // Order 0: the cluster and its eigenvalues.
        result.vectors[0].resize(m);
        result.eigenvalues[0].reinit(m, m);
        for (unsigned int j = 0; j < m; ++j)
          {
            result.vectors[0][j]        = e.nominal.modes[e.cluster_[j]];
            result.eigenvalues[0](j, j) = e.nominal.eigenvalues[e.cluster_[j]];
          }
        products.emplace_back(I.size(), q);
        if (order > 0)
          compute_products(model,
                           e.M0_phi,
                           directions,
                           0,
                           result.vectors[0],
                           products[k]);
      }

    for (unsigned int a = 1; a < I.size(); ++a)
      {
        const Splittings splittings = splittings_of(I, a);
        // The systems of multi-index a, cluster by cluster, column by column.
        std::vector<BorderedSystem> systems;
        std::vector<unsigned int>   owner;
        for (unsigned int k = 0; k < clusters.size(); ++k)
          {
            const EigenDerivatives &e = *clusters[k];
            const unsigned int      m = e.cluster_.size();
            results[k].vectors[a].resize(m);
            results[k].eigenvalues[a].reinit(m, m);
            for (unsigned int j = 0; j < m; ++j)
              {
                BorderedSystem system;
                system.cluster = e.cluster_;
                system.j       = j;
                system.r.reinit(n);
                system.c.resize(m);
                right_hand_side(results[k],
                                a,
                                splittings,
                                products[k],
                                j,
                                system.r,
                                system.c);
                systems.push_back(std::move(system));
                owner.push_back(k);
              }
          }
        // Deflated CG, one batch per solver (the clusters of one basis
        // normally share one), then the direct path for what it left.
        std::vector<bool> batched(systems.size(), false);
        for (unsigned int s = 0; s < systems.size(); ++s)
          {
            const DeflatedBorderedSolver *solver =
              clusters[owner[s]]->deflated.get();
            if (batched[s] || solver == nullptr)
              continue;
            std::vector<BorderedSystem> batch;
            std::vector<unsigned int>   positions;
            for (unsigned int t = s; t < systems.size(); ++t)
              if (clusters[owner[t]]->deflated.get() == solver)
                {
                  batch.push_back(std::move(systems[t]));
                  positions.push_back(t);
                  batched[t] = true;
                }
            solver->solve(batch);
            for (unsigned int i = 0; i < batch.size(); ++i)
              systems[positions[i]] = std::move(batch[i]);
          }
        unsigned int s = 0;
        for (unsigned int k = 0; k < clusters.size(); ++k)
          {
            const unsigned int m = clusters[k]->cluster_.size();
            for (unsigned int j = 0; j < m; ++j, ++s)
              {
                if (!systems[s].solved)
                  clusters[k]->solve_directly(systems[s]);
                results[k].vectors[a][j] = std::move(systems[s].x);
                for (unsigned int i = 0; i < m; ++i)
                  results[k].eigenvalues[a](i, j) = systems[s].mu[i];
              }
            if (I.order(a) < order)
              compute_products(model,
                               clusters[k]->M0_phi,
                               directions,
                               a,
                               results[k].vectors[a],
                               products[k]);
          }
      }
    return results;
  }


  EigenpairDerivatives
  EigenDerivatives::derivatives(const unsigned int order) const
  {
    AssertThrow(order == 1 || order == 2,
                ExcMessage("Lee's derivatives: order must be 1 or 2."));
    AssertThrow(cluster_.size() == 1,
                ExcMessage(
                  "modal reanalysis: " + describe_modes(nominal, cluster_) +
                  " form a cluster of close eigenvalues; the "
                  "derivatives of its individual modes are not "
                  "defined. Expand the cluster's subspace "
                  "instead."));
    const unsigned int               n_p = model.n_parameters();
    std::vector<std::vector<double>> identity(n_p,
                                              std::vector<double>(n_p, 0.));
    for (unsigned int k = 0; k < n_p; ++k)
      identity[k][k] = 1;
    const EigenTaylorCoefficients taylor =
      taylor_coefficients(identity, order, /*mass_normalise=*/true);
    const MultiIndexSet &I = taylor.indices;

    EigenpairDerivatives result;
    result.mode = cluster_[0];
    for (unsigned int k = 0; k < n_p; ++k)
      {
        std::vector<unsigned int> e(n_p, 0);
        e[k]                 = 1;
        const unsigned int a = I.index(e);
        result.eigenvalue.push_back(taylor.eigenvalues[a](0, 0));
        result.mode_shape.push_back(taylor.vectors[a][0]);
      }
    if (order == 2)
      {
        result.second_eigenvalue.reinit(n_p, n_p);
        result.second_mode_shape.resize(n_p, std::vector<Vector<double>>(n_p));
        for (unsigned int k = 0; k < n_p; ++k)
          for (unsigned int l = 0; l < n_p; ++l)
            {
              std::vector<unsigned int> e(n_p, 0);
              ++e[k];
              ++e[l];
              const unsigned int a = I.index(e);
              // phi_alpha = D^alpha phi / alpha!, and (2,0,..)! = 2.
              const double factor = I.factorial(a);
              result.second_eigenvalue(k, l) =
                factor * taylor.eigenvalues[a](0, 0);
              result.second_mode_shape[k][l] = taylor.vectors[a][0];
              result.second_mode_shape[k][l] *= factor;
            }
      }
    return result;
  }
} // namespace FuzzyContact
