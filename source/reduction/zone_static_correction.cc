// ZoneStaticCorrection (zone_static_correction.h): the dense algebra of
// its files, and the constructor: the Krylov levels from probes of the
// static correction. The basis: zone_static_correction_basis.cc; the
// active and inert parts: zone_static_correction_split.cc.

#include <fuzzycontact/base/lapack_errors.h>
#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/base/timer_section.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include "zone_static_correction_data.h"
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>

namespace FuzzyContact
{
  namespace ZoneCorrectionAlgebra
  {
    // X := M X, one column at a time.
    void
    sparse_product_in_place(const SparseMatrix<double> &M,
                            Block                      &X,
                            const unsigned int          b)
    {
      const unsigned int n = M.n();
      AssertDimension(M.m(), n);
      AssertDimension(X.size(), std::size_t(n) * b);
      Vector<double> x(n), y(n);
      for (unsigned int j = 0; j < b; ++j)
        {
          double *column = X.data() + std::size_t(j) * n;
          std::copy(column, column + n, x.begin());
          M.vmult(y, x);
          std::copy(y.begin(), y.end(), column);
        }
    }

    // M X for a sparse M and a column-major block X with b columns.
    Block
    sparse_product(const SparseMatrix<double> &M,
                   const Block                &X,
                   const unsigned int          b)
    {
      Block Y = X;
      sparse_product_in_place(M, Y, b);
      return Y;
    }

    // A := (A + A^T) / 2 for a square A (round-off made symmetric).
    void
    symmetrise(FullMatrix<double> &A)
    {
      for (unsigned int i = 0; i < A.m(); ++i)
        for (unsigned int j = 0; j < i; ++j)
          A(i, j) = A(j, i) = 0.5 * (A(i, j) + A(j, i));
    }

    // Eigenpairs of the symmetric row-major G, ascending; the eigenvectors
    // as the columns of a row-major matrix.
    std::pair<std::vector<double>, FullMatrix<double>>
    eigen(const FullMatrix<double> &G)
    {
      const types::blas_int n = G.m();
      std::vector<double>   values(n);
      FullMatrix<double>    vectors(n, n);
      if (n == 0)
        return {values, vectors};
      FullMatrix<double> A    = G; // symmetric: row- and column-major alike
      types::blas_int    info = 0, lwork = -1;
      double             size = 0;
      syev("V", "U", &n, &A(0, 0), &n, values.data(), &size, &lwork, &info);
      lwork = static_cast<types::blas_int>(size);
      std::vector<double> work(std::max<types::blas_int>(lwork, 1));
      syev("V",
           "U",
           &n,
           &A(0, 0),
           &n,
           values.data(),
           work.data(),
           &lwork,
           &info);
      AssertThrow(info == 0,
                  ExcMessage("LAPACK's symmetric eigensolver (dsyev) failed "
                             "in the Krylov static correction."));
      // Column-major eigenvectors: vector j at A_cm(:, j) = A_rm(j, :).
      vectors.copy_transposed(A);
      return {values, vectors};
    }

    // L with A = L L^T (row-major symmetric A; column-major lower L).
    FullMatrix<double>
    cholesky(const FullMatrix<double> &A, const std::string &what)
    {
      FullMatrix<double>    L    = A;
      const types::blas_int k    = A.m();
      types::blas_int       info = 0;
      if (k > 0)
        potrf("L", &k, &L(0, 0), &k, &info);
      AssertThrow(info == 0,
                  ExcMessage(what +
                             ": the re-analysed reduced stiffness is "
                             "not positive definite (LAPACK dpotrf, "
                             "pivot " +
                             std::to_string(info) + ")."));
      return L;
    }

    // A := A L^{-T} for row-major A (rows x k), L from cholesky().
    void
    right_solve(const FullMatrix<double> &L, FullMatrix<double> &A)
    {
      const types::blas_int k = L.m(), rows = A.m();
      types::blas_int       info = 0;
      if (k > 0 && rows > 0)
        trtrs("L", "N", "N", &k, &rows, &L(0, 0), &k, &A(0, 0), &k, &info);
      Assert(info == 0, ExcInternalError());
    }

    // The columns [first, first + count) of A.
    FullMatrix<double>
    columns(const FullMatrix<double> &A,
            const unsigned int        first,
            const unsigned int        count)
    {
      FullMatrix<double> B(A.m(), count);
      for (unsigned int i = 0; i < A.m(); ++i)
        for (unsigned int j = 0; j < count; ++j)
          B(i, j) = A(i, first + j);
      return B;
    }

