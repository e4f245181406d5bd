// realistic_suite: the fast path on scenes like a user's, measured as the
// user runs it. For every scene of the suite it runs step-4 (the whole
// study: the optimisation on the reduced model, the proofs of its bounds,
// the vertex method and the Extension Principle of exact full-order solves
// on reused factorisations), one process after the other, and reads its
// results.json:
//
//  - one reduced evaluation: the time inside the reduced model over the
//    optimisation's evaluations (the contact solves, each started from its
//    nearest evaluated neighbour), and the optimisation's whole time over
//    them (with the optimiser's own work between evaluations);
//  - one exact evaluation on reused factorisations: the time inside the
//    full-order model over the Extension Principle's samples (each an
//    independent full-order contact solve on the factorisations and flexibility
//    columns of the nominal stiffness, where that is exact);
//  - their ratio, measured in the same run;
//  - the proofs: the largest |reduced - exact| at the bounds' arguments,
//    relative to each output's range;
//  - the bounds against the Extension Principle: how far the optimisation's
//    interval falls short of the sampled one (relative to the range; a
//    bound beyond it, confirmed by its proof, is the sample's miss, not an
//    error);
//  - the spot checks (step-4's key 'spot checks' of subsection Proofs,
//    fuzzy/spot_checks.h): some of the optimisation's points solved by the
//    full-order model too, after the Extension Principle: one evaluation of
//    each model at the same points, and the largest |reduced - exact|
//    there relative to each output's range;
//  - the study's wall time, the whole program's, and its peak memory.
//
// The scenes: a filleted punch held by contact alone on a foundation
// (prm/step-4-punch.prm with two load stages, by the exact reduced solver
// and by FL2C; prm/step-4-punch-one-stage.prm without), a grout zone under it
// (prm/step-4-punch-grout.prm), the Hertz roller (prm/step-4-hertz.prm), three
// bodies in two contact pairs (prm/step-4-three-beams.prm), a block held by
// contact alone on a slope (prm/step-4-slope.prm) and kinked responses against
// a dense reference (prm/step-4-kinked.prm).
//
// Usage (from the repository's top folder):
//   build/realistic_suite [--spot-checks=N] [step-4 program, default
//                         build/step-4] [prm folder, default prm]
//                         [scene names ...]
// (N spot checks per scene, 40 by default, 10 on the grout zone, whose
// exact solves factorise; 0 for a step-4 older than the key.)
// prints a Markdown table and writes realistic_suite.md; each run's files
// stay in realistic-suite-runs/<scene>/. Another step-4 (an older build)
// measures the same suite before a change.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/output/report.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

using namespace FuzzyContact;
namespace fs = std::filesystem;

namespace
{
  struct SuiteScene
  {
    std::string name;
    std::string description;
    std::string step_file;
    // Lines of the step file to replace for the suite: key -> value.
    std::map<std::string, std::string> settings;
  };

  const std::vector<SuiteScene> suite = {
    {"punch-stages",
     "punch held by contact alone, press then push (2 stages, 4 steps)",
     "step-4-punch.prm",
     {}},
    {"punch-stages-fl2c",
     "the same, its reduced model solved by FL2C",
     "step-4-punch.prm",
     {{"contact solver", "fl2c"}}},
    {"punch-one-stage",
     "punch held by contact alone, press and push together",
     "step-4-punch-one-stage.prm",
     {}},
    {"punch-grout",
     "grout zone under the punch (zone modulus +-50 %)",
     "step-4-punch-grout.prm",
     {{"Proofs/spot checks", "10"}}},
    {"hertz",
     "Hertz roller on a block (curved contact)",
     "step-4-hertz.prm",
     {{"number of alpha levels", "6"},
      {"points per dimension", "3"},
      {"contact solver", "reduced exact"}}},
    {"three-beams",
     "three bodies, two contact pairs",
     "step-4-three-beams.prm",
     {{"contact solver", "reduced exact"}, {"reuse factorisations", "true"}}},
    {"slope", "block held by contact alone on a slope", "step-4-slope.prm", {}},
    {"kinked",
     "kinked responses, dense reference (20 points per parameter)",
     "step-4-kinked.prm",
     {{"mesh refinements", "0"},
      {"points per dimension", "20"},
      {"reuse factorisations", "true"},
      {"number of alpha levels", "6"}}}};

