// Hertz validation: the roller of prm/hertz.prm (a half cylinder from a Gmsh
// geometry, its arc an exact circle) pressed onto the block by a prescribed
// displacement, frictionless, in plane strain. For each global refinement
// of the shipped meshes, the full-order contact solver's contact force P,
// contact half-width and peak pressure are set beside Hertz's
// a = sqrt(4 P R / (pi E*)) and p0 = 2 P / (pi a), with the slave-node
// spacing at the edge of the contact zone and the time of one cold solve.
// The pressure profile of the shipped mesh against p0 sqrt(1 - x^2/a^2) goes
// to hertz-profile.dat and hertz-profile.png (gnuplot) in the current folder.
// Then the stress in the block under the middle of the contact: the largest
// von Mises stress and in-plane shear and their depths, against McEwen's
// closed form (HertzTheory::subsurface_peaks()). doc/validation.md records
// the output.
//
//   build/hertz_validation [path/to/prm/hertz.prm [finest refinement]]

#include <fuzzycontact/fe/hertz_theory.h>
#include <fuzzycontact/study/contact_scene.h>
#include <fuzzycontact/study/full_order_model.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>

using namespace FuzzyContact;

namespace
{
  struct Row
  {
    unsigned int                           refinements, dofs_slave, dofs_master;
    double                                 force, time;
    HertzTheory::Cylinder                  theory;
    HertzTheory::ContactZone               zone;
    std::vector<HertzTheory::ProfilePoint> profile;
    HertzTheory::SubsurfacePeaks           peaks;
  };

