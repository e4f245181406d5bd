#include <fuzzycontact/output/contact_face_plot.h>
#include <fuzzycontact/output/gnuplot_picture.h>

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <utility>
#include <vector>

namespace FuzzyContact
{
  namespace
  {
    // The solvers of @p c that did not fail.
    std::vector<const SolverRun *>
    answered(const ContactCase &c)
    {
      std::vector<const SolverRun *> runs;
      for (const SolverRun &run : c.runs)
        if (run.failure.empty())
          runs.push_back(&run);
      return runs;
    }
  } // namespace


  std::string
  contact_face_data(const ContactCase &c, const ContactScene &bodies)
  {
    const ContactInterface &interface = bodies.interface();
    const Scene            &scene     = bodies.scene();
    std::ostringstream      data;
    data << std::setprecision(10)
         << "# per contact pair and solver: position along the pair's mean "
            "tangent [m], tributary length [m], pressure [Pa], shear [Pa]\n";
    for (unsigned int pair = 0; pair < c.pairs.size(); ++pair)
      {
        // The pair's slave nodes along its mean tangent.
        Tensor<1, 2>                                 tangent;
        std::vector<std::pair<double, unsigned int>> along;
        for (unsigned int k = 0; k < interface.n_nodes(); ++k)
          if (interface.node(k).pair == pair)
            tangent += interface.node(k).tangent;
        if (tangent.norm() > 0)
          tangent /= tangent.norm();
        for (unsigned int k = 0; k < interface.n_nodes(); ++k)
          if (interface.node(k).pair == pair)
            along.emplace_back(tangent * interface.node(k).slave.position, k);
        std::sort(along.begin(), along.end());
        const double thickness =
          scene.components[scene.component_index(c.pairs[pair].slave_component)]
            .thickness;
        for (const SolverRun *run : answered(c))
          {
            const Vector<double> &p = run->solution.p;
            data << "# " << c.pairs[pair].name << ": " << run->solution.solver
                 << "\n";
            for (const auto &[s, k] : along)
              {
                const double area =
                  interface.node(k).tributary_length * thickness;
                data << s << " " << interface.node(k).tributary_length << " "
                     << p[normal_row(k)] / area << " "
                     << p[tangential_row(k)] / area << "\n";
              }
            data << "\n\n";
          }
      }
    return data.str();
  }


  bool
  add_contact_face_plot(OutputFiles        &output,
                        const ContactCase  &c,
                        const ContactScene &bodies,
                        const std::string  &label,
                        std::string        &message)
  {
    const std::string basename                = c.file_stem(label) + "-face";
    const std::vector<const SolverRun *> runs = answered(c);
    std::ostringstream                   script;
    script << "# gnuplot script: gnuplot " << basename << ".gp\n"
           << "set terminal pngcairo noenhanced size 1280,"
           << 420 * c.pairs.size() + 40 << " font \",11\"\n"
           << "set output " << gnuplot_quoted(basename + ".png") << "\n"
           << "set multiplot layout " << c.pairs.size() << ",2 title "
           << gnuplot_quoted("contact pressure and shear, " + c.scene +
                             ", mu = " + c.friction_label())
           << "\nset grid\nset key top right box opaque font \",9\"\n"
           << "set xlabel \"position along the pair's tangent [mm]\"\n";
    const std::array<std::string, 2> what   = {{"pressure", "shear"}};
    const std::array<int, 2>         column = {{3, 4}};
    for (unsigned int pair = 0; pair < c.pairs.size(); ++pair)
      for (unsigned int w = 0; w < 2; ++w)
        {
          script << "set title "
                 << gnuplot_quoted(c.pairs[pair].name + ": " + what[w])
                 << "\nset ylabel " << gnuplot_quoted(what[w] + " [MPa]")
                 << "\nplot ";
          for (unsigned int r = 0; r < runs.size(); ++r)
            script << (r ? ", \\\n     " : "")
                   << gnuplot_quoted(basename + ".dat") << " index "
                   << pair * runs.size() + r << " using ($1*1e3):($"
                   << column[w] << "*1e-6) with "
                   << (r == 0
                         ? "linespoints lw 2 pt 7 ps 0.5"
                         : "points pt " + std::to_string(4 + 2 * r) + " ps 0.8")
                   << " title " << gnuplot_quoted(runs[r]->solution.solver);
          script << "\n";
        }
    script << "unset multiplot\n";
    return add_gnuplot_picture(output,
                               basename,
                               contact_face_data(c, bodies),
                               script.str(),
                               message);
  }
} // namespace FuzzyContact
