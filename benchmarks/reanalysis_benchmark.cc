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

#include <fuzzycontact/fe/component.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/modal/mode_comparison.h>
#include <fuzzycontact/reanalysis/combined_approximations.h>
#include <fuzzycontact/reanalysis/exact_resolve.h>
#include <fuzzycontact/reanalysis/first_order_taylor.h>
#include <fuzzycontact/reanalysis/homotopy_perturbation.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>
#include <fuzzycontact/reanalysis/reanalysis_parameters.h>
#include <fuzzycontact/reanalysis/residual_check.h>
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

  std::string
  sci(const double x, const int digits = 1)
  {
    std::ostringstream s;
    s << std::scientific << std::setprecision(digits) << x;
    return s.str();
  }

  std::string
  fix(const double x, const int digits)
  {
    std::ostringstream s;
    s << std::fixed << std::setprecision(digits) << x;
    return s.str();
  }

  struct Study
  {
    std::string              label;
    std::vector<std::string> parameters;
    // Samples are drawn uniformly in [-range, range] for every parameter.
    double range;
  };
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
  const Scene scene = Scene::read(scene_file);

  const std::vector<Study> studies = {
    {"1 parameter (beam.root.E), +-20 %", {"beam.root.E"}, 0.2},
    {"3 parameters (beam.root.E, beam.tip.E, beam.tip.rho), +-15 %",
     {"beam.root.E", "beam.tip.E", "beam.tip.rho"},
     0.15}};
  const unsigned int n_samples   = 5;
  const unsigned int orders[]    = {1, 2, 3};
  const double       truncation  = 1e-6;
  const double       cluster_gap = 1e-2;

  std::cout << "Modal reanalysis benchmark: " << scene_file
            << ", 9 modes, 1 thread, truncation tolerance " << truncation
            << "\n";

  for (const Study &study : studies)
    {
      std::cout << "\n## " << study.label << "\n\n"
                << "| DoFs | method | order | basis | offline [s] | online per "
                   "sample [s] | exact re-solve [s] | speed-up | max rel. "
                   "error | min MAC |\n"
                << "|---|---|---|---|---|---|---|---|---|---|\n";
      for (const unsigned int r : refinements)
        {
          const Component component(scene.components[0], scene.plane_model, r);
          ModalParameters modal;
          modal.n_modes = 9;
          const ModalBasis nominal =
            ModalSolver(modal).solve(component.stiffness_matrix(),
                                     component.mass_matrix(),
                                     "beam");
          const ParameterModel model(component, study.parameters);

          std::mt19937                           random(12345);
          std::uniform_real_distribution<double> uniform(-study.range,
                                                         study.range);
          std::vector<std::vector<double>>       samples(n_samples);
          for (auto &t : samples)
            for (unsigned int k = 0; k < study.parameters.size(); ++k)
              t.push_back(uniform(random));

          // The exact re-solve: time and reference modes (3 extra modes for
          // the MAC pairing, solved separately and not timed).
          const ExactResolve exact(model, modal);
          ModalParameters    more = modal;
          more.n_modes            = 12;
          const ExactResolve                reference(model, more);
          std::vector<double>               exact_times;
          std::vector<ModalBasis>           exact_modes;
          std::vector<SparseMatrix<double>> masses(n_samples);
          for (unsigned int s = 0; s < n_samples; ++s)
            {
              Timer timer;
              exact.solve(samples[s]);
              exact_times.push_back(timer.wall_time());
              exact_modes.push_back(reference.solve(samples[s]));
              SparseMatrix<double> K;
              model.matrices(samples[s], K, masses[s]);
            }
          const double time_exact = median(exact_times);

          const auto report = [&](const std::string               &method,
                                  const unsigned int               order,
                                  const unsigned int               basis,
                                  const double                     offline,
                                  const double                     online,
                                  const std::function<ReanalysisResult(
                                    const std::vector<double> &)> &reanalyse) {
            double max_error = 0, min_mac = 1;
            for (unsigned int s = 0; s < n_samples; ++s)
              {
                const ReanalysisResult result = reanalyse(samples[s]);
                const ModeComparison   c = compare_modes(result.eigenvalues,
                                                       result.modes,
                                                       exact_modes[s],
                                                       masses[s]);
                max_error = std::max(max_error, c.max_relative_error);
                min_mac   = std::min(min_mac, c.min_mac);
              }
            std::cout << "| " << component.n_dofs() << " | " << method << " | "
                      << (order ? std::to_string(order) : "-") << " | "
                      << (basis ? std::to_string(basis) : "-") << " | "
                      << fix(offline, 2) << " | " << sci(online, 2) << " | "
                      << fix(time_exact, 3) << " | "
                      << fix(time_exact / online, 0) << "x | " << sci(max_error)
                      << " | " << fix(min_mac, 8) << " |" << std::endl;
          };

          // Parameter-independent HPTP: offline once up to order 3, online at
          // each order (the eigenvalues and Y only: nothing of size n_dofs).
          {
            ParameterIndependentReanalysis pi;
            Timer                          timer;
            pi.offline(component,
                       nominal,
                       study.parameters,
                       3,
                       truncation,
                       cluster_gap);
            const double offline = timer.wall_time();
            for (const unsigned int order : orders)
              {
                std::vector<double> times;
                for (const auto &t : samples)
                  times.push_back(time_median(
                    [&]() {
                      pi.online(t, order);
                    },
                    3));
                report("hptp-pi",
                       order,
                       pi.basis_size(order),
                       offline,
                       median(times),
                       [&](const std::vector<double> &t) {
                         return pi.reanalyse(t, order);
                       });
              }
            // The optional work of size n_dofs, for reference.
            const ReanalysedModes r      = pi.online(samples[0], 2);
            const double          expand = time_median(
              [&]() {
                pi.modes(r);
              },
              3);
            pi.residuals(samples[0], r); // factorises K0 once
            const double check = time_median(
              [&]() {
                pi.residuals(samples[0], r);
              },
              3);
            std::cout << "| " << component.n_dofs()
                      << " | (hptp-pi, order 2: expanding the 9 modes T Y "
                      << sci(expand, 2) << " s; residual check "
                      << sci(check, 2) << " s) | | | | | | | | |" << std::endl;
          }

          // The sample-dependent rivals: their online cost grows with the mesh.
          {
            Timer                      timer;
            const HomotopyPerturbation hptp(model,
                                            nominal,
                                            truncation,
                                            cluster_gap);
            const double               offline = timer.wall_time();
            for (const unsigned int order : {1u, 2u})
              {
                std::vector<double> times;
                for (const auto &t : samples)
                  {
                    Timer tt;
                    hptp.reanalyse(t, order);
                    times.push_back(tt.wall_time());
                  }
                report("hptp",
                       order,
                       0,
                       offline,
                       median(times),
                       [&](const std::vector<double> &t) {
                         return hptp.reanalyse(t, order);
                       });
              }
          }
          {
            Timer                        timer;
            const CombinedApproximations ca(model, nominal, truncation);
            const double                 offline = timer.wall_time();
            std::vector<double>          times;
            for (const auto &t : samples)
              {
                Timer tt;
                ca.reanalyse(t, 2);
                times.push_back(tt.wall_time());
              }
            report("ca",
                   2,
                   0,
                   offline,
                   median(times),
                   [&](const std::vector<double> &t) {
                     return ca.reanalyse(t, 2);
                   });
          }
          {
            Timer                  timer;
            const FirstOrderTaylor taylor(model, nominal, cluster_gap);
            const double           offline = timer.wall_time();
            std::vector<double>    times;
            for (const auto &t : samples)
              times.push_back(time_median(
                [&]() {
                  taylor.reanalyse(t);
                },
                3));
            report("taylor",
                   1,
                   0,
                   offline,
                   median(times),
                   [&](const std::vector<double> &t) {
                     return taylor.reanalyse(t);
                   });
          }
        }
    }
  return 0;
}
