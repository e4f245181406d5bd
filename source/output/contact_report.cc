#include <fuzzycontact/base/input.h>
#include <fuzzycontact/output/contact_report.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/output/stress_postprocessor.h>

#include <deal.II/numerics/data_out.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <sstream>

namespace FuzzyContact
{
  namespace
  {
    const std::vector<std::string> paper_names = {"slave.ux",
                                                  "slave.uy",
                                                  "master1.ux",
                                                  "master1.uy",
                                                  "master2.ux",
                                                  "master2.uy",
                                                  "Fn"};

    // Digits of an output's values in the tables.
    int
    digits(const Observation &o)
    {
      return o.unit() == "m" ? 3 : o.unit() == "N" ? 5 : 4;
    }

    unsigned int
    width(const Observation &o)
    {
      return std::max<unsigned int>(13, o.name.size() + 2);
    }

    // |a - b| / |b| of the slave displacement vector.
    double
    vector_error(const double ax,
                 const double ay,
                 const double bx,
                 const double by)
    {
      const double reference = std::hypot(bx, by);
      const double error     = std::hypot(ax - bx, ay - by);
      if (reference == 0)
        return error == 0 ? 0. : 1.;
      return error / reference;
    }

    double
    slave_error(const SolverRun    &run,
                const SolverRun    &reference,
                const Observations &o)
    {
      const unsigned int x = o.index("slave.ux"), y = o.index("slave.uy");
      return vector_error(run.outputs[x],
                          run.outputs[y],
                          reference.outputs[x],
                          reference.outputs[y]);
    }

    // The rigid-body part of the full-order displacement of each body held
    // by contact alone, per free motion: {"m": translation} or {"rad":
    // rotation about the pole its name gives}. Empty without such bodies or
    // without the full-order fields.
    nlohmann::json
    rigid_parts(const ContactCase &c)
    {
      nlohmann::json   parts = nlohmann::json::object();
      const SolverRun &ref   = c.runs[0];
      if (c.free_motions.empty() || c.bodies == nullptr ||
          ref.fields.size() != c.bodies->n_components())
        return parts;
      for (unsigned int b = 0; b < c.bodies->n_components(); ++b)
        {
          const Component     &body = c.bodies->component(b);
          const Vector<double> a    = body.rigid_part(ref.fields[b]);
          for (unsigned int j = 0; j < a.size(); ++j)
            {
              const std::string name =
                body.name() + ": " + body.free_motion_names()[j];
              const double angle = body.free_motion_angles()[j];
              parts[name] = angle != 0 ? nlohmann::json{{"rad", a[j] * angle}}
                                       : nlohmann::json{{"m", a[j]}};
            }
        }
      return parts;
    }
  } // namespace


