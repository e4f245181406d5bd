#include <fuzzycontact/base/lapack_errors.h>
#include <fuzzycontact/base/lapack_extras.h>
#include <fuzzycontact/base/timer_section.h>
#include <fuzzycontact/reduction/zone_static_correction.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <random>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    // Blocks of full-length vectors are stored column-major (column j from
    // data[j * n]), as BLAS and CHOLMOD's multi-column solve read them.
    // FullMatrix is row-major: its data is the column-major transpose.
    using Block = std::vector<double>;

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

    // M X for a sparse M and a column-major block X with b columns.
    Block
    sparse_product(const SparseMatrix<double> &M,
                   const Block                &X,
                   const unsigned int          b)
    {
      const unsigned int n = M.n();
      Block              Y(std::size_t(n) * b);
      Vector<double>     x(n), y(n);
      for (unsigned int j = 0; j < b; ++j)
        {
          std::copy(X.begin() + std::size_t(j) * n,
                    X.begin() + std::size_t(j + 1) * n,
                    x.begin());
          M.vmult(y, x);
          std::copy(y.begin(), y.end(), Y.begin() + std::size_t(j) * n);
        }
      return Y;
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
  } // namespace


  struct ZoneStaticCorrection::Data
  {
    Data(const Component &component, const std::vector<std::string> &names)
        : component(component)
        , model(component, names)
    {
    }

    const Component                        &component;
    ParameterModel                          model;
    std::shared_ptr<const ReducedComponent> psi;
    std::shared_ptr<const SparseCholesky>   factor;
    const SparseMatrix<double>             *C = nullptr;
    std::vector<types::global_dof_index>    observed, attachment, B;
    ZoneCorrectionSettings                  settings;
    types::blas_int                         n   = 0;
    unsigned int                            n_s = 0;
    // Psi = K0^{-1} F, F zero outside B, F_B (|B| x n_s).
    FullMatrix<double> F_B;

    // The explicit vectors Z (column-major n x r), K0-orthonormal and
    // K0-orthogonal to Psi.
    Block        Z;
    unsigned int r = 0;
    // V^T K_k V per parameter (k = n_s + r), C V, O V and V^T f (per load;
    // per zone for a prescribed displacement).
    std::vector<FullMatrix<double>>          A;
    FullMatrix<double>                       CV, OV;
    std::vector<std::vector<Vector<double>>> Vf;
    mutable std::vector<bool>                per_zone;
    // C Psi Psi^T C^T: the contact flexibility at the nominal point (C Z
    // vanishes), formed once.
    FullMatrix<double> W0;

    // The split (see the header): Q = [Q_a, Q_c] orthogonal (k x k, Q_a
    // its first n_active columns, diagonalising the one parameter's
    // projection), the active projections, and the blocks of both parts.
    unsigned int                             n_active = 0;
    FullMatrix<double>                       Q;
    std::vector<FullMatrix<double>>          A_active;
    std::vector<double>                      lambda;
    bool                                     diagonal = false;
    FullMatrix<double>                       H_a, O_a, H_c, O_c;
    std::vector<std::vector<Vector<double>>> f_a, f_c;

    // The corners of the box (relative changes), the largest |t|, and
    // their exact contact flexibilities and load gaps (made once).
    std::vector<std::vector<double>>         corners;
    double                                   t_max = 0;
    std::vector<FullMatrix<double>>          exact_W;
    std::vector<std::vector<Vector<double>>> exact_g;

    ZoneCorrectionCheck check;

    unsigned int
    k() const
    {
      return n_s + r;
    }

    // The loads' vectors at their reference forces: the load of each
    // component load l, one per zone for a prescribed displacement.
    std::vector<std::vector<Vector<double>>>
    load_vectors() const;

    // sum_z a_z f[z], a_z the zone modulus for a prescribed displacement
    // (load l), else 1.
    Vector<double>
    combine(const unsigned int                 l,
            const std::vector<Vector<double>> &f,
            const std::vector<double>         &moduli,
            const unsigned int                 size) const
    {
      Vector<double> v(size);
      for (unsigned int z = 0; z < f.size(); ++z)
        v.add(per_zone[l] ? moduli[z] : 1., f[z]);
      return v;
    }

    // X := K0^{-1} X (b columns), counted.
    void
    solve(Block &X, const unsigned int b)
    {
      factor->solve(X.data(), b);
      check.back_substitutions += b;
    }

    // Psi c for a row-major c (n_s x b): one back-substitution a column.
    Block
    psi_times(const FullMatrix<double> &c)
    {
      const unsigned int b = c.n();
      Block              X(std::size_t(n) * b, 0.);
      if (b == 0)
        return X;
      const FullMatrix<double> Fc = product(F_B, c); // |B| x b
      for (unsigned int j = 0; j < b; ++j)
        for (unsigned int i = 0; i < B.size(); ++i)
          X[std::size_t(j) * n + B[i]] = Fc(i, j);
      solve(X, b);
      return X;
    }

    // Psi^T K0 X = F_B^T X_B (no back-substitution): n_s x b.
    FullMatrix<double>
    psi_products(const Block &X, const unsigned int b) const
    {
      FullMatrix<double> XB(B.size(), b);
      for (unsigned int j = 0; j < b; ++j)
        for (unsigned int i = 0; i < B.size(); ++i)
          XB(i, j) = X[std::size_t(j) * n + B[i]];
      return transpose_product(F_B, XB);
    }

    // The candidates X (b columns) made K0-orthogonal to Psi and Z (twice)
    // and compressed: the directions of what is left whose K0-norm is at
    // least @p threshold are appended to Z (K0-orthonormal), and returned.
    Block
    add_block(Block X, const unsigned int b, const double threshold);

    // The projections of the new columns [first, r) of Z: V^T K_k z (with
    // Y_k = K0^{-1} K_k Z_new, returned: the next level's candidates), C z,
    // O z, z^T f.
    std::vector<Block>
    extend(const unsigned int first);

    // The split into active and inert parts, and their blocks.
    void
    split();

    // The reduced contact flexibility at t (the split's form), and its
    // relative errors against @p W and @p g (exact there).
    std::pair<double, double>
    errors(const std::vector<double>         &t,
           const FullMatrix<double>          &W,
           const std::vector<Vector<double>> &g) const;

    // The largest errors over the corners, into check.
    void
    measure(TimerOutput *timer);

    // The exact contact flexibility and load gaps at t (a factorisation).
    std::pair<FullMatrix<double>, std::vector<Vector<double>>>
    exact(const std::vector<double> &t) const;
  };


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


  Block
  ZoneStaticCorrection::Data::add_block(Block              X,
                                        const unsigned int b,
                                        const double       threshold)
  {
    const SparseMatrix<double> &K0 = model.nominal_stiffness();
    if (b == 0)
      return {};
    for (unsigned int pass = 0; pass < 2; ++pass)
      {
        // Psi: X -= Psi (Psi^T K0 X), one back-substitution a column.
        const FullMatrix<double> c = psi_products(X, b);
        const Block              P = psi_times(c);
        for (std::size_t i = 0; i < X.size(); ++i)
          X[i] -= P[i];
        // Z: X -= Z (Z^T K0 X).
        if (r > 0)
          {
            const Block              KX = sparse_product(K0, X, b);
            const FullMatrix<double> G =
              transpose_product(Z.data(), r, KX.data(), b, n);
            add_product(X.data(), b, -1., Z.data(), r, G, n);
          }
      }
    // What is left: its Gram matrix and its principal directions.
    Block              KX = sparse_product(K0, X, b);
    FullMatrix<double> G  = transpose_product(X.data(), b, KX.data(), b, n);
    KX.clear();
    for (unsigned int i = 0; i < b; ++i)
      for (unsigned int j = 0; j < i; ++j)
        G(i, j) = G(j, i) = 0.5 * (G(i, j) + G(j, i));
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
    X.clear();
    // Once more within itself, so that N^T K0 N = I to round-off: N := N
    // L^{-T} with N^T K0 N = L L^T.
    {
      const Block        KN = sparse_product(K0, N, n_new);
      FullMatrix<double> G2 =
        transpose_product(N.data(), n_new, KN.data(), n_new, n);
      for (unsigned int i = 0; i < n_new; ++i)
        for (unsigned int j = 0; j < i; ++j)
          G2(i, j) = G2(j, i) = 0.5 * (G2(i, j) + G2(j, i));
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
        for (unsigned int i = 0; i < n_active; ++i)
          for (unsigned int j = 0; j < i; ++j)
            A_active[0](i, j) = A_active[0](j, i) =
              0.5 * (A_active[0](i, j) + A_active[0](j, i));
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
            Y       = sparse_product(d.model.stiffness_derivative(p), Y, l);
            d.solve(Y, l);
            const FullMatrix<double> MO = d.psi_products(Y, l); // n_s x l
            if (all)
              M[p] = MO;
            else
              {
                // Nystrom: M = (M Omega) (Omega^T M Omega)^+ (M Omega)^T,
                // the pseudo-inverse by eigenpairs above round-off.
                FullMatrix<double> OMO = transpose_product(Omega, MO);
                for (unsigned int i = 0; i < l; ++i)
                  for (unsigned int j = 0; j < i; ++j)
                    OMO(i, j) = OMO(j, i) = 0.5 * (OMO(i, j) + OMO(j, i));
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
            const Block P = d.psi_times(MO);
            for (std::size_t i = 0; i < Y.size(); ++i)
              Y[i] -= P[i];
            X.insert(X.end(), Y.begin(), Y.end());
            b += l;
            X.insert(X.end(), mode_images[p].begin(), mode_images[p].end());
            b += mode_images[p].size() / d.n;
          }
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


  std::pair<double, double>
  ZoneStaticCorrection::error_at(const std::vector<double> &values) const
  {
    const std::vector<double> t = data->model.relative_changes(values);
    const auto [W, g]           = data->exact(t);
    return data->errors(t, W, g);
  }
} // namespace FuzzyContact