  Row
  run(const Scene &scene, const unsigned int refinements)
  {
    ContactScene   bodies(scene, refinements);
    Timer          timer;
    FullOrderModel full(bodies, ObservedDofs(bodies.n_components()));
    full.set_state(SceneState(scene));
    const ContactSolution solution = full.solve_with_fields();
    timer.stop();

    const ComponentDescription &roller = scene.components[0];
    const ComponentDescription &block  = scene.components[1];
    AssertThrow(roller.mesh.arcs.size() == 1,
                ExcMessage("hertz_validation: the roller needs one arc."));
    const auto &arc = roller.mesh.arcs.begin()->second;
    Row         row{refinements,
            bodies.component(0).n_dofs(),
            bodies.component(1).n_dofs(),
            solution.normal_force,
            timer.wall_time(),
            {arc.radius,
                     HertzTheory::contact_modulus(roller.zones[0].youngs_modulus,
                                          roller.zones[0].poissons_ratio,
                                          block.zones[0].youngs_modulus,
                                          block.zones[0].poissons_ratio),
                     solution.normal_force / roller.thickness},
            {},
            {},
            {}};
    // The first contact is the arc's lowest point.
    const Point<2> origin(arc.centre[0], arc.centre[1] - arc.radius);
    row.profile = HertzTheory::profile(bodies.interface(),
                                       solution,
                                       0,
                                       origin,
                                       roller.thickness);
    row.zone    = HertzTheory::contact_zone(row.profile);
    row.peaks   = HertzTheory::subsurface_peaks(row.theory,
                                              bodies.component(1),
                                              solution.displacements[1],
                                              origin,
                                              block.zones[0].youngs_modulus,
                                              block.zones[0].poissons_ratio);
    return row;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                file = argc > 1 ? argv[1] : "prm/hertz.prm";
  const unsigned int               finest = argc > 2 ? std::atoi(argv[2]) : 2;
  const Scene                      scene  = Scene::read(file);

  std::cout << "Hertz validation on " << file
            << " (full-order solver, frictionless, plane strain)\n"
            << " refinements  DoFs roller/block  P [N/m]       a_FE [mm]"
               "  a_Hertz [mm]  spacing [mm]  p0_FE [MPa]  p0_Hertz [MPa]"
               "  p0 error  nodal p0 error  solve [s]\n";
  std::vector<Row> rows;
  for (unsigned int r = 0; r <= finest; ++r)
    {
      const Row   &row = rows.emplace_back(run(scene, r));
      const double a = row.theory.half_width(), p0 = row.theory.peak_pressure();
      std::cout << std::setw(12) << r << std::setw(10) << row.dofs_slave << "/"
                << std::setw(7) << std::left << row.dofs_master << std::right
                << std::scientific << std::setprecision(4) << std::setw(13)
                << row.force << std::fixed << std::setprecision(4)
                << std::setw(12) << 1e3 * row.zone.half_width << std::setw(14)
                << 1e3 * a << std::setw(14) << 1e3 * row.zone.node_spacing
                << std::setprecision(1) << std::setw(13)
                << 1e-6 * row.zone.peak_pressure << std::setw(16) << 1e-6 * p0
                << std::showpos << std::setprecision(2) << std::setw(9)
                << 100 * (row.zone.peak_pressure / p0 - 1) << "%"
                << std::setw(15)
                << 100 * (row.zone.nodal_peak_pressure / p0 - 1) << "%"
                << std::noshowpos << std::setprecision(3) << std::setw(11)
                << row.time << "\n";
    }

  // The stress under the middle of the contact, in the block, against
  // McEwen's closed form for the same P (surface to 3a, every 0.05 a).
  std::cout << "\nStress in the block under the middle of the contact "
               "(finite element / closed form, in p0 and a of Hertz):\n"
            << " refinements  von Mises max     at depth      shear max"
               "         at depth\n";
  for (const Row &row : rows)
    {
      const double a = row.theory.half_width(), p0 = row.theory.peak_pressure();
      const HertzTheory::SubsurfacePeaks &q = row.peaks;
      std::cout << std::setw(12) << row.refinements << std::fixed
                << std::setprecision(4) << std::setw(9)
                << q.fe_von_mises.value / p0 << " / " << q.von_mises.value / p0
                << std::setprecision(2) << std::setw(7)
                << q.fe_von_mises.depth / a << " / " << q.von_mises.depth / a
                << std::setprecision(4) << std::setw(9) << q.fe_shear.value / p0
                << " / " << q.shear.value / p0 << std::setprecision(2)
                << std::setw(7) << q.fe_shear.depth / a << " / "
                << q.shear.depth / a << "\n";
    }

  const Row    &shipped = rows.front();
  std::ofstream data("hertz-profile.dat");
  data << "# x/a_Hertz  p/p0_Hertz: nodal, averaged over the node and its "
          "neighbours (shipped mesh)\n";
  const std::vector<double> averaged =
    HertzTheory::averaged_pressures(shipped.profile);
  for (unsigned int i = 0; i < shipped.profile.size(); ++i)
    if (std::abs(shipped.profile[i].x) < 2 * shipped.theory.half_width())
      data << shipped.profile[i].x / shipped.theory.half_width() << " "
           << shipped.profile[i].pressure / shipped.theory.peak_pressure()
           << " " << averaged[i] / shipped.theory.peak_pressure() << "\n";
  data.close();
  std::ofstream plot("hertz-profile.gp");
  plot << "set terminal pngcairo size 800,500\n"
       << "set output 'hertz-profile.png'\n"
       << "set xlabel 'x / a (Hertz)'\nset ylabel 'p / p0 (Hertz)'\n"
       << "set key top right\nset grid\nset xrange [-1.6:1.6]\n"
       << "set samples 801\n"
       << "f(x) = abs(x) < 1 ? sqrt(1 - x*x) : 0\n"
       << "plot f(x) with lines lw 2 title 'Hertz', "
       << "'hertz-profile.dat' using 1:2 with points pt 6 ps 1 title "
          "'nodal force / tributary area', "
       << "'hertz-profile.dat' using 1:3 with linespoints pt 7 ps 0.8 title "
          "'averaged over the node and its two neighbours'\n";
  plot.close();
  if (std::system("gnuplot hertz-profile.gp") != 0)
    std::cerr << "gnuplot failed: hertz-profile.png not written\n";
  return 0;
}
