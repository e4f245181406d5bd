// study_benchmark: what a whole fuzzy study costs against the mesh size, and
// what its two exact references cost, measured in one run on this machine.
//
// For the default study (prm/step-4.prm: the overlap scene, P1.E and P2.E
// +-5 %, the tip load 10-100 kN, 11 alpha levels, FL2C tolerance 1e-9) at
// 1, 2, 3 (and 4) mesh refinements (5k, 20k, 80k, 320k DoFs per body), and
// for the zone study (prm/step-4-zones.prm) at 20k DoFs per body:
//   - one cold full-order solve (new factorisations, refined fields), the
//     median of three parameter points;
//   - the offline build of the reduced model;
//   - one online evaluation, FL2C and exact reduced (active set), medians
//     over random points of the support box;
//   - the fast study (offline + optimisation) and the error of its bounds
//     against the reference;
//   - the reference reusing factorisations where exact (run), and the
//     reference of independent analyses: run where it takes under about a
//     minute, otherwise estimated as (number of samples) x (cold solve),
//     and said so;
//   - the peak resident memory of the process after the fast study and
//     after the references of each size (the sizes grow, so it is the
//     largest size's peak; the zone study at 20k comes before 80k).
//
// Usage (from the repository's top folder):
//   build/study_benchmark [prm folder] [largest refinement, default 3]
// prints Markdown tables, writes study_benchmark.md, study_benchmark.dat and
// study_benchmark.png (gnuplot) to the current folder; doc/performance.md
// holds a copy.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/contact/active_set_solver.h>
#include <fuzzycontact/fuzzy/extension_principle.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/fuzzy/optimisation_method.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/output/report.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/study/fuzzy_contact_model.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <sys/resource.h>

using namespace FuzzyContact;

namespace
{
  Report report;

  // The fuzzy parameters of prm/step-4.prm and prm/step-4-zones.prm.
  const std::string              default_study = R"(
set fuzzy parameters = P1.E, P2.E, P1.tip.force
subsection Fuzzy parameter P1.E
  set values   = 0.95, 1, 1.05
  set relative = true
end
subsection Fuzzy parameter P2.E
  set values   = 0.95, 1, 1.05
  set relative = true
end
subsection Fuzzy parameter P1.tip.force
  set values = 10e3, 50e3, 100e3
end
)";
  const std::string              zone_study    = R"(
set fuzzy parameters = P1.root.E, P1.tip.force
subsection Fuzzy parameter P1.root.E
  set values   = 0.95, 1, 1.05
  set relative = true
end
subsection Fuzzy parameter P1.tip.force
  set values = 10e3, 50e3, 100e3