  ContactCase::ContactCase(const ContactScene &bodies,
                           const SceneState   &state,
                           const double        load)
      : scene(bodies.scene().name)
      , plane_model(bodies.scene().plane_model)
      , load(load)
      , zone_moduli(state.zone_moduli)
      , mu(state.friction_coefficients)
      , pairs(bodies.scene().contact_pairs)
      , n_dofs(bodies.n_dofs())
      , n_nodes(bodies.interface().n_nodes())
      , bodies(&bodies)
  {
    for (unsigned int c = 0; c < bodies.n_components(); ++c)
      for (const std::string &motion : bodies.component(c).free_motion_names())
        free_motions.push_back(bodies.component(c).name() + ": " + motion);
    std::ostringstream text;
    const Scene       &s = bodies.scene();
    for (unsigned int c = 0; c < s.components.size(); ++c)
      for (unsigned int l = 0; l < s.components[c].loads.size(); ++l)
        if (s.components[c].loads[l].is_displacement)
          text << (text.str().empty() ? "" : ", ") << s.components[c].name
               << "." << s.components[c].loads[l].name << " displaced by "
               << state.load_forces[c][l] << " m";
    // Each body's weight: rho g over the body, at the state's densities.
    if (s.gravity.norm() > 0)
      text << (text.str().empty() ? "" : ", ") << "gravity (" << s.gravity[0]
           << ", " << s.gravity[1] << ") m/s^2 (the bodies' weight)";
    // The forces, each with its direction, and their resultant (the
    // pressures' resultants follow their faces' shapes: named apart).
    std::vector<std::string> forces, pressures;
    std::string              along; // (of the last force)
    Tensor<1, 2>             resultant;
    for (unsigned int c = 0; c < s.components.size(); ++c)
      for (unsigned int l = 0; l < s.components[c].loads.size(); ++l)
        {
          const EdgeLoad &edge_load = s.components[c].loads[l];
          if (edge_load.is_displacement || edge_load.is_weight)
            continue;
          const double       f = state.load_forces[c][l];
          std::ostringstream one;
          one << s.components[c].name << "." << edge_load.name << " " << f;
          if (edge_load.is_pressure)
            pressures.push_back(one.str() + " Pa normal pressure");
          else
            {
              std::ostringstream direction;
              direction << "along (" << edge_load.direction[0] << ", "
                        << edge_load.direction[1] << ")";
              along = direction.str();
              forces.push_back(one.str() + " N " + along);
              resultant += f * edge_load.direction;
            }
        }
    if (forces.size() + pressures.size() > 1)
      {
        for (const std::string &f : forces)
          text << (text.str().empty() ? "" : ", ") << f;
        for (const std::string &f : pressures)
          text << (text.str().empty() ? "" : ", ") << f;
        if (forces.size() > 1)
          {
            // (A component below round-off of the other is zero.)
            const double size = resultant.norm();
            for (unsigned int d = 0; d < 2; ++d)
              if (std::abs(resultant[d]) <= 1e-12 * size)
                resultant[d] = 0;
            text << "; resultant force (" << resultant[0] << ", "
                 << resultant[1] << ") N";
          }
      }
    else if (forces.size() == 1)
      text << (text.str().empty() ? "" : ", ") << "F = " << load << " N "
           << along;
    else if (pressures.size() == 1)
      text << (text.str().empty() ? "" : ", ") << pressures[0];
    else if (text.str().empty() || load != 0)
      text << (text.str().empty() ? "" : ", ") << "F = " << load << " N";
    // A load history replaces the proportional load steps.
    if (!s.load_stages.empty())
      {
        text << ", in load stages";
        for (const LoadStage &stage : s.load_stages)
          text << (&stage == &s.load_stages.front() ? " " : ", ") << stage.name
               << " (" << stage.n_load_steps << " step"
               << (stage.n_load_steps > 1 ? "s" : "") << ")";
      }
    loading = text.str();
  }


  SolverRun
  SolverRun::attempt(const std::string                      &name,
                     const std::function<void(SolverRun &)> &solve)
  {
    SolverRun run;
    try
      {
        solve(run);
      }
    catch (const ExceptionBase &e)
      {
        run                 = SolverRun();
        run.solution.solver = name;
        run.failure         = Utilities::trim(Input::message_of(e));
        AssertThrow(!run.failure.empty(), ExcInternalError());
      }
    return run;
  }


  bool
  ContactCase::uniform_friction() const
  {
    return std::all_of(mu.begin(), mu.end(), [&](const double m) {
      return m == mu[0];
    });
  }


  std::string
  ContactCase::file_stem(const std::string &label) const
  {
    std::string mu = friction_label();
    std::replace(mu.begin(), mu.end(), ' ', '_');
    mu.erase(std::remove(mu.begin(), mu.end(), ','), mu.end());
    return "contact-" + label + "-mu" + mu;
  }


  std::string
  ContactCase::friction_label() const
  {
    std::ostringstream s;
    if (uniform_friction())
      s << mu[0];
    else
      for (unsigned int p = 0; p < mu.size(); ++p)
        s << (p > 0 ? ", " : "") << pairs[p].name << " " << mu[p];
    return s.str();
  }


