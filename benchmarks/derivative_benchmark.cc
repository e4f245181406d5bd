// derivative_benchmark: Lee's eigen-derivatives of the zone study by the two
// solvers of their bordered systems (eigen_derivatives.h), measured in one
// run: deflated CG on the shared Cholesky factorisation of the stiffness
// against one UMFPACK LU factorisation of each bordered matrix.
//
// For component P1 of a scene (default prm/overlap-zones.prm, the scene of
// prm/step-4-zones.prm) at each mesh refinement asked for, with the nominal
// modes of step-4 (9, ARPACK on the shared factorisation) and the
// parameters of the zone study (default P1.root.E), up to Taylor order 3:
//   - the time of the offline stage "Lee's derivatives" of the
//     parameter-independent HPTP by each solver (the best of three runs,
//     each solver in turn), the CG steps and the factorisations;
//   - the largest difference of the Taylor coefficients of the two
//     solvers, ||x_cg - x_lu||_M0 / ||x_lu||_M0 and |mu_cg - mu_lu| /
//     lambda_j, over every mode and multi-index;
//   - the largest relative difference of the HPTP-PI eigenvalues of the
//     two solvers at the corners of a +-5 % box (order 1 and 3).
// For reference, one factorisation of the stiffness (CHOLMOD) and the
// ARPACK modes on it are timed too; and what each exact solve of a zone
// study pays for its new factorisation of the stiffness (the contact and
// load DoFs last, as ContactScene orders them): with the symbolic analysis
// made afresh, and shared with the previous factorisation of the pattern
// (SparseCholesky; medians of five).
//
// Usage (from the repository's top folder):
//   build/derivative_benchmark [scene.prm] [parameters] [refinement ...]
// e.g. build/derivative_benchmark prm/overlap-zones.prm P1.root.E 1 2 3
// (parameters separated by commas). Prints a Markdown table.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/modal/modal_solver.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/reanalysis/eigen_derivatives.h>
#include <fuzzycontact/reanalysis/parameter_independent_reanalysis.h>
#include <fuzzycontact/reanalysis/reanalysis_method.h>
#include <fuzzycontact/study/contact_scene.h>

#include <deal.II/base/multithread_info.h>
#include <deal.II/base/timer.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace dealii;
using namespace FuzzyContact;
using Format::fixed;
using Format::scientific;

namespace
{
  struct Run
  {
    double                                         lee = 1e300;
    ParameterIndependentReanalysis::DerivativeCost cost;
  };

  // The offline build of HPTP-PI by @p method; the time of its stage
  // "reanalysis offline: Lee's derivatives".
  double
  lee_time(ParameterIndependentReanalysis       &pi,
           const Component                      &component,
           const ModalBasis                     &nominal,
           const std::vector<std::string>       &parameters,
           const DerivativeSolver                method,
           std::shared_ptr<const SparseCholesky> factorisation)
  {
    TimerOutput timer(std::cout, TimerOutput::never, TimerOutput::wall_times);
    pi.offline(component,
               nominal,
               parameters,
               3,
               1e-6,
               1e-2,
               &timer,
               method,
               std::move(factorisation));
    return timer.get_summary_data(TimerOutput::total_wall_time)
      .at("reanalysis offline: Lee's derivatives");
  }

