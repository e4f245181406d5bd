// fl2c_convergence: FL2C on distributed contact, with and without the coarse
// correction, against the exact reduced solver, at several mesh sizes.
//
// For the scenes `stacked` (one pair, the whole interface touches) and
// `three-beams` (two pairs, mu = 0 and 0.5) at 0, 1, 2 (and 3) mesh
// refinements (the scenes' subdivisions times 1, 2, 4, 8), each with mu = 0,
// the scene's own coefficients, and mu = 2 at twice the scene's load:
//   - the exact reduced solution (ActiveSetSolver, tolerance 1e-10) on the
//     reduced model with static correction (the static correction alone,
//     no modes: FL2C and the exact solver solve the same reduced problem);
//   - FL2C with its defaults (coarse correction, tolerance 1e-4) and FL2C
//     without the coarse correction (the paper's regulators alone, at most
//     20000 sweeps): sweeps, final residual, relative error of F_n and of
//     the slave node's displacement against the exact reduced solution, and
//     the time of one solve (median of 7 on the ready model; one solve
//     without the correction);
//   - one cold full-order solve (new factorisations) of the same state.
// Then the residual after each sweep on `stacked` (mu = 0.3) at the largest
// refinement up to 2, with and without the correction (3000 sweeps at most), to
// fl2c_convergence.dat and fl2c_convergence.png (gnuplot;
// doc/fl2c-convergence.png is a copy).
//
// Usage (from the repository's top folder):
//   build/fl2c_convergence [prm folder] [largest refinement, default 2]
//                          [smallest refinement, default 0]

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_state.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>
#include <fuzzycontact/study/observations.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

using namespace FuzzyContact;

namespace
{
  Report report;

  struct Run
  {
    std::vector<double> outputs; // slave.ux, slave.uy, Fn
    unsigned int        sweeps   = 0;
    double              residual = 0;
    double              time     = 0;
    std::string         failure;
  };

  // The largest relative error of the slave displacement and of F_n.
  std::pair<double, double>
  errors(const Run &run, const Run &exact)
  {
    const double u  = std::hypot(exact.outputs[0], exact.outputs[1]);
    const double du = std::hypot(run.outputs[0] - exact.outputs[0],
                                 run.outputs[1] - exact.outputs[1]);
    return {du / u,
            std::abs(run.outputs[2] - exact.outputs[2]) /
              std::abs(exact.outputs[2])};
  }

  Run
  solve(ReducedOrderModel   &model,
        const SceneState    &state,
        const ContactSolver &solver,
        const Observations  &outputs,
        const unsigned int   repetitions = 7)
  {
    Run                 run;
    std::vector<double> times;
    try
      {
        for (unsigned int i = 0; i < repetitions; ++i)
          {
            model.set_state(state);
            Timer                 timer;
            const ContactSolution s = model.solve(solver);
            times.push_back(timer.wall_time());
            run.outputs  = outputs.values(s);
            run.sweeps   = s.iterations;
            run.residual = s.residual;
          }
        std::sort(times.begin(), times.end());
        run.time = times[times.size() / 2];
      }
    catch (const dealii::ExceptionBase &e)
      {
        run.failure = Input::message_of(e);
      }
    return run;
  }

  std::string
  row(const std::string &name, const Run &run, const Run &exact)
  {
    std::ostringstream out;
    if (!run.failure.empty())
      {
        const std::size_t at = run.failure.find("complementarity residual");
        out << " | " << name << ": failed ("
            << (at == std::string::npos ? run.failure
                                        : run.failure.substr(at, 40))
            << ") | | |";
        return out.str();
      }
    const auto [du, dfn] = errors(run, exact);
    out << " | " << name << run.sweeps << " | "
        << Format::scientific(run.residual, 1) << " | "
        << Format::scientific(du, 1) << " / " << Format::scientific(dfn, 1)
        << " | " << Format::fixed(1e6 * run.time, 0);
    return out.str();
  }

  void
  measure(const std::string &prm,
          const std::string &scene_name,
          const unsigned int refinements)
  {
    const Scene          scene = Scene::read(prm + "/" + scene_name + ".prm");
    ContactScene         bodies(scene, refinements, 1e-8);
    const Observations   outputs({"slave.ux", "slave.uy", "Fn"}, bodies);
    ReducedModelSettings settings;
    ReducedOrderModel    model(bodies,
                            std::vector<ModalBasis>(bodies.n_components()),
                            outputs.dofs(),
                            {},
                            settings);
    FL2CParameters       corrected, plain;
    plain.coarse_correction = FL2CParameters::CoarseCorrection::none;
    plain.max_iterations    = 20000;
    // mu = 0, the scene's own, and mu = 2 at twice the load (the corner of
    // prm/step-4-stacked.prm's box).
    for (const int friction : {0, 1, 2})
      {
        SceneState state(scene);
        if (friction != 1)
          std::fill(state.friction_coefficients.begin(),
                    state.friction_coefficients.end(),
                    friction);
        if (friction == 2)
          for (auto &forces : state.load_forces)
            for (double &f : forces)
              f *= 2;
        const Run      exact = solve(model, state, ActiveSetSolver(), outputs);
        const Run      fc = solve(model, state, FL2CSolver(corrected), outputs);
        const Run      fp = solve(model, state, FL2CSolver(plain), outputs, 1);
        FullOrderModel full(bodies, outputs.dofs());
        full.set_state(state);
        Timer timer;
        full.solve();
        const double       cold = timer.wall_time();
        std::ostringstream out;
        out << "| " << scene_name << " | " << bodies.n_dofs()[0] << " | "
            << (friction == 0   ? "0"
                : friction == 1 ? "scene"
                                : "2, 2F")
            << " | " << Format::fixed(1e6 * exact.time, 0) << row("", fc, exact)
            << row("", fp, exact) << " | " << Format::fixed(cold, 3) << " | "
            << Format::fixed(cold / fc.time, 0) << "x |\n";
        report.say(out.str());
      }
  }