  namespace ContactReport
  {
    std::string
    default_outputs()
    {
      return "slave.ux, slave.uy, master1.ux, master1.uy, master2.ux, "
             "master2.uy, Fn, Ft";
    }


    std::vector<std::string>
    observed_outputs(const std::vector<std::string> &chosen)
    {
      std::vector<std::string> names = chosen;
      for (const std::string &name : paper_names)
        if (std::find(names.begin(), names.end(), name) == names.end())
          names.push_back(name);
      if (std::find(names.begin(), names.end(), "Ft") == names.end())
        names.push_back("Ft");
      return names;
    }


    std::string
    case_table(const ContactCase  &c,
               const Observations &o,
               const unsigned int  n_shown)
    {
      const SolverRun   &ref = c.runs[0];
      std::ostringstream out;
      // One figure when the components have one size, else each.
      std::string dofs = std::to_string(c.n_dofs[0]);
      const bool  same =
        std::all_of(c.n_dofs.begin(), c.n_dofs.end(), [&](const auto n) {
          return n == c.n_dofs[0];
        });
      for (unsigned int k = 1; k < c.n_dofs.size() && !same; ++k)
        dofs += "/" + std::to_string(c.n_dofs[k]);
      out << "\nCase " << c.scene << " (" << to_string(c.plane_model) << "), "
          << c.loading << ", mu = " << c.friction_label() << "; " << dofs
          << (same ? " DoFs per component, " : " DoFs (the components), ")
          << c.n_nodes << " slave nodes\n";
      out << " solver              ";
      for (unsigned int k = 0; k < n_shown; ++k)
        out << std::setw(width(o[k])) << o[k].name;
      out << "    it   residual   time [s]  speed-up\n";
      for (const SolverRun &run : c.runs)
        {
          const ContactSolution &s = run.solution;
          out << " " << std::left << std::setw(20) << s.solver << std::right;
          if (!run.failure.empty())
            {
              out << "failed: " << run.failure << "\n";
              continue;
            }
          for (unsigned int k = 0; k < n_shown; ++k)
            out << std::setw(width(o[k]))
                << Format::scientific(run.outputs[k], digits(o[k]));
          out << std::setw(6) << s.iterations << std::setw(11)
              << Format::scientific(s.residual, 1) << std::setw(11)
              << Format::scientific(s.time, 2) << std::setw(10)
              << Format::fixed(ref.solution.time / std::max(s.time, 1e-9), 0)
              << "\n";
        }
      out << " relative errors against full_order (slave u: the slave "
             "displacement vector)\n solver              ";
      for (unsigned int k = 0; k < n_shown; ++k)
        out << std::setw(width(o[k])) << o[k].name;
      out << "      slave u\n";
      for (unsigned int r = 1; r < c.runs.size(); ++r)
        {
          const SolverRun &run = c.runs[r];
          if (!run.failure.empty())
            continue;
          out << " " << std::left << std::setw(20) << run.solution.solver
              << std::right;
          for (unsigned int k = 0; k < n_shown; ++k)
            out << std::setw(width(o[k]))
                << Format::scientific(relative_error(run.outputs[k],
                                                     ref.outputs[k]),
                                      1);
          out << std::setw(13)
              << Format::scientific(slave_error(run, ref, o), 1) << "\n";
        }
      const ContactSolution &s = ref.solution;
      out << " closed nodes (full_order): "
          << s.n_nodes() - s.count(ContactStatus::open) << " ("
          << s.count(ContactStatus::stick) << " stick, "
          << s.count(ContactStatus::slip) << " slip); full_order warm re-solve "
          << Format::scientific(c.full_order_warm_time, 2)
          << " s (same stiffness: factorisations and columns of W reused)\n";
      const nlohmann::json rigid = rigid_parts(c);
      if (!rigid.empty())
        {
          out << " held by contact alone, their free motions solved with the "
                 "contact (full_order; the rigid-body part of the "
                 "displacement, a least-squares fit over the body's nodes):";
          for (const auto &[name, value] : rigid.items())
            out << " " << name << " by "
                << Format::scientific(value.begin().value().get<double>(), 3)
                << " " << value.begin().key() << ";";
          out << "\n";
        }
      if (!c.beam_theory.empty())
        out << " " << c.beam_theory << "\n";
      out << " time: one solve (full_order cold, with its factorisations; "
             "reduced solvers on a ready reduced model)\n";
      return out.str();
    }


