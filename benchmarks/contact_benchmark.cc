// contact_benchmark: what the speed of the reduced contact solvers costs in
// accuracy, measured in one run on this machine.
//
//  Part A (per scene, 20434 DoFs per component, F = 50 kN, mu = 0.3):
//    modes 5, 9, 20, 40 x static correction off/on x solver (reduced exact,
//    FL2C at regulator tolerances 1e-2 ... 1e-6) -> error of F_n and of the
//    slave displacement against the full-order answer, iterations, and the
//    time per solve (median of repeated solves on a ready reduced model),
//    beside the time of a full-order solve (cold: with its factorisations;
//    warm: same stiffness, factorisations and columns of W reused).
//  Part B (overlap and stacked, 9 modes): the reduced/full time ratio at
//    5418, 20434 and 79266 DoFs per component, with the offline costs (the
//    static correction is skipped where it would need more than about 2 GB).
//
// Usage (from the repository's top folder):
//   build/contact_benchmark [prm folder] [quick]
// prints Markdown tables (doc/contact.md holds a copy) and writes them to
// contact_benchmark.md.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_state.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>
#include <fuzzycontact/study/observations.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

using namespace FuzzyContact;

namespace
{
  Report report;

  void
  say(const std::string &text)
  {
    report.say(text);
  }

  std::string
  sci(const double v, const int digits = 1)
  {
    return Format::scientific(v, digits);
  }

  std::string
  fixed(const double v, const int digits = 0)
  {
    return Format::fixed(v, digits);
  }

  // Median wall time of @p f over repeated calls (at least 3, and at least
  // 0.2 s in total); a call that alone takes longer than 0.2 s is timed
  // once.
  double
  median_time_per_call(const std::function<void()> &f)
  {
    std::vector<double> times;
    Timer               total;
    while (times.size() < 3 || (total.wall_time() < 0.2 && times.size() < 1000))
      {
        Timer t;
        f();
        times.push_back(t.wall_time());
        if (times.size() == 1 && times[0] > 0.2)
          break;
      }
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
  }

  double
  relative(const double a, const double b)
  {
    return std::abs(a - b) / std::abs(b);
  }

  double
  relative(const std::array<double, 2> &a, const std::array<double, 2> &b)
  {
    return std::hypot(a[0] - b[0], a[1] - b[1]) / std::hypot(b[0], b[1]);
  }

  // A scene's bodies, set to F = 50 kN (the scene's load) and mu = 0.3, and
  // the slave node's displacements as outputs.
  struct Bodies
  {
    ContactScene scene;
    Observations outputs;
    SceneState   state;

    Bodies(const std::string &file,
           const unsigned int refinements,
           const double       mu)
        : scene(Scene::read(file), refinements)
        , outputs({"slave.ux", "slave.uy"}, scene)
        , state(scene.scene())
    {
      for (double &m : state.friction_coefficients)
        m = mu;
    }

    std::array<double, 2>
    slave(const ContactSolution &s) const
    {
      const std::vector<double> u = outputs.values(s);
      return {{u[0], u[1]}};
    }
  };

  struct FullReference
  {
    ContactSolution       solution;
    std::array<double, 2> slave;
    double                cold, warm;
  };

  FullReference
  full_reference(Bodies &bodies)
  {
    FullReference r;
    {
      FullOrderModel full(bodies.scene, bodies.outputs.dofs());
      full.set_state(bodies.state);
      r.solution = full.solve();
      r.slave    = bodies.slave(r.solution);
      r.cold     = r.solution.time;
      r.warm     = median_time_per_call([&]() {
        full.solver().solve();
      });
    }
    // A second cold solve, to see the spread.
    FullOrderModel again(bodies.scene, bodies.outputs.dofs());
    again.set_state(bodies.state);
    r.cold = std::min(r.cold, again.solve().time);
    return r;
  }

  std::vector<ModalBasis>
  modes(const Bodies &bodies, const unsigned int n, double &time)
  {
    ModalParameters parameters;
    parameters.n_modes = n;
    Timer                         t;
    const std::vector<ModalBasis> bases =
      component_modes(bodies.scene, parameters);
    time = t.wall_time();
    return bases;
  }

  // A reduced model of the bodies on the given bases; times of the static
  // correction (with the projections) and of forming W.
  struct Model
  {
    std::unique_ptr<ReducedOrderModel> model;
    double                             reduction_time = 0;
    double                             w_time         = 0;
    unsigned int                       size           = 0;
  };

