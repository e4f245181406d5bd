// Cattaneo-Mindlin validation: the roller of prm/cattaneo-mindlin.prm (the
// Hertz geometry, both bodies of one steel, mu = 0.3) is pressed down in a
// first load stage and moved sideways in a second one. For each sideways
// displacement of the roller's top (support shear), the full-order
// solver's normal force P, tangential force Q, contact half-width a and
// stick-zone half-width c are set beside Cattaneo-Mindlin's
// c = a sqrt(1 - Q / (mu P)), with the slave-node spacing at the edges of
// the stick zone; doc/validation.md records the output.
//
//   build/cattaneo_mindlin [path/to/prm/cattaneo-mindlin.prm [u_x ...]]

#include <fuzzycontact/fe/hertz_theory.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <cstdlib>
#include <iomanip>
#include <iostream>

using namespace FuzzyContact;

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string   file = argc > 1 ? argv[1] : "prm/cattaneo-mindlin.prm";
  std::vector<double> shifts;
  for (int i = 2; i < argc; ++i)
    shifts.push_back(std::atof(argv[i]));
  if (shifts.empty())
    shifts = {10e-6, 20e-6, 30e-6, 36e-6, 40e-6};
  const Scene scene = Scene::read(file);

  const ComponentDescription &roller = scene.components[0];
  unsigned int                shear  = roller.loads.size();
  for (unsigned int l = 0; l < roller.loads.size(); ++l)
    if (roller.loads[l].name == "shear")
      shear = l;
  AssertThrow(shear < roller.loads.size() && roller.mesh.arcs.size() == 1,
              ExcMessage("cattaneo_mindlin: the roller needs one arc and a "
                         "support called shear."));
  const auto  &arc = roller.mesh.arcs.begin()->second;
  const double mu  = scene.contact_pairs[0].friction_coefficient;

  ContactScene   bodies(scene, 0);
  FullOrderModel full(bodies, ObservedDofs(bodies.n_components()));
  std::cout << "Cattaneo-Mindlin validation on " << file
            << " (full-order solver, plane strain, mu = " << mu << ", stages";
  for (const LoadStage &stage : scene.load_stages)
    std::cout << " " << stage.name << ": " << stage.n_load_steps << " steps";
  std::cout << ")\n  u_x [um]  P [N/m]      Q [N/m]      Q/(mu P)  a [mm]"
               "   c [mm]   c_CM [mm]  (c - c_CM)/spacing  stick/slip nodes"
               "  solve [s]\n";
  for (const double shift : shifts)
    {
      SceneState state(scene);
      state.load_forces[0][shear] = shift;
      full.set_state(state);
      Timer                 timer;
      const ContactSolution s = full.solve();
      timer.stop();
      const Point<2> origin(arc.centre[0], arc.centre[1] - arc.radius);
      const auto     profile =
        HertzTheory::profile(bodies.interface(), s, 0, origin, 1.);
      const auto   zone  = HertzTheory::contact_zone(profile);
      const auto   stick = HertzTheory::stick_zone(profile);
      const double P = s.normal_force, Q = s.tangential_force;
      const double c_cm =
        HertzTheory::stick_half_width(zone.half_width, Q, mu, P);
      std::cout << std::fixed << std::setprecision(2) << std::setw(10)
                << 1e6 * shift << std::scientific << std::setprecision(4)
                << std::setw(13) << P << std::setw(13) << Q << std::fixed
                << std::setprecision(3) << std::setw(10)
                << std::abs(Q) / (mu * P) << std::setprecision(4)
                << std::setw(9) << 1e3 * zone.half_width << std::setw(9)
                << 1e3 * stick.half_width << std::setw(11) << 1e3 * c_cm
                << std::showpos << std::setprecision(2) << std::setw(20)
                << (stick.half_width - c_cm) / stick.node_spacing
                << std::noshowpos << std::setw(11)
                << s.count(ContactStatus::stick) << "/" << std::left
                << std::setw(6) << s.count(ContactStatus::slip) << std::right
                << std::setprecision(3) << std::setw(10) << timer.wall_time()
                << "\n";
    }

  // The same final loads in one proportional stage of 10 steps (the
  // tangential load grows with the contact zone): friction depends on the
  // path, and the stick zone is another one.
  Scene proportional = scene;
  proportional.load_stages.clear();
  ContactScene   plain(proportional, 0);
  FullOrderModel once(plain, ObservedDofs(plain.n_components()));
  once.set_n_load_steps(10);
  const ContactSolution s = once.solve();
  const auto            profile =
    HertzTheory::profile(plain.interface(),
                         s,
                         0,
                         Point<2>(arc.centre[0], arc.centre[1] - arc.radius),
                         1.);
  std::cout << "The scene's loads (u_x = " << std::setprecision(2)
            << 1e6 * roller.loads[shear].total_force
            << " um) in one proportional stage of 10 steps: Q/(mu P) = "
            << std::setprecision(3)
            << std::abs(s.tangential_force) / (mu * s.normal_force)
            << ", stick/slip nodes " << s.count(ContactStatus::stick) << "/"
            << s.count(ContactStatus::slip) << ", c = " << std::setprecision(4)
            << 1e3 * HertzTheory::stick_zone(profile).half_width << " mm\n";
  return 0;
}
