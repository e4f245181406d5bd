#include <fuzzycontact/base/progress.h>
#include <fuzzycontact/base/timer_section.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/base/exceptions.h>

#include "reduced_order_model_component.h"
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    // The reduced matrices of the basis vectors [begin, begin + n) of @p r.
    ReducedComponentMatrices
    columns(const ReducedComponentMatrices &r,
            const unsigned int              begin,
            const unsigned int              n)
    {
      ReducedComponentMatrices part = r.without_basis();
      part.stiffness                = block(r.stiffness, begin, n, begin, n);
      part.gap_operator =
        block(r.gap_operator, 0, r.gap_operator.m(), begin, n);
      for (const Vector<double> &load : r.loads)
        {
          Vector<double> f(n);
          for (unsigned int i = 0; i < n; ++i)
            f[i] = load[begin + i];
          part.loads.push_back(std::move(f));
        }
      part.observation = block(r.observation, 0, r.observation.m(), begin, n);
      // The weight's exact responses, in the first part only.
      if (begin > 0)
        {
          part.weight_load = -1;
          part.weight_gaps.clear();
          part.weight_observation.clear();
          part.weight_rigid_loads.clear();
        }
      return part;
    }

    // s if @p values = s * @p nominal for one factor s > 0, else 0.
    double
    common_factor(const std::vector<double> &values,
                  const std::vector<double> &nominal)
    {
      const double s = values[0] / nominal[0];
      for (unsigned int z = 0; z < values.size(); ++z)
        if (std::abs(values[z] / nominal[z] - s) > 1e-14 * s)
          return 0;
      return s;
    }
  } // namespace


  ReducedOrderModel::ReducedOrderModel(
    const ContactScene                 &bodies,
    const std::vector<ModalBasis>      &modes,
    const ObservedDofs                 &observed,
    const std::vector<VaryingQuantity> &varying,
    const ReducedModelSettings         &settings,
    TimerOutput                        *timer,
    const MPI_Comm                      comm)
      : bodies(bodies)
      , settings(settings)
      , solver(std::make_unique<FL2CSolver>())
      , varying(varying)
      , comm(comm)
  {
    const unsigned int n_c = bodies.n_components();
    AssertThrow(modes.size() == n_c && observed.size() == n_c,
                ExcMessage("ReducedOrderModel: one modal basis and one list "
                           "of observed DoFs per component are expected."));
    const ContactInterface &interface = bodies.interface();
    const SceneState        scene_values(bodies.scene());
    for (unsigned int c = 0; c < n_c; ++c)
      AssertThrow(bodies.component(c).zone_moduli() ==
                      scene_values.zone_moduli[c] &&
                    bodies.component(c).zone_densities() ==
                      scene_values.zone_densities[c],
                  ExcMessage("ReducedOrderModel: component " +
                             bodies.component(c).name() +
                             " is not at the scene's materials; a reduced "
                             "model is built at the nominal state."));

    // Which components need a reanalysis: those with a varying modulus of
    // a single zone (a density changes no static stiffness: with gravity,
    // the weight's zone responses follow it exactly).
    const bool gravity = bodies.scene().gravity.norm() > 0;
    for (unsigned int c = 0; c < n_c; ++c)
      {
        auto m               = std::make_unique<ComponentModel>();
        m->nominal_moduli    = bodies.component(c).zone_moduli();
        m->nominal_densities = bodies.component(c).zone_densities();
        for (const VaryingQuantity &v : varying)
          if (v.quantity.is_material() && v.quantity.component == c)
            {
              m->quantities.push_back(v.quantity);
              m->hptp = m->hptp || v.quantity.reshapes_stiffness();
            }
        // The weight's exact response K^{-1} w would change with a
        // re-analysed stiffness (SceneQuantity::parse() refuses this).
        AssertThrow(!m->hptp || !gravity,
                    ExcMessage("ReducedOrderModel: component " +
                               bodies.component(c).name() +
                               " carries its weight (the scene has gravity), "
                               "whose response the reanalysis of its zone "
                               "moduli does not follow."));
        m->modes = modes[c];
        models.push_back(std::move(m));
      }

    // With several ranks, each component is built on one (builders()),
    // with its reanalysis, and its blocks of the reduced contact problem
    // are formed there and sent to all.
    owner             = builders(n_c, varying, comm);
    const bool spread = Utilities::MPI::job_supports_mpi() &&
                        Utilities::MPI::n_mpi_processes(comm) > 1;
    const unsigned int rank =
      spread ? Utilities::MPI::this_mpi_process(comm) : 0;
    for (unsigned int c = 0; c < n_c; ++c)
      if (owner[c] == rank)
        build_component(*models[c], c, observed[c], timer);
    std::vector<ReducedComponentMatrices> nominal;
    for (unsigned int c = 0; c < n_c; ++c)
      {
        ComponentModel &m = *models[c];
        // Residual flexibility: the static correction modes' part of a
        // re-analysed component stays (set below as the fixed part); only
        // its modal part will change. At the nominal point the split is
        // exact: the correction modes are K-orthogonal to the modes,
        // K_r = diag(Lambda, I).
        m.split =
          m.hptp &&
          settings.zone_correction ==
            ReducedModelSettings::ZoneCorrection::residual_flexibility &&
          m.n_corrections > 0;
        if (m.hptp && owner[c] == rank)
          build_reanalysis(m, c, timer);
        // (A Krylov static correction starts at the nominal values: its
        // active part; the inert part is set below as the fixed part.)
        nominal.push_back(
          m.split ? columns(m.nominal_matrices, 0, m.n_modes)
          : m.zone != nullptr
            ? m.zone->matrices(zone_values(m, scene_values), m.nominal_matrices)
            : m.nominal_matrices);
      }

    // (With several ranks, each forms its components' blocks, and then
    // they are exchanged: this section includes the wait for the others.)
    auto scope = timer_section(timer, "reduced contact flexibility");
    if (spread)
      {
        reduced = std::make_unique<ReducedContactModel>(
          std::move(nominal),
          interface.initial_gaps(),
          interface.friction_coefficients(),
          owner,
          comm);
        for (unsigned int c = 0; c < n_c; ++c)
          exchange_component(*models[c], owner[c], comm);
      }
    else
      reduced = std::make_unique<ReducedContactModel>(
        std::move(nominal),
        interface.initial_gaps(),
        interface.friction_coefficients());
    reduced->set_load_stages(bodies.scene().load_stages);
    for (unsigned int c = 0; c < n_c; ++c)
      if (models[c]->split)
        reduced->set_fixed_part(c,
                                columns(models[c]->nominal_matrices,
                                        models[c]->n_modes,
                                        models[c]->n_corrections));
      else
        set_inert_part(c);
  }


  // The inert part of a Krylov static correction (K_r = I whatever the
  // parameters) as the fixed part of its component, or none.
  void
  ReducedOrderModel::set_inert_part(const unsigned int c)
  {
    const ComponentModel &m = *models[c];
    if (m.zone == nullptr)
      return;
    if (m.zone->size() > m.zone->check().n_active)
      reduced->set_fixed_part(c, m.zone->fixed_matrices(m.nominal_matrices));
    else
      reduced->clear_fixed_part(c);
  }


  bool
  ReducedOrderModel::solves_here() const
  {
    for (const auto &m : models)
      if (m->hptp && m->reanalysis == nullptr && m->zone == nullptr)
        return false;
    return true;
  }


  // The reduced basis of component c from the shared factorisation of its
  // stiffness, and its nominal reduced matrices.
  void
  ReducedOrderModel::build_component(
    ComponentModel                             &m,
    const unsigned int                          c,
    const std::vector<types::global_dof_index> &observed,
    TimerOutput                                *timer)
  {
    const Component        &component = bodies.component(c);
    const ContactInterface &interface = bodies.interface();
    {
      const auto factorisation = bodies.stiffness_factorisation(c, timer);
      auto       scope = timer_section(timer, "static correction modes");
      m.reduced        = std::make_shared<ReducedComponent>(component,
                                                     m.modes,
                                                     factorisation,
                                                     interface.contact_dofs(c),
                                                     settings.static_correction,
                                                     settings.rank_tolerance);
    }
    {
      auto scope = timer_section(timer, "reduced matrices");
      m.nominal_matrices =
        m.reduced->matrices(interface.gap_operator(c), observed);
    }
    m.n_modes       = m.reduced->n_modes();
    m.n_corrections = m.reduced->n_corrections();
    ProgressLines::stage("static correction of " + component.name() + " done",
                         c + 1,
                         bodies.n_components());
  }


  // Sends what the other ranks need of a component built on rank @p owner
  // besides its blocks of the reduced contact problem (ReducedContactModel
  // sends those): the sizes of its basis and of its reanalysis, and its
  // eigenvalues (for the description).
  void
  ReducedOrderModel::exchange_component(ComponentModel    &m,
                                        const unsigned int owner,
                                        const MPI_Comm     comm)
  {
    const std::vector<unsigned int> sizes =
      Utilities::MPI::broadcast(comm,
                                std::vector<unsigned int>{m.n_modes,
                                                          m.n_corrections,
                                                          m.reanalysis_order,
                                                          m.reanalysis_vectors},
                                owner);
    m.n_modes            = sizes[0];
    m.n_corrections      = sizes[1];
    m.reanalysis_order   = sizes[2];
    m.reanalysis_vectors = sizes[3];
    m.modes.eigenvalues =
      Utilities::MPI::broadcast(comm, m.modes.eigenvalues, owner);
    m.zone_description =
      Utilities::MPI::broadcast(comm, m.zone_description, owner);
  }


  unsigned int
  ReducedOrderModel::add_snapshots(
    const std::vector<std::vector<Vector<double>>> &fields,
    TimerOutput                                    *timer)
  {
    AssertDimension(fields.size(), models.size());
    const bool spread = Utilities::MPI::job_supports_mpi() &&
                        Utilities::MPI::n_mpi_processes(comm) > 1;
    const unsigned int rank =
      spread ? Utilities::MPI::this_mpi_process(comm) : 0;
    auto         scope = timer_section(timer, "model made richer (snapshots)");
    unsigned int added = 0;
    for (unsigned int c = 0; c < models.size(); ++c)
      {
        ComponentModel &m = *models[c];
        if (owner[c] == rank && !fields[c].empty())
          {
            if (m.hptp)
              {
                // The Krylov static correction, if the component does not
                // have it yet: its residual flexibility (kept nominal) or
                // its Galerkin form on T Y(p) cannot take snapshots.
                if (m.zone == nullptr)
                  {
                    build_zone_correction(m, c, timer);
                    if (m.split)
                      reduced->clear_fixed_part(c);
                    m.split = false;
                  }
                added += m.zone->add_vectors(fields[c]);
                m.zone_description = m.zone->describe();
                set_inert_part(c);
              }
            else
              {
                const unsigned int n = m.reduced->add_vectors(fields[c]);
                if (n > 0)
                  m.nominal_matrices =
                    m.reduced->matrices(bodies.interface().gap_operator(c),
                                        m.nominal_matrices.observed_dofs);
                added += n;
              }
          }
        // The blocks of a component not re-analysed are those of its
        // nominal matrices (scaled per state): formed where it was built,
        // sent to all. A re-analysed one is replaced per state.
        if (!m.hptp)
          {
            const unsigned int changed =
              spread
                ? Utilities::MPI::broadcast(comm,
                                            owner[c] == rank ? m.reduced->size()
                                                             : 0u,
                                            owner[c])
                : m.reduced->size();
            if (changed != m.n_modes + m.n_corrections + m.n_added)
              {
                if (spread)
                  reduced->replace_component(c,
                                             m.nominal_matrices,
                                             owner[c],
                                             comm);
                else
                  reduced->replace_component(c, m.nominal_matrices);
                m.n_added = changed - m.n_modes - m.n_corrections;
              }
          }
        else if (spread)
          m.zone_description =
            Utilities::MPI::broadcast(comm, m.zone_description, owner[c]);
      }
    return spread ? Utilities::MPI::sum(added, comm) : added;
  }


  const ZoneCorrectionCheck *
  ReducedOrderModel::zone_correction_check(const unsigned int c) const
  {
    AssertIndexRange(c, models.size());
    return models[c]->zone != nullptr ? &models[c]->zone->check() : nullptr;
  }


  ReducedOrderModel::~ReducedOrderModel() = default;


  void
  ReducedOrderModel::set_state(const SceneState &state)
  {
    AssertThrow(solves_here(),
                ExcMessage("ReducedOrderModel: this MPI rank does not hold "
                           "the reanalysis of every re-analysed component "
                           "(they were built on the first rank); it cannot "
                           "solve."));
    const ContactInterface &interface = bodies.interface();
    AssertThrow(state.zone_moduli.size() == models.size(),
                ExcMessage("ReducedOrderModel: the state is not one of this "
                           "scene."));
    std::vector<double> scales(models.size(), 1.);
    for (unsigned int c = 0; c < models.size(); ++c)
      {
        const ComponentModel &m = *models[c];
        if (m.hptp)
          {
            reduced->replace_component(
              c,
              m.zone != nullptr
                ? m.zone->matrices(zone_values(m, state), m.nominal_matrices)
                : reanalysed_matrices(m, state));
            continue;
          }
        // Moduli that are the nominal ones times one factor scale the
        // stiffness exactly. Densities do not change the static stiffness
        // (nor the span of the modes it was reduced with); with gravity the
        // weight follows them through its exact zone responses.
        scales[c] = common_factor(state.zone_moduli[c], m.nominal_moduli);
        AssertThrow(scales[c] > 0,
                    ExcMessage("The reduced model of component " +
                               bodies.component(c).name() +
                               " has no reanalysis: it represents changes of "
                               "the moduli of all its zones by one factor "
                               "only, but the state to solve changes its "
                               "zones differently."));
      }
    reduced->set_stiffness_scales(scales);
    reduced->set_zone_densities(state.zone_densities);
    reduced->set_load_forces(state.load_forces);
    // (Per slave node, so only when they change: a study that varies
    // neither sets them once.)
    if (contact_conditions_set && state.gap_offsets == gap_offsets &&
        state.friction_coefficients == friction_coefficients)
      return;
    ContactProblem &problem = reduced->problem();
    problem.g_initial       = interface.initial_gaps(state.gap_offsets);
    problem.mu  = interface.friction_coefficients(state.friction_coefficients);
    gap_offsets = state.gap_offsets;
    friction_coefficients  = state.friction_coefficients;
    contact_conditions_set = true;
  }


  unsigned int
  ReducedOrderModel::n_modes(const unsigned int c) const
  {
    AssertIndexRange(c, models.size());
    return models[c]->n_modes;
  }


  unsigned int
  ReducedOrderModel::n_corrections(const unsigned int c) const
  {
    AssertIndexRange(c, models.size());
    return models[c]->n_corrections;
  }


  std::vector<unsigned int>
  ReducedOrderModel::reanalysis_orders() const
  {
    std::vector<unsigned int> n;
    for (const auto &m : models)
      n.push_back(m->hptp ? m->reanalysis_order : 0);
    return n;
  }


  std::string
  ReducedOrderModel::describe() const
  {
    std::ostringstream out;
    for (unsigned int c = 0; c < models.size(); ++c)
      {
        const ComponentModel &m         = *models[c];
        const Component      &component = bodies.component(c);
        out << "  " << component.name() << ": " << component.n_dofs()
            << " DoFs";
        // (A mesh file refined by the default of the key: its cells are
        // 4^r of the file's, which a user should see.)
        const unsigned int refinements =
          component.triangulation().n_levels() - 1;
        if (refinements > 0)
          out << " (" << component.triangulation().n_active_cells()
              << " cells: its mesh refined " << refinements
              << " time(s), key 'mesh refinements')";
        out << ", ";
        if (m.n_modes == 0)
          out << "no modes, ";
        else
          out << m.n_modes << " modes (" << std::setprecision(4)
              << m.modes.frequencies()[0] << " to "
              << m.modes.frequencies().back() << " Hz) + ";
        out << m.n_corrections << " static correction modes; ";
        if (m.quantities.empty())
          out << "no fuzzy material";
        else
          {
            out << "fuzzy";
            for (const SceneQuantity &q : m.quantities)
              out << " " << q.name;
            if (m.hptp && !m.zone_description.empty())
              {
                out << ": " << m.zone_description;
                if (m.reanalysis_order > 0)
                  out << "; modes by the parameter-independent HPTP, order "
                      << m.reanalysis_order << " (" << m.reanalysis_vectors
                      << " basis vectors)";
              }
            else if (m.hptp)
              {
                out << ": parameter-independent HPTP, order "
                    << m.reanalysis_order << " (" << m.reanalysis_vectors
                    << " basis vectors";
                // (On the rank that built it: how Lee's systems were solved.)
                if (m.reanalysis != nullptr)
                  {
                    const auto &cost = m.reanalysis->derivative_cost();
                    out << "; Lee's derivatives: ";
                    if (cost.method == DerivativeSolver::deflated_cg)
                      out << cost.systems << " systems by deflated CG, "
                          << cost.cg_iterations << " steps";
                    if (cost.factorisations > 0)
                      out << (cost.method == DerivativeSolver::deflated_cg
                                ? ", "
                                : "")
                          << cost.factorisations
                          << " bordered matrices factorised";
                  }
                out << ")";
              }
            else
              {
                // (A density enters through the weight alone.)
                bool moduli = false, densities = false;
                for (const SceneQuantity &q : m.quantities)
                  (q.kind == SceneQuantity::Kind::density ? densities
                                                          : moduli) = true;
                if (moduli)
                  out << ": exact scaling of the stiffness"
                      << (m.n_modes > 0 ? " (modes unchanged)" : "");
                if (densities)
                  out << (moduli ? "; " : ": ")
                      << "the weight's exact zone responses, times the "
                         "densities";
              }
          }
        out << "\n";
      }
    return out.str();
  }


  std::vector<Vector<double>>
  ReducedOrderModel::displacement_fields(const ContactSolution &s) const
  {
    const std::vector<Vector<double>> q = reduced->coordinates(s.p, 1.);
    std::vector<Vector<double>>       u(models.size());
    for (unsigned int c = 0; c < models.size(); ++c)
      {
        AssertThrow(!models[c]->hptp,
                    ExcMessage("ReducedOrderModel: the displacement field of "
                               "a re-analysed component is not available."));
        AssertThrow(models[c]->reduced != nullptr,
                    ExcMessage("ReducedOrderModel: the basis of component " +
                               bodies.component(c).name() +
                               " was built on another MPI rank; its "
                               "displacement field is not available here."));
        models[c]->reduced->expand(q[c], u[c]);
        // The weight's exact response.
        const std::vector<double> a = reduced->weight_coefficients(c);
        for (unsigned int z = 0; z < a.size(); ++z)
          u[c].add(a[z], models[c]->reduced->weight_responses()[z]);
      }
    // The free motions of the bodies held by contact alone.
    unsigned int first = 0;
    for (unsigned int c = 0; c < models.size(); ++c)
      {
        const Component &component = bodies.component(c);
        for (unsigned int j = 0; j < component.free_motions().size(); ++j)
          u[c].add(s.rigid[first + j], component.free_motions()[j]);
        first += component.free_motions().size();
      }
    return u;
  }
} // namespace FuzzyContact