end
)";
  const std::vector<std::string> outputs = {"slave.ux", "slave.uy", "Fn", "Ft"};

  FuzzyParameterSet
  fuzzy_parameters(const Scene &scene, const std::string &text)
  {
    FuzzyParameterSet set;
    Input::parse_in_passes(
      text,
      "study_benchmark",
      [&](ParameterHandler &prm) {
        set.declare_parameters(prm);
      },
      [&](ParameterHandler &prm) {
        return set.learn_names(prm);
      },
      [&](ParameterHandler &prm) {
        set.parse_parameters(prm, scene);
      });
    return set;
  }

  double
  peak_memory_gb()
  {
    rusage usage;
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss / 1024. / 1024.; // kB on Linux
  }

  // Median wall time of @p f over the points.
  template <typename F>
  double
  median_time(const std::vector<std::vector<double>> &points, const F &f)
  {
    std::vector<double> t;
    for (const auto &p : points)
      {
        Timer timer;
        f(p);
        t.push_back(timer.wall_time());
      }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
  }

  std::vector<std::vector<double>>
  random_points(const FuzzyParameterSet &set,
                const unsigned int       n,
                const unsigned int       seed)
  {
    std::mt19937                           random(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<std::vector<double>>       points(n);
    for (auto &p : points)
      for (const FuzzyNumber &x : set.numbers())
        {
          const Interval i = x.alpha_cut(0);
          p.push_back(i.lower + u(random) * (i.upper - i.lower));
        }
    return points;
  }

  struct Row
  {
    std::string   study;
    unsigned int  dofs = 0;
    double        cold = 0, offline = 0, online_fl2c = 0, online_exact = 0;
    double        fast = 0, fast_error = 0, reusing = 0, independent = 0;
    bool          independent_run = false;
    unsigned long samples = 0, evaluations = 0;
    double        memory = 0, fast_memory = 0;
  };

  Row
  measure(const std::string &prm,
          const std::string &scene_file,
          const std::string &study,
          const std::string &label,
          const unsigned int refinements)
  {
    Row row;
    row.study                       = label;
    const Scene               scene = Scene::read(prm + "/" + scene_file);
    const FuzzyParameterSet   set   = fuzzy_parameters(scene, study);
    FuzzyContactModelSettings settings;
    settings.mesh_refinements       = refinements;
    settings.fl2c.tolerance         = 1e-9; // as prm/step-4.prm
    const std::vector<double> alpha = alpha_levels(11);

    Timer             offline;
    FuzzyContactModel model(scene, set, outputs, settings);
    row.offline = offline.wall_time();
    row.dofs    = model.n_dofs()[0];

    const Response reduced = [&](const std::vector<double> &p) {
      return model.reduced(p);
    };
    const Response exact = [&](const std::vector<double> &p) {
      return model.full_order(p);
    };
    const FuzzyOutputBounds fast = OptimisationMethod().bounds(set.numbers(),
                                                               alpha,
                                                               reduced,
                                                               outputs,
                                                               MPI_COMM_WORLD);
    row.fast                     = row.offline + fast.wall_time;
    row.evaluations              = fast.n_evaluations;
    row.fast_memory              = peak_memory_gb();

    const auto            points = random_points(set, 41, refinements);
    const ActiveSetSolver active_set;
    row.online_fl2c  = median_time(points, reduced);
    row.online_exact = median_time(points, [&](const std::vector<double> &p) {
      return model.reduced(p, active_set);
    });

    model.set_reuse_factorisations(true);
    const ExtensionPrinciple reference(4);
    const FuzzyOutputBounds  reusing =
      reference.bounds(set.numbers(), alpha, exact, outputs, MPI_COMM_WORLD);
    row.reusing = reusing.wall_time;
    row.samples = reusing.n_evaluations;
    for (unsigned int k = 0; k < outputs.size(); ++k)
      row.fast_error =
        std::max(row.fast_error,
                 max_relative_difference(fast.bounds[k], reusing.bounds[k]));

    model.set_reuse_factorisations(false);
    row.cold            = median_time(random_points(set, 3, 7), exact);
    row.independent_run = row.cold * row.samples < 60;
    row.independent =
      row.independent_run
        ? reference.bounds(set.numbers(), alpha, exact, outputs, MPI_COMM_WORLD)
            .wall_time
        : row.cold * row.samples;
    row.memory = peak_memory_gb();
    return row;
  }

  std::string
  fixed(const double v, const int digits)
  {
    return Format::fixed(v, digits);
  }

  void
  say_row(const Row &r)
  {
    std::ostringstream out;
    out << "| " << r.study << " | " << r.dofs << " | " << fixed(r.cold, 2)
        << " | " << fixed(r.offline, 2) << " | "
        << fixed(1e6 * r.online_fl2c, 0) << " | "
        << fixed(1e6 * r.online_exact, 0) << " | " << fixed(r.fast, 2) << " | "
        << Format::scientific(r.fast_error, 1) << " | " << fixed(r.reusing, 2)
        << " | " << fixed(r.independent, 1)
        << (r.independent_run ? "" : " (est.)") << " | "
        << fixed(r.cold * r.samples, 1) << " | "
        << fixed(r.independent / r.fast, 0) << "x | "
        << fixed(r.reusing / r.fast, 2) << "x | " << fixed(r.fast_memory, 2)
        << " | " << fixed(r.memory, 2) << " |\n";
    report.say(out.str());
  }

  void
  plot(const std::vector<Row> &rows)
  {
    std::ostringstream dat;
    dat << "# dofs cold offline online_fl2c online_exact fast reusing "
           "independent memory_gb fast_memory_gb\n";
    for (const Row &r : rows)
      if (r.study == "default")
        dat << r.dofs << " " << r.cold << " " << r.offline << " "
            << r.online_fl2c << " " << r.online_exact << " " << r.fast << " "
            << r.reusing << " " << r.independent << " " << r.memory << " "
            << r.fast_memory << "\n";
    write_file_atomically("study_benchmark.dat", dat.str());
    const std::string script =
      R"gp(set terminal pngcairo enhanced size 900,640 font ",11"
set output "study_benchmark.png"
set logscale xy
set format y "10^{%L}"
set format y2 "%g"
set xlabel "DoFs per body"
set ylabel "wall time [s]"
set y2label "peak memory [GB]"
set y2tics
set logscale y2
set key below maxrows 3 width -4
set grid
plot "study_benchmark.dat" u 1:2 w lp t "one cold full-order solve", \
     "" u 1:3 w lp t "offline build", \
     "" u 1:4 w lp t "one evaluation, FL2C", \
     "" u 1:5 w lp t "one evaluation, exact reduced", \
     "" u 1:6 w lp lw 2 t "fast study", \
     "" u 1:7 w lp t "reference, reused factorisations", \
     "" u 1:8 w lp t "reference, independent analyses", \
     "" u 1:10 axes x1y2 w lp dt 2 t "peak memory, fast study (right)", \
     "" u 1:9 axes x1y2 w lp dt 3 t "peak memory, with references (right)"
)gp";
    write_file_atomically("study_benchmark.gp", script);
    if (std::system("gnuplot study_benchmark.gp") != 0)
      report.say("(gnuplot failed: no study_benchmark.png)\n");
  }
} // namespace


