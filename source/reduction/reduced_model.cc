#include <fuzzycontact/base/mpi_wait.h>
#include <fuzzycontact/reduction/reduced_model.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>
#include <deal.II/lac/lapack_templates.h>

#include <boost/serialization/vector.hpp>

#include "reduced_model_flexibility.h"
#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  namespace
  {
    // FullMatrix is row-major; LAPACK reads its data column-major, as the
    // transpose. These helpers keep that straight.

    // L with K = L L^T, for the symmetric K (column-major lower triangle:
    // the row-major upper one).
    FullMatrix<double>
    cholesky(const FullMatrix<double> &K)
    {
      FullMatrix<double>    L    = K;
      const types::blas_int k    = K.m();
      types::blas_int       info = 0;
      if (k > 0)
        potrf("L", &k, &L(0, 0), &k, &info);
      AssertThrow(info == 0,
                  ExcMessage("ReducedContactModel: the reduced stiffness of a "
                             "component is not positive definite (LAPACK "
                             "dpotrf, pivot " +
                             std::to_string(info) +
                             "): a modulus or density orders of magnitude "
                             "from the others (e.g. 'relative = false' with "
                             "factor-like values) can cause this."));
      return L;
    }

    // A := A L^{-T} for a row-major A (n x k): its column-major view is
    // A^T (k x n), and L^{-1} A^T is what the triangular solve gives.
    void
    right_solve(const FullMatrix<double> &L, FullMatrix<double> &A)
    {
      const types::blas_int k = L.m(), n = A.m();
      types::blas_int       info = 0;
      if (k > 0 && n > 0)
        trtrs("L", "N", "N", &k, &n, &L(0, 0), &k, &A(0, 0), &k, &info);
      Assert(info == 0, ExcInternalError());
    }

    // v := L^{-1} v, or L^{-T} v.
    void
    solve(const FullMatrix<double> &L, Vector<double> &v, const bool transposed)
    {
      const types::blas_int k = L.m(), one = 1;
      types::blas_int       info = 0;
      if (k > 0)
        trtrs("L",
              transposed ? "T" : "N",
              "N",
              &k,
              &one,
              &L(0, 0),
              &k,
              v.data(),
              &k,
              &info);
      Assert(info == 0, ExcInternalError());
    }

    void
    check_finite(const FullMatrix<double> &A)
    {
      for (unsigned int i = 0; i < A.m(); ++i)
        for (unsigned int j = 0; j < A.n(); ++j)
          AssertThrow(std::isfinite(A(i, j)),
                      ExcMessage("ReducedContactModel: the reduced contact "
                                 "flexibility of a component has a non-finite "
                                 "entry."));
    }
  } // namespace


  void
  ReducedContactModel::Part::add_column(const unsigned int j,
                                        const double       a,
                                        double            *w) const
  {
    const unsigned int m = diagonal.size();
    // W_c is positive semi-definite: a zero diagonal entry (a contact row
    // the component has no part in) makes its whole column zero.
    if (diagonal[j] == 0)
      return;
    if (!low_rank)
      {
        // W_c is symmetric: its row j is its column j.
        const double *row = &flexibility(j, 0);
        for (unsigned int i = 0; i < m; ++i)
          w[i] += a * row[i];
        return;
      }
    // W_c(:, j) = U U(j, :)^T, one matrix-vector product (BLAS): U's
    // row-major data is the column-major U^T (k x m).
    const types::blas_int k = U.n(), rows = m, one = 1;
    if (k == 0 || m == 0)
      return;
    const double beta = 1;
    gemv("T", &k, &rows, &a, &U(0, 0), &k, &U(j, 0), &one, &beta, w, &one);
  }


  ReducedContactModel::ReducedContactModel(
    std::vector<ReducedComponentMatrices> components,
    const Vector<double>                 &g_initial,
    const std::vector<double>            &mu)
      : variable(components.size())
      , fixed(components.size())
      , scales(components.size(), 1.)
  {
    const unsigned int m = g_initial.size();
    AssertThrow(mu.size() * 2 == m,
                ExcMessage("ReducedContactModel: 2 gap rows per friction "
                           "coefficient are expected."));
    problem_.g_initial = g_initial;
    problem_.mu        = mu;
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        variable[c].matrices = std::move(components[c]);
        compute_blocks(variable[c]);
      }
    finish_construction();
  }


  void
  ReducedContactModel::finish_construction()
  {
    for (const Part &part : variable)
      {
        load_forces.push_back(part.matrices.reference_forces);
        densities.push_back(part.matrices.zone_densities);
      }
    // The free motions: every component's after the previous one's.
    const unsigned int m         = problem_.g_initial.size();
    unsigned int       n_motions = 0;
    first_motion.clear();
    for (const Part &part : variable)
      {
        first_motion.push_back(n_motions);
        n_motions += part.matrices.rigid_gaps.n();
      }
    problem_.rigid.gaps.reinit(m, n_motions);
    problem_.rigid.names.clear();
    for (unsigned int c = 0; c < variable.size(); ++c)
      {
        const ReducedComponentMatrices &r = variable[c].matrices;
        AssertThrow(r.rigid_gaps.n() == 0 ||
                      (r.rigid_gaps.m() == m &&
                       r.motion_names.size() == r.rigid_gaps.n() &&
                       r.rigid_loads.size() == r.reference_forces.size() &&
                       r.rigid_observation.m() == r.observed_dofs.size()),
                    ExcMessage("ReducedContactModel: the free motions of a "
                               "component do not fit its matrices."));
        for (unsigned int j = 0; j < r.rigid_gaps.n(); ++j)
          {
            for (unsigned int i = 0; i < m; ++i)
              problem_.rigid.gaps(i, first_motion[c] + j) = r.rigid_gaps(i, j);
            problem_.rigid.names.push_back(r.motion_names[j]);
          }
      }
    problem_.rigid_load.reinit(n_motions);

    flexibility_         = std::make_shared<Flexibility>(*this);
    problem_.flexibility = flexibility_;
    flexibility_changed();
  }


  ReducedContactModel::ReducedContactModel(
    std::vector<ReducedComponentMatrices> components,
    const Vector<double>                 &g_initial,
    const std::vector<double>            &mu,
    const std::vector<unsigned int>      &owner,
    const MPI_Comm                        comm)
      : variable(components.size())
      , fixed(components.size())
      , scales(components.size(), 1.)
  {
    AssertThrow(mu.size() * 2 == g_initial.size(),
                ExcMessage("ReducedContactModel: 2 gap rows per friction "
                           "coefficient are expected."));
    AssertDimension(owner.size(), components.size());
    problem_.g_initial = g_initial;
    problem_.mu        = mu;
    // Every rank forms its components' blocks, then they are exchanged.
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    for (unsigned int c = 0; c < components.size(); ++c)
      if (rank == owner[c])
        {
          variable[c].matrices = std::move(components[c]);
          compute_blocks(variable[c]);
        }
    wait_for_all_ranks(comm);
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        Part received = Utilities::MPI::broadcast(comm, variable[c], owner[c]);
        if (rank != owner[c])
          variable[c] = std::move(received);
      }
    finish_construction();
  }


  ReducedContactModel::~ReducedContactModel() = default;


  void
  ReducedContactModel::compute_blocks(Part &part, const bool dense) const
  {
    const unsigned int              m        = problem_.g_initial.size();
    const ReducedComponentMatrices &r        = part.matrices;
    const bool                      diagonal = r.stiffness_diagonal.size() > 0;
    const unsigned int              k =
      diagonal ? r.stiffness_diagonal.size() : r.stiffness.m();
    bool loads_fit = r.loads.size() == r.reference_forces.size() &&
                     r.loads.size() == r.stiffness_proportional.size();
    for (const Vector<double> &f : r.loads)
      loads_fit = loads_fit && f.size() == k;
    loads_fit = loads_fit &&
                (r.weight_load < 0 ||
                 (static_cast<unsigned int>(r.weight_load) < r.loads.size() &&
                  r.weight_gaps.size() == r.zone_densities.size() &&
                  r.weight_observation.size() == r.zone_densities.size()));
    for (const Vector<double> &g : r.weight_gaps)
      loads_fit = loads_fit && g.size() == m;
    for (const Vector<double> &u : r.weight_observation)
      loads_fit = loads_fit && u.size() == r.observed_dofs.size();
    AssertThrow((diagonal ? r.stiffness.m() == 0 : r.stiffness.n() == k) &&
                  r.gap_operator.m() == m && r.gap_operator.n() == k &&
                  loads_fit && r.observation.m() == r.observed_dofs.size() &&
                  (r.observed_dofs.empty() || r.observation.n() == k),
                ExcMessage("ReducedContactModel: the reduced matrices of a "
                           "component do not fit together."));
    if (diagonal)
      {
        // L = diag(sqrt(d)): no factorisation, and every solve a scaling.
        part.factor.reinit(0, 0);
        part.root_diagonal.reinit(k);
        for (unsigned int i = 0; i < k; ++i)
          {
            AssertThrow(r.stiffness_diagonal[i] > 0 &&
                          std::isfinite(r.stiffness_diagonal[i]),
                        ExcMessage("ReducedContactModel: the reduced "
                                   "stiffness of a component is not positive "
                                   "definite (a diagonal entry " +
                                   std::to_string(r.stiffness_diagonal[i]) +
                                   ")."));
            part.root_diagonal[i] = std::sqrt(r.stiffness_diagonal[i]);
          }
      }
    else
      {
        part.root_diagonal.reinit(0);
        part.factor = cholesky(r.stiffness);
      }
    // A := A L^{-T} (rows of A scaled, for a diagonal L).
    const auto right_solve_part = [&](FullMatrix<double> &A) {
      if (!diagonal)
        right_solve(part.factor, A);
      else
        for (unsigned int i = 0; i < A.m(); ++i)
          for (unsigned int l = 0; l < k; ++l)
            A(i, l) /= part.root_diagonal[l];
    };

    // U = C_r L^{-T}: W_c = C_r K_r^{-1} C_r^T = U U^T.
    FullMatrix<double> U = r.gap_operator;
    right_solve_part(U);
    check_finite(U);
    // (A diagonal K_r is a part that changes with every state: its columns
    // are combined when a solver asks for them, never the whole W_c; a
    // fixed part is formed once, dense, so that its columns cost O(m).)
    part.low_rank = !dense && (2 * k < m || diagonal);
    part.diagonal.reinit(m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int l = 0; l < k; ++l)
        part.diagonal[i] += U(i, l) * U(i, l);
    if (part.low_rank)
      {
        part.U = U;
        part.flexibility.reinit(0, 0);
      }
    else
      {
        part.flexibility.reinit(m, m);
        U.mTmult(part.flexibility, U);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int j = 0; j < i; ++j)
            part.flexibility(i, j) = part.flexibility(j, i) =
              0.5 * (part.flexibility(i, j) + part.flexibility(j, i));
        part.U.reinit(0, 0);
      }

    // Recovery of the observed displacements without a reduced solve:
    // u_obs = lambda O K_r^{-1} f_r + (O K_r^{-1} C_r^T) p, with
    // O K_r^{-1} C_r^T = (O L^{-T}) U^T.
    const unsigned int n_obs = r.observed_dofs.size();
    FullMatrix<double> O_L   = r.observation;
    right_solve_part(O_L);
    part.observation_flexibility.reinit(n_obs, m);
    if (n_obs > 0 && k > 0)
      O_L.mTmult(part.observation_flexibility, U);
    part.load_gaps.clear();
    part.observation_loads.clear();
    for (const Vector<double> &f : r.loads)
      {
        // h = L^{-1} f: g = C_r K_r^{-1} f = U h, u = O L^{-T} h.
        Vector<double> h = f;
        if (diagonal)
          for (unsigned int l = 0; l < k; ++l)
            h[l] /= part.root_diagonal[l];
        else
          solve(part.factor, h, false);
        Vector<double> g(m), u(n_obs);
        U.vmult(g, h);
        if (n_obs > 0)
          O_L.vmult(u, h);
        AssertThrow((m == 0 || std::isfinite(g.l2_norm())) &&
                      (n_obs == 0 || std::isfinite(u.l2_norm())),
                    ExcMessage("ReducedContactModel: the load response of a "
                               "component is not finite."));
        part.load_gaps.push_back(std::move(g));
        part.observation_loads.push_back(std::move(u));
      }
    // The weight's exact zone responses as they are.
    part.weight_gaps        = r.weight_gaps;
    part.weight_observation = r.weight_observation;
    part.present            = true;
    part.has_matrices       = true;
  }


  void
  ReducedContactModel::flexibility_changed(const bool scales_only)
  {
    unsigned long previous = 0;
    if (!scales_only)
      known_scales.clear();
    for (const auto &[s, state] : known_scales)
      if (s == scales)
        previous = state;
    flexibility_->reset(previous);
    if (previous == 0)
      {
        if (known_scales.size() == max_known_scales)
          known_scales.erase(known_scales.begin());
        known_scales.emplace_back(scales, flexibility_->state());
      }
    assemble_load_gaps();
  }


  void
  ReducedContactModel::set_stiffness_scales(const std::vector<double> &s)
  {
    AssertThrow(s.size() == variable.size(),
                ExcMessage("ReducedContactModel: one stiffness scale per "
                           "component is expected."));
    for (const double x : s)
      AssertThrow(x > 0 && std::isfinite(x),
                  ExcMessage("ReducedContactModel: stiffness scales must be "
                             "positive."));
    if (s == scales)
      return;
    scales = s;
    flexibility_changed(true);
  }


  void
  ReducedContactModel::replace_component(const unsigned int       c,
                                         ReducedComponentMatrices matrices)
  {
    AssertIndexRange(c, variable.size());
    variable[c].matrices = std::move(matrices);
    scales[c]            = 1.;
    compute_blocks(variable[c]);
    flexibility_changed();
  }


  void
  ReducedContactModel::replace_component(const unsigned int       c,
                                         ReducedComponentMatrices matrices,
                                         const unsigned int       owner,
                                         const MPI_Comm           comm)
  {
    AssertIndexRange(c, variable.size());
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    if (rank == owner)
      {
        variable[c].matrices = std::move(matrices);
        compute_blocks(variable[c]);
      }
    Part received = Utilities::MPI::broadcast(comm, variable[c], owner);
    if (rank != owner)
      variable[c] = std::move(received);
    scales[c] = 1.;
    flexibility_changed();
  }


  void
  ReducedContactModel::clear_fixed_part(const unsigned int c)
  {
    AssertIndexRange(c, fixed.size());
    fixed[c] = Part();
    flexibility_changed();
  }


  void
  ReducedContactModel::set_fixed_part(const unsigned int       c,
                                      ReducedComponentMatrices matrices)
  {
    AssertIndexRange(c, fixed.size());
    AssertThrow(matrices.observed_dofs == variable[c].matrices.observed_dofs,
                ExcMessage("ReducedContactModel: the fixed part of a "
                           "component must observe the same DoFs."));
    fixed[c].matrices = std::move(matrices);
    compute_blocks(fixed[c], true);
    flexibility_changed();
  }


  const ContactProblem &
  ReducedContactModel::problem() const
  {
    return problem_;
  }

  ContactProblem &
  ReducedContactModel::problem()
  {
    return problem_;
  }


  FullMatrix<double>
  ReducedContactModel::component_flexibility(const unsigned int c) const
  {
    AssertIndexRange(c, variable.size());
    const unsigned int  m = problem_.g_initial.size();
    FullMatrix<double>  W(m, m);
    std::vector<double> w(m);
    for (unsigned int j = 0; j < m; ++j)
      {
        std::fill(w.begin(), w.end(), 0.);
        for (const Part *part : {&variable[c], &fixed[c]})
          if (part->present)
            part->add_column(j, 1. / scales[c], w.data());
        for (unsigned int i = 0; i < m; ++i)
          W(i, j) = w[i];
      }
    return W;
  }


  FullMatrix<double>
  ReducedContactModel::flexibility() const
  {
    const unsigned int m = problem_.g_initial.size();
    FullMatrix<double> W(m, m);
    for (unsigned int c = 0; c < variable.size(); ++c)
      W.add(1., component_flexibility(c));
    return W;
  }


  unsigned int
  ReducedContactModel::n_components() const
  {
    return variable.size();
  }


  std::vector<Vector<double>>
  ReducedContactModel::coordinates(const Vector<double> &p,
                                   const double          load_factor) const
  {
    std::vector<Vector<double>> q;
    for (unsigned int c = 0; c < variable.size(); ++c)
      {
        if (!variable[c].has_matrices)
          {
            q.emplace_back(); // formed on another rank
            continue;
          }
        std::vector<Vector<double>> parts;
        for (const Part *part : {&variable[c], &fixed[c]})
          if (part->present)
            {
              Vector<double> rhs(part->matrices.gap_operator.n());
              for (unsigned int l = 0; l < part->matrices.loads.size(); ++l)
                rhs.add(load_factor * this->load_factor(c, l),
                        part->matrices.loads[l]);
              part->matrices.gap_operator.Tvmult_add(rhs, p);
              if (part->root_diagonal.size() > 0)
                for (unsigned int l = 0; l < rhs.size(); ++l)
                  rhs[l] /= part->root_diagonal[l] * part->root_diagonal[l];
              else
                {
                  solve(part->factor, rhs, false);
                  solve(part->factor, rhs, true);
                }
              rhs /= scales[c];
              parts.push_back(std::move(rhs));
            }
        Vector<double> qc(parts[0].size() +
                          (parts.size() > 1 ? parts[1].size() : 0));
        for (unsigned int i = 0; i < parts[0].size(); ++i)
          qc[i] = parts[0][i];
        if (parts.size() > 1)
          for (unsigned int i = 0; i < parts[1].size(); ++i)
            qc[parts[0].size() + i] = parts[1][i];
        q.push_back(std::move(qc));
      }
    return q;
  }


  ContactSolution
  ReducedContactModel::solution(const ContactState &state,
                                const double        load_factor,
                                const std::string  &solver) const
  {
    ContactSolution s;
    s.solver     = solver;
    s.p          = state.p;
    s.g          = state.g;
    s.status     = state.status;
    s.iterations = state.iterations;
    s.residual   = state.residual;
    s.rigid      = state.rigid;
    s.compute_totals();
    s.observed.resize(variable.size());
    for (unsigned int c = 0; c < variable.size(); ++c)
      for (unsigned int row = 0;
           row < variable[c].matrices.observed_dofs.size();
           ++row)
        {
          double u = 0;
          for (const Part *part : {&variable[c], &fixed[c]})
            if (part->present)
              {
                for (unsigned int l = 0; l < part->observation_loads.size();
                     ++l)
                  u += load_factor * this->load_factor(c, l) *
                       part->observation_loads[l][row];
                for (unsigned int j = 0; j < state.p.size(); ++j)
                  if (state.p[j] != 0)
                    u += part->observation_flexibility(row, j) * state.p[j];
              }
          u /= scales[c];
          // The weight's exact response.
          const std::vector<double> a = weight_coefficients(c);
          for (unsigned int z = 0; z < a.size(); ++z)
            for (const Part *part : {&variable[c], &fixed[c]})
              if (part->present && z < part->weight_observation.size())
                u += load_factor * a[z] * part->weight_observation[z][row];
          const ReducedComponentMatrices &r = variable[c].matrices;
          for (unsigned int j = 0; j < r.rigid_observation.n(); ++j)
            u += r.rigid_observation(row, j) * state.rigid[first_motion[c] + j];
          s.observed[c].push_back(u);
        }
    return s;
  }
} // namespace FuzzyContact
