// Benchmark of the modal reanalysis (not a test): time per parameter sample
// of each method against the exact ARPACK re-solve, on the cantilever of
// prm/cantilever-zones.prm refined to about 5k, 20k and 80k DoFs, with the
// error of each answer next to its time. The tables go into
// doc/reanalysis.md.
//
//   build/reanalysis_benchmark [scene.prm] [refinement ...]
//
// from the repository's top folder (default scene prm/cantilever-zones.prm,
// default refinements 1 2 3).
//
// One thread (deal.II's thread limit set to 1; BLAS and UMFPACK are serial
// here anyway), so that the ratios do not depend on what else the machine
// is doing with its second core. Each online time is the median over
// several samples; the exact re-solve is timed from forming K(t), M(t) to
// the 9 modes (UMFPACK factorisation + ARPACK).

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/modal/mode_comparison.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/reanalysis/exact_resolve.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>
#include <fuzzycontact/reanalysis/reanalysis_factory.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/scene/scene.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using namespace FuzzyContact;
using Format::fixed;
using Format::scientific;

namespace
{
  double
  median(std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
  }

  // Median wall time of f over @p repetitions calls, each repeated until at
  // least 2 ms have passed (so that microsecond calls are measurable).
  double
  time_median(const std::function<void()> &f, const unsigned int repetitions)
  {
    std::vector<double> times;
    for (unsigned int r = 0; r < repetitions; ++r)
      {
        Timer        timer;
        unsigned int calls = 0;
        do
          {
            f();
            ++calls;
          }
        while (timer.wall_time() < 2e-3);
        times.push_back(timer.wall_time() / calls);
      }
    return median(times);
  }

  struct Study
  {
    std::string              label;
    std::vector<std::string> parameters;
    // Samples are drawn uniformly in [-range, range] for every parameter.
    double range;
  };

  using Reanalyse =
    std::function<ReanalysisResult(const std::vector<double> &)>;


  // The samples of one study on one mesh, their exact re-solves (time and
  // reference modes), and the table rows of the methods measured against
  // them.
  class MeshBenchmark
  {
  public:
    MeshBenchmark(const ParameterModel &model,
                  const Study          &study,
                  const unsigned int    n_samples)
        : model(model)
        , samples(n_samples)
        , masses(n_samples)
    {
      std::mt19937                           random(12345);
      std::uniform_real_distribution<double> uniform(-study.range, study.range);
      for (auto &t : samples)
        for (unsigned int k = 0; k < study.parameters.size(); ++k)
          t.push_back(uniform(random));

      // 3 extra modes for the MAC pairing, solved separately and not timed.
      ModalParameters modal;
      modal.n_modes = 9;
      const ExactResolve exact(model, modal);
      ModalParameters    more = modal;
      more.n_modes            = 12;
      const ExactResolve  reference(model, more);
      std::vector<double> exact_times;
      for (unsigned int s = 0; s < n_samples; ++s)
        {
          Timer timer;
          exact.solve(samples[s]);
          exact_times.push_back(timer.wall_time());
          exact_modes.push_back(reference.solve(samples[s]));
          SparseMatrix<double> K;
          model.matrices(samples[s], K, masses[s]);
        }
      time_exact = median(exact_times);
    }

    // The median over the samples of the time @p online takes, measured
    // once per sample, or as the median of 3 repeated measurements if
    // @p repeat.
    double
    online_time(const std::function<void(const std::vector<double> &)> &online,
                const bool repeat) const
    {
      std::vector<double> times;
      for (const auto &t : samples)
        if (repeat)
          times.push_back(time_median(
            [&]() {
              online(t);
            },
            3));
        else
          {
            Timer timer;
            online(t);
            times.push_back(timer.wall_time());
          }
      return median(times);
    }

    // One table row: times, and the worst error and MAC over the samples.
    void
    row(const std::string &method,
        const unsigned int order,
        const unsigned int basis,
        const double       offline,
        const double       online,
        const Reanalyse   &reanalyse) const
    {
      double max_error = 0, min_mac = 1;
      for (unsigned int s = 0; s < samples.size(); ++s)
        {
          const ReanalysisResult result = reanalyse(samples[s]);
          const ModeComparison   c      = compare_modes(result.eigenvalues,
                                                 result.modes,
                                                 exact_modes[s],
                                                 masses[s]);
          max_error = std::max(max_error, c.max_relative_error);
          min_mac   = std::min(min_mac, c.min_mac);
        }
      std::cout << "| " << n_dofs() << " | " << method << " | "
                << (order ? std::to_string(order) : "-") << " | "
                << (basis ? std::to_string(basis) : "-") << " | "
                << fixed(offline, 2) << " | " << scientific(online, 2) << " | "
                << fixed(time_exact, 3) << " | "
                << fixed(time_exact / online, 0) << "x | "
                << scientific(max_error) << " | " << fixed(min_mac, 8) << " |"
                << std::endl;
    }

    unsigned int
    n_dofs() const
    {
      return model.component().n_dofs();
    }

    const ParameterModel             &model;
    std::vector<std::vector<double>>  samples;
    std::vector<ModalBasis>           exact_modes;
    std::vector<SparseMatrix<double>> masses;
    double                            time_exact;
  };


