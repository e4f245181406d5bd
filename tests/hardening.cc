// Bad input gets a clear answer: LAPACK's error handler replaced, keys set
// twice refused, ParameterHandler's mangled names given back in the user's
// spelling, physical ranges, the memory estimate, output written as a set
// and never with a NaN.

#include <fuzzycontact/base/input.h>
#include <fuzzycontact/base/lapack_errors.h>
#include <fuzzycontact/base/limits.h>
#include <fuzzycontact/base/parameter_file.h>
#include <fuzzycontact/fuzzy/fuzzy_parameters.h>
#include <fuzzycontact/output/output_files.h>
#include <fuzzycontact/scene/scene.h>
#include <fuzzycontact/scene/scene_limits.h>
#include <fuzzycontact/study/input_checks.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include "test_utilities.h"
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <tuple>

using namespace FuzzyContact;
using namespace FuzzyContact::Testing;

extern "C" void
dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);

namespace
{
  namespace fs = std::filesystem;

  const std::string scene_text = R"(
subsection Scene
  set name       = beam
  set components = P1
end
subsection Component P1
  set lower left corner  = 0, 0
  set upper right corner = 0.2, 0.008
  set subdivisions       = 25, 1
  set E                  = 210e9
  set nu                 = 0.3
  set rho                = 7900
  set clamped faces      = left
  set loads              = tip
  subsection Load tip
    set face        = right
    set total force = 1000
    set direction   = 0, -1
  end
end
)";

  std::string
  read_error(const std::string &text)
  {
    return error_of([&]() {
      Scene::read_from_string(text, "beam.prm");
    });
  }

  std::string
  read_file(const fs::path &path)
  {
    std::ifstream      in(path);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }
} // namespace


// An illegal argument to a LAPACK routine ends the program with exit status
// 0 under LAPACK's own XERBLA. Ours records it: the routine returns, and
// the error is reported. Run in a child process, so that LAPACK's XERBLA
// (if ours were not linked in) ends the child, not the tests.
namespace
{
  // Calls LAPACK with an illegal argument; exits with 42 if the error was
  // recorded and the routine returned.
  void
  illegal_lapack_call_then_exit()
  {
    LapackErrors::install();
    const int n = -1, lda = 1;
    int       info = 0;
    double    a    = 1;
    dpotrf_("L", &n, &a, &lda, &info);
    const std::string what = LapackErrors::take();
    const bool ok = info == -2 && what.find("DPOTRF") != std::string::npos &&
                    what.find("argument 2") != std::string::npos &&
                    !LapackErrors::pending();
    std::exit(ok ? 42 : 1);
  }
} // namespace

TEST(LapackErrors, IllegalArgumentIsRecordedNotFatal)
{
  EXPECT_EXIT(illegal_lapack_call_then_exit(),
              ::testing::ExitedWithCode(42),
              "");
}

TEST(LapackErrors, CheckThrowsNamingTheContext)
{
  const int n = -1, lda = 1;
  int       info = 0;
  double    a    = 1;
  dpotrf_("L", &n, &a, &lda, &info);
  const std::string message = error_of([]() {
    LapackErrors::check("the modes of P1");
  });
  EXPECT_NE(message.find("the modes of P1: LAPACK routine DPOTRF"),
            std::string::npos)
    << message;
  EXPECT_FALSE(LapackErrors::pending());
  EXPECT_EQ(error_of([]() {
              LapackErrors::check("nothing");
            }),
            "");
}


TEST(ParameterFile, KeySetTwiceIsRefusedWithBothLines)
{
  const std::string text    = "set a = 1\nsubsection S\n  set b = 2\n"
                              "  # comment\n  set  b   = 3\nend\nset c = 1\n";
  const std::string message = error_of([&]() {
    Input::scan_parameter_text(text, "x.prm");
  });
  EXPECT_NE(message.find("x.prm, line 5: the key <b> is set a second time in "
                         "subsection <S> (first on line 3)"),
            std::string::npos)
    << message;
  // The same key in two subsections is fine.
  EXPECT_EQ(error_of([]() {
              Input::scan_parameter_text(
                "subsection A\nset b = 1\nend\nsubsection B\nset b = 1\nend\n",
                "y.prm");
            }),
            "");
}

TEST(ParameterFile, MangledNamesComeBackInTheUsersSpelling)
{
  EXPECT_EQ(Input::demangle_message(
              "No entry Component_20P1.lower_20left_20corner here"),
            "No entry Component P1.lower left corner here");
  // Names with underscores that are not escapes stay as they are.
  EXPECT_EQ(Input::demangle_message("my_key and x_2"), "my_key and x_2");
  // A mandatory key that is missing: named with its subsection.
  const std::string message =
    read_error(replace(scene_text, "  set lower left corner  = 0, 0\n", ""));
  EXPECT_NE(message.find("<lower left corner> in subsection <Component P1>"),
            std::string::npos)
    << message;
  EXPECT_EQ(message.find("_20"), std::string::npos) << message;
  EXPECT_NE(message.find("beam.prm"), std::string::npos) << message;
}