    nlohmann::json
    case_json(const ContactCase  &c,
              const Observations &o,
              const unsigned int  n_shown)
    {
      const SolverRun &ref = c.runs[0];
      nlohmann::json   j;
      j["scene"]       = c.scene;
      j["plane_model"] = to_string(c.plane_model);
      j["load"]        = c.load;
      if (c.uniform_friction())
        j["mu"] = c.mu[0];
      else
        for (unsigned int p = 0; p < c.mu.size(); ++p)
          j["mu"][c.pairs[p].name] = c.mu[p];
      j["n_dofs_per_component"]   = c.n_dofs;
      j["n_slave_nodes"]          = c.n_nodes;
      j["full_order_warm_time_s"] = c.full_order_warm_time;
      if (!c.free_motions.empty())
        j["rigid_body_part_full_order"] = rigid_parts(c);
      j["solvers"]     = nlohmann::json::array();
      const auto value = [&](const SolverRun &run, const std::string &name) {
        return run.outputs[o.index(name)];
      };
      for (const SolverRun &run : c.runs)
        {
          const ContactSolution &s = run.solution;
          nlohmann::json         e;
          e["name"] = s.solver;
          if (!run.failure.empty())
            {
              e["failed"] = run.failure;
              j["solvers"].push_back(e);
              continue;
            }
          e["Fn"]                   = value(run, "Fn");
          e["Ft"]                   = value(run, "Ft");
          e["slave_ux"]             = value(run, "slave.ux");
          e["slave_uy"]             = value(run, "slave.uy");
          e["master_displacements"] = {
            {value(run, "master1.ux"), value(run, "master1.uy")},
            {value(run, "master2.ux"), value(run, "master2.uy")}};
          e["iterations"]   = s.iterations;
          e["time_s"]       = s.time;
          e["residual"]     = s.residual;
          e["closed_nodes"] = s.n_nodes() - s.count(ContactStatus::open);
          e["Fn_error"]    = relative_error(value(run, "Fn"), value(ref, "Fn"));
          e["Ft_error"]    = relative_error(value(run, "Ft"), value(ref, "Ft"));
          e["slave_error"] = slave_error(run, ref, o);
          for (unsigned int k = 0; k < n_shown; ++k)
            {
              e["outputs"][o[k].name] = run.outputs[k];
              e["output_errors"][o[k].name] =
                relative_error(run.outputs[k], ref.outputs[k]);
            }
          if (s.solver == "reduced_exact_modes")
            j["reduced_exact_modes"] = e;
          else
            j["solvers"].push_back(e);
        }
      return j;
    }


