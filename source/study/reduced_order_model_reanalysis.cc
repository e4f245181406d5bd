// ReducedOrderModel (reduced_order_model.h): the components whose zone
// materials are re-analysed, by the Krylov static correction or by the
// parameter-independent HPTP, offline and per state.

#include <fuzzycontact/base/timer_section.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/base/exceptions.h>

#include "reduced_order_model_component.h"
#include <algorithm>
#include <cmath>

namespace FuzzyContact
{
  namespace
  {
    // The names of @p quantities.
    std::vector<std::string>
    names_of(const std::vector<SceneQuantity> &quantities)
    {
      std::vector<std::string> names;
      for (const SceneQuantity &q : quantities)
        names.push_back(q.name);
      return names;
    }

    // The ranges of @p quantities, from the study's @p varying ones.
    std::vector<Interval>
    ranges_of(const std::vector<SceneQuantity>   &quantities,
              const std::vector<VaryingQuantity> &varying)
    {
      std::vector<Interval> ranges;
      for (const SceneQuantity &q : quantities)
        for (const VaryingQuantity &v : varying)
          if (v.quantity.name == q.name)
            ranges.push_back(v.range);
      return ranges;
    }

    // The values of @p quantities at @p state.
    std::vector<double>
    values_of(const std::vector<SceneQuantity> &quantities,
              const SceneState                 &state,
              const Scene                      &scene)
    {
      std::vector<double> values;
      for (const SceneQuantity &q : quantities)
        values.push_back(q.value(state, scene));
      return values;
    }
  } // namespace