  // Residual after each sweep on `stacked`, mu = 0.3, with and without the
  // coarse correction.
  void
  history(const std::string &prm, const unsigned int refinements)
  {
    const Scene          scene = Scene::read(prm + "/stacked.prm");
    ContactScene         bodies(scene, refinements, 1e-8);
    const Observations   outputs({"slave.ux"}, bodies);
    ReducedModelSettings settings;
    ReducedOrderModel    model(bodies,
                            std::vector<ModalBasis>(bodies.n_components()),
                            outputs.dofs(),
                            {},
                            settings);
    model.set_state(SceneState(scene));
    std::ostringstream dat;
    dat << "# sweep residual (block 0: coarse correction, block 1: none)\n";
    for (const auto c : {FL2CParameters::CoarseCorrection::active_set,
                         FL2CParameters::CoarseCorrection::none})
      {
        FL2CParameters parameters;
        parameters.coarse_correction = c;
        parameters.tolerance         = 1e-12;
        parameters.max_iterations    = 3000;
        FL2CSolver solver(parameters);
        solver.set_monitor([&](const unsigned int sweep, const double r) {
          dat << sweep << " " << std::max(r, 1e-17) << "\n";
        });
        try
          {
            model.solve(solver);
          }
        catch (const dealii::ExceptionBase &)
          {
          }
        dat << "\n\n";
      }
    write_file_atomically("fl2c_convergence.dat", dat.str());
    const std::string title = "FL2C on stacked (" +
                              std::to_string(bodies.n_dofs()[0]) +
                              " DoFs per body, mu = 0.3, F = 50 kN)";
    write_file_atomically(
      "fl2c_convergence.gp",
      "set terminal pngcairo enhanced size 1000,480 font \",11\"\n"
      "set output \"fl2c_convergence.png\"\n"
      "set multiplot layout 1,2 title \"" +
        title +
        "\"\n"
        "set logscale y\nset format y \"10^{%L}\"\nset grid\n"
        "set ylabel \"relative complementarity residual\"\n"
        "set key top right\n"
        "set xlabel \"sweep (0: the starting state)\"\nset xrange [0:20]\n"
        "plot \"fl2c_convergence.dat\" index 0 w lp pt 7 lw 2 t \"with the "
        "coarse correction\", \"\" index 1 w lp pt 6 t \"regulators "
        "alone\"\n"
        "set xlabel \"sweep\"\nset xrange [1:*]\nset logscale x\n"
        "plot \"fl2c_convergence.dat\" index 1 w l lw 2 t \"regulators alone "
        "(the paper's sweeps)\"\n"
        "unset multiplot\n");
    if (std::system("gnuplot fl2c_convergence.gp") != 0)
      report.say("(gnuplot failed: no fl2c_convergence.png)\n");
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm = argc > 1 ? argv[1] : "prm";
  const unsigned int largest  = argc > 2 ? std::atoi(argv[2]) : 2;
  const unsigned int smallest = argc > 3 ? std::atoi(argv[3]) : 0;
  try
    {
      report.say(
        "# fl2c_convergence\n\nFL2C against the exact reduced solution "
        "(static correction, F = 50 kN as in the scenes). Per FL2C variant: "
        "sweeps | residual | error of the slave displacement / of F_n | "
        "time of one solve [us] (median of 7; without correction: one). Cold: "
        "one full-order solve "
        "with its factorisations [s]; speed-up: cold / FL2C with "
        "correction.\n\n"
        "| scene | DoFs/body | mu | exact [us] | FL2C sweeps | residual | "
        "error u / F_n | FL2C [us] | no correction: sweeps | residual | "
        "error u / F_n | [us] | cold solve [s] | speed-up |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
      for (unsigned int r = smallest; r <= largest; ++r)
        for (const std::string scene : {"stacked", "three-beams"})
          measure(prm, scene, r);
      history(prm, std::min(largest, 2u));
      write_file_atomically("fl2c_convergence.md", report.text());
      std::cout << "\nWrote fl2c_convergence.md, .dat, .png" << std::endl;
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::cerr << "fl2c_convergence: error: " << Input::message_of(e)
                << std::endl;
      return 1;
    }
  return 0;
}
