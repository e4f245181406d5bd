#include <fuzzycontact/base/input.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace FuzzyContact
{
  void
  FuzzyContactModelSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("mesh refinements",
                      "2",
                      Patterns::Integer(0, 6),
                      "Global refinements of every component mesh (2: "
                      "about 20k DoFs per component in the default scenes).");
    prm.enter_subsection("Reduced models");
    prm.declare_entry("static correction",
                      "true",
                      Patterns::Bool(),
                      "Add static correction modes for the contact and load "
                      "DoFs to each component's modes (else modes only, "
                      "as in the paper).");
    prm.declare_entry("zone correction",
                      "residual flexibility",
                      Patterns::Selection("residual flexibility|galerkin"),
                      "For zone moduli and densities (re-analysed modes): "
                      "keep the static correction's flexibility at its "
                      "nominal value ('residual flexibility', cheap) or "
                      "project the stiffness onto [re-analysed modes, static "
                      "correction modes] ('galerkin', more accurate, a dense "
                      "factorisation per evaluation).");
    prm.leave_subsection();
    ModalParameters::declare_parameters(prm);
    ReanalysisSettings::declare_parameters(prm);
    FL2CParameters::declare_parameters(prm);
  }


  void
  FuzzyContactModelSettings::parse_parameters(ParameterHandler &prm)
  {
    mesh_refinements = prm.get_integer("mesh refinements");
    prm.enter_subsection("Reduced models");
    static_correction = prm.get_bool("static correction");
    zone_correction   = prm.get("zone correction") == "galerkin"
                          ? ZoneCorrection::galerkin
                          : ZoneCorrection::residual_flexibility;
    prm.leave_subsection();
    modal.parse_parameters(prm);
    AssertThrow(modal.cutoff_frequency == 0,
                ExcMessage("Modal analysis: the fuzzy study needs a fixed "
                           "number of modes; set cutoff frequency = 0."));
    reanalysis.parse_parameters(prm);
    fl2c.parse_parameters(prm);
  }


  namespace
  {
    // Copies the block [rows, columns) of @p A.
    FullMatrix<double>
    block(const FullMatrix<double> &A,
          const unsigned int        row_begin,
          const unsigned int        n_rows,
          const unsigned int        column_begin,
          const unsigned int        n_columns);

    // The reduced matrices of the basis vectors [begin, begin + n) of @p r.
    ReducedComponentMatrices
    columns(const ReducedComponentMatrices &r,
            const unsigned int              begin,
            const unsigned int              n)
    {
      ReducedComponentMatrices part;
      part.stiffness = block(r.stiffness, begin, n, begin, n);
      part.gap_operator =
        block(r.gap_operator, 0, r.gap_operator.m(), begin, n);
      part.load.reinit(n);
      for (unsigned int i = 0; i < n; ++i)
        part.load[i] = r.load[begin + i];
      part.observed_dofs = r.observed_dofs;
      part.observation   = block(r.observation, 0, r.observation.m(), begin, n);
      return part;
    }

    // Copies the block [rows, columns) of @p A.
    FullMatrix<double>
    block(const FullMatrix<double> &A,
          const unsigned int        row_begin,
          const unsigned int        n_rows,
          const unsigned int        column_begin,
          const unsigned int        n_columns)
    {
      FullMatrix<double> B(n_rows, n_columns);
      for (unsigned int i = 0; i < n_rows; ++i)
        for (unsigned int j = 0; j < n_columns; ++j)
          B(i, j) = A(row_begin + i, column_begin + j);
      return B;
    }
  } // namespace


  FuzzyContactModel::FuzzyContactModel(
    const Scene                     &scene_,
    const FuzzyParameterSet         &fuzzy,
    const FuzzyContactModelSettings &settings,
    TimerOutput                     *timer)
      : scene(scene_)
      , fuzzy(fuzzy)
      , settings(settings)
  {
    AssertThrow(!scene.contact_pairs.empty(),
                ExcMessage("The fuzzy contact study needs a scene with a "
                           "contact pair."));
    const auto time = [&](const std::string &section) {
      return timer != nullptr
               ? std::make_unique<TimerOutput::Scope>(*timer, section)
               : std::unique_ptr<TimerOutput::Scope>();
    };

    // Meshes, matrices and the contact interface.
    for (const ComponentDescription &d : scene.components)
      {
        components.push_back(
          std::make_unique<Component>(d,
                                      scene.plane_model,
                                      settings.mesh_refinements,
                                      timer));
        component_pointers.push_back(components.back().get());
      }
    {
      auto scope = time("contact interface");
      interface = std::make_unique<ContactInterface>(scene, component_pointers);
    }
    report = interface->report_nodes(interface->report_node());
    observed =
      std::vector<std::vector<types::global_dof_index>>(components.size());
    for (const FaceNode *node :
         {&report.slave, &report.master[0], &report.master[1]})
      for (unsigned int d = 0; d < 2; ++d)
        observed[node->component].push_back(node->dofs[d]);
    nominal_gaps = interface->initial_gaps();
    nominal_mu   = interface->friction_coefficients();

    // What each fuzzy parameter acts on.
    models.resize(components.size());
    const auto &parameters = fuzzy.parameters();
    for (unsigned int i = 0; i < parameters.size(); ++i)
      {
        const SceneQuantity &q = parameters[i].quantity;
        switch (q.kind)
          {
            case SceneQuantity::Kind::youngs_modulus:
            case SceneQuantity::Kind::density:
              models[q.component].parameters.push_back(i);
              models[q.component].names.push_back(q.name);
              break;
            case SceneQuantity::Kind::load:
              {
                for (unsigned int c = 0; c < scene.components.size(); ++c)
                  for (unsigned int l = 0; l < scene.components[c].loads.size();
                       ++l)
                    AssertThrow((c == q.component && l == q.load) ||
                                  scene.components[c].loads[l].total_force == 0,
                                ExcMessage(
                                  "Fuzzy parameter " + q.name +
                                  ": a fuzzy load must be the only non-zero "
                                  "load of the scene (the study scales the "
                                  "load vector), but " +
                                  scene.components[c].name + "." +
                                  scene.components[c].loads[l].name +
                                  " is not zero."));
                nominal_load = q.value(scene);
                AssertThrow(nominal_load != 0,
                            ExcMessage("Fuzzy parameter " + q.name +
                                       ": the scene's value of the load is "
                                       "zero, so the load vector has no "
                                       "direction to scale; declare a "
                                       "non-zero total force."));
                load_parameter = i;
                break;
              }
            case SceneQuantity::Kind::friction:
            case SceneQuantity::Kind::gap:
              AssertThrow(scene.contact_pairs.size() == 1,
                          ExcMessage("Fuzzy parameter " + q.name +
                                     ": fuzzy friction and gaps are supported "
                                     "for scenes with one contact pair."));
              if (q.kind == SceneQuantity::Kind::friction)
                friction_parameter = i;
              else
                {
                  gap_parameter = i;
                  nominal_gap   = q.value(scene);
                }
              break;
          }
      }
    for (ComponentModel &m : models)
      {
        if (m.parameters.empty())
          continue;
        bool whole = true;
        for (const unsigned int i : m.parameters)
          {
            const SceneQuantity &q = parameters[i].quantity;
            whole                  = whole && q.zone < 0;
            if (q.kind == SceneQuantity::Kind::youngs_modulus && q.zone < 0)
              m.modulus_parameter = i;
          }
        m.treatment = whole ? Treatment::scaling : Treatment::hptp;
      }

    // Whether component c's static correction enters as a fixed residual
    // flexibility beside its re-analysed modes.
    const auto splits = [&](const unsigned int c) {
      return models[c].treatment == Treatment::hptp &&
             settings.zone_correction ==
               FuzzyContactModelSettings::ZoneCorrection::
                 residual_flexibility &&
             models[c].reduced->n_corrections() > 0;
    };

    // Modes, static correction and reduced matrices of every component.
    const ModalSolver                     solver(settings.modal);
    std::vector<ReducedComponentMatrices> nominal;
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        ComponentModel  &m         = models[c];
        const Component &component = *components[c];
        {
          auto scope = time("modes (ARPACK)");
          m.modes    = solver.solve(component.stiffness_matrix(),
                                 component.mass_matrix(),
                                 "Component " + component.name());
        }
        {
          auto scope = time("static correction modes");
          m.reduced =
            std::make_unique<ReducedComponent>(component,
                                               m.modes,
                                               interface->contact_dofs(c),
                                               settings.static_correction);
        }
        {
          auto scope = time("reduced matrices");
          m.nominal_matrices =
            m.reduced->matrices(interface->gap_operator(c), observed[c]);
        }
        // Residual flexibility: the static correction modes' part of a
        // re-analysed component stays (set below as the fixed part); only
        // its modal part will change. At the nominal point the split is
        // exact: the correction modes are K-orthogonal to the modes,
        // K_r = diag(Lambda, I).
        if (splits(c))
          nominal.push_back(
            columns(m.nominal_matrices, 0, m.reduced->n_modes()));
        else
          nominal.push_back(m.nominal_matrices);

        if (m.treatment != Treatment::hptp)
          continue;

        // Zone parameters: the parameter-independent HPTP, its order chosen
        // from the tolerance at the corners of the parameters' support box.
        m.reanalysis = std::make_unique<ParameterIndependentReanalysis>();
        m.reanalysis->offline(component,
                              m.modes,
                              m.names,
                              settings.reanalysis.max_order,
                              settings.reanalysis.truncation_tolerance,
                              settings.reanalysis.cluster_gap,
                              timer);
        {
          auto scope = time("reanalysis order selection");
          std::vector<std::vector<double>> corners;
          const unsigned int               n = m.parameters.size();
          for (unsigned long corner = 0; corner < (1ul << n); ++corner)
            {
              std::vector<double> values(n);
              for (unsigned int k = 0; k < n; ++k)
                {
                  const Interval support =
                    parameters[m.parameters[k]].number.alpha_cut(0);
                  values[k] = (corner >> k) & 1 ? support.upper : support.lower;
                }
              corners.push_back(m.reanalysis->model().relative_changes(values));
            }
          m.reanalysis->select_order(corners,
                                     settings.reanalysis.order_tolerance,
                                     settings.reanalysis.residual_check);
        }

        // What turns Y(p) into reduced matrices: C T, the rows of T at the
        // observed DoFs, T^T f, and for the Galerkin correction also
        // T^T K_z Psi, Psi^T K_z Psi, C Psi, the rows of Psi and Psi^T f.
        auto                scope = time("reanalysis projections");
        const ReducedBasis &T     = m.reanalysis->basis();
        const unsigned int  n_m   = m.reduced->n_modes();
        const bool          galerkin =
          settings.zone_correction ==
          FuzzyContactModelSettings::ZoneCorrection::galerkin;
        const unsigned int n_s = galerkin ? m.reduced->n_corrections() : 0;
        const unsigned int n_T = T.size();
        Vector<double>     Kt(component.n_dofs());
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
            m.psi_K_psi.push_back(
              n_s > 0 ? block(m.reduced->zone_stiffness(z), n_m, n_s, n_m, n_s)
                      : FullMatrix<double>());
          }
        const SparseMatrix<double> &C = interface->gap_operator(c);
        m.C_T                         = T.apply(C);
        const FullMatrix<double> C_V  = m.reduced->project_rows(C);
        m.C_psi                       = block(C_V, 0, C_V.m(), n_m, n_s);
        m.O_T.reinit(observed[c].size(), n_T);
        for (unsigned int r = 0; r < observed[c].size(); ++r)
          for (unsigned int i = 0; i < n_T; ++i)
            m.O_T(r, i) = T[i][observed[c][r]];
        const FullMatrix<double> O_V = m.reduced->rows(observed[c]);
        m.O_psi                      = block(O_V, 0, O_V.m(), n_m, n_s);
        m.T_f                        = T.project(component.load_vector());
        const Vector<double> V_f = m.reduced->project(component.load_vector());
        m.psi_f.reinit(n_s);
        for (unsigned int j = 0; j < n_s; ++j)
          m.psi_f[j] = V_f[n_m + j];
      }
    {
      auto scope    = time("reduced contact flexibility");
      reduced_model = std::make_unique<ReducedContactModel>(std::move(nominal),
                                                            nominal_gaps,
                                                            nominal_mu);
      for (unsigned int c = 0; c < models.size(); ++c)
        if (splits(c))
          reduced_model->set_fixed_part(
            c,
            columns(models[c].nominal_matrices,
                    models[c].reduced->n_modes(),
                    models[c].reduced->n_corrections()));
    }
  }


  void
  FuzzyContactModel::set_reuse_factorisations(const bool reuse_)
  {
    reuse = reuse_;
  }


  std::vector<std::string>
  FuzzyContactModel::output_names()
  {
    return {"ux", "uy", "Fn", "Ft"};
  }


  void
  FuzzyContactModel::check_values(const std::vector<double> &values) const
  {
    AssertThrow(values.size() == fuzzy.parameters().size(),
                ExcMessage("The model expects one value per fuzzy "
                           "parameter."));
    for (unsigned int i = 0; i < values.size(); ++i)
      AssertThrow(std::isfinite(values[i]),
                  ExcMessage("Fuzzy parameter " +
                             fuzzy.parameters()[i].quantity.name +
                             ": the value to evaluate is not finite."));
  }


  std::vector<double>
  FuzzyContactModel::relative_changes(const ComponentModel      &model,
                                      const std::vector<double> &values) const
  {
    std::vector<double> absolute;
    for (const unsigned int i : model.parameters)
      absolute.push_back(values[i]);
    return model.reanalysis->model().relative_changes(absolute);
  }


  // The reduced matrices of a component on the reanalysed basis
  // V(p) = [T Y(p), Psi]:
  //   K_r = [Y^T (T^T K T) Y, Y^T (T^T K Psi); sym., Psi^T K Psi],
  //   C_r = [C T Y, C Psi],  f_r = [Y^T T^T f, Psi^T f],  O = [O T Y, O Psi],
  // with K = sum_z E_z(p) K_z, from the projections made offline.
  ReducedComponentMatrices
  FuzzyContactModel::reanalysed_matrices(
    const ComponentModel      &m,
    const std::vector<double> &values) const
  {
    const std::vector<double> t     = relative_changes(m, values);
    const ReanalysedModes     modes = m.reanalysis->online(t);
    const unsigned int        n_T   = modes.basis_size;
    const unsigned int        n_m   = modes.Y.n();
    // (0 unless the static correction enters by Galerkin projection)
    const unsigned int        n_s = m.C_psi.n();
    const unsigned int        k   = n_m + n_s;
    const std::vector<double> E = m.reanalysis->model().zone_materials(t).first;

    const FullMatrix<double> Y = block(modes.Y, 0, n_T, 0, n_m);
    ReducedComponentMatrices r;

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

    // C_r, f_r and the observation rows
    // [A(:, 0..n_T) Y, B]: the rows of an operator on the new basis
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
    r.load.reinit(k);
    for (unsigned int j = 0; j < n_m; ++j)
      for (unsigned int i = 0; i < n_T; ++i)
        r.load[j] += Y(i, j) * m.T_f[i];
    for (unsigned int j = 0; j < n_s; ++j)
      r.load[n_m + j] = m.psi_f[j];
    r.observed_dofs = m.nominal_matrices.observed_dofs;
    r.observation   = on_basis(m.O_T, m.O_psi);
    return r;
  }


  std::vector<double>
  FuzzyContactModel::reduced(const std::vector<double> &values)
  {
    check_values(values);

    std::vector<double> scales(components.size(), 1.);
    for (unsigned int c = 0; c < models.size(); ++c)
      {
        const ComponentModel &m = models[c];
        if (m.treatment == Treatment::scaling && m.modulus_parameter >= 0)
          scales[c] =
            values[m.modulus_parameter] /
            fuzzy.parameters()[m.modulus_parameter].quantity.value(scene);
        else if (m.treatment == Treatment::hptp)
          reduced_model->replace_component(c, reanalysed_matrices(m, values));
      }
    reduced_model->set_stiffness_scales(scales);

    ContactProblem &problem = reduced_model->problem();
    problem.g_initial       = nominal_gaps;
    if (gap_parameter >= 0)
      problem.shift_gaps(values[gap_parameter] - nominal_gap);
    problem.mu = nominal_mu;
    if (friction_parameter >= 0)
      problem.set_friction_coefficient(values[friction_parameter]);
    const double load_factor =
      load_parameter >= 0 ? values[load_parameter] / nominal_load : 1.;

    const ContactState state =
      FL2CSolver(settings.fl2c).solve(problem, load_factor, 1, "FL2C");
    const ContactSolution s =
      reduced_model->solution(state, load_factor, &report, "fl2c");
    return {s.slave_displacement[0],
            s.slave_displacement[1],
            s.normal_force,
            s.tangential_force};
  }


  std::vector<double>
  FuzzyContactModel::full_order(const std::vector<double> &values)
  {
    check_values(values);
    const SceneState changed = fuzzy.state(scene, values);
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        const std::vector<double> &moduli    = changed.zone_moduli[c];
        const std::vector<double> &densities = changed.zone_densities[c];
        if (moduli != components[c]->zone_moduli() ||
            densities != components[c]->zone_densities())
          components[c]->set_zone_materials(moduli, densities);
      }
    interface->set_friction_coefficient(changed.friction_coefficients[0]);
    interface->set_gap_offset(
      gap_parameter >= 0 ? values[gap_parameter] - nominal_gap : 0.);
    const double load_factor =
      load_parameter >= 0 ? values[load_parameter] / nominal_load : 1.;

    ContactSolution s;
    if (reuse)
      {
        if (full == nullptr)
          {
            // Factorise the nominal stiffness first: every later stiffness
            // that is a multiple of it then reuses these factorisations, on
            // every MPI rank alike, so all ranks compute the same numbers.
            std::vector<std::vector<double>> moduli, densities;
            for (const auto &c : components)
              {
                moduli.push_back(c->zone_moduli());
                densities.push_back(c->zone_densities());
                std::vector<double> E, rho;
                for (const MaterialZone &z : c->description().zones)
                  {
                    E.push_back(z.youngs_modulus);
                    rho.push_back(z.density);
                  }
                c->set_zone_materials(E, rho);
              }
            full = std::make_unique<FullOrderContact>(component_pointers,
                                                      *interface);
            full->set_displacement_fields(false);
            full->solve(&report);
            for (unsigned int c = 0; c < components.size(); ++c)
              components[c]->set_zone_materials(moduli[c], densities[c]);
          }
        full->set_load_factor(load_factor);
        s = full->solve(&report);
      }
    else
      {
        // An independent analysis: new factorisations, refined fields.
        FullOrderContact analysis(component_pointers, *interface);
        analysis.set_load_factor(load_factor);
        s = analysis.solve(&report);
      }
    return {s.slave_displacement[0],
            s.slave_displacement[1],
            s.normal_force,
            s.tangential_force};
  }


  std::vector<unsigned int>
  FuzzyContactModel::n_dofs() const
  {
    std::vector<unsigned int> n;
    for (const auto &c : components)
      n.push_back(c->n_dofs());
    return n;
  }


  std::vector<unsigned int>
  FuzzyContactModel::reanalysis_orders() const
  {
    std::vector<unsigned int> n;
    for (const ComponentModel &m : models)
      n.push_back(m.reanalysis ? m.reanalysis->order() : 0);
    return n;
  }


  std::string
  FuzzyContactModel::describe() const
  {
    std::ostringstream out;
    for (unsigned int c = 0; c < components.size(); ++c)
      {
        const ComponentModel &m = models[c];
        out << "  " << components[c]->name() << ": " << components[c]->n_dofs()
            << " DoFs, " << m.reduced->n_modes() << " modes ("
            << std::setprecision(4) << m.modes.frequencies()[0] << " to "
            << m.modes.frequencies().back() << " Hz) + "
            << m.reduced->n_corrections() << " static correction modes; ";
        switch (m.treatment)
          {
            case Treatment::fixed:
              out << "no fuzzy material";
              break;
            case Treatment::scaling:
              out << "fuzzy";
              for (const std::string &n : m.names)
                out << " " << n;
              out << ": exact scaling of the stiffness (modes unchanged)";
              break;
            case Treatment::hptp:
              out << "fuzzy";
              for (const std::string &n : m.names)
                out << " " << n;
              out << ": parameter-independent HPTP, order "
                  << m.reanalysis->order() << " ("
                  << m.reanalysis->basis_size(m.reanalysis->order())
                  << " basis vectors)";
              break;
          }
        out << "\n";
      }
    out << "  contact: " << interface->n_nodes()
        << " slave nodes; report node (" << report.slave.position[0] << ", "
        << report.slave.position[1] << ")\n";
    return out.str();
  }
} // namespace FuzzyContact