  double
  m_norm(const SparseMatrix<double> &M, const Vector<double> &v)
  {
    return std::sqrt(M.matrix_norm_square(v));
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  MultithreadInfo::set_thread_limit(1);
  const std::string scene_file = argc > 1 ? argv[1] : "prm/overlap-zones.prm";
  const std::vector<std::string> parameters =
    Utilities::split_string_list(argc > 2 ? argv[2] : "P1.root.E", ',');
  std::vector<unsigned int> refinements;
  for (int i = 3; i < argc; ++i)
    refinements.push_back(std::atoi(argv[i]));
  if (refinements.empty())
    refinements = {1, 2, 3};
  try
    {
      std::cout
        << "# derivative_benchmark\n\n"
        << scene_file
        << ", first component, Taylor order 3, 9 nominal modes, 1 thread\n\n"
        << "| DoFs | parameters | factorisation [s] | ARPACK [s] | Lee, "
           "direct [s] | LU factorisations | Lee, deflated CG [s] | systems "
           "| CG steps (mean) | left to LU | speed-up | coefficients: max "
           "dx / |x| (M0) | max dmu / lambda | eigenvalues, order 1 | "
           "eigenvalues, order 3 | refactorisation, analysis afresh [s] | "
           "refactorisation, analysis shared [s] |\n"
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
           "---|\n";
      for (const unsigned int r : refinements)
        {
          const Scene        scene = Scene::read(scene_file);
          const ContactScene bodies(scene, r);
          const Component   &component = bodies.component(0);
          Timer              clock;
          const auto         factorisation = bodies.stiffness_factorisation(0);
          const double       t_factorisation = clock.wall_time();
          ModalParameters    modal;
          modal.n_modes = 9;
          clock.restart();
          const ModalBasis nominal =
            ModalSolver(modal).solve(component.stiffness_matrix(),
                                     component.mass_matrix(),
                                     *factorisation,
                                     "P1");
          const double t_arpack = clock.wall_time();

          // Best of three, the solvers in turn.
          Run                            direct, deflated;
          ParameterIndependentReanalysis pi_direct, pi_deflated;
          for (unsigned int repetition = 0; repetition < 3; ++repetition)
            {
              direct.lee    = std::min(direct.lee,
                                    lee_time(pi_direct,
                                             component,
                                             nominal,
                                             parameters,
                                             DerivativeSolver::direct,
                                             factorisation));
              direct.cost   = pi_direct.derivative_cost();
              deflated.lee  = std::min(deflated.lee,
                                      lee_time(pi_deflated,
                                               component,
                                               nominal,
                                               parameters,
                                               DerivativeSolver::deflated_cg,
                                               factorisation));
              deflated.cost = pi_deflated.derivative_cost();
            }

          // The coefficients of the two solvers, mode by mode.
          const ParameterModel            &model = pi_direct.model();
          const unsigned int               n_p   = model.n_parameters();
          std::vector<std::vector<double>> identity(n_p,
                                                    std::vector<double>(n_p,
                                                                        0.));
          for (unsigned int k = 0; k < n_p; ++k)
            identity[k][k] = 1;
          const auto cg =
            std::make_shared<DeflatedBorderedSolver>(model,
                                                     pi_direct.nominal(),
                                                     factorisation);
          double dx = 0, dmu = 0;
          for (const auto &cluster : pi_direct.clusters())
            {
              const bool                    single = cluster.size() == 1;
              const EigenTaylorCoefficients a =
                EigenDerivatives(model, pi_direct.nominal(), cluster, 1e-2)
                  .taylor_coefficients(identity, 3, single);
              const EigenTaylorCoefficients b =
                EigenDerivatives(model,
                                 pi_direct.nominal(),
                                 cluster,
                                 1e-2,
                                 nullptr,
                                 cg)
                  .taylor_coefficients(identity, 3, single);
              for (unsigned int i = 1; i < a.indices.size(); ++i)
                for (unsigned int j = 0; j < cluster.size(); ++j)
                  {
                    Vector<double> d = b.vectors[i][j];
                    d -= a.vectors[i][j];
                    dx =
                      std::max(dx,
                               m_norm(model.nominal_mass(), d) /
                                 m_norm(model.nominal_mass(), a.vectors[i][j]));
                    for (unsigned int l = 0; l < cluster.size(); ++l)
                      dmu =
                        std::max(dmu,
                                 std::abs(b.eigenvalues[i](l, j) -
                                          a.eigenvalues[i](l, j)) /
                                   pi_direct.nominal().eigenvalues[cluster[j]]);
                  }
            }

          // The HPTP-PI eigenvalues of the two at the corners of +-5 %.
          double de1 = 0, de3 = 0;
          for (unsigned long corner = 0; corner < (1ul << n_p); ++corner)
            {
              std::vector<double> t(n_p);
              for (unsigned int k = 0; k < n_p; ++k)
                t[k] = (corner >> k) & 1 ? 0.05 : -0.05;
              for (const unsigned int order : {1u, 3u})
                {
                  const auto la = pi_direct.online(t, order).eigenvalues;
                  const auto lb = pi_deflated.online(t, order).eigenvalues;
                  for (unsigned int j = 0; j < la.size(); ++j)
                    (order == 1 ? de1 : de3) =
                      std::max(order == 1 ? de1 : de3,
                               std::abs(lb[j] - la[j]) / la[j]);
                }
            }

          // A new factorisation of the stiffness's pattern: afresh (two
          // other patterns factorised in between push it out of the
          // analyses SparseCholesky keeps), and right after another.
          const auto          last = bodies.boundary_dofs(0);
          const auto         &K    = component.stiffness_matrix();
          std::vector<double> afresh, shared;
          for (unsigned int repetition = 0; repetition < 5; ++repetition)
            {
              for (const types::global_dof_index other : {0u, 1u})
                {
                  SparseCholesky evict;
                  evict.factorize(K, {other});
                }
              for (std::vector<double> *times : {&afresh, &shared})
                {
                  SparseCholesky F;
                  clock.restart();
                  F.factorize(K, last);
                  times->push_back(clock.wall_time());
                }
            }
          std::sort(afresh.begin(), afresh.end());
          std::sort(shared.begin(), shared.end());

          std::string names;
          for (const std::string &p : parameters)
            names += (names.empty() ? "" : ", ") + p;
          const auto &c = deflated.cost;
          std::cout << "| " << component.n_dofs() << " | " << names << " | "
                    << fixed(t_factorisation, 3) << " | " << fixed(t_arpack, 3)
                    << " | " << fixed(direct.lee, 3) << " | "
                    << direct.cost.factorisations << " | "
                    << fixed(deflated.lee, 3) << " | " << c.systems << " | "
                    << fixed(c.systems ? double(c.cg_iterations) / c.systems
                                       : 0.,
                             1)
                    << " | " << c.not_solved_by_cg << " | "
                    << fixed(direct.lee / deflated.lee, 1) << "x | "
                    << scientific(dx, 1) << " | " << scientific(dmu, 1) << " | "
                    << scientific(de1, 1) << " | " << scientific(de3, 1)
                    << " | " << fixed(afresh[2], 3) << " | "
                    << fixed(shared[2], 3) << " |" << std::endl;
        }
    }
  catch (const ExceptionBase &e)
    {
      std::cerr << "derivative_benchmark: error: " << Input::message_of(e)
                << std::endl;
      return 1;
    }
  return 0;
}
