// The basis of ZoneStaticCorrection (zone_static_correction.h): blocks of
// candidates made K0-orthogonal to it, compressed and appended, their
// projections, and snapshots (add_vectors()).

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include "zone_static_correction_data.h"
#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  namespace
  {
    // A^T B for column-major blocks A (n x a) and B (n x b), row-major.
    FullMatrix<double>
    transpose_product(const double         *A,
                      const unsigned int    a,
                      const double         *B,
                      const unsigned int    b,
                      const types::blas_int n)
    {
      FullMatrix<double> result(a, b);
      if (a == 0 || b == 0 || n == 0)
        return result;
      // The row-major a x b result is the column-major b x a B^T A.
      const types::blas_int ai = a, bi = b;
      const double          one = 1, zero = 0;
      gemm("T",
           "N",
           &bi,
           &ai,
           &n,
           &one,
           B,
           &n,
           A,
           &n,
           &zero,
           &result(0, 0),
           &bi);
      return result;
    }

    // D += alpha A X for column-major A (n x a), D (n x b) and a row-major
    // X (a x b).
    void
    add_product(double                   *D,
                const unsigned int        b,
                const double              alpha,
                const double             *A,
                const unsigned int        a,
                const FullMatrix<double> &X,
                const types::blas_int     n)
    {
      if (a == 0 || b == 0 || n == 0)
        return;
      AssertDimension(X.m(), a);
      AssertDimension(X.n(), b);
      // X's row-major data is the column-major X^T (b x a, leading b).
      const types::blas_int ai = a, bi = b;
      const double          one = 1;
      gemm("N", "T", &n, &bi, &ai, &alpha, A, &n, &X(0, 0), &bi, &one, D, &n);
    }
  } // namespace


  std::vector<std::vector<Vector<double>>>
  ZoneStaticCorrection::Data::load_vectors() const
  {
    std::vector<std::vector<Vector<double>>> f;
    const auto  &loads = component.description().loads;
    unsigned int s     = 0;
    per_zone.assign(loads.size(), false);
    for (unsigned int l = 0; l < loads.size(); ++l)
      {
        f.emplace_back();
        if (loads[l].is_weight)
          continue;
        if (loads[l].is_displacement)
          {
            per_zone[l] = true;
            for (const Vector<double> &d :
                 component.displacement_zone_loads()[s])
              {
                Vector<double> v = d;
                v *= component.reference_load_force(l);
                f.back().push_back(std::move(v));
              }
            ++s;
            continue;
          }
        f.back().push_back(component.reference_load_vector(l));
      }
    return f;
  }


  FullMatrix<double>
  ZoneStaticCorrection::Data::energy_products(const double      *A,
                                              const unsigned int a,
                                              const Block       &X,
                                              const unsigned int b) const
  {
    const SparseMatrix<double> &K0 = model.nominal_stiffness();
    FullMatrix<double>          G(a, b);
    for (unsigned int first = 0; first < b; first += chunk_columns)
      {
        const unsigned int m = std::min(chunk_columns, b - first);
        Block              KX(X.begin() + std::size_t(first) * n,
                 X.begin() + std::size_t(first + m) * n);
        sparse_product_in_place(K0, KX, m);
        const FullMatrix<double> Gc = transpose_product(A, a, KX.data(), m, n);
        for (unsigned int i = 0; i < a; ++i)
          for (unsigned int j = 0; j < m; ++j)
            G(i, first + j) = Gc(i, j);
      }
    return G;
  }


  Block
  ZoneStaticCorrection::Data::add_block(Block              X,
                                        const unsigned int b,
                                        const double       threshold)
  {
    if (b == 0)
      return {};
    // (Products with K0 and Psi are made a chunk of columns at a time:
    // X is the only block of all the candidates held.)
    for (unsigned int pass = 0; pass < 2; ++pass)
      {
        // Psi: X -= Psi (Psi^T K0 X), one back-substitution a column.
        subtract_psi_times(X, b, psi_products(X, b));
        // Z: X -= Z (Z^T K0 X).
        if (r > 0)
          {
            const FullMatrix<double> G = energy_products(Z.data(), r, X, b);
            add_product(X.data(), b, -1., Z.data(), r, G, n);
          }
      }
    // What is left: its Gram matrix and its principal directions.
    FullMatrix<double> G = energy_products(X.data(), b, X, b);
    symmetrise(G);
    const auto [values, vectors]      = eigen(G);
    const double              largest = values.empty() ? 0. : values.back();
    std::vector<unsigned int> kept;
    for (unsigned int i = 0; i < b; ++i)
      // (never directions at the round-off of the largest)
      if (values[i] > 0 && std::sqrt(values[i]) >= threshold &&
          values[i] > 1e-13 * largest)
        kept.push_back(i);
    const unsigned int n_new = kept.size();
    if (n_new == 0)
      return {};
    FullMatrix<double> S(b, n_new);
    for (unsigned int i = 0; i < b; ++i)
      for (unsigned int j = 0; j < n_new; ++j)
        S(i, j) = vectors(i, kept[j]) / std::sqrt(values[kept[j]]);
    Block N(std::size_t(n) * n_new, 0.);
    add_product(N.data(), n_new, 1., X.data(), b, S, n);
    Block().swap(X);
    // Once more within itself, so that N^T K0 N = I to round-off: N := N
    // L^{-T} with N^T K0 N = L L^T.
    {
      FullMatrix<double> G2 = energy_products(N.data(), n_new, N, n_new);
      symmetrise(G2);
      const FullMatrix<double> L = cholesky(G2, "Krylov static correction");
      FullMatrix<double>       Zt(n_new, n_new); // column-major L^{-T}
      for (unsigned int i = 0; i < n_new; ++i)
        Zt(i, i) = 1;
      const types::blas_int ri   = n_new;
      types::blas_int       info = 0;
      trtrs("L", "T", "N", &ri, &ri, &L(0, 0), &ri, &Zt(0, 0), &ri, &info);
      AssertThrow(info == 0, ExcInternalError());
      FullMatrix<double> LinvT(n_new, n_new);
      LinvT.copy_transposed(Zt);
      Block M(std::size_t(n) * n_new, 0.);
      add_product(M.data(), n_new, 1., N.data(), n_new, LinvT, n);
      N.swap(M);
    }
    Z.insert(Z.end(), N.begin(), N.end());
    r += n_new;
    return N;
  }


  std::vector<Block>
  ZoneStaticCorrection::Data::extend(const unsigned int first)
  {
    const unsigned int n_new = r - first;
    const unsigned int kk    = k();
    const double      *New   = Z.data() + std::size_t(first) * n;
    const Block        N(New, New + std::size_t(n) * n_new);
    std::vector<Block> next;
    for (unsigned int p = 0; p < model.n_parameters(); ++p)
      {
        // V^T K_k N: Psi^T K_k N = Psi^T K0 (K0^{-1} K_k N) and Z^T K_k N.
        Block KN = sparse_product(model.stiffness_derivative(p), N, n_new);
        const FullMatrix<double> ZKN =
          transpose_product(Z.data(), r, KN.data(), n_new, n);
        solve(KN, n_new); // now K0^{-1} K_k N
        const FullMatrix<double> PKN = psi_products(KN, n_new);
        FullMatrix<double>       old = A[p];
        A[p].reinit(kk, kk);
        for (unsigned int i = 0; i < old.m(); ++i)
          for (unsigned int j = 0; j < old.n(); ++j)
            A[p](i, j) = old(i, j);
        for (unsigned int j = 0; j < n_new; ++j)
          {
            for (unsigned int i = 0; i < n_s; ++i)
              A[p](i, n_s + first + j) = A[p](n_s + first + j, i) = PKN(i, j);
            for (unsigned int i = 0; i < r; ++i)
              A[p](n_s + i, n_s + first + j) = A[p](n_s + first + j, n_s + i) =
                ZKN(i, j);
          }
        for (unsigned int i = n_s + first; i < kk; ++i)
          for (unsigned int j = n_s + first; j < i; ++j)
            A[p](i, j) = A[p](j, i) = 0.5 * (A[p](i, j) + A[p](j, i));
        next.push_back(std::move(KN));
      }
    // C z, O z and z^T f.
    const auto widen = [&](FullMatrix<double> &X, const unsigned int rows) {
      FullMatrix<double> old = X;
      X.reinit(rows, kk);
      for (unsigned int i = 0; i < rows; ++i)
        for (unsigned int j = 0; j < old.n(); ++j)
          X(i, j) = old(i, j);
    };
    widen(CV, C->m());
    widen(OV, observed.size());
    Vector<double> z(n), g(C->m());
    for (unsigned int j = 0; j < n_new; ++j)
      {
        std::copy(New + std::size_t(j) * n,
                  New + std::size_t(j + 1) * n,
                  z.begin());
        C->vmult(g, z);
        for (unsigned int i = 0; i < g.size(); ++i)
          CV(i, n_s + first + j) = g[i];
        for (unsigned int i = 0; i < observed.size(); ++i)
          OV(i, n_s + first + j) = z[observed[i]];
      }
    const auto f = load_vectors();
    for (unsigned int l = 0; l < f.size(); ++l)
      for (unsigned int zz = 0; zz < f[l].size(); ++zz)
        {
          Vector<double> v(kk);
          for (unsigned int j = 0; j < n_s + first; ++j)
            v[j] = Vf[l][zz][j];
          for (unsigned int j = 0; j < n_new; ++j)
            {
              double        s = 0;
              const double *x = New + std::size_t(j) * n;
              for (types::blas_int i = 0; i < n; ++i)
                s += x[i] * f[l][zz][i];
              v[n_s + first + j] = s;
            }
          Vf[l][zz] = std::move(v);
        }
    return next;
  }

  unsigned int
  ZoneStaticCorrection::add_vectors(const std::vector<Vector<double>> &u)
  {
    Data          &d = *data;
    Block          X;
    unsigned int   b  = 0;
    const auto    &K0 = d.model.nominal_stiffness();
    Vector<double> Ku(d.n);
    for (const Vector<double> &v : u)
      {
        AssertDimension(v.size(), static_cast<std::size_t>(d.n));
        K0.vmult(Ku, v);
        const double e = v * Ku;
        if (!(e > 0) || !std::isfinite(e))
          continue;
        for (const double x : v)
          X.push_back(x / std::sqrt(e));
        ++b;
      }
    const unsigned int first = d.r;
    d.add_block(std::move(X), b, 1e-10);
    const unsigned int added = d.r - first;
    if (added > 0)
      {
        d.check.n_snapshots += added;
        d.extend(first);
        d.measure(nullptr);
      }
    return added;
  }
} // namespace FuzzyContact