  // The step file with the suite's settings, its scene named by its
  // absolute path and its output in @p output.
  std::string
  edited_step_file(const SuiteScene &scene,
                   const fs::path   &prm,
                   const fs::path   &output)
  {
    std::istringstream in(
      Input::read_text_file((prm / scene.step_file).string()));
    std::ostringstream          out;
    std::string                 line;
    std::map<std::string, bool> used;
    while (std::getline(in, line))
      {
        const std::string trimmed = dealii::Utilities::trim(line);
        std::string       key;
        if (trimmed.rfind("set ", 0) == 0 &&
            trimmed.find('=') != std::string::npos)
          key =
            dealii::Utilities::trim(trimmed.substr(4, trimmed.find('=') - 4));
        if (key == "scene")
          {
            const std::string value =
              dealii::Utilities::trim(trimmed.substr(trimmed.find('=') + 1));
            line = "set scene = " + fs::absolute(prm / value).string();
          }
        else if (key == "output directory")
          line = "set output directory = " + output.string();
        else if (scene.settings.count(key) > 0)
          {
            line = line.substr(0, line.find("set ")) + "set " + key + " = " +
                   scene.settings.at(key);
            used[key] = true;
          }
        out << line << "\n";
      }
    std::string text = out.str();
    // Settings the file does not set: at its top level, or "Section/key" in
    // that subsection.
    for (const auto &[key, value] : scene.settings)
      if (!used[key])
        {
          const std::size_t slash = key.find('/');
          if (slash == std::string::npos)
            text = "set " + key + " = " + value + "\n" + text;
          else
            text += "subsection " + key.substr(0, slash) + "\n  set " +
                    key.substr(slash + 1) + " = " + value + "\nend\n";
        }
    return text;
  }

  struct Run
  {
    int            status = -1;
    double         wall   = 0;
    double         memory = 0; // peak resident set [GB]
    nlohmann::json results;
    std::string    warnings;
  };

  // Runs @p program on @p step_file in @p folder, stdout and stderr to
  // files there; its exit status, wall time and peak memory.
  Run
  run_program(const std::string &program,
              const fs::path    &step_file,
              const fs::path    &folder)
  {
    Run           run;
    dealii::Timer timer;
    const pid_t   pid = fork();
    AssertThrow(pid >= 0, dealii::ExcMessage("realistic_suite: fork failed"));
    if (pid == 0)
      {
        const std::string out = (folder / "stdout.txt").string();
        const std::string err = (folder / "stderr.txt").string();
        if (!std::freopen(out.c_str(), "w", stdout) ||
            !std::freopen(err.c_str(), "w", stderr))
          _exit(127);
        execl(program.c_str(),
              program.c_str(),
              step_file.c_str(),
              static_cast<char *>(nullptr));
        _exit(127);
      }
    int           status = 0;
    struct rusage usage;
    wait4(pid, &status, 0, &usage);
    run.wall   = timer.wall_time();
    run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    run.memory = usage.ru_maxrss / 1048576.; // kB -> GB
    return run;
  }

  double
  number(const nlohmann::json &j, const std::string &key)
  {
    return j.contains(key) && j[key].is_number() ? j[key].get<double>() : 0.;
  }

  std::string
  sci(const double v, const int digits = 1)
  {
    return Format::scientific(v, digits);
  }

  std::string
  fixed(const double v, const int digits)
  {
    return Format::fixed(v, digits);
  }