    std::string
    offline(const std::string             &label,
            const ContactScene            &bodies,
            const std::vector<ModalBasis> &modes,
            const ReducedOrderModel       &corrected,
            const TimerOutput             &scene_timer,
            const TimerOutput             &modal_timer,
            const TimerOutput             &corrected_timer,
            nlohmann::json                &json)
    {
      const auto s = scene_timer.get_summary_data(TimerOutput::total_wall_time);
      const auto a = modal_timer.get_summary_data(TimerOutput::total_wall_time);
      const auto b =
        corrected_timer.get_summary_data(TimerOutput::total_wall_time);
      const std::map<std::string, double> times = {
        {"assembly", s.at("assembly")},
        {"modes", s.at("modes (ARPACK)")},
        {"static correction",
         b.at("static correction modes") + b.at("reduced matrices")},
        {"W (modes)", a.at("reduced contact flexibility")},
        {"W (corrected)", b.at("reduced contact flexibility")}};

      std::ostringstream out;
      out << "\n" << label << ": " << bodies.n_components() << " components (";
      for (unsigned int c = 0; c < bodies.n_components(); ++c)
        out << (c > 0 ? ", " : "") << bodies.component(c).name() << " "
            << bodies.component(c).n_dofs() << " DoFs, " << modes[c].size()
            << " modes up to " << std::fixed << std::setprecision(0)
            << modes[c].frequencies().back() << " Hz + "
            << corrected.n_corrections(c) << " correction modes";
      out << "), " << bodies.interface().n_nodes() << " slave nodes\n";
      out << " offline [s]: assembly " << std::setprecision(3)
          << times.at("assembly") << ", modes " << times.at("modes")
          << ", static correction " << times.at("static correction") << ", W "
          << times.at("W (modes)") << " (modes) / " << times.at("W (corrected)")
          << " (corrected)\n";
      json["scene"]       = bodies.scene().name;
      json["plane_model"] = to_string(bodies.scene().plane_model);
      json["times_s"]     = times;
      for (unsigned int c = 0; c < bodies.n_components(); ++c)
        json["components"].push_back(
          {{"name", bodies.component(c).name()},
           {"n_dofs", bodies.component(c).n_dofs()},
           {"n_modes", modes[c].size()},
           {"highest_frequency_hz", modes[c].frequencies().back()},
           {"n_correction_modes", corrected.n_corrections(c)}});
      return out.str();
    }


    void
    add_vtu(OutputFiles        &output,
            const ContactCase  &c,
            const ContactScene &bodies,
            const std::string  &label)
    {
      const ContactInterface           &interface = bodies.interface();
      const Vector<double>             &p         = c.runs[0].solution.p;
      const std::vector<Vector<double>> forces    = interface.nodal_forces(p);
      for (unsigned int i = 0; i < bodies.n_components(); ++i)
        {
          const Component &component = bodies.component(i);
          // Contact pressure and shear traction at the slave nodes, as the
          // two scalar fields of one DoF vector (x slot: pressure, y slot:
          // shear).
          Vector<double> traction(component.n_dofs());
          for (unsigned int k = 0; k < interface.n_nodes(); ++k)
            {
              const ContactNode &node = interface.node(k);
              if (node.slave.component != i)
                continue;
              const double area =
                node.tributary_length * component.description().thickness;
              traction[node.slave.dofs[0]] = p[normal_row(k)] / area;
              traction[node.slave.dofs[1]] = p[tangential_row(k)] / area;
            }
          DataOut<2> data_out;
          data_out.attach_dof_handler(component.dof_handler());
          const std::vector<
            DataComponentInterpretation::DataComponentInterpretation>
            vector(2, DataComponentInterpretation::component_is_part_of_vector),
            scalars(2, DataComponentInterpretation::component_is_scalar);
          for (const SolverRun &run : c.runs)
            if (run.fields.size() == bodies.n_components())
              data_out.add_data_vector(
                run.fields[i],
                std::vector<std::string>(2, "u_" + run.solution.solver),
                DataOut<2>::type_dof_data,
                vector);
          // The stresses of the reference's field (the full order, the
          // first run; none if it failed), at every point the VTU has,
          // with the case's moduli.
          const StressPostprocessor stresses(component, c.zone_moduli[i]);
          if (!c.runs.empty() &&
              c.runs[0].fields.size() == bodies.n_components())
            data_out.add_data_vector(c.runs[0].fields[i], stresses);
          data_out.add_data_vector(forces[i],
                                   std::vector<std::string>(2, "contact_force"),
                                   DataOut<2>::type_dof_data,
                                   vector);
          data_out.add_data_vector(traction,
                                   std::vector<std::string>{"contact_pressure",
                                                            "contact_shear"},
                                   DataOut<2>::type_dof_data,
                                   scalars);
          data_out.build_patches(component.mapping(), component.fe().degree);
          std::ostringstream vtu;
          data_out.write_vtu(vtu);
          output.add(c.file_stem(label) + "-" + component.name() + ".vtu",
                     vtu.str());
        }
    }