int
main(int argc, char **argv)
{
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const std::string                        prm = argc > 1 ? argv[1] : "prm";
  const unsigned int largest = argc > 2 ? std::atoi(argv[2]) : 3;
  try
    {
      report.say(
        "# study_benchmark\n\nWall times of one run on this machine (1 "
        "process, Release, OpenBLAS serial); one evaluation is the median "
        "over 41 random points; the error is the largest relative "
        "difference of the fast study's bounds from the reusing reference's "
        "(the same 641 or 161 exact samples). 'est.': independent-analysis "
        "reference estimated as samples x cold solve (not run).\n\n"
        "| study | DoFs/body | cold solve [s] | offline [s] | eval FL2C "
        "[us] | eval exact [us] | fast study [s] | bound error | reference "
        "reusing [s] | reference independent [s] | samples x cold solve [s] "
        "| speed-up vs independent | reusing / fast | peak memory, fast "
        "study [GB] | peak memory, with references [GB] |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
      std::vector<Row> rows;
      for (unsigned int r = 1; r <= largest; ++r)
        {
          rows.push_back(
            measure(prm, "overlap.prm", default_study, "default", r));
          say_row(rows.back());
          if (r == 2)
            {
              rows.push_back(
                measure(prm, "overlap-zones.prm", zone_study, "zones", r));
              say_row(rows.back());
            }
        }
      plot(rows);
      write_file_atomically("study_benchmark.md", report.text());
      std::cout << "\nWrote study_benchmark.md, .dat, .png" << std::endl;
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::cerr << "study_benchmark: error: " << Input::message_of(e)
                << std::endl;
      return 1;
    }
  return 0;
}