  // Zone parameters: the parameter-independent HPTP, its order chosen
  // from the tolerance at the corners of the quantities' ranges, and what
  // turns Y(p) into reduced matrices: C T, the rows of T at the observed
  // DoFs, T^T f_l, and for the Galerkin correction also T^T K_z Psi,
  // Psi^T K_z Psi, C Psi, the rows of Psi and Psi^T f_l.
  void
  ReducedOrderModel::build_reanalysis(ComponentModel    &m,
                                      const unsigned int c,
                                      TimerOutput       *timer)
  {
    const Component               &component = bodies.component(c);
    const std::vector<std::string> names     = names_of(m.quantities);
    const std::vector<Interval>    ranges    = ranges_of(m.quantities, varying);
    const bool                     krylov =
      settings.zone_correction == ReducedModelSettings::ZoneCorrection::krylov;
    if (krylov && m.n_modes == 0)
      {
        // No modes: the static correction and its Krylov vectors alone.
        build_zone_correction(m, c, timer);
        return;
      }
    const ReanalysisSettings &rs = settings.reanalysis;
    // The order is the lowest whose change to the next order meets the
    // tolerance at the corners of the box, so the basis is first built up
    // to order 2 only: when order 1 is chosen, order 3's systems are never
    // solved. Otherwise it is built again up to the maximum order and the
    // choice made on it: the same order and the same leading columns of the
    // basis as building every order at once.
    const auto build = [&](const unsigned int order) {
      m.reanalysis = std::make_unique<ParameterIndependentReanalysis>();
      // Lee's derivatives by deflated CG use the factorisation of the
      // stiffness that the modes and the static correction were built on.
      m.reanalysis->offline(component,
                            m.modes,
                            names,
                            order,
                            rs.truncation_tolerance,
                            rs.cluster_gap,
                            timer,
                            rs.derivative_solver,
                            bodies.stiffness_factorisation(c));
      auto scope = timer_section(timer, "reanalysis order selection");
      std::vector<std::vector<double>> corners;
      const unsigned int               n = names.size();
      for (unsigned long corner = 0; corner < (1ul << n); ++corner)
        {
          std::vector<double> values(n);
          for (unsigned int k = 0; k < n; ++k)
            values[k] = (corner >> k) & 1 ? ranges[k].upper : ranges[k].lower;
          corners.push_back(m.reanalysis->model().relative_changes(values));
        }
      return m.reanalysis->select_order(corners,
                                        rs.order_tolerance,
                                        rs.residual_check);
    };
    const unsigned int first = std::min(rs.max_order, 2u);
    if (build(first) == first && first < rs.max_order)
      build(rs.max_order);
    m.reanalysis_order   = m.reanalysis->order();
    m.reanalysis_vectors = m.reanalysis->basis_size(m.reanalysis_order);
    if (krylov)
      {
        // The modes and their HPTP terms join the static correction and
        // its Krylov vectors in one Galerkin basis.
        build_zone_correction(m, c, timer);
        return;
      }

    auto                scope = timer_section(timer, "reanalysis projections");
    const ReducedBasis &T     = m.reanalysis->basis();
    const unsigned int  n_m   = m.reduced->n_modes();
    const bool          galerkin = settings.zone_correction ==
                          ReducedModelSettings::ZoneCorrection::galerkin;
    const unsigned int n_s = galerkin ? m.reduced->n_corrections() : 0;
    const unsigned int n_T = T.size();
    Vector<double>     Kt(component.n_dofs());
    const std::vector<FullMatrix<double>> Kz =
      n_s > 0 ? m.reduced->zone_stiffnesses()
              : std::vector<FullMatrix<double>>();
    for (unsigned int z = 0; z < component.n_zones(); ++z)
      {
        FullMatrix<double> TKpsi(n_T, n_s);
        for (unsigned int i = 0; i < n_T && n_s > 0; ++i)
          {
            component.zone_stiffness_matrix(z).vmult(Kt, T[i]);
            const Vector<double> q = m.reduced->project(Kt);
            for (unsigned int j = 0; j < n_s; ++j)
              TKpsi(i, j) = q[n_m + j];
          }
        m.T_K_psi.push_back(std::move(TKpsi));
        m.psi_K_psi.push_back(n_s > 0 ? block(Kz[z], n_m, n_s, n_m, n_s)
                                      : FullMatrix<double>());
      }
    const SparseMatrix<double> &C = bodies.interface().gap_operator(c);
    m.C_T                         = T.apply(C);
    const FullMatrix<double> C_V  = m.reduced->project_rows(C);
    m.C_psi                       = block(C_V, 0, C_V.m(), n_m, n_s);
    const auto &observed          = m.nominal_matrices.observed_dofs;
    m.O_T.reinit(observed.size(), n_T);
    for (unsigned int r = 0; r < observed.size(); ++r)
      for (unsigned int i = 0; i < n_T; ++i)
        m.O_T(r, i) = T[i][observed[r]];
    const FullMatrix<double> O_V = m.reduced->rows(observed);
    m.O_psi                      = block(O_V, 0, O_V.m(), n_m, n_s);
    for (unsigned int l = 0; l < component.description().loads.size(); ++l)
      {
        const Vector<double> f = component.reference_load_vector(l);
        m.T_f.push_back(T.project(f));
        const Vector<double> V_f = m.reduced->project(f);
        Vector<double>       psi_f(n_s);
        for (unsigned int j = 0; j < n_s; ++j)
          psi_f[j] = V_f[n_m + j];
        m.psi_f.push_back(std::move(psi_f));
      }
  }


