// The contact patch test: the two blocks of prm/patch-test.prm (one
// material, frictionless, plane strain, compressed by a prescribed
// displacement of the upper block's top face) on matching and non-matching
// meshes, Q1 and Q2, the slave (upper) face finer and coarser than the
// master face, at the scene's mesh and refined once. The exact solution is
// a uniform uniaxial stress (fe/patch_test.h); for each mesh the program
// prints the error of the nodal contact pressure (max and RMS, relative),
// of the displacement (largest nodal error over the largest displacement),
// of the total contact force, and the force balance (support reactions
// against the contact force, and the largest residual K u - C^T p on a
// free DoF, both relative to the contact force). doc/validation.md records
// the output.
//
//   build/patch_test [path/to/prm/patch-test.prm]

#include <fuzzycontact/fe/patch_test.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>

#include <deal.II/base/mpi.h>

#include <iomanip>
#include <iostream>

using namespace FuzzyContact;

namespace
{
  PatchTest::Errors
  run(Scene              scene,
      const unsigned int degree,
      const unsigned int slave_cells,
      const unsigned int master_cells,
      const unsigned int refinements)
  {
    scene.components[0].fe_degree       = degree;
    scene.components[1].fe_degree       = degree;
    scene.components[0].subdivisions[0] = slave_cells;
    scene.components[1].subdivisions[0] = master_cells;
    ContactScene   bodies(scene, refinements);
    FullOrderModel full(bodies, ObservedDofs(bodies.n_components()));
    full.set_state(SceneState(scene));
    const ContactSolution solution = full.solve();

    const ComponentDescription          &upper = scene.components[0];
    const ComponentDescription          &lower = scene.components[1];
    const PatchTest::UniaxialCompression exact{
      scene.plane_model,
      upper.zones[0].youngs_modulus,
      upper.zones[0].poissons_ratio,
      upper.upper_right[1] - lower.lower_left[1],
      -upper.supports[0].displacement[1]};
    return PatchTest::measure(bodies.components(),
                              bodies.interface(),
                              solution,
                              exact);
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string file  = argc > 1 ? argv[1] : "prm/patch-test.prm";
  const Scene       scene = Scene::read(file);

  std::cout << "Contact patch test on " << file
            << " (full-order solver, frictionless, "
            << (scene.plane_model == PlaneModel::plane_strain ? "plane strain"
                                                              : "plane stress")
            << ")\n"
            << "  p  cells slave:master  refinements  slave nodes (closed)"
               "  pressure error max / RMS   displacement error"
               "  force error  reaction balance  equilibrium residual\n";
  const std::pair<unsigned int, unsigned int> meshes[] = {{5, 5},
                                                          {7, 5},
                                                          {5, 7},
                                                          {13, 8},
                                                          {8, 13}};
  for (const unsigned int degree : {1u, 2u})
    for (const auto &[slave, master] : meshes)
      for (const unsigned int r : {0u, 1u})
        {
          const PatchTest::Errors e = run(scene, degree, slave, master, r);
          std::cout << std::setw(3) << degree << std::setw(11) << slave << ":"
                    << std::left << std::setw(9) << master << std::right
                    << std::setw(12) << r << std::setw(14) << e.n_slave_nodes
                    << " (" << std::setw(3) << e.n_closed << ")"
                    << std::scientific << std::setprecision(2) << std::setw(14)
                    << e.max_pressure_error << " / " << std::setw(8)
                    << e.rms_pressure_error << std::setw(20)
                    << e.max_displacement_error << std::setw(13)
                    << e.contact_force / e.exact_force - 1 << std::setw(18)
                    << e.reaction_balance << std::setw(22)
                    << e.equilibrium_residual << "\n";
        }
  return 0;
}