    FullMatrix<double>
    product(const FullMatrix<double> &A, const FullMatrix<double> &B)
    {
      FullMatrix<double> C(A.m(), B.n());
      if (A.m() > 0 && B.n() > 0 && A.n() > 0)
        A.mmult(C, B);
      return C;
    }

    FullMatrix<double>
    transpose_product(const FullMatrix<double> &A, const FullMatrix<double> &B)
    {
      FullMatrix<double> C(A.n(), B.n());
      if (A.n() > 0 && B.n() > 0 && A.m() > 0)
        A.Tmmult(C, B);
      return C;
    }

    Vector<double>
    transpose_product(const FullMatrix<double> &A, const Vector<double> &v)
    {
      Vector<double> w(A.n());
      if (A.m() > 0 && A.n() > 0)
        A.Tvmult(w, v);
      return w;
    }
  } // namespace ZoneCorrectionAlgebra


  ZoneStaticCorrection::ZoneStaticCorrection(
    const Component                              &component,
    const std::vector<std::string>               &parameter_names,
    const std::vector<std::pair<double, double>> &ranges,
    std::shared_ptr<const ReducedComponent>       static_part,
    const std::vector<Vector<double>>            &modes,
    const SparseMatrix<double>                   &gap_operator,
    const std::vector<types::global_dof_index>   &observed,
    const ZoneCorrectionSettings                 &settings,
    TimerOutput                                  *timer)
  {
    const std::string what = "Component " + component.name();
    AssertThrow(!parameter_names.empty() &&
                  ranges.size() == parameter_names.size(),
                ExcMessage(what + ": the Krylov static correction needs its "
                                  "parameters and their ranges."));
    AssertThrow(settings.tolerance > 0 && settings.max_degree >= 1,
                ExcMessage(what + ": the Krylov static correction needs a "
                                  "positive tolerance and at least one "
                                  "level."));
    AssertThrow(static_part != nullptr && static_part->n_modes() == 0 &&
                  static_part->n_added() == 0 &&
                  static_part->n_corrections() > 0,
                ExcMessage(what + ": the Krylov static correction needs the "
                                  "nominal static correction without "
                                  "modes."));
    auto scope = timer_section(timer, "zone static correction (Krylov)");
    data       = std::make_unique<Data>(component, parameter_names);
    Data &d    = *data;
    for (unsigned int p = 0; p < d.model.n_parameters(); ++p)
      AssertThrow(d.model.affects_stiffness(p),
                  ExcMessage(what + ": " + parameter_names[p] +
                             " is not a modulus; the Krylov static "
                             "correction re-analyses moduli only."));
    d.psi      = std::move(static_part);
    d.factor   = d.psi->stiffness_factorisation();
    d.C        = &gap_operator;
    d.observed = observed;
    d.settings = settings;
    d.n        = component.n_dofs();
    d.B        = d.psi->boundary_dofs();
    d.F_B      = d.psi->correction_loads();
    d.n_s      = d.psi->n_corrections();
    for (const auto &entry : gap_operator)
      d.attachment.push_back(entry.column());
    std::sort(d.attachment.begin(), d.attachment.end());
    d.attachment.erase(std::unique(d.attachment.begin(), d.attachment.end()),
                       d.attachment.end());
    const unsigned int n_p = parameter_names.size();
    const unsigned int n_s = d.n_s;

    // The corners of the box.
    for (unsigned long corner = 0; corner < (1ul << n_p); ++corner)
      {
        std::vector<double> values(n_p);
        for (unsigned int p = 0; p < n_p; ++p)
          values[p] = (corner >> p) & 1 ? ranges[p].second : ranges[p].first;
        d.corners.push_back(d.model.relative_changes(values));
        for (const double t : d.corners.back())
          d.t_max = std::max(d.t_max, std::abs(t));
      }

    // The static part: C Psi, O Psi, Psi^T f (the nominal correction's),
    // and the first Krylov block Y_k = K0^{-1} K_k Psi, in chunks of
    // columns, whose rows at B give Psi^T K_k Psi.
    d.CV = d.psi->project_rows(gap_operator);
    d.OV = d.psi->rows(observed);
    {
      const auto f = d.load_vectors();
      d.Vf.resize(f.size());
      for (unsigned int l = 0; l < f.size(); ++l)
        for (const Vector<double> &v : f[l])
          d.Vf[l].push_back(d.psi->project(v));
    }
    d.W0.reinit(gap_operator.m(), gap_operator.m());
    if (n_s > 0)
      d.CV.mTmult(d.W0, d.CV);
    d.check.n_static = n_s;

    // The exact flexibilities at the corners.
    {
      auto check_scope =
        timer_section(timer, "zone static correction check (exact corners)");
      for (const auto &t : d.corners)
        {
          auto [W, g] = d.exact(t);
          d.exact_W.push_back(std::move(W));
          d.exact_g.push_back(std::move(g));
          ProgressLines::stage("exact contact flexibility of " +
                                 component.name() +
                                 " at a corner of the fuzzy box",
                               d.exact_W.size(),
                               d.corners.size());
        }
      d.check.n_corners = d.corners.size();
    }

    // The modes and their HPTP terms, scaled to a unit K0-norm.
    d.A.assign(n_p, FullMatrix<double>(n_s, n_s));
    std::vector<Block> mode_images(n_p);
    if (!modes.empty())
      {
        Block T;
        for (const Vector<double> &v : modes)
          {
            AssertDimension(v.size(), component.n_dofs());
            Vector<double> Kv(v.size());
            d.model.nominal_stiffness().vmult(Kv, v);
            const double e = std::sqrt(std::max(0., v * Kv));
            for (const double x : v)
              T.push_back(x / e);
          }
        d.add_block(std::move(T), modes.size(), 0.);
        d.check.n_modes = d.r;
        mode_images     = d.extend(0);
      }
    const unsigned int                    n_modes_kept = d.r;
    const std::vector<FullMatrix<double>> A_modes      = d.A;

    // Level 1, from l probes Omega (n_s x l) of the static correction:
    // Y = K0^{-1} K_k Psi Omega, whose rows at B give M Omega with
    // M = Psi^T K_k Psi; the static block of A_k is M's Nystrom
    // approximation (M Omega) (Omega^T M Omega)^+ (M Omega)^T, exact once
    // l exceeds M's numerical rank (all of it: Omega = I when l reaches
    // n_s / 2), and the first Krylov block is Y - Psi (M Omega), the part
    // of K0^{-1} K_k Psi Omega K0-orthogonal to Psi. A zone away from the
    // contact gives M a small numerical rank (Saint-Venant): a few probes;
    // a zone under it, all. l doubles while the probes are too few for
    // M's rank, and while the contact flexibility misses the tolerance.
    const double tau = std::sqrt(settings.tolerance) / 10;
    std::mt19937 random(20261127);
    for (unsigned int samples = 32;; samples *= 2)
      {
        const bool                       all = 2 * samples >= n_s;
        const unsigned int               l   = all ? n_s : samples;
        std::normal_distribution<double> normal(0., 1. / std::sqrt(l));
        FullMatrix<double>               Omega(n_s, l);
        for (unsigned int i = 0; i < n_s; ++i)
          for (unsigned int j = 0; j < l; ++j)
            Omega(i, j) = all ? (i == j) : normal(random);
        // The static blocks and the first Krylov candidates.
        Block                           X;
        unsigned int                    b      = 0;
        bool                            enough = true;
        std::vector<FullMatrix<double>> M(n_p);
        for (unsigned int p = 0; p < n_p; ++p)
          {
            Block Y = d.psi_times(Omega);
            sparse_product_in_place(d.model.stiffness_derivative(p), Y, l);
            d.solve(Y, l);
            const FullMatrix<double> MO = d.psi_products(Y, l); // n_s x l
            if (all)
              M[p] = MO;
            else
              {
                // Nystrom: M = (M Omega) (Omega^T M Omega)^+ (M Omega)^T,
                // the pseudo-inverse by eigenpairs above round-off.
                FullMatrix<double> OMO = transpose_product(Omega, MO);
                symmetrise(OMO);
                const auto [values, vectors] = eigen(OMO);
                const double largest = values.empty() ? 0. : values.back();
                std::vector<unsigned int> kept;
                for (unsigned int i = 0; i < l; ++i)
                  if (values[i] > 1e-14 * largest)
                    kept.push_back(i);
                // (too few probes for M's rank: more of them)
                if (kept.size() + 8 > l)
                  enough = false;
                FullMatrix<double> S(l, kept.size());
                for (unsigned int i = 0; i < l; ++i)
                  for (unsigned int j = 0; j < kept.size(); ++j)
                    S(i, j) = vectors(i, kept[j]) / std::sqrt(values[kept[j]]);
                const FullMatrix<double> F = product(MO, S);
                M[p].reinit(n_s, n_s);
                if (F.n() > 0)
                  F.mTmult(M[p], F);
              }
            d.subtract_psi_times(Y, l, MO);
            if (X.empty())
              X = std::move(Y);
            else
              X.insert(X.end(), Y.begin(), Y.end());
            b += l;
            X.insert(X.end(), mode_images[p].begin(), mode_images[p].end());
            b += mode_images[p].size() / d.n;
          }
        ProgressLines::note("Krylov static correction of " + component.name() +
                            ": " + std::to_string(l) +
                            " probes of its static correction, " +
                            std::to_string(d.check.back_substitutions) +
                            " back-substitutions so far");
        if (!enough)
          continue;
        // A_k = [M, Psi^T K_k T; ., T^T K_k T] so far.
        const unsigned int kk = n_s + n_modes_kept;
        for (unsigned int p = 0; p < n_p; ++p)
          {
            d.A[p].reinit(kk, kk);
            for (unsigned int i = 0; i < n_s; ++i)
              for (unsigned int j = 0; j < n_s; ++j)
                d.A[p](i, j) = 0.5 * (M[p](i, j) + M[p](j, i));
            if (n_modes_kept > 0)
              for (unsigned int i = 0; i < kk; ++i)
                for (unsigned int j = n_s; j < kk; ++j)
                  d.A[p](i, j) = d.A[p](j, i) = A_modes[p](i, j);
          }
        // (a probe block's singular values are the block's within a factor
        // 1 -+ sqrt(rank / l))
        const double threshold =
          (all ? 1. : 0.3) * tau / std::max(d.t_max, 1e-3);
        unsigned int first = d.r;
        d.add_block(std::move(X), b, threshold);
        d.check.n_krylov         = d.r - n_modes_kept;
        d.check.degree           = 1;
        std::vector<Block> level = d.extend(first);
        d.measure(timer);
        // (On a large mesh a level takes minutes.)
        const auto say_level = [&](const unsigned int degree) {
          ProgressLines::note(
            "Krylov static correction of " + component.name() + ": level " +
            std::to_string(degree) + " from " + std::to_string(l) +
            " probes, " + std::to_string(d.check.back_substitutions) +
            " back-substitutions so far");
        };
        say_level(1);
        for (unsigned int degree = 2; degree <= settings.max_degree &&
                                      !d.check.tolerance_met && d.r > first;
             ++degree)
          {
            Block        Xn;
            unsigned int bn = 0;
            for (unsigned int p = 0; p < n_p; ++p)
              {
                Xn.insert(Xn.end(), level[p].begin(), level[p].end());
                bn += level[p].size() / d.n;
              }
            first = d.r;
            d.add_block(std::move(Xn),
                        bn,
                        tau / std::pow(std::max(d.t_max, 1e-3), degree));
            if (d.r == first)
              break;
            d.check.n_krylov = d.r - n_modes_kept;
            d.check.degree   = degree;
            level            = d.extend(first);
            d.measure(timer);
            say_level(degree);
          }
        d.check.probes = l;
        if (d.check.tolerance_met || all)
          break;
        // More probes: the Krylov vectors start again.
        d.Z.resize(std::size_t(d.n) * n_modes_kept);
        d.r  = n_modes_kept;
        d.CV = columns(d.CV, 0, kk);
        d.OV = columns(d.OV, 0, kk);
        for (auto &f : d.Vf)
          for (Vector<double> &v : f)
            {
              Vector<double> w(kk);
              for (unsigned int i = 0; i < kk; ++i)
                w[i] = v[i];
              v = w;
            }
      }
    LapackErrors::check(what + ": the Krylov static correction");
  }