  // The Krylov static correction of component c (zone_static_correction.h)
  // for its modulus quantities over their ranges, with the modes and their
  // HPTP terms if the component has a reanalysis.
  void
  ReducedOrderModel::build_zone_correction(ComponentModel    &m,
                                           const unsigned int c,
                                           TimerOutput       *timer)
  {
    const Component &component = bodies.component(c);
    // (Its parameters are the moduli: a density changes no stiffness.)
    m.zone_quantities.clear();
    for (const SceneQuantity &q : m.quantities)
      if (q.kind != SceneQuantity::Kind::density)
        m.zone_quantities.push_back(q);
    const std::vector<std::string>         names = names_of(m.zone_quantities);
    std::vector<std::pair<double, double>> ranges;
    for (const Interval &r : ranges_of(m.zone_quantities, varying))
      ranges.emplace_back(r.lower, r.upper);
    std::vector<Vector<double>> T;
    if (m.reanalysis != nullptr)
      {
        const ReducedBasis &basis = m.reanalysis->basis();
        for (unsigned int i = 0;
             i < m.reanalysis->basis_size(m.reanalysis_order);
             ++i)
          T.push_back(basis[i]);
      }
    // (On the nominal factorisation the basis was built on: the component
    // itself must be at its nominal materials.)
    AssertThrow(component.zone_moduli() == m.nominal_moduli,
                ExcMessage("ReducedOrderModel: component " + component.name() +
                           " is not at its nominal moduli; its Krylov static "
                           "correction is built there."));
    // The nominal static correction without modes: the component's own if
    // it has none.
    std::shared_ptr<const ReducedComponent> static_part = m.reduced;
    if (m.reduced->n_modes() > 0 || m.reduced->n_added() > 0 ||
        m.reduced->n_corrections() == 0)
      {
        auto scope  = timer_section(timer, "static correction modes");
        static_part = std::make_shared<ReducedComponent>(
          component,
          m.no_modes,
          m.reduced->stiffness_factorisation(),
          bodies.interface().contact_dofs(c),
          true,
          settings.rank_tolerance);
      }
    m.zone =
      std::make_unique<ZoneStaticCorrection>(component,
                                             names,
                                             ranges,
                                             static_part,
                                             T,
                                             bodies.interface().gap_operator(c),
                                             m.nominal_matrices.observed_dofs,
                                             settings.krylov,
                                             timer);
    m.zone_description = m.zone->describe();
  }


  // The parameter values of a component's Krylov static correction at
  // @p state (checked: the state changes its zones through them only).
  std::vector<double>
  ReducedOrderModel::zone_values(const ComponentModel &m,
                                 const SceneState     &state) const
  {
    const unsigned int  c = m.quantities.front().component;
    std::vector<double> values =
      values_of(m.zone_quantities, state, bodies.scene());
    const ParameterModel &model = m.zone->model();
    const auto            moduli =
      model.zone_materials(model.relative_changes(values)).first;
    for (unsigned int z = 0; z < moduli.size(); ++z)
      AssertThrow(std::abs(moduli[z] - state.zone_moduli[c][z]) <=
                    1e-12 * state.zone_moduli[c][z],
                  ExcMessage("The reduced model of component " +
                             bodies.component(c).name() +
                             " was built to vary its zone moduli through "
                             "its fuzzy parameters only; the state to solve "
                             "changes zone " +
                             bodies.scene().components[c].zones[z].name +
                             " otherwise."));
    return values;
  }