TEST(Limits, PhysicalRangesHaveUpperEnds)
{
  EXPECT_EQ(read_error(scene_text), "");
  for (const auto &[from, to, expected] :
       std::vector<std::tuple<std::string, std::string, std::string>>{
         {"set rho                = 7900",
          "set rho = 1e308",
          "Component P1: rho must lie between"},
         {"set E                  = 210e9",
          "set E = 1e-300",
          "Component P1: E must lie between 1000 and 1e+13"},
         {"set total force = 1000",
          "set total force = 1e308",
          "load tip: total force must lie between"},
         {"set nu                 = 0.3",
          "set nu = 0.4999999",
          "Component P1: nu must lie between -0.99 and 0.49"},
         {"set subdivisions       = 25, 1",
          "set subdivisions = 20000, 2000",
          "subdivisions (their product, the cells)"}})
    {
      const std::string message = read_error(replace(scene_text, from, to));
      EXPECT_NE(message.find(expected), std::string::npos)
        << to << ": " << message;
      EXPECT_NE(message.find("beam.prm"), std::string::npos) << message;
    }
  EXPECT_NE(
    error_of([]() {
      Input::integer_in_range(1000000, 1, 1000, "load steps");
    }).find("load steps must be an integer from 1 to 1000, got 1000000"),
    std::string::npos);
}

TEST(Limits, MemoryEstimateRefusesWhatCannotFit)
{
  const Scene scene = Scene::read_from_string(scene_text, "beam.prm");
  // 25 x 1 cells of degree 2: 51 x 3 nodes, 306 DoFs; each refinement
  // about quadruples them.
  EXPECT_EQ(SceneLimits::n_dofs(scene, 0, 0), 306);
  EXPECT_EQ(SceneLimits::n_dofs(scene, 0, 1), 2 * 101 * 5);
  EXPECT_NO_THROW(SceneLimits::check_memory(scene, 4, true));
  const std::string message = error_of([&]() {
    SceneLimits::check_memory(scene, 12, true);
  });
  EXPECT_NE(message.find("mesh refinements = 12 gives about"),
            std::string::npos)
    << message;
  EXPECT_NE(message.find("GiB"), std::string::npos) << message;
}

TEST(Limits, ModesMustFitTheFreeDoFs)
{
  const Scene scene =
    Scene::read_from_string(replace(scene_text,
                                    "set subdivisions       = 25, 1",
                                    "set subdivisions = 2, 1"),
                            "beam.prm");
  // 5 x 3 nodes = 30 DoFs, 6 of them clamped: 24 free.
  EXPECT_NO_THROW(InputChecks::check_modes_fit(scene, 0, 6));
  const std::string message = error_of([&]() {
    InputChecks::check_modes_fit(scene, 0, 9);
  });
  EXPECT_NE(message.find("number of modes = 9 needs at least 30 free DoFs"),
            std::string::npos)
    << message;
}

TEST(Limits, LoadOnAClampedFaceIsWarnedAbout)
{
  const Scene scene    = Scene::read_from_string(replace(scene_text,
                                                      "set face        = right",
                                                      "set face = left"),
                                              "beam.prm");
  const auto  warnings = SceneLimits::warnings(scene);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("load tip: it acts on the clamped face <left>"),
            std::string::npos)
    << warnings[0];
  EXPECT_TRUE(
    SceneLimits::warnings(Scene::read_from_string(scene_text, "beam.prm"))
      .empty());
}


TEST(Limits, OutputDirectoryCheckedUpFront)
{
  EXPECT_NE(error_of([]() {
              Input::check_output_directory(".");
            }).find("output directory <.> is the current folder"),
            std::string::npos);
  EXPECT_NE(error_of([]() {
              Input::check_output_directory("/proc/no/such/folder");
            }).find("cannot receive the results"),
            std::string::npos);
  EXPECT_NE(error_of([]() {
              Input::check_output_directory("/dev/null");
            }).find("exists and is not a folder"),
            std::string::npos);
  EXPECT_EQ(error_of([]() {
              Input::check_output_directory(
                (fs::temp_directory_path() / "fuzzycontact-a" / "b").string());
            }),
            "");
  EXPECT_EQ(error_of([]() {
              Input::check_output_directory("results/");
            }),
            "");
  EXPECT_NE(error_of([]() {
              Input::check_output_directory("/");
            }).find("is the current folder or one above it"),
            std::string::npos);
}