  std::unique_ptr<Model>
  reduce(const Bodies                  &bodies,
         const std::vector<ModalBasis> &bases,
         const bool                     corrected)
  {
    auto        m = std::make_unique<Model>();
    TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
    ReducedModelSettings settings;
    settings.static_correction = corrected;
    m->model =
      std::make_unique<ReducedOrderModel>(bodies.scene,
                                          bases,
                                          bodies.outputs.dofs(),
                                          std::vector<VaryingQuantity>(),
                                          settings,
                                          &timer);
    m->model->set_state(bodies.state);
    const auto t = timer.get_summary_data(TimerOutput::total_wall_time);
    m->reduction_time =
      t.at("static correction modes") + t.at("reduced matrices");
    m->w_time = t.at("reduced contact flexibility");
    for (unsigned int c = 0; c < bodies.scene.n_components(); ++c)
      m->size =
        std::max(m->size, m->model->n_modes(c) + m->model->n_corrections(c));
    return m;
  }

  // Solves with the exact solver (tolerance <= 0) or FL2C; returns the
  // solution and the median time per solve, or throws.
  std::pair<ContactSolution, double>
  reduced_solve(const Model &m, const double tolerance)
  {
    ContactSolution                      solution;
    std::unique_ptr<const ContactSolver> solver;
    if (tolerance <= 0)
      solver = std::make_unique<ActiveSetSolver>();
    else
      {
        FL2CParameters parameters;
        parameters.tolerance = tolerance;
        solver               = std::make_unique<FL2CSolver>(parameters);
      }
    const auto solve = [&]() {
      solution = m.model->solve(*solver);
    };
    return {solution, median_time_per_call(solve)};
  }


  void
  part_a(const std::string &prm, const bool quick)
  {
    const unsigned int        refinements = quick ? 0 : 2;
    const std::vector<double> tolerances  = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
    say("\n## A. Error and time per solve against the number of modes, the "
        "static correction and the regulator tolerance\n");
    for (const std::string name : {"overlap", "stacked"})
      {
        Bodies              bodies(prm + "/" + name + ".prm", refinements, 0.3);
        const FullReference ref                 = full_reference(bodies);
        double              modal_time          = 0;
        const std::vector<ModalBasis> all_modes = modes(bodies, 40, modal_time);
        std::ostringstream            out;
        out
          << "\n### " << name << ": " << bodies.scene.n_dofs()[0]
          << " DoFs per component, " << bodies.scene.interface().n_nodes()
          << " slave nodes, F = 50 kN, mu = 0.3\n\n"
          << "full_order: F_n = " << fixed(ref.solution.normal_force, 1)
          << " N, slave (ux, uy) = (" << sci(ref.slave[0], 4) << ", "
          << sci(ref.slave[1], 4) << ") m; one solve " << sci(ref.cold, 2)
          << " s cold (factorisations, columns of W, displacements), "
          << sci(ref.warm, 2)
          << " s warm (same stiffness). 40 modes per component: "
          << fixed(modal_time, 2) << " s (ARPACK).\n\n"
          << "| modes | correction | basis size | offline [s] (correction + W) "
             "| solver | tolerance | F_n error | slave u error | iterations | "
             "time per solve [s] | full cold / reduced | full warm / reduced "
             "|\n|---|---|---|---|---|---|---|---|---|---|---|---|\n";
        say(out.str());
        for (const unsigned int n : {5u, 9u, 20u, 40u})
          {
            std::vector<ModalBasis> bases;
            for (const ModalBasis &b : all_modes)
              bases.push_back(leading_modes(b, n));
            for (const bool corrected : {false, true})
              {
                const auto          model = reduce(bodies, bases, corrected);
                std::vector<double> tols  = {0.};
                tols.insert(tols.end(), tolerances.begin(), tolerances.end());
                for (const double tol : tols)
                  {
                    std::ostringstream row;
                    row << "| " << n << " | " << (corrected ? "yes" : "no")
                        << " | " << model->size << " | "
                        << fixed(model->reduction_time, 2) << " + "
                        << fixed(model->w_time, 3) << " | "
                        << (tol <= 0 ? "reduced exact" : "FL2C") << " | "
                        << (tol <= 0 ? "1e-10 (residual)" : sci(tol, 0))
                        << " | ";
                    try
                      {
                        const auto [s, t] = reduced_solve(*model, tol);
                        row << sci(relative(s.normal_force,
                                            ref.solution.normal_force))
                            << " | "
                            << sci(relative(bodies.slave(s), ref.slave))
                            << " | " << s.iterations << " | " << sci(t, 2)
                            << " | " << fixed(ref.cold / t) << " | "
                            << fixed(ref.warm / t) << " |\n";
                      }
                    catch (const dealii::ExceptionBase &e)
                      {
                        // Only FL2C's running out of sweeps is a result;
                        // anything else is a failure of the benchmark.
                        const std::string message = Input::message_of(e);
                        if (tol <= 0 || message.find("did not converge") ==
                                          std::string::npos)
                          throw;
                        row << "no convergence | | 20000 (max) | | | |\n";
                      }
                    say(row.str());
                  }
              }
          }
      }
  }