  ZoneStaticCorrection::~ZoneStaticCorrection() = default;


  unsigned int
  ZoneStaticCorrection::size() const
  {
    return data->k();
  }


  const ZoneCorrectionCheck &
  ZoneStaticCorrection::check() const
  {
    return data->check;
  }


  const ParameterModel &
  ZoneStaticCorrection::model() const
  {
    return data->model;
  }


  std::string
  ZoneStaticCorrection::describe() const
  {
    const ZoneCorrectionCheck &c = data->check;
    std::ostringstream         out;
    out << "static correction re-analysed by Krylov vectors (" << c.degree
        << " level(s): " << c.n_static << " static";
    if (c.n_modes > 0)
      out << " + " << c.n_modes << " modes and HPTP terms";
    out << " + " << c.n_krylov << " Krylov";
    if (c.n_snapshots > 0)
      out << " + " << c.n_snapshots << " snapshot";
    out << " vectors, " << c.n_active << " of them changing with the "
        << "parameters; " << c.probes << " probes of the static correction, "
        << c.back_substitutions << " back-substitutions; contact flexibility "
        << std::scientific << std::setprecision(1) << c.flexibility_error;
    if (c.load_error > 0)
      out << ", load gaps " << c.load_error;
    out << " off the exact at the " << c.n_corners
        << " corners of the support box, tolerance " << data->settings.tolerance
        << (c.tolerance_met ? "" : ": NOT MET") << ")";
    return out.str();
  }
} // namespace FuzzyContact