// results.json queued as JSON keeps its nulls (a level without bounds, a
// proof without an exact value: n/a, as doc/fuzzy-study.md says) and is
// written; a NaN among its numbers is refused, writing nothing. Queued as
// text, a null is still taken for a NaN the dump turned into null (step-4's
// results were refused whole for their n/a values before).
TEST(Output, JsonNullsAreValuesAndItsNaNsAreRefused)
{
  const fs::path where = fs::temp_directory_path() / "fuzzycontact-json-test";
  fs::remove_all(where);
  const auto written = [&](const std::function<void(OutputFiles &)> &queue) {
    fs::remove_all(where);
    OutputFiles files(where.string());
    queue(files);
    try
      {
        files.write_all();
      }
    catch (const dealii::ExceptionBase &)
      {
        return false;
      }
    return fs::exists(where / "results.json");
  };
  nlohmann::json n_a;
  n_a["bounds"] = {1.5, nullptr};
  EXPECT_TRUE(written([&](OutputFiles &f) {
    f.add_json("results.json", n_a);
  }));
  nlohmann::json nan;
  nan["bounds"] = {1.5, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_FALSE(written([&](OutputFiles &f) {
    f.add_json("results.json", nan);
  }));
  EXPECT_FALSE(fs::exists(where / "results.json"));
  EXPECT_FALSE(written([&](OutputFiles &f) {
    f.add("results.json", n_a.dump(2));
  }));
  fs::remove_all(where);
}

TEST(Output, WrittenAsOneSetReplacingTheOldOne)
{
  const fs::path where = fs::temp_directory_path() / "fuzzycontact-set-test";
  fs::remove_all(where);
  fs::create_directories(where);
  const fs::path out = where / "results";
  // A staging folder of a killed run (a process id that cannot exist).
  fs::create_directories(where / ".results.new-999999999");
  {
    OutputFiles files(out.string());
    files.add("report.txt", "old\n");
    files.add("old-only.txt", "x\n");
    files.write_all();
  }
  {
    OutputFiles files(out.string());
    files.add("report.txt", "new\n");
    files.write_all();
  }
  EXPECT_EQ(read_file(out / "report.txt"), "new\n");
  EXPECT_FALSE(fs::exists(out / "old-only.txt")); // a set, not a mix
  unsigned int entries = 0;
  for (const auto &e : fs::directory_iterator(where))
    {
      ++entries;
      EXPECT_EQ(e.path().filename(), "results") << e.path();
    }
  EXPECT_EQ(entries, 1u);
  fs::remove_all(where);
}

TEST(Output, NothingIsWrittenWithANaN)
{
  const fs::path where = fs::temp_directory_path() / "fuzzycontact-nan-test";
  fs::remove_all(where);
  for (const std::string &bad :
       {std::string("{\"Fn\": null}\n"), std::string("F_n = -nan N\n")})
    {
      OutputFiles files(where.string());
      files.add("results.json", "{\"Fn\": 1.5}\n");
      files.add(bad[0] == '{' ? "b.json" : "report.txt", bad);
      const std::string message = error_of([&]() {
        files.write_all();
      });
      EXPECT_NE(message.find("not a finite number"), std::string::npos)
        << message;
      EXPECT_FALSE(fs::exists(where));
    }
}


TEST(FuzzyParameters, ASubsectionAloneDeclaresAParameter)
{
  const Scene       scene = Scene::read_from_string(scene_text, "beam.prm");
  const std::string sections =
    "subsection Fuzzy parameter P1.E\n  set values = 1e11, 2e11, 3e11\nend\n"
    "subsection Fuzzy parameter P1.tip.force\n  set values = 1, 2, 3\nend\n";
  const auto names = [&](const std::string &text) {
    FuzzyParameterSet set;
    set.add_names_of_subsections(
      Input::scan_parameter_text(text, "study.prm").top_level_subsections);
    Input::parse_in_passes(
      text,
      "study.prm",
      [&](dealii::ParameterHandler &prm) {
        set.declare_parameters(prm);
      },
      [&](dealii::ParameterHandler &prm) {
        return set.learn_names(prm);
      },
      [&](dealii::ParameterHandler &prm) {
        set.parse_parameters(prm, scene);
      });
    return set.names();
  };
  EXPECT_EQ(names(sections),
            (std::vector<std::string>{"P1.E", "P1.tip.force"}));
  // The list may set the order; the other subsections follow.
  EXPECT_EQ(names("set fuzzy parameters = P1.tip.force\n" + sections),
            (std::vector<std::string>{"P1.tip.force", "P1.E"}));
  // A listed name still needs its subsection, named in the user's spelling.
  const std::string message = error_of([&]() {
    names("set fuzzy parameters = P1.rho\n" + sections);
  });
  EXPECT_NE(message.find("<values> in subsection <Fuzzy parameter P1.rho>"),
            std::string::npos)
    << message;
}


// A fuzzy study's parameters against its scene and contact solver, before
// anything is computed (InputChecks::check, called by step-4 after reading
// its file): a fuzzy gap whose support goes below zero is an initial
// penetration, refused like a negative gap of the scene, naming the key
// (within the interface's round-off, 1e-8 of the 0.2 m master face, it
// passes as the scene's does); a friction support below zero is refused
// where the support is read, naming the key; FL2C's absolute transition
// points without the coarse correction are refused for parameters that
// change W or the gaps, and accepted otherwise.
TEST(InputChecks, FuzzyGapFrictionAndFL2CCalibrationRefusedUpFront)
{
  const Scene scene = Scene::read(source_dir + "/prm/overlap.prm");
  const auto  fuzzy = [&](const std::string &name, const std::string &values) {
    return fuzzy_parameters(scene,
                            "set fuzzy parameters = " + name +
                              "\nsubsection Fuzzy parameter " + name +
                              "\nset values = " + values + "\nend\n");
  };
  const FL2CParameters fl2c;
  const auto           check = [&](const FuzzyParameterSet &set,
                         const FL2CParameters    &parameters,
                         const std::string       &solver = "fl2c") {
    return error_of([&]() {
      InputChecks::check(set, scene, solver, parameters);
    });
  };

  const std::string gap = check(fuzzy("interface.gap", "-1e-4, 0, 1e-4"), fl2c);
  EXPECT_NE(gap.find("Fuzzy parameter interface.gap: initial penetration of "
                     "0.0001 m at the lower end of its support (the gap of "
                     "contact pair interface would be -0.0001 m); at most "
                     "2e-09 m is accepted as round-off."),
            std::string::npos)
    << gap;
  EXPECT_EQ(check(fuzzy("interface.gap", "-1e-10, 0, 1e-4"), fl2c), "");
  EXPECT_EQ(check(fuzzy("interface.gap", "0, 1e-5, 1e-4"), fl2c), "");

  const std::string mu = error_of([&]() {
    fuzzy("interface.mu", "-0.1, 0.3, 0.5");
  });
  EXPECT_NE(mu.find("Fuzzy parameter interface.mu: the ends of its support"),
            std::string::npos)
    << mu;
  EXPECT_NE(mu.find("must lie between 0 and 10"), std::string::npos) << mu;

  FL2CParameters paper;
  paper.calibration       = FL2CParameters::Calibration::prm;
  paper.coarse_correction = FL2CParameters::CoarseCorrection::none;
  for (const auto &[name, values] :
       {std::make_pair("P1.E", "2e11, 2.1e11, 2.2e11"),
        std::make_pair("P1.tip.force", "1e4, 5e4, 1e5"),
        std::make_pair("interface.gap", "0, 1e-5, 1e-4")})
    {
      const std::string message = check(fuzzy(name, values), paper);
      EXPECT_NE(message.find(std::string("FL2C: calibration = prm with coarse "
                                         "correction = none and the fuzzy "
                                         "parameter ") +
                             name),
                std::string::npos)
        << message;
      // Automatic calibration, the coarse correction or the exact solver:
      // accepted.
      FL2CParameters corrected = paper;
      corrected.coarse_correction =
        FL2CParameters::CoarseCorrection::active_set;
      FL2CParameters automatic = paper;
      automatic.calibration    = FL2CParameters::Calibration::automatic;
      EXPECT_EQ(check(fuzzy(name, values), corrected), "") << name;
      EXPECT_EQ(check(fuzzy(name, values), automatic), "") << name;
      EXPECT_EQ(check(fuzzy(name, values), paper, "reduced exact"), "") << name;
    }
  EXPECT_EQ(check(fuzzy("interface.mu", "0, 0.3, 0.5"), paper), "");
}


TEST(ParameterFile, ThePathMustBeAReadableFile)
{
  const fs::path folder = fs::temp_directory_path() / "fuzzycontact-prm-dir";
  fs::create_directories(folder);
  EXPECT_NE(error_of([&]() {
              Input::read_text_file(folder.string());
            }).find("it is a folder, not a file"),
            std::string::npos);
  EXPECT_NE(error_of([&]() {
              Input::read_text_file((folder / "none.prm").string());
            }).find("there is no such file"),
            std::string::npos);
  EXPECT_NE(error_of([]() {
              Input::read_text_file(" ");
            }).find("its name is empty"),
            std::string::npos);
  fs::remove_all(folder);
}