  // The parameter-independent HPTP: offline once up to order 3, online at
  // each order (the eigenvalues and Y only: nothing of size n_dofs), and the
  // optional work of size n_dofs for reference.
  void
  benchmark_parameter_independent(const MeshBenchmark      &bench,
                                  const ModalBasis         &nominal,
                                  const ReanalysisSettings &settings)
  {
    Timer      timer;
    const auto method =
      create_reanalysis_method("hptp-pi", bench.model, nominal, settings);
    const double offline = timer.wall_time();
    const auto  &pi =
      dynamic_cast<const ParameterIndependentReanalysis &>(*method);
    for (unsigned int order = 1; order <= 3; ++order)
      bench.row("hptp-pi",
                order,
                pi.basis_size(order),
                offline,
                bench.online_time(
                  [&](const std::vector<double> &t) {
                    pi.online(t, order);
                  },
                  true),
                [&](const std::vector<double> &t) {
                  return pi.reanalyse(t, order);
                });
    const std::vector<double> &t      = bench.samples[0];
    const ReanalysedModes      r      = pi.online(t, 2);
    const double               expand = time_median(
      [&]() {
        pi.modes(r);
      },
      3);
    pi.residuals(t, r); // factorises K0 once
    const double check = time_median(
      [&]() {
        pi.residuals(t, r);
      },
      3);
    std::cout << "| " << bench.n_dofs()
              << " | (hptp-pi, order 2: expanding the 9 modes T Y "
              << scientific(expand, 2) << " s; residual check "
              << scientific(check, 2) << " s) | | | | | | | | |" << std::endl;
  }


  // The sample-dependent rivals, whose online cost grows with the mesh:
  // HPTP at orders 1 and 2, CA at order 2, first-order Taylor.
  void
  benchmark_sample_dependent(const MeshBenchmark      &bench,
                             const ModalBasis         &nominal,
                             const ReanalysisSettings &settings)
  {
    const std::vector<std::pair<std::string, std::vector<unsigned int>>>
      methods = {{"hptp", {1, 2}}, {"ca", {2}}, {"taylor", {1}}};
    for (const auto &[name, orders] : methods)
      {
        Timer      timer;
        const auto method =
          create_reanalysis_method(name, bench.model, nominal, settings);
        const double offline = timer.wall_time();
        for (const unsigned int order : orders)
          bench.row(name,
                    order,
                    0,
                    offline,
                    bench.online_time(
                      [&](const std::vector<double> &t) {
                        method->reanalyse(t, order);
                      },
                      /*repeat=*/name == "taylor"),
                    [&](const std::vector<double> &t) {
                      return method->reanalyse(t, order);
                    });
      }
  }
} // namespace


namespace
{
  void
  run(const std::string &scene_file, std::vector<unsigned int> refinements)
  {
    const Scene scene = Scene::read(scene_file);

    const std::vector<Study> studies = {
      {"1 parameter (beam.root.E), +-20 %", {"beam.root.E"}, 0.2},
      {"3 parameters (beam.root.E, beam.tip.E, beam.tip.rho), +-15 %",
       {"beam.root.E", "beam.tip.E", "beam.tip.rho"},
       0.15}};
    // Every method is made by the library's factory with these settings.
    ReanalysisSettings settings;
    settings.max_order            = 3;
    settings.truncation_tolerance = 1e-6;
    settings.cluster_gap          = 1e-2;

    std::cout << "Modal reanalysis benchmark: " << scene_file
              << ", 9 modes, 1 thread, truncation tolerance "
              << settings.truncation_tolerance << "\n";
    for (const Study &study : studies)
      {
        std::cout
          << "\n## " << study.label << "\n\n"
          << "| DoFs | method | order | basis | offline [s] | online per "
             "sample [s] | exact re-solve [s] | speed-up | max rel. "
             "error | min MAC |\n"
          << "|---|---|---|---|---|---|---|---|---|---|\n";
        for (const unsigned int r : refinements)
          {
            const Component component(scene.components[0],
                                      scene.plane_model,
                                      r);
            ModalParameters modal;
            modal.n_modes = 9;
            const ModalBasis nominal =
              ModalSolver(modal).solve(component.stiffness_matrix(),
                                       component.mass_matrix(),
                                       "beam");
            const ParameterModel model(component, study.parameters);
            const MeshBenchmark  bench(model, study, /*n_samples=*/5);
            benchmark_parameter_independent(bench, nominal, settings);
            benchmark_sample_dependent(bench, nominal, settings);
          }
      }
  }
} // namespace


int
main(int argc, char **argv)
{
  MultithreadInfo::set_thread_limit(1);
  std::string               scene_file = "prm/cantilever-zones.prm";
  std::vector<unsigned int> refinements;
  for (int a = 1; a < argc; ++a)
    {
      const std::string arg = argv[a];
      if (arg.size() > 4 && arg.substr(arg.size() - 4) == ".prm")
        scene_file = arg;
      else
        refinements.push_back(std::atoi(arg.c_str()));
    }
  if (refinements.empty())
    refinements = {1, 2, 3};
  try
    {
      run(scene_file, refinements);
    }
  catch (const ExceptionBase &e)
    {
      std::cerr << "reanalysis_benchmark: error: " << Input::message_of(e)
                << std::endl;
      return 1;
    }
  return 0;
}