  void
  part_b(const std::string &prm, const bool quick)
  {
    say("\n## B. Reduced / full time ratio against the mesh size (9 modes, "
        "F = 50 kN, mu = 0.3)\n\n"
        "| scene | DoFs per component | full cold [s] | full warm [s] | "
        "modes [s] | correction + W [s] | reduced exact, corrected [s] | "
        "FL2C, corrected [s] | FL2C, modes [s] | full cold / reduced exact | "
        "full cold / FL2C corrected | full cold / FL2C modes | F_n error "
        "FL2C corrected | F_n error FL2C modes |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    const std::vector<unsigned int> levels =
      quick ? std::vector<unsigned int>{0, 1}
            : std::vector<unsigned int>{1, 2, 3};
    for (const std::string name : {"overlap", "stacked"})
      for (const unsigned int r : levels)
        {
          Bodies              bodies(prm + "/" + name + ".prm", r, 0.3);
          const FullReference ref             = full_reference(bodies);
          double              modal_time      = 0;
          const std::vector<ModalBasis> bases = modes(bodies, 9, modal_time);
          const auto                    modal = reduce(bodies, bases, false);
          // The static correction stores K^{-1} for every contact DoF: skip
          // it where that needs more than about 2 GB.
          const double bytes = 8. * bodies.scene.n_dofs()[0] *
                               bodies.scene.interface().n_rows() * 2;
          const bool             with_correction = bytes < 2e9;
          std::unique_ptr<Model> corrected;
          if (with_correction)
            corrected = reduce(bodies, bases, true);

          const auto [fm, t_fm] = reduced_solve(*modal, 1e-4);
          std::ostringstream row;
          row << "| " << name << " | " << bodies.scene.n_dofs()[0] << " | "
              << sci(ref.cold, 2) << " | " << sci(ref.warm, 2) << " | "
              << fixed(modal_time, 2) << " | ";
          if (with_correction)
            {
              const auto [re, t_re] = reduced_solve(*corrected, 0);
              const auto [fc, t_fc] = reduced_solve(*corrected, 1e-4);
              row << fixed(corrected->reduction_time, 1) << " + "
                  << fixed(corrected->w_time, 2) << " | " << sci(t_re, 2)
                  << " | " << sci(t_fc, 2) << " | " << sci(t_fm, 2) << " | "
                  << fixed(ref.cold / t_re) << " | " << fixed(ref.cold / t_fc)
                  << " | " << fixed(ref.cold / t_fm) << " | "
                  << sci(relative(fc.normal_force, ref.solution.normal_force))
                  << " | ";
            }
          else
            row << "skipped (" << fixed(bytes / 1e9, 1) << " GB) | | | "
                << sci(t_fm, 2) << " | | | " << fixed(ref.cold / t_fm)
                << " | | ";
          row << sci(relative(fm.normal_force, ref.solution.normal_force))
              << " |\n";
          say(row.str());
        }
  }
} // namespace


int
main(int argc, char **argv)
{
  const std::string prm   = argc > 1 ? argv[1] : "prm";
  const bool        quick = argc > 2 && std::string(argv[2]) == "quick";
  try
    {
      say("# contact_benchmark" + std::string(quick ? " (quick)" : "") +
          "\n\nTimes are wall times of one run on this machine (2 cores "
          "shared, Release, OpenBLAS serial); they vary by about 30 % between "
          "runs. Errors are relative to the full-order answer of the same "
          "mesh.\n");
      part_a(prm, quick);
      part_b(prm, quick);
      write_file_atomically("contact_benchmark.md", report.text());
      std::cout << "\nWrote contact_benchmark.md" << std::endl;
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::cerr << "contact_benchmark: error: " << Input::message_of(e)
                << std::endl;
      return 1;
    }
  return 0;
}
