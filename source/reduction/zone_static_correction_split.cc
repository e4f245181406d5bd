// The split of ZoneStaticCorrection's basis (zone_static_correction.h)
// into an active part, which changes with the parameters, and an inert
// one: the reduced matrices of both at a state, and their errors against
// exact factorisations (at the corners of the box, or at a point).

#include <fuzzycontact/base/lapack_extras.h>
#include <fuzzycontact/base/timer_section.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include "zone_static_correction_data.h"
#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  void
  ZoneStaticCorrection::Data::split()
  {
    const unsigned int kk = k();
    // The numerical range of sum_k A_k (PSD): its pivoted Cholesky
    // factorisation stops at pivots below eps.
    FullMatrix<double> S(kk, kk);
    for (const FullMatrix<double> &a : A)
      S.add(1., a);
    double largest = 0;
    for (unsigned int i = 0; i < kk; ++i)
      largest = std::max(largest, S(i, i));
    // A prescribed displacement's forces follow the zone moduli: no part
    // of such a component is inert.
    const bool all_active =
      std::find(per_zone.begin(), per_zone.end(), true) != per_zone.end();
    types::blas_int              rank = kk;
    std::vector<types::blas_int> piv(kk);
    for (unsigned int i = 0; i < kk; ++i)
      piv[i] = i + 1;
    FullMatrix<double> L = S; // symmetric: column-major alike
    if (!all_active && kk > 0 && largest > 0)
      {
        const types::blas_int ki = kk;
        std::vector<double>   work(2 * kk);
        types::blas_int       info = 0;
        const double          tol  = 1e-14 * largest / std::max(t_max, 1e-2);
        dpstrf_("L",
                &ki,
                &L(0, 0),
                &ki,
                piv.data(),
                &rank,
                &tol,
                work.data(),
                &info);
        AssertThrow(info >= 0,
                    ExcMessage("LAPACK's pivoted Cholesky factorisation "
                               "(dpstrf) failed in the Krylov static "
                               "correction."));
      }
    n_active = all_active ? kk : rank;
    // Q = [Q_a, Q_c]: the QR factorisation of P L_rank (k x rank), whose
    // columns span the range; Q_c completes it.
    Q.reinit(kk, kk);
    if (n_active == kk)
      for (unsigned int i = 0; i < kk; ++i)
        Q(i, i) = 1;
    else if (n_active > 0)
      {
        // Column-major k x k array holding P L_rank in its first columns.
        std::vector<double> M(std::size_t(kk) * kk, 0.);
        for (types::blas_int j = 0; j < rank; ++j)
          for (unsigned int i = j; i < kk; ++i)
            M[std::size_t(j) * kk + piv[i] - 1] = L(j, i); // L_cm(i, j)
        const types::blas_int ki = kk, ri = rank;
        std::vector<double>   tau(kk);
        types::blas_int       info = 0, lwork = -1;
        double                size = 0;
        geqrf(&ki, &ri, M.data(), &ki, tau.data(), &size, &lwork, &info);
        lwork =
          std::max<types::blas_int>(static_cast<types::blas_int>(size), kk);
        std::vector<double> work(lwork);
        geqrf(&ki, &ri, M.data(), &ki, tau.data(), work.data(), &lwork, &info);
        AssertThrow(info == 0, ExcInternalError());
        orgqr(&ki,
              &ki,
              &ri,
              M.data(),
              &ki,
              tau.data(),
              work.data(),
              &lwork,
              &info);
        AssertThrow(info == 0, ExcInternalError());
        for (unsigned int i = 0; i < kk; ++i)
          for (unsigned int j = 0; j < kk; ++j)
            Q(i, j) = M[std::size_t(j) * kk + i];
      }
    else
      for (unsigned int i = 0; i < kk; ++i)
        Q(i, i) = 1;
    // The active projections; with one parameter, diagonalised.
    FullMatrix<double> Qa = columns(Q, 0, n_active);
    A_active.clear();
    for (const FullMatrix<double> &a : A)
      A_active.push_back(transpose_product(Qa, product(a, Qa)));
    diagonal = (A.size() == 1);
    if (diagonal)
      {
        symmetrise(A_active[0]);
        auto [values, vectors] = eigen(A_active[0]);
        lambda                 = values;
        Qa                     = product(Qa, vectors);
      }
    const FullMatrix<double> Qc = columns(Q, n_active, kk - n_active);
    H_a                         = product(CV, Qa);
    O_a                         = product(OV, Qa);
    H_c                         = product(CV, Qc);
    O_c                         = product(OV, Qc);
    f_a.assign(Vf.size(), {});
    f_c.assign(Vf.size(), {});
    for (unsigned int l = 0; l < Vf.size(); ++l)
      for (const Vector<double> &v : Vf[l])
        {
          f_a[l].push_back(transpose_product(Qa, v));
          f_c[l].push_back(transpose_product(Qc, v));
        }
    check.n_active = n_active;
  }


  std::pair<double, double>
  ZoneStaticCorrection::Data::errors(const std::vector<double>         &t,
                                     const FullMatrix<double>          &W,
                                     const std::vector<Vector<double>> &g) const
  {
    // K_r^{-1} = Q_c Q_c^T + Q_a K_a(t)^{-1} Q_a^T: W_r = W0 + H_a
    // (K_a^{-1} - I) H_a^T, with H_a = C V Q_a.
    const unsigned int m = C->m();
    FullMatrix<double> Ka(n_active, n_active);
    for (unsigned int i = 0; i < n_active; ++i)
      Ka(i, i) = 1;
    for (unsigned int p = 0; p < t.size(); ++p)
      {
        if (diagonal)
          for (unsigned int i = 0; i < n_active; ++i)
            Ka(i, i) += t[p] * lambda[i];
        else
          Ka.add(t[p], A_active[p]);
      }
    const FullMatrix<double> L = cholesky(Ka, "Component " + component.name());
    FullMatrix<double>       U = H_a;
    right_solve(L, U);
    FullMatrix<double> Wr = W0;
    if (n_active > 0)
      {
        FullMatrix<double> UU(m, m), HH(m, m);
        U.mTmult(UU, U);
        H_a.mTmult(HH, H_a);
        Wr.add(1., UU);
        Wr.add(-1., HH);
      }
    Wr.add(-1., W);
    const double norm = W.frobenius_norm();
    const double flexibility =
      norm > 0 ? Wr.frobenius_norm() / norm : Wr.frobenius_norm();
    double     load   = 0;
    const auto moduli = model.zone_materials(t).first;
    for (unsigned int l = 0; l < g.size(); ++l)
      {
        if (Vf[l].empty() || g[l].l2_norm() == 0)
          continue;
        // g_r = H_c f_c + H_a K_a^{-1} f_a.
        Vector<double> gr(m), h = combine(l, f_a[l], moduli, n_active);
        if (n_active > 0)
          {
            const types::blas_int ki = n_active, one = 1;
            types::blas_int       info = 0;
            trtrs("L",
                  "N",
                  "N",
                  &ki,
                  &one,
                  &L(0, 0),
                  &ki,
                  h.data(),
                  &ki,
                  &info);
            U.vmult(gr, h);
          }
        if (H_c.n() > 0)
          H_c.vmult_add(gr, combine(l, f_c[l], moduli, H_c.n()));
        gr -= g[l];
        load = std::max(load, gr.l2_norm() / g[l].l2_norm());
      }
    return {flexibility, load};
  }


  void
  ZoneStaticCorrection::Data::measure(TimerOutput *timer)
  {
    split();
    auto scope =
      timer_section(timer, "zone static correction check (exact corners)");
    check.flexibility_error = check.load_error = 0;
    for (unsigned int c = 0; c < corners.size(); ++c)
      {
        const auto e            = errors(corners[c], exact_W[c], exact_g[c]);
        check.flexibility_error = std::max(check.flexibility_error, e.first);
        check.load_error        = std::max(check.load_error, e.second);
      }
    check.tolerance_met = check.flexibility_error <= settings.tolerance &&
                          check.load_error <= settings.tolerance;
  }


  std::pair<FullMatrix<double>, std::vector<Vector<double>>>
  ZoneStaticCorrection::Data::exact(const std::vector<double> &t) const
  {
    // K(t) from the zone matrices, factorised with the contact DoFs last:
    // (K^{-1}) on them is the inverse of the factor's trailing block.
    SparseMatrix<double> K, M;
    model.matrices(t, K, M);
    SparseCholesky factorisation;
    factorisation.factorize(K,
                            attachment,
                            "Component " + component.name() +
                              ": the stiffness at a corner of the fuzzy box");
    const std::vector<types::global_dof_index> &T =
      factorisation.trailing_dofs();
    const FullMatrix<double> G = factorisation.trailing_inverse();
    std::vector<int>         position(n, -1);
    for (unsigned int i = 0; i < T.size(); ++i)
      position[T[i]] = i;
    const unsigned int m = C->m();
    FullMatrix<double> CT(m, T.size()); // C restricted to T
    for (unsigned int i = 0; i < m; ++i)
      for (auto it = C->begin(i); it != C->end(i); ++it)
        {
          AssertThrow(position[it->column()] >= 0, ExcInternalError());
          CT(i, position[it->column()]) += it->value();
        }
    FullMatrix<double> W(m, m);
    if (T.size() > 0)
      {
        const FullMatrix<double> CG = product(CT, G);
        CG.mTmult(W, CT);
      }
    // The load gaps at t: the loads at the moduli of t.
    const auto                  moduli = model.zone_materials(t).first;
    std::vector<Vector<double>> g;
    const auto                  f = load_vectors();
    for (unsigned int l = 0; l < f.size(); ++l)
      {
        g.emplace_back(m);
        if (f[l].empty())
          continue;
        Vector<double> u = combine(l, f[l], moduli, n);
        factorisation.solve(u);
        C->vmult(g.back(), u);
      }
    return {W, g};
  }

  ReducedComponentMatrices
  ZoneStaticCorrection::matrices(const std::vector<double>      &values,
                                 const ReducedComponentMatrices &nominal) const
  {
    const Data               &d      = *data;
    const std::vector<double> t      = d.model.relative_changes(values);
    const auto                moduli = d.model.zone_materials(t).first;
    ReducedComponentMatrices  r      = nominal.without_basis();
    r.stiffness_proportional.assign(r.stiffness_proportional.size(), false);
    const unsigned int na = d.n_active;
    if (d.diagonal)
      {
        r.stiffness_diagonal.reinit(na);
        for (unsigned int i = 0; i < na; ++i)
          {
            r.stiffness_diagonal[i] = 1 + t[0] * d.lambda[i];
            AssertThrow(r.stiffness_diagonal[i] > 0,
                        ExcMessage("Component " + d.component.name() +
                                   ": the re-analysed reduced stiffness is "
                                   "not positive definite at this state."));
          }
      }
    else
      {
        r.stiffness.reinit(na, na);
        for (unsigned int i = 0; i < na; ++i)
          r.stiffness(i, i) = 1;
        for (unsigned int p = 0; p < t.size(); ++p)
          r.stiffness.add(t[p], d.A_active[p]);
      }
    r.gap_operator = d.H_a;
    r.observation  = d.O_a;
    for (unsigned int l = 0; l < d.f_a.size(); ++l)
      r.loads.push_back(d.combine(l, d.f_a[l], moduli, na));
    return r;
  }


  ReducedComponentMatrices
  ZoneStaticCorrection::fixed_matrices(
    const ReducedComponentMatrices &nominal) const
  {
    const Data              &d  = *data;
    const unsigned int       nc = d.k() - d.n_active;
    ReducedComponentMatrices r  = nominal.without_basis();
    r.stiffness_proportional.assign(r.stiffness_proportional.size(), false);
    // (the weight and the free motions are the active part's)
    r.weight_load = -1;
    r.weight_gaps.clear();
    r.weight_observation.clear();
    r.weight_rigid_loads.clear();
    r.rigid_gaps.reinit(r.rigid_gaps.m(), 0);
    r.rigid_observation.reinit(r.rigid_observation.m(), 0);
    r.rigid_loads.assign(r.rigid_loads.size(), Vector<double>());
    r.motion_names.clear();
    r.stiffness_diagonal.reinit(nc);
    r.stiffness_diagonal = 1.;
    r.gap_operator       = d.H_c;
    r.observation        = d.O_c;
    const std::vector<double> nominal_moduli =
      d.model.zone_materials(std::vector<double>(d.model.n_parameters(), 0.))
        .first;
    for (unsigned int l = 0; l < d.f_c.size(); ++l)
      r.loads.push_back(d.combine(l, d.f_c[l], nominal_moduli, nc));
    return r;
  }

  std::pair<double, double>
  ZoneStaticCorrection::error_at(const std::vector<double> &values) const
  {
    const std::vector<double> t = data->model.relative_changes(values);
    const auto [W, g]           = data->exact(t);
    return data->errors(t, W, g);
  }
} // namespace FuzzyContact
