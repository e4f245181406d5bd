// A block on a slope against statics: prm/slope.prm, a block held by
// nothing but its contact on a 20-degree slope, pressed by a vertical
// force F on its top face (or, prm/slope-weight.prm, under its own weight
// F = rho g A t: the block's area A from its mesh). For each friction
// coefficient, the full-order solver's normal and tangential contact forces are
// set beside statics' N = F cos(theta) and T = F sin(theta), which hold
// whatever the pressure distribution as long as the block stays put (mu >=
// tan(theta)); below tan(theta) there is no static equilibrium, which the
// solver reports (the unbalanced fraction of the load's resultant). The reduced
// model (modes + static correction, FL2C) is set beside the full order; the
// block's rigid-body part (a least-squares fit of its displacement) shows it
// does not move as a whole beyond the elastic deformation. doc/validation.md
// records the output.
//
//   build/slope_statics [path/to/prm/slope.prm [mu ...]]
//   build/slope_statics prm/slope-weight.prm

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/fl2c.h>
#include <fuzzycontact/study/component_modes.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>
#include <fuzzycontact/study/reduced_order_model.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>
#include <deal.II/grid/grid_tools.h>

#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>

using namespace FuzzyContact;

namespace
{
  std::string
  scientific(const double x)
  {
    std::ostringstream out;
    out << std::scientific << std::setprecision(1) << x;
    return out.str();
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                file = argc > 1 ? argv[1] : "prm/slope.prm";
  std::vector<double>              coefficients;
  for (int i = 2; i < argc; ++i)
    coefficients.push_back(std::atof(argv[i]));
  const double theta = 20 * M_PI / 180;
  if (coefficients.empty())
    coefficients =
      {0.2, 0.3, 0.99 * std::tan(theta), 1.01 * std::tan(theta), 0.4, 0.5, 1.0};
  Scene scene = Scene::read(file);

  ContactScene     bodies(scene, 0);
  const Component &block = bodies.component(0);
  // The force on the block: its top load, or its weight rho |g| A t.
  const double F =
    scene.gravity.norm() > 0
      ? scene.components[0].zones[0].density * scene.gravity.norm() *
          GridTools::volume(block.triangulation(), block.mapping()) *
          scene.components[0].thickness
      : scene.components[0].loads[0].total_force;
  FullOrderModel    full(bodies, ObservedDofs(bodies.n_components()));
  ReducedOrderModel reduced(bodies,
                            component_modes(bodies, ModalParameters()),
                            ObservedDofs(bodies.n_components()),
                            std::vector<VaryingQuantity>(),
                            ReducedModelSettings());
  FL2CParameters    fl2c_parameters;
  fl2c_parameters.tolerance = 1e-10;
  const FL2CSolver fl2c(fl2c_parameters);

  std::cout << "Block on a slope (" << file
            << ", theta = 20 deg, tan(theta) = " << std::setprecision(4)
            << std::tan(theta) << ", F = " << F
            << (scene.gravity.norm() > 0 ? " N/m (its weight)" : " N/m") << "; "
            << bodies.n_dofs()[0] << "/" << bodies.n_dofs()[1] << " DoFs, "
            << bodies.interface().n_nodes()
            << " slave nodes; full-order solver, and FL2C on modes + static "
               "correction)\n"
               "      mu   N/(F cos)-1   T/(F sin)-1   FL2C-full (N, T)   "
               "stick/slip  block: u_x [m]   u_y [m]     rotation [rad]  "
               "solve [s]\n";
  for (const double mu : coefficients)
    {
      SceneState state(scene);
      std::fill(state.friction_coefficients.begin(),
                state.friction_coefficients.end(),
                mu);
      std::cout << std::fixed << std::setprecision(4) << std::setw(8) << mu;
      try
        {
          full.set_state(state);
          Timer                 timer;
          const ContactSolution s = full.solve();
          timer.stop();
          reduced.set_state(state);
          const ContactSolution r = reduced.solve(fl2c, "fl2c");
          // The block's free motions: x, y, rotation about its centre.
          const Vector<double> a = block.rigid_part(s.displacements[0]);
          const double N = s.normal_force, T = std::abs(s.tangential_force);
          std::cout << std::scientific << std::setprecision(2) << std::showpos
                    << std::setw(14) << N / (F * std::cos(theta)) - 1
                    << std::setw(14) << T / (F * std::sin(theta)) - 1
                    << std::noshowpos << std::setw(10)
                    << std::abs(r.normal_force - N) / N << std::setw(9)
                    << std::abs(r.tangential_force - s.tangential_force) / N
                    << std::setw(8) << s.count(ContactStatus::stick) << "/"
                    << std::left << std::setw(4) << s.count(ContactStatus::slip)
                    << std::right << std::showpos << std::setw(14) << a[0]
                    << std::setw(11) << a[1] << std::setw(16)
                    << a[2] * block.free_motion_angles()[2] << std::noshowpos
                    << std::fixed << std::setprecision(3) << std::setw(10)
                    << timer.wall_time() << "\n";
        }
      catch (const ExceptionBase &e)
        {
          // Statics: it needs mu = tan(theta) exactly.
          const std::string m    = Input::message_of(e);
          const auto        from = m.find(", would be ");
          std::cout
            << "   "
            << (from == std::string::npos
                  ? "failed: " + m
                  : "slides: no static equilibrium; the friction it "
                    "needs, mu = " +
                      m.substr(from + 11, m.find(")", from) - from - 11) +
                      ", is tan(theta) to " +
                      scientific(std::abs(std::atof(m.c_str() + from + 11) /
                                            std::tan(theta) -
                                          1)))
            << "\n";
        }
    }
  return 0;
}
