#include <fuzzycontact/base/sparse_direct_solver.h>
#include <fuzzycontact/reduction/reduced_model.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <cmath>
#include <limits>
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


  ReducedComponent::ReducedComponent(
    const Component                            &component,
    const ModalBasis                           &modes,
    const std::vector<types::global_dof_index> &attachment_dofs,
    const bool                                  static_correction,
    const double                                rank_tolerance)
      : component(component)
      , modes(modes)
  {
    const unsigned int          n_m = modes.size();
    const SparseMatrix<double> &K   = component.stiffness_matrix();
    AssertThrow(n_m > 0 || static_correction,
                ExcMessage("Component " + component.name() +
                           ": a reduced basis needs modes or the static "
                           "correction."));

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
    lambda_inverse.reinit(n_m, n_m);
    if (n_m > 0)
      lambda_inverse.invert(lambda);

    unsigned int n_s = 0;
    if (static_correction)
      {
        // Columns of E: unit loads at the attachment DoFs, then the unit
        // load vectors of the component.
        std::vector<const Vector<double> *> loads;
        for (unsigned int l = 0; l < component.description().loads.size(); ++l)
          if (component.unit_load_vector(l).linfty_norm() > 0)
            loads.push_back(&component.unit_load_vector(l));
        const unsigned int n_a = attachment_dofs.size();
        const unsigned int n_e = n_a + loads.size();
        AssertThrow(n_e > 0,
                    ExcMessage("Component " + component.name() +
                               ": the static correction has neither contact "
                               "DoFs nor loads to attach modes to."));

        SparseDirectSolver inverse;
        inverse.factorize(K);
        psi_raw.assign(n_e, Vector<double>(component.n_dofs()));
        for (unsigned int e = 0; e < n_e; ++e)
          {
            if (e < n_a)
              psi_raw[e][attachment_dofs[e]] = 1;
            else
              psi_raw[e] = *loads[e - n_a];
            inverse.solve(psi_raw[e]);
          }
        // E^T v for a vector v.
        const auto E_transpose = [&](const unsigned int    e,
                                     const Vector<double> &v) -> double {
          return e < n_a ? v[attachment_dofs[e]] : (*loads[e - n_a]) * v;
        };

        B.reinit(n_m, n_e);
        for (unsigned int j = 0; j < n_m; ++j)
          for (unsigned int e = 0; e < n_e; ++e)
            B(j, e) = E_transpose(e, modes.modes[j]);

        // S = E^T K^{-1} E - B^T Lambda^{-1} B.
        FullMatrix<double> S(n_e, n_e), R(n_m, n_e);
        for (unsigned int a = 0; a < n_e; ++a)
          for (unsigned int e = 0; e < n_e; ++e)
            S(a, e) = E_transpose(a, psi_raw[e]);
        if (n_m > 0)
          {
            lambda_inverse.mmult(R, B);
            FullMatrix<double> BtR(n_e, n_e);
            B.Tmmult(BtR, R);
            S.add(-1., BtR);
          }
        for (unsigned int a = 0; a < n_e; ++a)
          for (unsigned int e = 0; e < a; ++e)
            S(a, e) = S(e, a) = 0.5 * (S(a, e) + S(e, a));

        // K-orthonormalise: S = Q D Q^T, X = Q_kept D_kept^{-1/2}.
        double bound = 0;
        for (unsigned int a = 0; a < n_e; ++a)
          {
            double row = 0;
            for (unsigned int e = 0; e < n_e; ++e)
              row += std::abs(S(a, e));
            bound = std::max(bound, row);
          }
        LAPACKFullMatrix<double> S_lapack(n_e, n_e);
        S_lapack = S;
        Vector<double>     d;
        FullMatrix<double> Q;
        S_lapack.compute_eigenvalues_symmetric(
          -2 * bound - 1e-300,
          2 * bound + 1e-300,
          2 * std::numeric_limits<double>::min(),
          d,
          Q);
        const double              d_max = d.size() > 0 ? d.linfty_norm() : 0.;
        std::vector<unsigned int> kept;
        for (unsigned int i = 0; i < d.size(); ++i)
          if (d[i] > rank_tolerance * d_max)
            kept.push_back(i);
        n_s = kept.size();
        X.reinit(n_e, n_s);
        for (unsigned int s = 0; s < n_s; ++s)
          for (unsigned int e = 0; e < n_e; ++e)
            X(e, s) = Q(e, kept[s]) / std::sqrt(d[kept[s]]);
        // From here on B holds R = Lambda^{-1} Phi^T E.
        B = R;
      }

    K_r.reinit(n_m + n_s, n_m + n_s);
    for (unsigned int i = 0; i < n_m; ++i)
      for (unsigned int j = 0; j < n_m; ++j)
        K_r(i, j) = lambda(i, j);
    for (unsigned int s = 0; s < n_s; ++s)
      K_r(n_m + s, n_m + s) = 1;
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
  ReducedComponent::size() const
  {
    return n_modes() + n_corrections();
  }

  bool
  ReducedComponent::has_static_correction() const
  {
    return !psi_raw.empty();
  }

  const FullMatrix<double> &
  ReducedComponent::stiffness() const
  {
    return K_r;
  }


  Vector<double>
  ReducedComponent::project(const Vector<double> &f) const
  {
    const unsigned int n_m = n_modes(), n_s = n_corrections();
    Vector<double>     q(n_m + n_s);
    Vector<double>     phi_f(n_m);
    for (unsigned int j = 0; j < n_m; ++j)
      q[j] = phi_f[j] = modes.modes[j] * f;
    if (n_s > 0)
      {
        // Psi_res^T f = Psi_raw^T f - R^T Phi^T f, then X^T.
        Vector<double> psi_f(psi_raw.size());
        for (unsigned int e = 0; e < psi_raw.size(); ++e)
          psi_f[e] = psi_raw[e] * f;
        if (n_m > 0)
          {
            Vector<double> correction(psi_raw.size());
            B.Tvmult(correction, phi_f);
            psi_f -= correction;
          }
        Vector<double> qs(n_s);
        X.Tvmult(qs, psi_f);
        for (unsigned int s = 0; s < n_s; ++s)
          q[n_m + s] = qs[s];
      }
    return q;
  }


  FullMatrix<double>
  ReducedComponent::project_rows(const SparseMatrix<double> &C) const
  {
    AssertDimension(C.n(), component.n_dofs());
    const unsigned int m = C.m(), n_m = n_modes(), n_s = n_corrections();
    FullMatrix<double> Cr(m, n_m + n_s);
    FullMatrix<double> C_phi(m, n_m);
    Vector<double>     column(m);
    for (unsigned int j = 0; j < n_m; ++j)
      {
        C.vmult(column, modes.modes[j]);
        for (unsigned int i = 0; i < m; ++i)
          Cr(i, j) = C_phi(i, j) = column[i];
      }
    if (n_s > 0)
      {
        FullMatrix<double> C_psi(m, psi_raw.size());
        for (unsigned int e = 0; e < psi_raw.size(); ++e)
          {
            C.vmult(column, psi_raw[e]);
            for (unsigned int i = 0; i < m; ++i)
              C_psi(i, e) = column[i];
          }
        // C Psi_res = C Psi_raw - (C Phi) R.
        if (n_m > 0)
          {
            FullMatrix<double> C_phi_R(m, psi_raw.size());
            C_phi.mmult(C_phi_R, B);
            C_psi.add(-1., C_phi_R);
          }
        FullMatrix<double> C_corr(m, n_s);
        C_psi.mmult(C_corr, X);
        for (unsigned int i = 0; i < m; ++i)
          for (unsigned int s = 0; s < n_s; ++s)
            Cr(i, n_m + s) = C_corr(i, s);
      }
    return Cr;
  }


  FullMatrix<double>
  ReducedComponent::rows(const std::vector<types::global_dof_index> &dofs) const
  {
    const unsigned int n_m = n_modes(), n_s = n_corrections();
    FullMatrix<double> V(dofs.size(), n_m + n_s);
    for (unsigned int r = 0; r < dofs.size(); ++r)
      {
        AssertIndexRange(dofs[r], component.n_dofs());
        for (unsigned int j = 0; j < n_m; ++j)
          V(r, j) = modes.modes[j][dofs[r]];
        if (n_s > 0)
          {
            Vector<double> psi_res(psi_raw.size());
            for (unsigned int e = 0; e < psi_raw.size(); ++e)
              {
                psi_res[e] = psi_raw[e][dofs[r]];
                for (unsigned int j = 0; j < n_m; ++j)
                  psi_res[e] -= modes.modes[j][dofs[r]] * B(j, e);
              }
            for (unsigned int s = 0; s < n_s; ++s)
              for (unsigned int e = 0; e < psi_raw.size(); ++e)
                V(r, n_m + s) += psi_res[e] * X(e, s);
          }
      }
    return V;
  }


  void
  ReducedComponent::expand(const Vector<double> &q, Vector<double> &u) const
  {
    const unsigned int n_m = n_modes(), n_s = n_corrections();
    AssertDimension(q.size(), n_m + n_s);
    u.reinit(component.n_dofs());
    Vector<double> qm(n_m);
    for (unsigned int j = 0; j < n_m; ++j)
      qm[j] = q[j];
    if (n_s > 0)
      {
        // Psi q_s = Psi_raw (X q_s) - Phi R (X q_s).
        Vector<double> qs(n_s), xq(psi_raw.size()), rxq(n_m);
        for (unsigned int s = 0; s < n_s; ++s)
          qs[s] = q[n_m + s];
        X.vmult(xq, qs);
        for (unsigned int e = 0; e < psi_raw.size(); ++e)
          u.add(xq[e], psi_raw[e]);
        if (n_m > 0)
          {
            B.vmult(rxq, xq);
            qm -= rxq;
          }
      }
    for (unsigned int j = 0; j < n_m; ++j)
      u.add(qm[j], modes.modes[j]);
  }


  FullMatrix<double>
  ReducedComponent::zone_stiffness(const unsigned int zone) const
  {
    AssertIndexRange(zone, component.n_zones());
    const unsigned int k = size();
    FullMatrix<double> Kz(k, k);
    if (component.n_zones() == 1)
      {
        Kz = K_r;
        Kz /= component.zone_moduli()[0];
        return Kz;
      }
    std::vector<Vector<double>> V(k);
    Vector<double>              e(k), Kv(component.n_dofs());
    for (unsigned int j = 0; j < k; ++j)
      {
        e    = 0;
        e[j] = 1;
        expand(e, V[j]);
      }
    for (unsigned int j = 0; j < k; ++j)
      {
        component.zone_stiffness_matrix(zone).vmult(Kv, V[j]);
        for (unsigned int i = 0; i <= j; ++i)
          Kz(i, j) = Kz(j, i) = V[i] * Kv;
      }
    return Kz;
  }


  ReducedComponentMatrices
  ReducedComponent::matrices(
    const SparseMatrix<double>                 &gap_operator,
    const std::vector<types::global_dof_index> &observed_dofs) const
  {
    ReducedComponentMatrices r;
    r.stiffness    = K_r;
    r.gap_operator = project_rows(gap_operator);
    for (unsigned int l = 0; l < component.description().loads.size(); ++l)
      {
        r.loads.push_back(project(component.reference_load_vector(l)));
        r.reference_forces.push_back(component.reference_load_force(l));
      }
    r.observed_dofs = observed_dofs;
    r.observation   = rows(observed_dofs);
    return r;
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
        load_forces.push_back(variable[c].matrices.reference_forces);
      }
    assemble_problem();
  }


  void
  ReducedContactModel::set_load_forces(
    const std::vector<std::vector<double>> &forces)
  {
    AssertThrow(forces.size() == variable.size(),
                ExcMessage("ReducedContactModel: one list of load forces per "
                           "component is expected."));
    for (unsigned int c = 0; c < forces.size(); ++c)
      {
        AssertThrow(forces[c].size() == load_forces[c].size(),
                    ExcMessage("ReducedContactModel: one force per load of "
                               "each component is expected."));
        for (const double f : forces[c])
          AssertThrow(std::isfinite(f),
                      ExcMessage("ReducedContactModel: load forces must be "
                                 "finite."));
      }
    if (forces == load_forces)
      return;
    load_forces = forces;
    assemble_load_gaps();
  }


  double
  ReducedContactModel::load_factor(const unsigned int c,
                                   const unsigned int l) const
  {
    return load_forces[c][l] / variable[c].matrices.reference_forces[l];
  }


  void
  ReducedContactModel::compute_blocks(Part &part) const
  {
    const unsigned int              m = problem_.g_initial.size();
    const ReducedComponentMatrices &r = part.matrices;
    const unsigned int              k = r.stiffness.m();
    bool loads_fit = r.loads.size() == r.reference_forces.size();
    for (const Vector<double> &f : r.loads)
      loads_fit = loads_fit && f.size() == k;
    AssertThrow(r.stiffness.n() == k && r.gap_operator.m() == m &&
                  r.gap_operator.n() == k && loads_fit &&
                  r.observation.m() == r.observed_dofs.size() &&
                  (r.observed_dofs.empty() || r.observation.n() == k),
                ExcMessage("ReducedContactModel: the reduced matrices of a "
                           "component do not fit together."));
    // (Kept behind a pointer: copying a LAPACKFullMatrix forgets that it
    // holds a factorisation.)
    part.factor = std::make_unique<LAPACKFullMatrix<double>>(k, k);
    LAPACKFullMatrix<double> &factor = *part.factor;
    factor                           = r.stiffness;
    factor.set_property(LAPACKSupport::symmetric);
    factor.compute_cholesky_factorization();

    // Y = K_r^{-1} C_r^T, W_c = C_r Y, g_load,c = C_r K_r^{-1} f_r.
    LAPACKFullMatrix<double> Y(k, m);
    for (unsigned int i = 0; i < k; ++i)
      for (unsigned int j = 0; j < m; ++j)
        Y(i, j) = r.gap_operator(j, i);
    factor.solve(Y);
    FullMatrix<double> Yf(k, m), Wc(m, m);
    for (unsigned int i = 0; i < k; ++i)
      for (unsigned int j = 0; j < m; ++j)
        Yf(i, j) = Y(i, j);
    r.gap_operator.mmult(Wc, Yf);
    for (unsigned int i = 0; i < m; ++i)
      for (unsigned int j = 0; j < i; ++j)
        Wc(i, j) = Wc(j, i) = 0.5 * (Wc(i, j) + Wc(j, i));
    part.flexibility = std::move(Wc);

    // Recovery of the observed displacements without a reduced solve:
    // u_obs = lambda O K_r^{-1} f_r + (O K_r^{-1} C_r^T) p.
    const unsigned int n_obs = r.observed_dofs.size();
    part.observation_flexibility.reinit(n_obs, m);
    if (n_obs > 0)
      r.observation.mmult(part.observation_flexibility, Yf);
    part.load_gaps.clear();
    part.observation_loads.clear();
    for (const Vector<double> &f : r.loads)
      {
        Vector<double> q = f;
        factor.solve(q);
        Vector<double> g(m), u(n_obs);
        r.gap_operator.vmult(g, q);
        if (n_obs > 0)
          r.observation.vmult(u, q);
        part.load_gaps.push_back(std::move(g));
        part.observation_loads.push_back(std::move(u));
      }
    part.present = true;
  }


  void
  ReducedContactModel::assemble_problem()
  {
    const unsigned int m = problem_.g_initial.size();
    problem_.W.reinit(m, m);
    for (unsigned int c = 0; c < variable.size(); ++c)
      for (const Part *part : {&variable[c], &fixed[c]})
        if (part->present)
          problem_.W.add(1. / scales[c], part->flexibility);
    assemble_load_gaps();
  }


  void
  ReducedContactModel::assemble_load_gaps()
  {
    problem_.g_load.reinit(problem_.g_initial.size());
    for (unsigned int c = 0; c < variable.size(); ++c)
      for (const Part *part : {&variable[c], &fixed[c]})
        if (part->present)
          for (unsigned int l = 0; l < part->load_gaps.size(); ++l)
            {
              const double factor = load_factor(c, l);
              if (factor != 0)
                problem_.g_load.add(factor / scales[c], part->load_gaps[l]);
            }
    problem_.check();
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
    assemble_problem();
  }


  void
  ReducedContactModel::replace_component(const unsigned int       c,
                                         ReducedComponentMatrices matrices)
  {
    AssertIndexRange(c, variable.size());
    variable[c].matrices = std::move(matrices);
    scales[c]            = 1.;
    compute_blocks(variable[c]);
    assemble_problem();
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
    compute_blocks(fixed[c]);
    assemble_problem();
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
    FullMatrix<double> W = variable[c].flexibility;
    if (fixed[c].present)
      W.add(1., fixed[c].flexibility);
    W /= scales[c];
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
        std::vector<Vector<double>> parts;
        for (const Part *part : {&variable[c], &fixed[c]})
          if (part->present)
            {
              Vector<double> rhs(part->matrices.stiffness.m());
              for (unsigned int l = 0; l < part->matrices.loads.size(); ++l)
                rhs.add(load_factor * this->load_factor(c, l),
                        part->matrices.loads[l]);
              part->matrices.gap_operator.Tvmult_add(rhs, p);
              part->factor->solve(rhs);
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
          s.observed[c].push_back(u / scales[c]);
        }
    return s;
  }
} // namespace FuzzyContact