  // The spot checks of results.json @p r: "checks, reduced / exact ms
  // (ratio), largest relative error" (empty if none were made).
  std::string
  same_points(const nlohmann::json &r)
  {
    if (!r.contains("spot_checks"))
      return "";
    const nlohmann::json &c       = r["spot_checks"];
    const double          reduced = number(c, "reduced_ms"),
                 exact            = number(c, "full_order_ms");
    double error                  = 0;
    for (const auto &o : c["outputs"])
      error = std::max(error, number(o, "relative_error"));
    return std::to_string(c.value("checked", 0)) + ", " + fixed(reduced, 3) +
           " / " + fixed(exact, 2) +
           (reduced > 0 ? " (" + fixed(exact / reduced, 1) + "x)" : "") + ", " +
           sci(error) +
           (c.value("all_within_tolerance", true) ? "" : " (beyond)");
  }
} // namespace


int
main(int argc, char **argv)
{
  try
    {
      std::vector<std::string> arguments(argv + 1, argv + argc);
      int                      spot_checks = 40;
      if (!arguments.empty() && arguments[0].rfind("--spot-checks=", 0) == 0)
        {
          const double n = Input::to_double(arguments[0].substr(14),
                                            "realistic_suite: --spot-checks");
          AssertThrow(n >= 0 && n == std::floor(n) && n < 1e6,
                      dealii::ExcMessage(
                        "realistic_suite: --spot-checks must be a whole "
                        "number, at least 0"));
          spot_checks = int(n);
          arguments.erase(arguments.begin());
        }
      const std::string program =
        arguments.size() > 0 ? arguments[0] : "build/step-4";
      const fs::path prm = arguments.size() > 1 ? arguments[1] : "prm";
      std::vector<std::string> chosen;
      for (std::size_t i = 2; i < arguments.size(); ++i)
        chosen.push_back(arguments[i]);
      AssertThrow(fs::exists(program),
                  dealii::ExcMessage("realistic_suite: no program <" + program +
                                     ">"));
      const fs::path runs = fs::absolute("realistic-suite-runs");

      Report report;
      report.say(
        "# realistic_suite\n\nstep-4 (" + program +
        ") on each scene, one run after the other on this machine (2 cores, "
        "Release). Per evaluation: the time inside the reduced model over "
        "the optimisation's evaluations, and beside it the optimisation's "
        "whole wall time over them (with the optimiser's own work); the time "
        "inside the full-order model over the Extension Principle's exact "
        "solves on reused factorisations (same run). Proof: the "
        "largest |reduced - exact| at the bounds' arguments; short: how far "
        "the bounds fall short of the Extension Principle's interval; both "
        "relative to each output's range. Same points: the spot checks, "
        "some of the optimisation's points solved by the full-order model "
        "too, after the Extension Principle (ms per evaluation, reduced as "
        "the optimisation ran it / exact, their ratio, and the largest "
        "|reduced - exact| there relative to the range).\n\n"
        "| scene | DoFs | solver | reduced: evaluations, ms each (with the "
        "optimiser) | exact: samples, ms each | exact / reduced (with the "
        "optimiser) | same points: checks, reduced / exact ms (ratio), "
        "error | proof error | short of the reference | study [s] | "
        "program [s] | memory [GB] | exit |\n"
        "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
      for (const SuiteScene &scene : suite)
        {
          if (!chosen.empty() &&
              std::find(chosen.begin(), chosen.end(), scene.name) ==
                chosen.end())
            continue;
          const fs::path folder = runs / scene.name;
          fs::remove_all(folder);
          fs::create_directories(folder);
          const fs::path output    = folder / "output";
          const fs::path step_file = folder / "step.prm";
          SuiteScene     edited    = scene;
          if (spot_checks == 0)
            edited.settings.erase("Proofs/spot checks");
          else if (edited.settings.count("Proofs/spot checks") == 0)
            edited.settings["Proofs/spot checks"] = std::to_string(spot_checks);
          std::ofstream(step_file) << edited_step_file(edited, prm, output);
          std::cout << "running " << scene.name << " ..." << std::endl;
          Run                run = run_program(program, step_file, folder);
          std::ostringstream row;
          row << "| " << scene.name << " (" << scene.description << ") | ";
          const fs::path json = output / "results.json";
          if (!fs::exists(json))
            {
              row << "| | | | | | | | | " << fixed(run.wall, 1) << " | "
                  << fixed(run.memory, 2) << " | " << run.status
                  << " (no results.json: " << (folder / "stderr.txt").string()
                  << ") |\n";
              report.say(row.str());
              continue;
            }
          const nlohmann::json r =
            nlohmann::json::parse(Input::read_text_file(json.string()));
          unsigned long dofs = 0;
          for (const auto &n : r["n_dofs"])
            dofs += n.get<unsigned long>();
          const nlohmann::json &evaluations = r["evaluations"];
          const nlohmann::json &time        = r["time_s"];
          const double          n_reduced = number(evaluations, "optimisation");
          const double n_exact = number(evaluations, "extension_principle");
          // (Older step-4 programs did not measure the time inside the
          // model: their wall times stand in.)
          const nlohmann::json &inside =
            r.contains("evaluation_time_s") ? r["evaluation_time_s"] : time;
          const double t_optimiser =
            n_reduced > 0 ? number(time, "optimisation") / n_reduced : 0;
          const double t_reduced =
            n_reduced > 0 ? number(inside, "optimisation") / n_reduced : 0;
          const double t_exact =
            n_exact > 0 ? number(inside, "extension_principle") / n_exact : 0;
          // Relative to each output's range, floored at 1e-9 of its largest
          // magnitude (as the report's relative differences): an output the
          // parameters cannot change (a total force held by statics) has a
          // range of round-off only.
          double proof = 0, short_of = 0;
          for (const auto &o : r["outputs"])
            {
              double magnitude = 0;
              for (const char *key : {"reference_lower", "reference_upper"})
                if (o.contains(key))
                  for (const auto &v : o[key])
                    if (v.is_number())
                      magnitude =
                        std::max(magnitude, std::abs(v.get<double>()));
              const double range =
                o.contains("reference_comparison")
                  ? number(o["reference_comparison"], "range")
                  : 0.;
              const double scale    = std::max(range, 1e-9 * magnitude);
              const double to_scale = scale > 0 ? range / scale : 1.;
              if (o.contains("proof"))
                proof =
                  std::max(proof,
                           to_scale * number(o["proof"],
                                             "max_abs_difference_over_range"));
              if (o.contains("reference_comparison"))
                short_of = std::max(short_of,
                                    to_scale * number(o["reference_comparison"],
                                                      "short_of_reference"));
            }
          row << dofs << " | " << r.value("contact_solver", std::string())
              << " | " << n_reduced << ", " << fixed(1e3 * t_reduced, 3) << " ("
              << fixed(1e3 * t_optimiser, 3) << ") | " << n_exact << ", "
              << fixed(1e3 * t_exact, 2) << " | "
              << (t_reduced > 0 ? fixed(t_exact / t_reduced, 1) : "")
              << (t_optimiser > 0 ? " (" + fixed(t_exact / t_optimiser, 1) + ")"
                                  : "")
              << " | " << same_points(r) << " | " << sci(proof) << " | "
              << sci(short_of) << " | " << fixed(number(time, "fuzzy_study"), 2)
              << " | " << fixed(run.wall, 1) << " | " << fixed(run.memory, 2)
              << " | " << run.status << " |\n";
          report.say(row.str());
        }
      write_file_atomically("realistic_suite.md", report.text());
      std::cout << "\nWrote realistic_suite.md" << std::endl;
    }
  catch (const dealii::ExceptionBase &e)
    {
      std::cerr << "realistic_suite: error: " << Input::message_of(e)
                << std::endl;
      return 1;
    }
  return 0;
}