    // The paper does not give its friction coefficient; the cases of the
    // paper scene (mu = 0 and the scene's mu) are all set beside it.
    std::string
    paper_comparison(const std::vector<ContactCase> &cases,
                     const Observations             &o,
                     const unsigned int              n_shown,
                     nlohmann::json                 &json)
    {
      struct Column
      {
        std::string           name;
        std::array<double, 7> values;
      };
      // Table 3 of Massa et al. (2013): Ux^e, Uy^e, Ux^m1, Uy^m1, Ux^m2,
      // Uy^m2 [m], F_n [N].
      const Column abaqus{
        "Abaqus (paper)",
        {{5.20e-5, -1.50e-3, 7.54e-5, -1.59e-3, 7.64e-5, -1.50e-3, 44407}}};
      const Column paper_fl2c{
        "FL2C (paper)",
        {{4.48e-5, -1.50e-3, 9.01e-5, -1.59e-3, 9.00e-5, -1.50e-3, 44505}}};
      std::vector<Column> columns = {abaqus, paper_fl2c};
      for (const ContactCase &c : cases)
        for (const SolverRun &run : c.runs)
          {
            const std::string &solver = run.solution.solver;
            if (!run.failure.empty() ||
                (solver != "full_order" && solver != "fl2c_modes" &&
                 solver != "fl2c_corrected"))
              continue;
            std::ostringstream name;
            name << solver << " mu=" << c.friction_label();
            Column column{name.str(), {}};
            for (unsigned int r = 0; r < paper_names.size(); ++r)
              column.values[r] = run.outputs[o.index(paper_names[r])];
            columns.push_back(column);
          }
      const std::array<std::string, 7> rows = {{"Ux slave",
                                                "Uy slave",
                                                "Ux m1",
                                                "Uy m1",
                                                "Ux m2",
                                                "Uy m2",
                                                "F_n [N]"}};

      std::ostringstream out;
      out << "\nComparison with Table 3 of the paper: " << cases[0].scene
          << " in plane strain, F = " << cases[0].load
          << " N (our reconstruction of the lost Fig. 4)\n";
      out << " quantity ";
      for (const Column &col : columns)
        out << std::setw(col.name.size() > 15 ? col.name.size() + 2 : 17)
            << col.name;
      out << "\n";
      for (unsigned int r = 0; r < rows.size(); ++r)
        {
          out << " " << std::left << std::setw(8) << rows[r] << std::right;
          for (const Column &col : columns)
            out << std::setw(col.name.size() > 15 ? col.name.size() + 2 : 17)
                << Format::scientific(col.values[r], r < 6 ? 3 : 5);
          out << "\n";
        }
      out << " |ours| / |Abaqus| for full_order mu="
          << cases[0].friction_label() << ":";
      for (unsigned int r = 0; r < rows.size(); ++r)
        out << " " << rows[r] << " " << std::fixed << std::setprecision(3)
            << std::abs(columns[2].values[r] / abaqus.values[r]) << ";";
      out << "\n (the paper lists Ux as positive where our fibres move "
             "towards -x; m1, m2 are the vertices of the master segment "
             "under the slave node)\n";
      if (!cases[0].beam_theory.empty())
        out << " " << cases[0].beam_theory << "\n";

      nlohmann::json j;
      for (const ContactCase &c : cases)
        j["cases"].push_back(case_json(c, o, n_shown));
      for (unsigned int i = 0; i < 2; ++i)
        j["paper"][i == 0 ? "abaqus" : "fl2c"] = {
          {"slave_ux", columns[i].values[0]},
          {"slave_uy", columns[i].values[1]},
          {"master_displacements",
           {{columns[i].values[2], columns[i].values[3]},
            {columns[i].values[4], columns[i].values[5]}}},
          {"Fn", columns[i].values[6]}};
      json["paper_comparison"] = j;
      return out.str();
    }
  } // namespace ContactReport
} // namespace FuzzyContact