  // The reduced matrices of a component on the reanalysed basis
  // V(p) = [T Y(p), Psi]:
  //   K_r = [Y^T (T^T K T) Y, Y^T (T^T K Psi); sym., Psi^T K Psi],
  //   C_r = [C T Y, C Psi],  f_r,l = [Y^T T^T f_l, Psi^T f_l],
  //   O = [O T Y, O Psi],
  // with K = sum_z E_z(p) K_z, from the projections made offline.
  ReducedComponentMatrices
  ReducedOrderModel::reanalysed_matrices(const ComponentModel &m,
                                         const SceneState     &state) const
  {
    const unsigned int        c = m.quantities.front().component;
    const std::vector<double> values =
      values_of(m.quantities, state, bodies.scene());
    const std::vector<double> t =
      m.reanalysis->model().relative_changes(values);
    const auto materials = m.reanalysis->model().zone_materials(t);
    for (unsigned int z = 0; z < materials.first.size(); ++z)
      AssertThrow(
        std::abs(materials.first[z] - state.zone_moduli[c][z]) <=
            1e-12 * state.zone_moduli[c][z] &&
          std::abs(materials.second[z] - state.zone_densities[c][z]) <=
            1e-12 * state.zone_densities[c][z],
        ExcMessage("The reduced model of component " +
                   bodies.component(c).name() +
                   " was built to vary its zone materials through " +
                   "its fuzzy parameters only; the state to solve "
                   "changes zone " +
                   bodies.scene().components[c].zones[z].name + " otherwise."));

    const ReanalysedModes modes = m.reanalysis->online(t);
    const unsigned int    n_T   = modes.basis_size;
    const unsigned int    n_m   = modes.Y.n();
    // (0 unless the static correction enters by Galerkin projection)
    const unsigned int        n_s = m.C_psi.n();
    const unsigned int        k   = n_m + n_s;
    const std::vector<double> E   = materials.first;

    const FullMatrix<double> Y = block(modes.Y, 0, n_T, 0, n_m);
    // (Reanalysed bodies carry no weight: refused in the constructor.)
    ReducedComponentMatrices r = m.nominal_matrices.without_basis();

    // K_r
    r.stiffness.reinit(k, k);
    {
      const FullMatrix<double> KT =
        m.reanalysis->reduced_stiffness(t, modes.order);
      FullMatrix<double> KY(n_T, n_m), YKY(n_m, n_m);
      KT.mmult(KY, Y);
      Y.Tmmult(YKY, KY);
      for (unsigned int i = 0; i < n_m; ++i)
        for (unsigned int j = 0; j < n_m; ++j)
          r.stiffness(i, j) = 0.5 * (YKY(i, j) + YKY(j, i));
    }
    if (n_s > 0)
      {
        FullMatrix<double> TKpsi(n_T, n_s), D(n_s, n_s);
        for (unsigned int z = 0; z < E.size(); ++z)
          {
            TKpsi.add(E[z], block(m.T_K_psi[z], 0, n_T, 0, n_s));
            D.add(E[z], m.psi_K_psi[z]);
          }
        FullMatrix<double> YTKpsi(n_m, n_s);
        Y.Tmmult(YTKpsi, TKpsi);
        for (unsigned int i = 0; i < n_m; ++i)
          for (unsigned int j = 0; j < n_s; ++j)
            r.stiffness(i, n_m + j) = r.stiffness(n_m + j, i) = YTKpsi(i, j);
        for (unsigned int i = 0; i < n_s; ++i)
          for (unsigned int j = 0; j < n_s; ++j)
            r.stiffness(n_m + i, n_m + j) = 0.5 * (D(i, j) + D(j, i));
      }

    // C_r, f_r and the observation rows: [A(:, 0..n_T) Y, B], the rows of
    // an operator on the new basis
    const auto on_basis = [&](const FullMatrix<double> &A,
                              const FullMatrix<double> &B) {
      const unsigned int rows = A.m();
      FullMatrix<double> AY(rows, n_m), result(rows, k);
      if (rows == 0)
        return result;
      block(A, 0, rows, 0, n_T).mmult(AY, Y);
      for (unsigned int i = 0; i < rows; ++i)
        {
          for (unsigned int j = 0; j < n_m; ++j)
            result(i, j) = AY(i, j);
          for (unsigned int j = 0; j < n_s; ++j)
            result(i, n_m + j) = B(i, j);
        }
      return result;
    };
    r.gap_operator = on_basis(m.C_T, m.C_psi);
    for (unsigned int l = 0; l < m.T_f.size(); ++l)
      {
        Vector<double> f(k);
        for (unsigned int j = 0; j < n_m; ++j)
          for (unsigned int i = 0; i < n_T; ++i)
            f[j] += Y(i, j) * m.T_f[l][i];
        for (unsigned int j = 0; j < n_s; ++j)
          f[n_m + j] = m.psi_f[l][j];
        r.loads.push_back(std::move(f));
      }
    r.observation = on_basis(m.O_T, m.O_psi);
    return r;
  }
} // namespace FuzzyContact
