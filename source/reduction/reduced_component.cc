#include <fuzzycontact/base/lapack_errors.h>
#include <fuzzycontact/base/lapack_extras.h>
#include <fuzzycontact/reduction/reduced_component.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  unsigned int
  modes_for_static_error(const ModalBasis     &modes,
                         const Vector<double> &f,
                         const Vector<double> &static_solution,
                         const double          tolerance,
                         const std::string    &what)
  {
    const double energy = f * static_solution;
    AssertThrow(energy > 0,
                ExcMessage(what + ": the mode error tolerance needs a "
                                  "non-zero load."));
    double captured = 0;
    double error    = 1;
    for (unsigned int j = 0; j < modes.size(); ++j)
      {
        const double a = modes.modes[j] * f;
        captured += a * a / modes.eigenvalues[j];
        error = std::sqrt(std::max(0., 1. - captured / energy));
        if (error <= tolerance)
          return j + 1;
      }
    std::ostringstream message;
    message << what << ": " << modes.size() << " modes leave a static error of "
            << error
            << " in the load response, more than the mode error tolerance "
            << tolerance << "; raise the number of modes or the cutoff.";
    AssertThrow(false, ExcMessage(message.str()));
    return modes.size();
  }


  namespace
  {
    // X (n x r) with X^T S X = I spanning S's range up to the pivots below
    // @p rank_tolerance times S's largest diagonal entry, by LAPACK's
    // pivoted Cholesky factorisation P^T S P = L L^T: X = P_r L_r^{-T}.
    FullMatrix<double>
    k_orthonormaliser(const FullMatrix<double> &S, const double rank_tolerance)
    {
      const types::blas_int n = S.m();
      if (n == 0)
        return FullMatrix<double>();
      double largest = 0;
      for (types::blas_int i = 0; i < n; ++i)
        largest = std::max(largest, S(i, i));
      AssertThrow(largest > 0 && std::isfinite(largest),
                  ExcMessage("The static correction's Gram matrix has no "
                             "positive diagonal entry."));
      // S is symmetric: its row-major data is its column-major data.
      FullMatrix<double>           L = S;
      std::vector<types::blas_int> piv(n);
      std::vector<double>          work(2 * n);
      types::blas_int              rank = 0, info = 0;
      const double                 tol = rank_tolerance * largest;
      dpstrf_("L",
              &n,
              &L(0, 0),
              &n,
              piv.data(),
              &rank,
              &tol,
              work.data(),
              &info);
      AssertThrow(info >= 0 && rank > 0,
                  ExcMessage("LAPACK's pivoted Cholesky factorisation of the "
                             "static correction's Gram matrix failed."));
      // Column-major L(i, j), i >= j, is the row-major L(j, i). Solve
      // L_r^T Z = I for Z = L_r^{-T} (an upper triangle).
      FullMatrix<double> Lr(rank, rank); // column-major L_r
      for (types::blas_int j = 0; j < rank; ++j)
        for (types::blas_int i = j; i < rank; ++i)
          Lr(j, i) = L(j, i);
      FullMatrix<double> Z(rank, rank); // column-major identity
      for (types::blas_int i = 0; i < rank; ++i)
        Z(i, i) = 1;
      trtrs("L",
            "T",
            "N",
            &rank,
            &rank,
            &Lr(0, 0),
            &rank,
            &Z(0, 0),
            &rank,
            &info);
      AssertThrow(info == 0,
                  ExcMessage("The static correction's Gram matrix is "
                             "singular to working precision."));
      // X(piv_i - 1, s) = Z(i, s), Z column-major: Z(i, s) is Z_rm(s, i).
      FullMatrix<double> X(n, rank);
      for (types::blas_int i = 0; i < rank; ++i)
        for (types::blas_int s = 0; s < rank; ++s)
          X(piv[i] - 1, s) = Z(s, i);
      return X;
    }
  } // namespace


  ReducedComponent::ReducedComponent(
    const Component                            &component,
    const ModalBasis                           &modes,
    std::shared_ptr<const SparseCholesky>       factorisation_,
    const std::vector<types::global_dof_index> &attachment_dofs,
    const bool                                  static_correction,
    const double                                rank_tolerance)
      : component(component)
      , modes(modes)
      , factorisation(std::move(factorisation_))
      , nominal_moduli(component.zone_moduli())
  {
    const unsigned int          n_m = modes.size();
    const SparseMatrix<double> &K   = component.stiffness_matrix();
    AssertThrow(n_m > 0 || static_correction,
                ExcMessage("Component " + component.name() +
                           ": a reduced basis needs modes or the static "
                           "correction."));
    AssertThrow(factorisation != nullptr &&
                  factorisation->n() == component.n_dofs(),
                ExcMessage("Component " + component.name() +
                           ": the reduced basis needs the factorisation of "
                           "its stiffness."));
    boundary = factorisation->trailing_dofs();
    position.assign(component.n_dofs(), -1);
    for (unsigned int i = 0; i < boundary.size(); ++i)
      position[boundary[i]] = i;

    // Lambda = Phi^T K Phi (diagonal up to the eigensolver's accuracy).
    lambda.reinit(n_m, n_m);
    Vector<double> Kphi(component.n_dofs());
    for (unsigned int j = 0; j < n_m; ++j)
      {
        AssertDimension(modes.modes[j].size(), component.n_dofs());
        K.vmult(Kphi, modes.modes[j]);
        for (unsigned int i = 0; i < n_m; ++i)
          lambda(i, j) = modes.modes[i] * Kphi;
      }
    for (unsigned int i = 0; i < n_m; ++i)
      for (unsigned int j = 0; j < i; ++j)
        lambda(i, j) = lambda(j, i) = 0.5 * (lambda(i, j) + lambda(j, i));

    // The modes at B.
    const unsigned int m = boundary.size();
    V_B.reinit(m, n_m);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < n_m; ++j)
        V_B(i, j) = modes.modes[j][boundary[i]];
    if (static_correction)
      build_static_correction(attachment_dofs, rank_tolerance);
    LapackErrors::check("Component " + component.name() +
                        ": the static correction");

    // The exact responses to the weight, per zone.
    if (component.weight_load() >= 0)
      for (const Vector<double> &w : component.weight_zone_loads())
        {
          Vector<double> u = w;
          u *= component.reference_load_force(component.weight_load());
          factorisation->solve(u);
          weight_fields.push_back(std::move(u));
        }

    const unsigned int n_s = X.n();
    K_r.reinit(n_m + n_s, n_m + n_s);
    for (unsigned int i = 0; i < n_m; ++i)
      for (unsigned int j = 0; j < n_m; ++j)
        K_r(i, j) = lambda(i, j);
    for (unsigned int s = 0; s < n_s; ++s)
      K_r(n_m + s, n_m + s) = 1;
  }


  void
  ReducedComponent::build_static_correction(
    const std::vector<types::global_dof_index> &attachment_dofs,
    const double                                rank_tolerance)
  {
    const unsigned int m = boundary.size(), n_m = modes.size();
    const auto         not_on_b = [&](const std::string &what) {
      return ExcMessage("Component " + component.name() + ": " + what +
                        " is not among the DoFs its stiffness factorisation "
                                "orders last.");
    };

    // Columns of E on B: unit loads at the attachment DoFs, then the unit
    // load vectors of the component.
    // A prescribed displacement's load (per metre) holds forces of the
    // order of the stiffness itself: its column is scaled to a largest
    // entry of 1 N, like the unit loads at the contact DoFs, so that the
    // rank test below does not take the contact columns for round-off.
    std::vector<const Vector<double> *> loads;
    std::vector<double>                 load_scales;
    // (Not the weight: it acts on every DoF, see the top of the header.)
    for (unsigned int l = 0; l < component.description().loads.size(); ++l)
      if (!component.description().loads[l].is_weight &&
          component.unit_load_vector(l).linfty_norm() > 0)
        {
          loads.push_back(&component.unit_load_vector(l));
          load_scales.push_back(
            component.description().loads[l].is_displacement
              ? 1. / component.unit_load_vector(l).linfty_norm()
              : 1.);
        }
    const unsigned int n_a = attachment_dofs.size();
    const unsigned int n_e = n_a + loads.size();
    AssertThrow(n_e > 0,
                ExcMessage("Component " + component.name() +
                           ": the static correction has neither contact "
                           "DoFs nor loads to attach modes to."));
    E_B.reinit(m, n_e);
    for (unsigned int e = 0; e < n_a; ++e)
      {
        AssertThrow(position[attachment_dofs[e]] >= 0,
                    not_on_b("a contact DoF"));
        E_B(position[attachment_dofs[e]], e) = 1;
      }
    for (unsigned int l = 0; l < loads.size(); ++l)
      for (unsigned int d = 0; d < loads[l]->size(); ++d)
        if ((*loads[l])[d] != 0)
          {
            AssertThrow(position[d] >= 0, not_on_b("a DoF of a load"));
            E_B(position[d], n_a + l) = load_scales[l] * (*loads[l])[d];
          }

    // Psi_raw at B = G E_B; B = Phi_B^T E_B, R = Lambda^{-1} B;
    // S = E_B^T G E_B - B^T R.
    const FullMatrix<double> G = factorisation->trailing_inverse();
    FullMatrix<double>       psi(m, n_e), S(n_e, n_e);
    G.mmult(psi, E_B);
    E_B.Tmmult(S, psi);
    FullMatrix<double> Phi_B(m, n_m), B(n_m, n_e);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < n_m; ++j)
        Phi_B(i, j) = V_B(i, j);
    R.reinit(n_m, n_e);
    if (n_m > 0)
      {
        Phi_B.Tmmult(B, E_B);
        FullMatrix<double> lambda_inverse(n_m, n_m);
        lambda_inverse.invert(lambda);
        lambda_inverse.mmult(R, B);
        FullMatrix<double> BtR(n_e, n_e);
        B.Tmmult(BtR, R);
        S.add(-1., BtR);
        // Psi_res at B = Psi_raw - Phi_B R.
        FullMatrix<double> PhiR(m, n_e);
        Phi_B.mmult(PhiR, R);
        psi.add(-1., PhiR);
      }
    for (unsigned int a = 0; a < n_e; ++a)
      for (unsigned int e = 0; e < a; ++e)
        S(a, e) = S(e, a) = 0.5 * (S(a, e) + S(e, a));

    X                      = k_orthonormaliser(S, rank_tolerance);
    const unsigned int n_s = X.n();
    FullMatrix<double> correction(m, n_s);
    psi.mmult(correction, X);
    V_B.reinit(m, n_m + n_s);
    for (unsigned int i = 0; i < m; ++i)
      {
        for (unsigned int j = 0; j < n_m; ++j)
          V_B(i, j) = Phi_B(i, j);
        for (unsigned int s = 0; s < n_s; ++s)
          V_B(i, n_m + s) = correction(i, s);
      }
  }


  unsigned int
  ReducedComponent::n_modes() const
  {
    return modes.size();
  }

  unsigned int
  ReducedComponent::n_corrections() const
  {
    return X.n();
  }

  unsigned int
  ReducedComponent::n_added() const
  {
    return added.size();
  }

  unsigned int
  ReducedComponent::size() const
  {
    return n_modes() + n_corrections() + n_added();
  }


  unsigned int
  ReducedComponent::add_vectors(const std::vector<Vector<double>> &u)
  {
    const unsigned int n = component.n_dofs();
    // K x at the nominal moduli.
    const auto stiffness_times = [&](const Vector<double> &x) {
      Vector<double> Kx(n), y(n);
      for (unsigned int z = 0; z < component.n_zones(); ++z)
        {
          component.zone_stiffness_matrix(z).vmult(y, x);
          Kx.add(nominal_moduli[z], y);
        }
      return Kx;
    };
    unsigned int n_new = 0;
    for (const Vector<double> &v : u)
      {
        AssertDimension(v.size(), n);
        const double own = std::sqrt(std::max(0., v * stiffness_times(v)));
        if (!(own > 0) || !std::isfinite(own))
          continue;
        Vector<double> w = v;
        for (unsigned int pass = 0; pass < 2; ++pass)
          {
            // c = K_r^{-1} V^T K w (K_r = diag(Lambda, I, I)), w -= V c.
            Vector<double> c = stiffness_products(w);
            if (n_modes() > 0)
              {
                FullMatrix<double> lambda_inverse(n_modes(), n_modes());
                lambda_inverse.invert(lambda);
                Vector<double> a(n_modes()), b(n_modes());
                for (unsigned int j = 0; j < n_modes(); ++j)
                  b[j] = c[j];
                lambda_inverse.vmult(a, b);
                for (unsigned int j = 0; j < n_modes(); ++j)
                  c[j] = a[j];
              }
            Vector<double> Vc;
            expand(c, Vc);
            w -= Vc;
          }
        const double rest = std::sqrt(std::max(0., w * stiffness_times(w)));
        if (!(rest > 1e-10 * own))
          continue;
        w /= rest;
        added.push_back(std::move(w));
        ++n_new;
      }
    // K_r = diag(Lambda, I, I).
    if (n_new > 0)
      {
        const FullMatrix<double> old = K_r;
        K_r.reinit(size(), size());
        for (unsigned int i = 0; i < old.m(); ++i)
          for (unsigned int j = 0; j < old.n(); ++j)
            K_r(i, j) = old(i, j);
        for (unsigned int i = old.m(); i < size(); ++i)
          K_r(i, i) = 1;
      }
    return n_new;
  }

  bool
  ReducedComponent::has_static_correction() const
  {
    return E_B.n() > 0;
  }

  const FullMatrix<double> &
  ReducedComponent::stiffness() const
  {
    return K_r;
  }


  const std::shared_ptr<const SparseCholesky> &
  ReducedComponent::stiffness_factorisation() const
  {
    return factorisation;
  }


  Vector<double>
  ReducedComponent::stiffness_products(const Vector<double> &x) const
  {
    const unsigned int n = component.n_dofs();
    AssertDimension(x.size(), n);
    const unsigned int n_m = n_modes(), n_s = n_corrections();
    Vector<double>     c(size()), phi_Kx(n_m);
    if (n_m > 0 || !added.empty())
      {
        // K x at the nominal moduli.
        Vector<double> Kx(n), y(n);
        for (unsigned int z = 0; z < component.n_zones(); ++z)
          {
            component.zone_stiffness_matrix(z).vmult(y, x);
            Kx.add(nominal_moduli[z], y);
          }
        for (unsigned int j = 0; j < n_m; ++j)
          c[j] = phi_Kx[j] = modes.modes[j] * Kx;
        for (unsigned int j = 0; j < added.size(); ++j)
          c[n_m + n_s + j] = added[j] * Kx;
      }
    if (n_s > 0)
      {
        // Psi^T K x = X^T (E^T x - R^T Phi^T K x).
        Vector<double> r = attachment_loads(x), s(n_s);
        if (n_m > 0)
          {
            Vector<double> Rt(r.size());
            R.Tvmult(Rt, phi_Kx);
            r -= Rt;
          }
        X.Tvmult(s, r);
        for (unsigned int j = 0; j < n_s; ++j)
          c[n_m + j] = s[j];
      }
    return c;
  }


  FullMatrix<double>
  ReducedComponent::correction_loads() const
  {
    FullMatrix<double> F(E_B.m(), X.n());
    if (X.n() > 0)
      E_B.mmult(F, X);
    return F;
  }


  const std::vector<types::global_dof_index> &
  ReducedComponent::boundary_dofs() const
  {
    return boundary;
  }


  Vector<double>
  ReducedComponent::attachment_loads(const Vector<double> &x) const
  {
    Vector<double> x_B(boundary.size()), Etx(E_B.n());
    for (unsigned int i = 0; i < boundary.size(); ++i)
      x_B[i] = x[boundary[i]];
    E_B.Tvmult(Etx, x_B);
    return Etx;
  }


  void
  ReducedComponent::correction_row(const Vector<double> &raw,
                                   const Vector<double> &modal,
                                   Vector<double>       &row) const
  {
    // Psi_res^T e_d = Psi_raw^T e_d - R^T Phi^T e_d, then X^T.
    Vector<double> residual = raw;
    if (n_modes() > 0)
      {
        Vector<double> correction(raw.size());
        R.Tvmult(correction, modal);
        residual -= correction;
      }
    row.reinit(n_corrections());
    X.Tvmult(row, residual);
  }


  Vector<double>
  ReducedComponent::project(const Vector<double> &f) const
  {
    AssertDimension(f.size(), component.n_dofs());
    const unsigned int n_m = n_modes(), n_s = n_corrections();
    Vector<double>     q(size());
    bool               on_boundary = true;
    for (unsigned int d = 0; d < f.size() && on_boundary; ++d)
      on_boundary = f[d] == 0 || position[d] >= 0;
    for (unsigned int j = 0; j < added.size(); ++j)
      q[n_m + n_s + j] = added[j] * f;
    if (on_boundary)
      {
        // V^T f = V_B^T f_B.
        Vector<double> f_B(boundary.size()), q_B(n_m + n_s);
        for (unsigned int i = 0; i < boundary.size(); ++i)
          f_B[i] = f[boundary[i]];
        V_B.Tvmult(q_B, f_B);
        for (unsigned int j = 0; j < n_m + n_s; ++j)
          q[j] = q_B[j];
        return q;
      }
    Vector<double> phi_f(n_m);
    for (unsigned int j = 0; j < n_m; ++j)
      q[j] = phi_f[j] = modes.modes[j] * f;
    if (n_s > 0)
      {
        // Psi_raw^T f = E^T K^{-1} f: one back-substitution.
        Vector<double> x = f;
        factorisation->solve(x);
        Vector<double> qs;
        correction_row(attachment_loads(x), phi_f, qs);
        for (unsigned int s = 0; s < n_s; ++s)
          q[n_m + s] = qs[s];
      }
    return q;
  }


  FullMatrix<double>
  ReducedComponent::rows(const std::vector<types::global_dof_index> &dofs) const
  {
    const unsigned int n_m = n_modes(), n_s = n_corrections();
    FullMatrix<double> V(dofs.size(), size());
    for (unsigned int r = 0; r < dofs.size(); ++r)
      {
        AssertIndexRange(dofs[r], component.n_dofs());
        for (unsigned int j = 0; j < added.size(); ++j)
          V(r, n_m + n_s + j) = added[j][dofs[r]];
        if (position[dofs[r]] >= 0)
          {
            for (unsigned int j = 0; j < n_m + n_s; ++j)
              V(r, j) = V_B(position[dofs[r]], j);
            continue;
          }
        Vector<double> modal(n_m);
        for (unsigned int j = 0; j < n_m; ++j)
          V(r, j) = modal[j] = modes.modes[j][dofs[r]];
        if (n_s > 0)
          {
            // Psi_raw^T e_d = E^T K^{-1} e_d: one back-substitution.
            Vector<double> x(component.n_dofs()), row;
            x[dofs[r]] = 1;
            factorisation->solve(x);
            correction_row(attachment_loads(x), modal, row);
            for (unsigned int s = 0; s < n_s; ++s)
              V(r, n_m + s) = row[s];
          }
      }
    return V;
  }


  FullMatrix<double>
  ReducedComponent::project_rows(const SparseMatrix<double> &C) const
  {
    AssertDimension(C.n(), component.n_dofs());
    // The rows of V at every DoF that C touches, then C V row by row.
    std::vector<types::global_dof_index> touched;
    for (const auto &entry : C)
      touched.push_back(entry.column());
    std::sort(touched.begin(), touched.end());
    touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
    const FullMatrix<double> V = rows(touched);
    FullMatrix<double>       Cr(C.m(), size());
    for (unsigned int i = 0; i < C.m(); ++i)
      for (auto it = C.begin(i); it != C.end(i); ++it)
        {
          const unsigned int r =
            std::lower_bound(touched.begin(), touched.end(), it->column()) -
            touched.begin();
          for (unsigned int j = 0; j < size(); ++j)
            Cr(i, j) += it->value() * V(r, j);
        }
    return Cr;
  }


  void
  ReducedComponent::expand(const Vector<double> &q, Vector<double> &u) const
  {
    const unsigned int n_m = n_modes(), n_s = n_corrections();
    AssertDimension(q.size(), size());
    u.reinit(component.n_dofs());
    Vector<double> qm(n_m);
    for (unsigned int j = 0; j < n_m; ++j)
      qm[j] = q[j];
    if (n_s > 0)
      {
        // Psi q_s = K^{-1} E (X q_s) - Phi R (X q_s): one back-substitution.
        Vector<double> qs(n_s), xq(E_B.m()), y(E_B.n());
        for (unsigned int s = 0; s < n_s; ++s)
          qs[s] = q[n_m + s];
        X.vmult(y, qs);
        E_B.vmult(xq, y);
        for (unsigned int i = 0; i < boundary.size(); ++i)
          u[boundary[i]] = xq[i];
        factorisation->solve(u);
        if (n_m > 0)
          {
            Vector<double> ry(n_m);
            R.vmult(ry, y);
            qm -= ry;
          }
      }
    for (unsigned int j = 0; j < n_m; ++j)
      u.add(qm[j], modes.modes[j]);
    for (unsigned int j = 0; j < added.size(); ++j)
      u.add(q[n_m + n_s + j], added[j]);
  }


  const std::vector<Vector<double>> &
  ReducedComponent::weight_responses() const
  {
    return weight_fields;
  }


  std::vector<FullMatrix<double>>
  ReducedComponent::zone_stiffnesses() const
  {
    const unsigned int              k = size();
    std::vector<FullMatrix<double>> Kz(component.n_zones(),
                                       FullMatrix<double>(k, k));
    if (component.n_zones() == 1)
      {
        Kz[0] = K_r;
        Kz[0] /= component.zone_moduli()[0];
        return Kz;
      }
    // The whole basis, one vector at a time (k back-substitutions).
    std::vector<Vector<double>> V(k);
    Vector<double>              e(k), Kv(component.n_dofs());
    for (unsigned int j = 0; j < k; ++j)
      {
        e    = 0;
        e[j] = 1;
        expand(e, V[j]);
      }
    for (unsigned int z = 0; z < component.n_zones(); ++z)
      for (unsigned int j = 0; j < k; ++j)
        {
          component.zone_stiffness_matrix(z).vmult(Kv, V[j]);
          for (unsigned int i = 0; i <= j; ++i)
            Kz[z](i, j) = Kz[z](j, i) = V[i] * Kv;
        }
    return Kz;
  }
} // namespace FuzzyContact
