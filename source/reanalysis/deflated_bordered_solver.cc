#include <fuzzycontact/reanalysis/deflated_bordered_solver.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  std::string
  to_string(const DerivativeSolver method)
  {
    return method == DerivativeSolver::deflated_cg ? "deflated cg" : "direct";
  }


  namespace
  {
    // C = alpha op(A) B + beta C, column-major, op(A) = A or A^T.
    void
    multiply(const bool         transpose_A,
             const unsigned int rows,
             const unsigned int columns,
             const unsigned int inner,
             const double       alpha,
             const double      *A,
             const unsigned int lda,
             const double      *B,
             const unsigned int ldb,
             const double       beta,
             double            *C,
             const unsigned int ldc)
    {
      if (rows == 0 || columns == 0)
        return;
      const types::blas_int m = rows, n = columns, k = inner, la = lda,
                            lb = ldb, lc = ldc;
      gemm(transpose_A ? "T" : "N",
           "N",
           &m,
           &n,
           &k,
           &alpha,
           A,
           &la,
           B,
           &lb,
           &beta,
           C,
           &lc);
    }

    double
    dot(const double *a, const double *b, const unsigned int n)
    {
      double s = 0;
      for (unsigned int i = 0; i < n; ++i)
        s += a[i] * b[i];
      return s;
    }
  } // namespace


  // The working data of one system (see the header for the names); its
  // vectors are column `slot` of the blocks of solve().
  struct DeflatedBorderedSolver::Shifted
  {
    BorderedSystem           *system = nullptr;
    double                    shift  = 0;
    std::vector<unsigned int> C, F;
    FullMatrix<double>        H, H_FF_inverse; // H = V^T A V (k x k)
    std::vector<double>       a_C, g_F;
    double                    rho = 0, rho0 = 0;
    unsigned int              slot     = 0;
    bool                      finished = false;
  };


  DeflatedBorderedSolver::DeflatedBorderedSolver(
    const ParameterModel                 &model,
    const ModalBasis                     &nominal,
    std::shared_ptr<const SparseCholesky> stiffness_factorisation,
    const DeflatedSolverSettings         &settings)
      : model(model)
      , nominal(nominal)
      , factorisation(std::move(stiffness_factorisation))
      , settings(settings)
      , n(model.nominal_stiffness().m())
      , k(nominal.size())
  {
    const SparseMatrix<double> &K0 = model.nominal_stiffness();
    const SparseMatrix<double> &M0 = model.nominal_mass();
    AssertThrow(k >= 1 && nominal.modes[0].size() == n,
                ExcMessage("modal reanalysis: the nominal modes do not belong "
                           "to the parameter model (internal)."));
    if (factorisation == nullptr)
      {
        auto F = std::make_shared<SparseCholesky>();
        F->factorize(K0,
                     {},
                     "Component " + model.component().name() +
                       ": the nominal stiffness matrix");
        factorisation = std::move(F);
      }
    AssertThrow(factorisation->n() == n,
                ExcMessage("modal reanalysis: the stiffness factorisation "
                           "does not belong to the parameter model "
                           "(internal)."));

    // K0 and M0 share the component's pattern.
    row_start.assign(1, 0);
    for (unsigned int i = 0; i < n; ++i)
      {
        auto kk = K0.begin(i);
        auto mm = M0.begin(i);
        for (; kk != K0.end(i); ++kk, ++mm)
          {
            Assert(mm->column() == kk->column(), ExcInternalError());
            column.push_back(kk->column());
            K_value.push_back(kk->value());
            M_value.push_back(mm->value());
          }
        row_start.push_back(column.size());
      }

    V.resize(n * k);
    MV.resize(n * k);
    std::vector<double> KV(n * k);
    for (unsigned int j = 0; j < k; ++j)
      std::copy(nominal.modes[j].begin(),
                nominal.modes[j].end(),
                V.begin() + j * n);
    for (unsigned int i = 0; i < n; ++i)
      for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
        for (unsigned int j = 0; j < k; ++j)
          {
            KV[j * n + i] += K_value[e] * V[j * n + column[e]];
            MV[j * n + i] += M_value[e] * V[j * n + column[e]];
          }
    VKV.reinit(k, k);
    VMV.reinit(k, k);
    double deviation = 0;
    for (unsigned int i = 0; i < k; ++i)
      for (unsigned int j = 0; j < k; ++j)
        {
          VKV(i, j) = dot(&V[i * n], &KV[j * n], n);
          VMV(i, j) = dot(&V[i * n], &MV[j * n], n);
          deviation = std::max(deviation, std::abs(VMV(i, j) - (i == j)));
        }
    // The projector P = I - V V^T M0 needs M0-orthonormal modes.
    orthonormal = deviation <= 1e-8;
    // U = P^T K0 V = K0 V - M0 V (V^T K0 V): the eigen-residuals of the
    // computed pairs, seen from the complement.
    U = KV;
    for (unsigned int j = 0; j < k; ++j)
      for (unsigned int i = 0; i < k; ++i)
        for (unsigned int r = 0; r < n; ++r)
          U[j * n + r] -= VKV(i, j) * MV[i * n + r];
  }


  const SparseCholesky &
  DeflatedBorderedSolver::stiffness_factorisation() const
  {
    return *factorisation;
  }


  DeflatedBorderedSolver::Statistics
  DeflatedBorderedSolver::statistics() const
  {
    return statistics_;
  }


  void
  DeflatedBorderedSolver::apply_shifted(const std::vector<double> &shifts,
                                        const double              *P,
                                        double                    *Q,
                                        const unsigned int n_columns) const
  {
    // Row by row, all the columns: each row of K0 and M0 is read once.
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int s = 0; s < n_columns; ++s)
        {
          const double *p   = P + std::size_t(s) * n;
          double        sum = 0;
          for (std::size_t e = row_start[i]; e < row_start[i + 1]; ++e)
            sum += (K_value[e] - shifts[s] * M_value[e]) * p[column[e]];
          Q[std::size_t(s) * n + i] = sum;
        }
  }


  void
  DeflatedBorderedSolver::project(const std::vector<double> &A,
                                  const std::vector<double> &B,
                                  double                    *Y,
                                  const unsigned int         n_columns,
                                  std::vector<double>       &T) const
  {
    T.assign(std::size_t(k) * n_columns, 0.);
    multiply(true, k, n_columns, n, 1., B.data(), n, Y, n, 0., T.data(), k);
    multiply(false, n, n_columns, k, -1., A.data(), n, T.data(), k, 1., Y, n);
  }


  void
  DeflatedBorderedSolver::solve(std::vector<BorderedSystem> &systems) const
  {
    const unsigned int S = systems.size();
    if (S == 0)
      return;
    // The vectors of the systems, one column each; the running systems
    // occupy the first n_running columns (slots).
    std::vector<double> Z(std::size_t(n) * S), R(Z.size()), Y(Z.size()),
      P(Z.size()), Q(Z.size()), T;
    const auto col = [&](std::vector<double> &block, const unsigned int slot) {
      return block.data() + std::size_t(slot) * n;
    };
    std::vector<Shifted>      work(S);
    std::vector<unsigned int> at_slot(S);
    std::vector<double>       shifts(S);
    unsigned int              n_running = 0;

    for (unsigned int s = 0; s < S; ++s)
      {
        BorderedSystem &b = systems[s];
        Shifted        &w = work[s];
        w.system          = &b;
        b.solved          = false;
        b.iterations      = 0;
        AssertThrow(b.j < b.cluster.size() && b.c.size() == b.cluster.size() &&
                      b.r.size() == n,
                    ExcMessage("bordered system of the wrong size (internal)"));
        w.C     = b.cluster;
        w.shift = nominal.eigenvalues[b.cluster[b.j]];
        for (unsigned int i = 0; i < k; ++i)
          if (std::find(w.C.begin(), w.C.end(), i) == w.C.end())
            w.F.push_back(i);
        w.H.reinit(k, k);
        for (unsigned int i = 0; i < k; ++i)
          for (unsigned int l = 0; l < k; ++l)
            w.H(i, l) = VKV(i, l) - w.shift * VMV(i, l);
        const unsigned int n_F = w.F.size();
        w.H_FF_inverse.reinit(n_F, n_F);
        for (unsigned int i = 0; i < n_F; ++i)
          for (unsigned int l = 0; l < n_F; ++l)
            w.H_FF_inverse(i, l) = w.H(w.F[i], w.F[l]);
        bool usable = orthonormal;
        if (usable && n_F > 0)
          {
            w.H_FF_inverse.gauss_jordan();
            for (unsigned int i = 0; i < n_F; ++i)
              for (unsigned int l = 0; l < n_F; ++l)
                usable = usable && std::isfinite(w.H_FF_inverse(i, l));
          }
        if (!usable)
          continue; // left to the direct path

        // a_C = -c; w = r - A V_C a_C with A V_c = U_c + M0 V (V^T K0
        // V_c) - l M0 V_c; g_F = V_F^T w; and the right-hand side on the
        // complement, P^T w - U_F H_FF^-1 g_F.
        w.slot          = n_running;
        at_slot[w.slot] = s;
        shifts[w.slot]  = w.shift;
        double *rhs     = col(R, w.slot);
        std::copy(b.r.begin(), b.r.end(), rhs);
        w.a_C.resize(w.C.size());
        std::vector<double> coefficients(k, 0.);
        for (unsigned int i = 0; i < w.C.size(); ++i)
          {
            const unsigned int c = w.C[i];
            w.a_C[i]             = -b.c[i];
            for (unsigned int r = 0; r < n; ++r)
              rhs[r] -= w.a_C[i] * U[std::size_t(c) * n + r];
            for (unsigned int l = 0; l < k; ++l)
              coefficients[l] += w.a_C[i] * (VKV(l, c) - w.shift * (l == c));
          }
        multiply(false,
                 n,
                 1,
                 k,
                 -1.,
                 MV.data(),
                 n,
                 coefficients.data(),
                 k,
                 1.,
                 rhs,
                 n);
        project(MV, V, rhs, 1, T);
        w.g_F.resize(n_F);
        std::vector<double> h(k, 0.);
        for (unsigned int i = 0; i < n_F; ++i)
          w.g_F[i] = T[w.F[i]];
        for (unsigned int i = 0; i < n_F; ++i)
          for (unsigned int l = 0; l < n_F; ++l)
            h[w.F[i]] += w.H_FF_inverse(i, l) * w.g_F[l];
        multiply(false, n, 1, k, -1., U.data(), n, h.data(), k, 1., rhs, n);
        ++n_running;
      }
    std::vector<Shifted *> running;
    for (unsigned int slot = 0; slot < n_running; ++slot)
      running.push_back(&work[at_slot[slot]]);

    // Drops the finished systems from the blocks (a solved one keeps its z
    // in its x), moving the running ones' columns to the front.
    const auto remove_finished = [&]() {
      unsigned int next = 0;
      for (unsigned int slot = 0; slot < running.size(); ++slot)
        {
          Shifted *w = running[slot];
          if (w->finished)
            {
              if (w->system->solved)
                {
                  w->system->x.reinit(n);
                  std::copy(col(Z, slot),
                            col(Z, slot) + n,
                            w->system->x.begin());
                }
              continue;
            }
          if (next != slot)
            for (std::vector<double> *block : {&Z, &R, &Y, &P})
              std::copy(col(*block, slot),
                        col(*block, slot) + n,
                        col(*block, next));
          running[next] = w;
          w->slot       = next;
          shifts[next]  = w->shift;
          ++next;
        }
      running.resize(next);
    };

    // Y = P K0^-1 R for the m running systems: one multi-column solve.
    const auto precondition = [&](const unsigned int m) {
      std::copy(R.begin(), R.begin() + std::size_t(m) * n, Y.begin());
      factorisation->solve(Y.data(), m);
      project(V, MV, Y.data(), m, T);
    };

    precondition(running.size());
    for (unsigned int slot = 0; slot < running.size(); ++slot)
      {
        Shifted *w = running[slot];
        w->rho = w->rho0 = dot(col(R, slot), col(Y, slot), n);
        std::copy(col(Y, slot), col(Y, slot) + n, col(P, slot));
        if (!(w->rho0 > 0)) // a zero right-hand side: z = 0
          {
            w->finished       = true;
            w->system->solved = (w->rho0 == 0);
          }
      }
    remove_finished();

    std::vector<double> G;
    for (unsigned int step = 1;
         step <= settings.max_iterations && !running.empty();
         ++step)
      {
        // Q = S P = P^T A P - U_F H_FF^-1 U_F^T P, with U^T p = V^T A p for
        // p in the complement.
        const unsigned int m = running.size();
        apply_shifted(shifts, P.data(), Q.data(), m);
        project(MV, V, Q.data(), m, T);
        G.assign(std::size_t(k) * m, 0.);
        for (unsigned int slot = 0; slot < m; ++slot)
          {
            const Shifted     &w   = *running[slot];
            const unsigned int n_F = w.F.size();
            for (unsigned int i = 0; i < n_F; ++i)
              for (unsigned int l = 0; l < n_F; ++l)
                G[slot * k + w.F[i]] +=
                  w.H_FF_inverse(i, l) * T[slot * k + w.F[l]];
          }
        multiply(false,
                 n,
                 m,
                 k,
                 -1.,
                 U.data(),
                 n,
                 G.data(),
                 k,
                 1.,
                 Q.data(),
                 n);
        for (unsigned int slot = 0; slot < m; ++slot)
          {
            Shifted     *w  = running[slot];
            const double pq = dot(col(P, slot), col(Q, slot), n);
            ++w->system->iterations;
            if (!(pq > 0) || !std::isfinite(pq))
              {
                w->finished = true; // not positive definite here
                continue;
              }
            const double  alpha = w->rho / pq;
            double       *z = col(Z, slot), *r = col(R, slot);
            const double *p = col(P, slot), *q = col(Q, slot);
            for (unsigned int i = 0; i < n; ++i)
              {
                z[i] += alpha * p[i];
                r[i] -= alpha * q[i];
              }
          }
        remove_finished();
        if (running.empty())
          break;
        precondition(running.size());
        for (unsigned int slot = 0; slot < running.size(); ++slot)
          {
            Shifted     *w   = running[slot];
            const double rho = dot(col(R, slot), col(Y, slot), n);
            if (std::sqrt(std::max(rho, 0.) / w->rho0) <= settings.tolerance)
              {
                w->finished       = true;
                w->system->solved = true;
                continue;
              }
            const double  beta = rho / w->rho;
            double       *p    = col(P, slot);
            const double *y    = col(Y, slot);
            for (unsigned int i = 0; i < n; ++i)
              p[i] = y[i] + beta * p[i];
            w->rho = rho;
          }
        remove_finished();
      }

    for (Shifted &w : work)
      {
        BorderedSystem &b = *w.system;
        statistics_.iterations += b.iterations;
        ++statistics_.systems;
        if (!b.solved)
          {
            ++statistics_.not_solved;
            continue;
          }
        // x holds z. a_F = H_FF^-1 (g_F - U_F^T z), x = z + V a, and mu.
        const unsigned int  n_F = w.F.size();
        std::vector<double> a(k, 0.), Uz(k, 0.);
        multiply(true,
                 k,
                 1,
                 n,
                 1.,
                 U.data(),
                 n,
                 b.x.begin(),
                 n,
                 0.,
                 Uz.data(),
                 k);
        for (unsigned int i = 0; i < w.C.size(); ++i)
          a[w.C[i]] = w.a_C[i];
        for (unsigned int i = 0; i < n_F; ++i)
          for (unsigned int l = 0; l < n_F; ++l)
            a[w.F[i]] += w.H_FF_inverse(i, l) * (w.g_F[l] - Uz[w.F[l]]);
        multiply(false,
                 n,
                 1,
                 k,
                 1.,
                 V.data(),
                 n,
                 a.data(),
                 k,
                 1.,
                 b.x.begin(),
                 n);
        b.mu.assign(w.C.size(), 0.);
        for (unsigned int i = 0; i < w.C.size(); ++i)
          {
            const unsigned int c = w.C[i];
            double mu = Uz[c] - dot(&V[std::size_t(c) * n], b.r.begin(), n);
            for (unsigned int l = 0; l < k; ++l)
              mu += w.H(c, l) * a[l];
            b.mu[i] = mu;
          }
      }
  }
} // namespace FuzzyContact
