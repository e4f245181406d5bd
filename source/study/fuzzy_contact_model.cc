#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/limits.h>
#include <fuzzycontact/base/timer_section.h>
#include <fuzzycontact/contact/static_equilibrium.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <boost/serialization/string.hpp>
#include <boost/serialization/vector.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  void
  FuzzyContactModelSettings::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("mesh refinements",
                      "2",
                      Patterns::Integer(0, 6),
                      "Global refinements of every component mesh, a mesh "
                      "file's too: each makes four cells of every cell (2: "
                      "about 20k DoFs per component in the default scenes; "
                      "a Gmsh mesh sized for its contact wants 0).");
    prm.declare_entry("contact solver",
                      "fl2c",
                      Patterns::Selection(contact_solver_names()),
                      "The contact solver of the reduced model: fl2c (the "
                      "paper's fuzzy regulators, with the coarse correction "
                      "of subsection FL2C) or reduced exact (the primal-dual "
                      "active set method of subsection Exact contact "
                      "solver).");
    ContactFormulation::declare_sliding_limit(prm);
    prm.enter_subsection("Reduced models");
    prm.declare_entry("static correction",
                      "true",
                      Patterns::Bool(),
                      "Add static correction modes for the contact and load "
                      "DoFs to each component's modes (else modes only, "
                      "as in the paper).");
    prm.declare_entry("zone correction",
                      "krylov",
                      Patterns::Selection(
                        "krylov|residual flexibility|galerkin"),
                      "For zone moduli: re-analyse the static correction by "
                      "Krylov vectors (K0^-1 K_z)^j K0^-1 E, compressed, "
                      "until the contact flexibility at the corners of the "
                      "fuzzy box is within 'zone correction tolerance' of "
                      "the exact one ('krylov'; no modes needed); or the "
                      "paper's re-analysed modes with the static correction's "
                      "flexibility kept at its nominal value ('residual "
                      "flexibility', cheap but wrong by the change of that "
                      "flexibility) or projected onto [re-analysed modes, "
                      "static correction modes] ('galerkin', a dense "
                      "factorisation per evaluation).");
    prm.declare_entry("zone correction tolerance",
                      "1e-8",
                      Patterns::Double(0),
                      "krylov: the relative error (Frobenius norm) of a "
                      "re-analysed component's contact flexibility and load "
                      "gaps at every corner of the fuzzy box, against exact "
                      "factorisations there, that the Krylov vectors must "
                      "reach.");
    prm.declare_entry("zone correction max degree",
                      "8",
                      Patterns::Integer(1, 50),
                      "krylov: the highest power j of K0^-1 K_z in the "
                      "Krylov vectors.");
    prm.declare_entry("modes",
                      "when needed",
                      Patterns::Selection("when needed|always"),
                      "'when needed': no modal analysis when the static "
                      "correction is on and every fuzzy parameter only "
                      "scales a body's stiffness (P1.E) or a load, or is a "
                      "friction coefficient or a gap: the static correction "
                      "alone is then exact. 'always': compute the modes "
                      "anyway (the paper's reduced basis).");
    prm.leave_subsection();
    ModalParameters::declare_parameters(prm);
    ReanalysisSettings::declare_parameters(prm);
    FL2CParameters::declare_parameters(prm);
    ActiveSetParameters::declare_parameters(prm);
  }


  void
  FuzzyContactModelSettings::parse_parameters(ParameterHandler &prm)
  {
    mesh_refinements = prm.get_integer("mesh refinements");
    contact_solver   = prm.get("contact solver");
    sliding_limit    = ContactFormulation::parse_sliding_limit(prm);
    prm.enter_subsection("Reduced models");
    reduced.static_correction         = prm.get_bool("static correction");
    const std::string zone_correction = prm.get("zone correction");
    reduced.zone_correction =
      zone_correction == "galerkin"
        ? ReducedModelSettings::ZoneCorrection::galerkin
      : zone_correction == "krylov"
        ? ReducedModelSettings::ZoneCorrection::krylov
        : ReducedModelSettings::ZoneCorrection::residual_flexibility;
    reduced.krylov.tolerance =
      Input::in_range(prm.get_double("zone correction tolerance"),
                      1e-15,
                      1e-1,
                      "Reduced models: zone correction tolerance",
                      "a relative error between 1e-15 and 0.1");
    reduced.krylov.max_degree = prm.get_integer("zone correction max degree");
    modes_when_needed         = (prm.get("modes") == "when needed");
    prm.leave_subsection();
    modal.parse_parameters(prm);
    AssertThrow(modal.cutoff_frequency == 0,
                ExcMessage("Modal analysis: the fuzzy study needs a fixed "
                           "number of modes; set cutoff frequency = 0."));
    reduced.reanalysis.parse_parameters(prm);
    fl2c.parse_parameters(prm);
    exact.parse_parameters(prm);
  }


  FuzzyContactModel::FuzzyContactModel(
    const Scene                     &scene_,
    const FuzzyParameterSet         &fuzzy,
    const std::vector<std::string>  &output_names,
    const FuzzyContactModelSettings &settings,
    TimerOutput                     *timer,
    const MPI_Comm                   comm)
      : scene(scene_)
      , fuzzy(fuzzy)
      , comm(comm)
  {
    {
      // Neighbours are measured in units of the parameters' supports.
      std::vector<double> widths;
      for (const FuzzyNumber &number : fuzzy.numbers())
        {
          const Interval support = number.alpha_cut(0);
          widths.push_back(support.upper - support.lower);
        }
      warm_starts = WarmStarts(widths);
    }
    AssertThrow(!scene.contact_pairs.empty(),
                ExcMessage("The fuzzy contact study needs a scene with a "
                           "contact pair."));
    Observations::check(output_names, scene);

    // A parameter that cannot change the static answer is not varied: a
    // density, unless gravity makes it scale its zone's weight.
    std::vector<VaryingQuantity> varying;
    for (const FuzzyParameter &p : fuzzy.parameters())
      {
        inert_parameters.push_back(
          p.quantity.kind == SceneQuantity::Kind::density &&
              scene.gravity.norm() == 0
            ? "a density: the contact problem is static, its answer "
              "depends on the stiffness and the loads only (the scene has "
              "no gravity)"
            : "");
        if (inert_parameters.back().empty())
          varying.push_back({p.quantity, p.number.alpha_cut(0)});
      }

    // Spread over the ranks, each assembles only the components it builds.
    builder =
      ReducedOrderModel::builders(scene.components.size(), varying, comm);
    std::vector<bool> assemble;
    if (Utilities::MPI::job_supports_mpi() &&
        Utilities::MPI::n_mpi_processes(comm) > 1)
      {
        n_ranks_building = Utilities::MPI::n_mpi_processes(comm);
        for (unsigned int c = 0; c < scene.components.size(); ++c)
          assemble.push_back(builder[c] ==
                             Utilities::MPI::this_mpi_process(comm));
      }
    bodies = std::make_unique<ContactScene>(scene,
                                            settings.mesh_refinements,
                                            1e-8,
                                            timer,
                                            assemble);
    bodies->set_sliding_limit(settings.sliding_limit);
    outputs       = std::make_unique<Observations>(output_names, *bodies);
    reduced_model = std::make_unique<ReducedOrderModel>(
      *bodies,
      modes_for(varying, settings, timer, comm),
      outputs->dofs(),
      varying,
      settings.reduced,
      timer,
      comm);
    std::unique_ptr<ContactSolver> solver =
      create_contact_solver(settings.contact_solver,
                            settings.exact,
                            settings.fl2c);
    solver_name = solver->name();
    {
      // A probe that does not converge quickly says nothing: 50
      // iterations from the warm start, then from the load path, and the
      // last resorts (one solve on the friction path) only if no probe
      // answers so (in a pin study they answered none of 1236 failed
      // probes and were two of the up to four attempts each made).
      ActiveSetParameters probe = settings.exact;
      probe.max_iterations      = std::min(probe.max_iterations, 50u);
      probe.max_path_solves     = 1;
      probe.last_resorts        = false;
      probe_solvers[0]          = std::make_unique<ActiveSetSolver>(probe);
      probe.last_resorts        = true;
      probe_solvers[1]          = std::make_unique<ActiveSetSolver>(probe);
    }
    reduced_model->set_contact_solver(std::move(solver),
                                      solver_name == "fl2c" ? "FL2C"
                                                            : solver_name);
    full_model = std::make_unique<FullOrderModel>(*bodies,
                                                  outputs->dofs(),
                                                  settings.exact);
    for (unsigned int c = 0; c < bodies->n_components(); ++c)
      if (!bodies->component(c).free_motion_names().empty())
        held_by_contact +=
          (held_by_contact.empty() ? "" : ", ") + bodies->component(c).name();

    // The ranks that can solve the reduced model (all but where some
    // components are re-analysed: the first rank).
    reduced_ranks = comm;
    if (n_ranks_building > 1 &&
        Utilities::MPI::min(reduced_model->solves_here() ? 1 : 0, comm) == 0)
      {
        const int ierr =
          MPI_Comm_split(comm,
                         reduced_model->solves_here() ? 0 : MPI_UNDEFINED,
                         Utilities::MPI::this_mpi_process(comm),
                         &reduced_ranks);
        AssertThrowMPI(ierr);
        own_reduced_ranks = true;
      }
  }


  FuzzyContactModel::~FuzzyContactModel()
  {
    if (own_reduced_ranks && reduced_ranks != MPI_COMM_NULL)
      MPI_Comm_free(&reduced_ranks);
  }


  MPI_Comm
  FuzzyContactModel::reduced_communicator() const
  {
    return reduced_ranks;
  }


  std::vector<ModalBasis>
  FuzzyContactModel::modes_for(const std::vector<VaryingQuantity> &varying,
                               const FuzzyContactModelSettings    &settings,
                               TimerOutput                        *timer,
                               const MPI_Comm                      comm)
  {
    // Modes enrich the basis only for what the static correction does not
    // span exactly: a zone's material (the modes of that component are then
    // re-analysed) or a study without static correction. A static answer
    // does not depend on a density; a body's modulus scales its stiffness,
    // and a body whose stiffness does not change shape is exact with the
    // static correction alone.
    // With the Krylov static correction (the default), a zone modulus is
    // followed by the static correction itself, checked at the corners of
    // the box: the modes are not needed for it either.
    const unsigned int n_c = bodies->n_components();
    const bool         all =
      !settings.modes_when_needed || !settings.reduced.static_correction;
    const bool krylov = settings.reduced.zone_correction ==
                        ReducedModelSettings::ZoneCorrection::krylov;
    std::vector<bool> needed(n_c, all);
    std::string       names;
    std::vector<bool> reshaped(n_c, false);
    for (const VaryingQuantity &v : varying)
      {
        if (v.quantity.reshapes_stiffness())
          {
            needed[v.quantity.component] =
              needed[v.quantity.component] || !krylov;
            reshaped[v.quantity.component] = true;
          }
        names += (names.empty() ? "" : ", ") + v.quantity.name;
      }
    // Why a component gets no modes.
    const auto reason = [&](const unsigned int c) {
      return reshaped[c]
               ? std::string(
                   "its zone moduli reshape its stiffness, and the static "
                   "correction follows them by Krylov vectors (zone "
                   "correction = krylov), checked at the corners of the "
                   "fuzzy box")
               : std::string(
                   "no fuzzy parameter changes the shape of its stiffness, "
                   "so the static correction alone makes its reduced "
                   "contact flexibility exact");
    };
    if (std::find(needed.begin(), needed.end(), true) != needed.end())
      {
        // Where the components are spread over the ranks, each computes the
        // modes of its own components only.
        std::vector<bool> owned = needed;
        if (n_ranks_building > 1)
          for (unsigned int c = 0; c < n_c; ++c)
            owned[c] =
              owned[c] && builder[c] == Utilities::MPI::this_mpi_process(comm);
        std::string without;
        for (unsigned int c = 0; c < n_c; ++c)
          if (!needed[c])
            without += (without.empty() ? "" : "; ") +
                       bodies->component(c).name() + ": " + reason(c);
        if (!without.empty())
          skipped_stages = "no modal analysis of " + without +
                           " (Reduced models/modes = always computes the "
                           "modes anyway)";
        return component_modes(*bodies, settings.modal, timer, owned);
      }
    if (std::find(reshaped.begin(), reshaped.end(), true) != reshaped.end())
      {
        std::string list;
        for (unsigned int c = 0; c < n_c; ++c)
          list += (list.empty() ? "" : "; ") + bodies->component(c).name() +
                  ": " + reason(c);
        skipped_stages = "no modal analysis (" + list +
                         "; Reduced models/modes = always computes the modes "
                         "anyway)";
        return std::vector<ModalBasis>(n_c);
      }
    skipped_stages =
      "no modal analysis: every fuzzy parameter (" + names +
      ") scales a body's stiffness or a load, is a density (a static answer "
      "does not depend on it), a friction coefficient or a gap, so the "
      "static correction alone makes the reduced contact flexibility exact "
      "(Reduced models/modes = always computes the modes anyway)";
    return std::vector<ModalBasis>(n_c);
  }


  const std::string &
  FuzzyContactModel::skipped() const
  {
    return skipped_stages;
  }


  const std::vector<std::string> &
  FuzzyContactModel::inert() const
  {
    return inert_parameters;
  }


  std::vector<FuzzyNumber>
  FuzzyContactModel::effective_numbers() const
  {
    std::vector<FuzzyNumber> numbers = fuzzy.numbers();
    for (unsigned int i = 0; i < numbers.size(); ++i)
      if (!inert_parameters[i].empty())
        numbers[i] = FuzzyNumber::crisp(numbers[i].alpha_cut(1).midpoint());
    return numbers;
  }


  const Observations &
  FuzzyContactModel::observations() const
  {
    return *outputs;
  }


  std::string
  FuzzyContactModel::contact_solver() const
  {
    return solver_name;
  }


  SceneState
  FuzzyContactModel::state(const std::vector<double> &values) const
  {
    AssertThrow(values.size() == fuzzy.parameters().size(),
                ExcMessage("The model expects one value per fuzzy "
                           "parameter."));
    for (unsigned int i = 0; i < values.size(); ++i)
      AssertThrow(std::isfinite(values[i]),
                  ExcMessage("Fuzzy parameter " +
                             fuzzy.parameters()[i].quantity.name +
                             ": the value to evaluate is not finite."));
    // Inert parameters at their nominal value (they cannot change the
    // answer; the reduced model was not built to vary them).
    std::vector<double> effective = values;
    for (unsigned int i = 0; i < values.size(); ++i)
      if (!inert_parameters[i].empty())
        effective[i] = fuzzy.parameters()[i].quantity.value(scene);
    return fuzzy.state(scene, effective);
  }


  void
  FuzzyContactModel::set_reuse_factorisations(const bool reuse)
  {
    full_model->set_reuse_factorisations(reuse);
  }


  void
  FuzzyContactModel::set_iterative_solves(
    const FullOrderModel::ChangedStiffness mode,
    const double                           tolerance,
    const unsigned int                     max_iterations,
    const std::string                     &keys)
  {
    full_model->set_iterative_solves(mode, tolerance, max_iterations, keys);
  }


  const IterativeSolveStatistics &
  FuzzyContactModel::iterative_statistics() const
  {
    return full_model->iterative_statistics();
  }


  const ReducedOrderModel &
  FuzzyContactModel::reduced_order_model() const
  {
    return *reduced_model;
  }


  unsigned int
  FuzzyContactModel::enrich(const std::vector<std::vector<double>> &points,
                            TimerOutput                            *timer)
  {
    // Every rank solves every point (the same factorisations give the same
    // fields) and keeps the fields of the components it built.
    std::vector<std::vector<Vector<double>>> fields(bodies->n_components());
    {
      auto scope = timer_section(timer, "model made richer (exact fields)");
      for (const std::vector<double> &p : points)
        {
          ContactSolution s;
          bool            answered = true;
          at_point(p, "the exact full-order solve for a snapshot", [&]() {
            full_model->set_state(state(p));
            try
              {
                s = full_model->solve_with_fields();
              }
            catch (const ExcNoStaticEquilibrium &)
              {
                answered = false;
              }
            catch (const ExceptionBase &)
              {
                // With bodies held by contact alone the exact model may
                // have no answer where the reduced one has (beyond small
                // sliding, or a solve that fails near a limit, which its
                // proof left out): no snapshot there, and the bound stays
                // unproven.
                if (!can_lose_equilibrium())
                  throw;
                answered = false;
              }
            return std::vector<double>();
          });
          if (!answered)
            continue;
          AssertThrow(s.displacements.size() == bodies->n_components(),
                      ExcMessage("FuzzyContactModel: the exact solver gave no "
                                 "displacement fields for a snapshot."));
          unsigned int first = 0;
          for (unsigned int c = 0; c < bodies->n_components(); ++c)
            {
              const Component &component = bodies->component(c);
              Vector<double>   u         = s.displacements[c];
              // Without the free motions: those are unknowns of the
              // contact problem, not of the basis.
              for (unsigned int j = 0; j < component.free_motions().size(); ++j)
                u.add(-s.rigid[first + j], component.free_motions()[j]);
              first += component.free_motions().size();
              if (builder[c] == (n_ranks_building > 1
                                   ? Utilities::MPI::this_mpi_process(comm)
                                   : 0))
                fields[c].push_back(std::move(u));
            }
        }
    }
    // The bases are enriched at the nominal materials (those they were
    // built at).
    bodies->set_materials(SceneState(scene));
    return reduced_model->add_snapshots(fields, timer);
  }


  double
  FuzzyContactModel::share_factorisations(TimerOutput *timer)
  {
    if (n_ranks_building <= 1)
      return 0;
    Timer wall;
    bodies->share_stiffness_factorisations(builder, comm, timer);
    return Utilities::MPI::max(wall.wall_time(), comm);
  }


  std::vector<RankWork>
  FuzzyContactModel::work_per_rank() const
  {
    RankWork mine;
    for (unsigned int c = 0; c < bodies->n_components(); ++c)
      {
        if (bodies->component(c).is_assembled())
          mine.assembled.push_back(bodies->component(c).name());
        if (bodies->n_factorisations(c) > 0)
          mine.factorised.push_back(bodies->component(c).name());
      }
    if (!Utilities::MPI::job_supports_mpi())
      return {mine};
    return Utilities::MPI::all_gather(comm, mine);
  }


  std::vector<unsigned int>
  FuzzyContactModel::n_dofs() const
  {
    return bodies->n_dofs();
  }


  std::vector<unsigned int>
  FuzzyContactModel::reanalysis_orders() const
  {
    return reduced_model->reanalysis_orders();
  }


  std::string
  FuzzyContactModel::describe() const
  {
    std::ostringstream out;
    out << reduced_model->describe();
    if (!skipped_stages.empty())
      out << "  " << skipped_stages << "\n";
    if (n_ranks_building > 1)
      {
        out << "  the components' reduced models were built on "
            << n_ranks_building << " MPI ranks (";
        for (unsigned int c = 0; c < builder.size(); ++c)
          out << (c > 0 ? ", " : "") << bodies->component(c).name()
              << " on rank " << builder[c];
        out << "), their reduced blocks exchanged\n";
        if (reduced_ranks != comm)
          out << "  the reduced model is solved on the first rank only: it "
                 "holds the reanalyses of the re-analysed components\n";
      }
    out << "  contact: " << bodies->interface().n_nodes() << " slave nodes in "
        << bodies->interface().n_pairs() << " contact pair(s), solved by "
        << (solver_name == "fl2c" ? "FL2C (fuzzy regulators"
                                  : "the exact reduced solver (" + solver_name)
        << ", key 'contact solver')\n"
        << "  outputs:";
    for (unsigned int i = 0; i < outputs->size(); ++i)
      {
        const Observation &o = (*outputs)[i];
        out << (i > 0 ? "," : "") << " " << o.name;
        if (o.kind == Observation::Kind::displacement)
          out << " (node (" << o.position[0] << ", " << o.position[1] << "))";
      }
    out << "\n";
    return out.str();
  }
} // namespace FuzzyContact
