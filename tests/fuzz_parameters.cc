// A seeded mutation fuzz of the step programs' parameter files.
//
// Each case copies one step file of a folder of base files (step-N*.prm)
// and every scene file of that folder into a fresh working folder, mutates
// them (1 to 3 random edits: extreme or malformed values, deleted, doubled
// or misspelt keys, renamed or unbalanced subsections, unknown names,
// unwritable output folders, ...), runs the step program there with a time
// limit, and classifies what happened:
//
//   refused    exit status 1, one clear message on stderr, nothing written
//   accepted   exit status 0, the results written, no NaN/inf in them
//   unproven   step-4's exit status 3: the results written (no NaN/inf),
//              some bounds not proven within the proofs' tolerance, said
//              on stderr (doc/fuzzy-study.md)
//   crash      killed by a signal, another exit status, or exit 0 without
//              results
//   hang       still running at the time limit
//   garbage    exit 0 with NaN/inf/null in the results or a LAPACK error
//              on the terminal, output written by a failed run, or
//              temporary files left behind
//   unclear    exit status 1 with an empty, mangled, generic or noisy
//              message, or one that names no parameter file
//
// The last four are failures: the program exits with status 1 if any case
// ended in one of them, and keeps the inputs of those cases.
//
//   fuzz_parameters --bin <folder of step-N> --base <folder of base .prm>
//                   --work <folder> [--cases N] [--seed S] [--timeout s]
//                   [--jobs J] [--log file]
//
// This program uses only the C++ standard library and POSIX, so that it
// builds in seconds and does not depend on the code it tests.

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <thread>
#include <tuple>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;

namespace
{
  // ---------------------------------------------------------------------
  // A small deterministic random number generator (splitmix64), so that a
  // seed gives the same cases with every standard library.
  class Random
  {
  public:
    explicit Random(const std::uint64_t seed)
        : state(seed)
    {
    }

    std::uint64_t
    next()
    {
      std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
      z               = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
      z               = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
      return z ^ (z >> 31);
    }

    /** A number in [0, n). */
    std::size_t
    below(const std::size_t n)
    {
      return n == 0 ? 0 : static_cast<std::size_t>(next() % n);
    }

    /** True with probability p. */
    bool
    chance(const double p)
    {
      return (next() >> 11) * (1.0 / 9007199254740992.0) < p;
    }

    template <typename T>
    const T &
    pick(const std::vector<T> &items)
    {
      return items[below(items.size())];
    }

  private:
    std::uint64_t state;
  };


  std::string
  trim(const std::string &s)
  {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string::npos)
      return "";
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
  }


  std::vector<std::string>
  split(const std::string &s, const char separator)
  {
    std::vector<std::string> items;
    std::string              item;
    std::istringstream       in(s);
    while (std::getline(in, item, separator))
      items.push_back(item);
    if (!s.empty() && s.back() == separator)
      items.emplace_back();
    return items;
  }


  std::string
  join(const std::vector<std::string> &items, const std::string &separator)
  {
    std::string s;
    for (std::size_t i = 0; i < items.size(); ++i)
      s += (i ? separator : "") + items[i];
    return s;
  }


  std::string
  read_file(const fs::path &path)
  {
    std::ifstream      in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
  }


  void
  write_file(const fs::path &path, const std::string &text)
  {
    std::ofstream out(path, std::ios::binary);
    out << text;
  }


  // ---------------------------------------------------------------------
  // A parameter file as lines, and the mutations.
  struct ParameterFile
  {
    std::string              name;
    std::vector<std::string> lines;
  };

  const std::regex set_line(R"(^(\s*set\s+)([^=]*?)(\s*=\s*)(.*)$)");
  const std::regex subsection_line(R"(^(\s*subsection\s+)(.*)$)");
  const std::regex end_line(R"(^\s*end\s*$)");

  // Lines of a kind: indices of 'set' lines, 'subsection' lines, ...
  std::vector<std::size_t>
  lines_matching(const ParameterFile &file, const std::regex &pattern)
  {
    std::vector<std::size_t> found;
    for (std::size_t i = 0; i < file.lines.size(); ++i)
      if (std::regex_match(file.lines[i], pattern))
        found.push_back(i);
    return found;
  }


  // The groups of a match as strings (a match refers into the line, which
  // the mutations change).
  std::vector<std::string>
  groups(const std::string &line, const std::regex &pattern)
  {
    std::smatch m;
    std::regex_match(line, m, pattern);
    std::vector<std::string> g;
    for (std::size_t i = 0; i < m.size(); ++i)
      g.push_back(m[i].str());
    return g;
  }


  // Values that break naive parsers or physics.
  const std::vector<std::string> extreme_numbers = {
    "0",          "-0",         "-1",          "1",
    "2",          "3",          "0.5",         "1e308",
    "-1e308",     "1e-300",     "1e200",       "-1e-300",
    "1e20",       "1e-20",      "1e9",         "1e-9",
    "nan",        "inf",        "-inf",        "2147483647",
    "2147483648", "4294967296", "-2147483649", "99999999999999999999",
    "7",          "100",        "1000",        "1e6",
    "0x10",       "1e",         "1.5",         "-0.5",
    "0.4999999",  "1e-12"};

  const std::vector<std::string> odd_texts = {
    "",    " ",   "x",    "abc",   ",",    "1,",   ", 1",
    "1;2", "1 2", "true", "maybe", "-",    "\"\"", "#",
    "é",   "P3",  "auto", "scene", "left", "none", "1, 1, 1"};

  std::string
  mutate_number(const std::string &original, Random &random)
  {
    if (random.chance(0.6))
      return random.pick(extreme_numbers);
    char                     *end   = nullptr;
    const double              value = std::strtod(original.c_str(), &end);
    const std::vector<double> factors =
      {-1, 0, 10, 1e3, 1e6, 1e12, 1e-3, 1e-6, 1e-12, 2, 0.5};
    std::ostringstream s;
    s.precision(17);
    s << value * random.pick(factors);
    return s.str();
  }


  bool
  looks_numeric(const std::string &s)
  {
    const std::string t = trim(s);
    if (t.empty())
      return false;
    char *end = nullptr;
    std::strtod(t.c_str(), &end);
    return end != t.c_str() && trim(end).empty();
  }


  // A new value for a 'set' line: one element of a list or the whole value.
  std::string
  mutate_value(const std::string &original, Random &random)
  {
    std::vector<std::string> items = split(original, ',');
    if (items.size() > 1 && random.chance(0.7))
      {
        const std::size_t i = random.below(items.size());
        switch (random.below(5))
          {
            case 0:
              items.erase(items.begin() + i);
              break;
            case 1:
              items.insert(items.begin() + i, items[i]);
              break;
            case 2:
              items.push_back(" " + random.pick(extreme_numbers));
              break;
            default:
              items[i] = " " + (looks_numeric(items[i])
                                  ? mutate_number(trim(items[i]), random)
                                  : random.pick(odd_texts));
          }
        return join(items, ",");
      }
    if (looks_numeric(original) && random.chance(0.8))
      return mutate_number(trim(original), random);
    if (random.chance(0.5))
      return random.pick(odd_texts);
    return random.pick(extreme_numbers);
  }


  // Changes a name: a typo, another name of the file, or a dotted name.
  std::string
  mutate_name(const std::string &name, Random &random)
  {
    if (name.empty())
      return "x";
    switch (random.below(5))
      {
        case 0:
          return name + "x";
        case 1:
          return name.substr(0, name.size() - 1);
        case 2:
          return name + "." + name;
        case 3:
          return "P3";
        default:
          {
            std::string s             = name;
            s[random.below(s.size())] = ' ';
            return s;
          }
      }
  }


  // One random edit of @p file; returns what it did.
  std::string
  mutate(ParameterFile &file, Random &random)
  {
    const std::vector<std::size_t> sets = lines_matching(file, set_line);
    const std::vector<std::size_t> subs = lines_matching(file, subsection_line);
    const std::vector<std::size_t> ends = lines_matching(file, end_line);
    const std::size_t              what = random.below(100);
    const auto                     where = [&](const std::size_t line) {
      return file.name + ":" + std::to_string(line + 1) + " ";
    };

    if (what < 45 && !sets.empty())
      {
        const std::size_t l     = random.pick(sets);
        const auto        g     = groups(file.lines[l], set_line);
        const std::string value = mutate_value(g[4], random);
        file.lines[l]           = g[1] + g[2] + g[3] + value;
        return where(l) + "value of <" + g[2] + "> -> <" + value + ">";
      }
    if (what < 55 && !sets.empty())
      {
        const std::size_t l       = random.pick(sets);
        const std::string removed = trim(file.lines[l]);
        file.lines.erase(file.lines.begin() + l);
        return where(l) + "deleted <" + removed + ">";
      }
    if (what < 62 && !sets.empty())
      {
        const std::size_t l = random.pick(sets);
        const auto        g = groups(file.lines[l], set_line);
        const std::string copy =
          g[1] + g[2] + g[3] +
          (random.chance(0.5) ? g[4] : mutate_value(g[4], random));
        file.lines.insert(file.lines.begin() + l + 1, copy);
        return where(l) + "key <" + g[2] + "> set twice";
      }
    if (what < 68 && !sets.empty())
      {
        const std::size_t l   = random.pick(sets);
        const auto        g   = groups(file.lines[l], set_line);
        const std::string key = mutate_name(g[2], random);
        file.lines[l]         = g[1] + key + g[3] + g[4];
        return where(l) + "key <" + g[2] + "> -> <" + key + ">";
      }
    if (what < 78 && !subs.empty())
      {
        const std::size_t l = random.pick(subs);
        const auto        g = groups(file.lines[l], subsection_line);
        const std::vector<std::string> words = split(trim(g[2]), ' ');
        std::string                    name  = trim(g[2]);
        if (words.size() > 1 && random.chance(0.7))
          {
            // Keep the kind ("Component", "Fuzzy parameter"), change the
            // name after it.
            const std::string kind =
              join(std::vector<std::string>(words.begin(), words.end() - 1),
                   " ");
            name = kind + " " + mutate_name(words.back(), random);
          }
        else
          name = mutate_name(name, random);
        file.lines[l] = g[1] + name;
        return where(l) + "subsection <" + trim(g[2]) + "> -> <" + name + ">";
      }
    if (what < 82 && !ends.empty())
      {
        const std::size_t l = random.pick(ends);
        file.lines.erase(file.lines.begin() + l);
        return where(l) + "deleted an <end>";
      }
    if (what < 85 && !subs.empty())
      {
        const std::size_t l       = random.pick(subs);
        const std::string removed = trim(file.lines[l]);
        file.lines.erase(file.lines.begin() + l);
        return where(l) + "deleted <" + removed + ">";
      }
    if (what < 92)
      {
        const std::vector<std::string> garbage = {
          "set unknown key = 1",
          "subsection Nowhere",
          "end",
          "this is not a parameter line",
          "set = 3",
          "set key without value",
          "include missing.prm",
          "set fuzzy parameters = P1.E",
          "subsection Fuzzy parameter P1.E\n  set values = 1, 2, 3\nend",
          "subsection Fuzzy parameter P2.rho\n  set values = 0.9, 1, "
          "1.1\n  set relative = true\nend",
          "subsection Fuzzy parameter interface.mu\n  set values = 0, 0.3, "
          "0.6\nend"};
        const std::size_t l = random.below(file.lines.size() + 1);
        const std::string g = random.pick(garbage);
        file.lines.insert(file.lines.begin() + l, g);
        return where(l) + "inserted <" + g + ">";
      }
    // Keys whose values name files and folders.
    std::vector<std::size_t> paths;
    for (const std::size_t l : sets)
      {
        const std::string key = trim(groups(file.lines[l], set_line)[2]);
        if (key == "output directory" || key == "scene" || key == "scenes" ||
            key == "paper scene")
          paths.push_back(l);
      }
    if (!paths.empty())
      {
        const std::size_t              l      = random.pick(paths);
        const auto                     g      = groups(file.lines[l], set_line);
        const std::vector<std::string> values = {"/proc/no/such/folder",
                                                 "",
                                                 ".",
                                                 "/",
                                                 "scene.prm",
                                                 "deep/er/folder",
                                                 "nowhere.prm",
                                                 "..",
                                                 "/dev/null",
                                                 "scene.prm/inside"};
        const std::string              path   = random.pick(values);
        file.lines[l]                         = g[1] + g[2] + g[3] + path;
        return where(l) + "<" + trim(g[2]) + "> -> <" + path + ">";
      }
    return "no change";
  }


  // ---------------------------------------------------------------------
  // A base case: a step file and the scenes beside it.
  struct BaseCase
  {
    std::string                program;   // step-N
    ParameterFile              step_file; // the file given on the command line
    std::vector<ParameterFile> scenes;
  };


  std::vector<BaseCase>
  read_base_cases(const fs::path &folder)
  {
    std::vector<ParameterFile> steps, scenes;
    for (const auto &entry : fs::directory_iterator(folder))
      if (entry.path().extension() == ".prm")
        {
          ParameterFile f;
          f.name  = entry.path().filename().string();
          f.lines = split(read_file(entry.path()), '\n');
          (f.name.rfind("step-", 0) == 0 ? steps : scenes).push_back(f);
        }
    const auto by_name = [](const ParameterFile &a, const ParameterFile &b) {
      return a.name < b.name;
    };
    std::sort(steps.begin(), steps.end(), by_name);
    std::sort(scenes.begin(), scenes.end(), by_name);
    std::vector<BaseCase> cases;
    for (const ParameterFile &s : steps)
      {
        // step-4-zones.prm is a file of step-4.
        const std::string stem = fs::path(s.name).stem().string();
        cases.push_back({stem.substr(0, stem.find('-', 5)), s, scenes});
      }
    return cases;
  }


  // The output folder a step file asks for (the last top-level setting).
  std::string
  output_directory(const ParameterFile &file, const std::string &program)
  {
    std::string folder = program + "-output";
    int         depth  = 0;
    std::smatch m;
    for (const std::string &line : file.lines)
      {
        if (std::regex_match(line, subsection_line))
          ++depth;
        else if (std::regex_match(line, end_line))
          --depth;
        else if (depth == 0 && std::regex_match(line, m, set_line) &&
                 trim(m[2].str()) == "output directory")
          folder = trim(m[4].str());
      }
    return folder;
  }


  // ---------------------------------------------------------------------
  // Running a case.
  struct Run
  {
    std::size_t                           index;
    std::string                           program;
    std::string                           output;
    std::vector<std::string>              mutations;
    fs::path                              folder;
    pid_t                                 pid = -1;
    std::chrono::steady_clock::time_point start;
    bool                                  timed_out = false;
    // The output folder existed before the run (an input file or the
    // case's own folder given as output directory).
    bool   output_existed = false;
    int    status         = 0;
    double seconds        = 0;
  };


  pid_t
  launch(const fs::path    &program,
         const fs::path    &folder,
         const std::string &argument)
  {
    const pid_t pid = ::fork();
    if (pid == 0)
      {
        ::setpgid(0, 0);
        if (::chdir(folder.c_str()) != 0)
          ::_exit(127);
        const int out =
          ::open("stdout.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err =
          ::open("stderr.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int in = ::open("/dev/null", O_RDONLY);
        ::dup2(in, 0);
        ::dup2(out, 1);
        ::dup2(err, 2);
        ::setenv("TMPDIR", (folder / "tmp").c_str(), 1);
        ::setenv("OMP_NUM_THREADS", "1", 1);
        ::setenv("OPENBLAS_NUM_THREADS", "1", 1);
        ::setenv("DEAL_II_NUM_THREADS", "1", 1);
        std::vector<char *> argv = {const_cast<char *>(program.c_str()),
                                    const_cast<char *>(argument.c_str()),
                                    nullptr};
        ::execv(program.c_str(), argv.data());
        ::_exit(127);
      }
    return pid;
  }


  // Words that must not appear in results: what NaN and inf print as.
  bool
  has_non_finite(const std::string &text, const bool json)
  {
    static const std::regex word(
      R"((^|[^A-Za-z0-9_])[-+]?(nan|inf|infinity)([^A-Za-z0-9_]|$))",
      std::regex::icase);
    static const std::regex null(R"((^|[^A-Za-z0-9_"])null([^A-Za-z0-9_"]|$))");
    return std::regex_search(text, word) ||
           (json && std::regex_search(text, null));
  }


  // What is wrong with the message of a refused run ("" if nothing).
  std::string
  message_problem(const std::string &program, const std::string &err)
  {
    const std::string        prefix = program + ": error: ";
    std::vector<std::string> other;
    std::string              message;
    for (const std::string &line : split(err, '\n'))
      {
        if (line.rfind(prefix, 0) == 0 && message.empty())
          message = line.substr(prefix.size());
        else if (!trim(line).empty() && line.rfind(program + ": warning", 0))
          other.push_back(line);
      }
    if (message.empty())
      return "no '" + prefix + "' line on stderr";
    if (!other.empty())
      return "other text on stderr: " + other.front();
    if (trim(message).size() < 15 ||
        message.find("(none)") != std::string::npos)
      return "empty or near-empty message";
    static const std::regex mangled(
      R"([A-Za-z0-9]_(20|2e|2c|2d|28|29|3c|3e)[A-Za-z0-9])");
    if (std::regex_search(message, mangled))
      return "mangled name";
    for (const char *generic : {"std::bad_alloc",
                                "unknown exception",
                                "An error occurred in line",
                                "Stacktrace",
                                "Additional information",
                                "ExcInternalError",
                                "basic_string",
                                "stoi",
                                "stod",
                                "vector::",
                                "terminate called",
                                "Exc"})
      if (message.find(generic) != std::string::npos)
        return std::string("generic text <") + generic + ">";
    if (message.find(".prm") == std::string::npos)
      return "names no parameter file";
    return "";
  }


  // Every file below @p folder whose name has @p part.
  std::vector<std::string>
  files_with(const fs::path &folder, const std::string &part)
  {
    std::vector<std::string> found;
    std::error_code          ec;
    for (auto it = fs::recursive_directory_iterator(folder, ec);
         !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
      if (it->path().filename().string().find(part) != std::string::npos)
        found.push_back(fs::relative(it->path(), folder).string());
    return found;
  }


  // The class of a finished run and a one-line reason.
  std::pair<std::string, std::string>
  classify(const Run &run)
  {
    const std::string err = read_file(run.folder / "stderr.txt");
    const std::string out = read_file(run.folder / "stdout.txt");
    // The output folder, if it lies inside the case's folder (outside it,
    // for instance "..", nothing can be told about what a run wrote).
    fs::path output = (run.folder / run.output).lexically_normal();
    if (run.output.empty() || run.output[0] == '/' ||
        output.string().rfind(run.folder.string() + "/", 0) != 0)
      output.clear();
    const bool wrote = !output.empty() && fs::exists(output / "results.json");
    if (run.timed_out)
      return {"hang", "still running after the time limit"};
    if (WIFSIGNALED(run.status))
      return {"crash",
              std::string("signal ") + strsignal(WTERMSIG(run.status))};
    const int code = WEXITSTATUS(run.status);
    if (err.find("On entry to") != std::string::npos ||
        out.find("On entry to") != std::string::npos)
      return {"garbage", "LAPACK error on the terminal"};
    std::vector<std::string> leftovers = files_with(run.folder, ".tmp-");
    for (const std::string &f : files_with(run.folder / "tmp", "fuzzycontact"))
      leftovers.push_back("tmp/" + f);
    if (!leftovers.empty())
      return {"garbage", "temporary files left: " + leftovers.front()};
    if (code == 0)
      {
        if (!wrote && !output.empty())
          return {"crash", "exit 0 but no " + run.output + "/results.json"};
        if (!output.empty())
          for (const char *name : {"results.json", "report.txt"})
            if (fs::exists(output / name) &&
                has_non_finite(read_file(output / name),
                               std::string(name) == "results.json"))
              return {"garbage", std::string("NaN/inf in ") + name};
        return {"accepted", ""};
      }
    if (code == 3 && run.program == "step-4" && wrote &&
        err.find("not proven within") != std::string::npos)
      {
        for (const char *name : {"results.json", "report.txt"})
          if (fs::exists(output / name) &&
              has_non_finite(read_file(output / name),
                             std::string(name) == "results.json"))
            return {"garbage", std::string("NaN/inf in ") + name};
        return {"unproven", ""};
      }
    if (code != 1)
      return {"crash", "exit status " + std::to_string(code)};
    if (!output.empty() && !run.output_existed && fs::exists(output))
      return {"garbage", "a failed run wrote " + run.output + "/"};
    const std::string problem = message_problem(run.program, err);
    if (!problem.empty())
      return {"unclear", problem};
    return {"refused", ""};
  }


  struct Options
  {
    fs::path      bin, base, work, log;
    unsigned int  cases   = 30;
    std::uint64_t seed    = 1;
    double        timeout = 60;
    unsigned int  jobs    = 2;
  };


  Options
  parse_options(int argc, char **argv)
  {
    Options options;
    for (int i = 1; i + 1 < argc; i += 2)
      {
        const std::string key = argv[i], value = argv[i + 1];
        if (key == "--bin")
          options.bin = value;
        else if (key == "--base")
          options.base = value;
        else if (key == "--work")
          options.work = value;
        else if (key == "--log")
          options.log = value;
        else if (key == "--cases")
          options.cases = std::stoul(value);
        else if (key == "--seed")
          options.seed = std::stoull(value);
        else if (key == "--timeout")
          options.timeout = std::stod(value);
        else if (key == "--jobs")
          options.jobs = std::max(1ul, std::stoul(value));
        else
          throw std::runtime_error("unknown option " + key);
      }
    if (options.bin.empty() || options.base.empty() || options.work.empty())
      throw std::runtime_error("usage: fuzz_parameters --bin <folder> --base "
                               "<folder> --work <folder> [--cases N] [--seed "
                               "S] [--timeout s] [--jobs J] [--log file]");
    return options;
  }


  // Writes the mutated files of case @p index into its folder.
  Run
  prepare(const Options               &options,
          const std::vector<BaseCase> &bases,
          const std::size_t            index)
  {
    Random   random(options.seed * 1000003ULL + index);
    BaseCase base = bases[index % bases.size()];
    Run      run;
    run.index   = index;
    run.program = base.program;
    run.folder  = options.work / ("case-" + std::to_string(index));
    fs::remove_all(run.folder);
    fs::create_directories(run.folder / "tmp");

    const std::size_t n_mutations =
      1 + (random.chance(0.3) ? 1 : 0) + (random.chance(0.1) ? 1 : 0);
    for (std::size_t k = 0; k < n_mutations; ++k)
      {
        ParameterFile &target =
          (base.scenes.empty() || random.chance(0.55))
            ? base.step_file
            : base.scenes[random.below(base.scenes.size())];
        std::string what = mutate(target, random);
        std::replace(what.begin(), what.end(), '\n', '|');
        run.mutations.push_back(what);
      }
    run.output = output_directory(base.step_file, base.program);
    for (const ParameterFile &scene : base.scenes)
      write_file(run.folder / scene.name, join(scene.lines, "\n"));
    if (random.chance(0.01))
      {
        // The parameter file is a folder.
        fs::create_directories(run.folder / base.step_file.name);
        run.mutations.push_back("the parameter file is a folder");
      }
    else
      write_file(run.folder / base.step_file.name,
                 join(base.step_file.lines, "\n"));
    std::error_code ignore;
    run.output_existed =
      !run.output.empty() && fs::exists(run.folder / run.output, ignore);
    return run;
  }
} // namespace


int
main(int argc, char **argv)
{
  Options options;
  try
    {
      options = parse_options(argc, argv);
    }
  catch (const std::exception &e)
    {
      std::cerr << e.what() << std::endl;
      return 2;
    }
  const std::vector<BaseCase> bases = read_base_cases(options.base);
  if (bases.empty())
    {
      std::cerr << "no step-N*.prm in " << options.base << std::endl;
      return 2;
    }
  fs::create_directories(options.work);
  std::ofstream log;
  if (!options.log.empty())
    log.open(options.log);

  std::map<std::string, unsigned int> counts;
  for (const char *c : {"refused",
                        "accepted",
                        "unproven",
                        "crash",
                        "hang",
                        "garbage",
                        "unclear"})
    counts[c] = 0;
  std::vector<Run> running;
  std::size_t      next   = 0;
  const auto       finish = [&](Run &run) {
    std::string kind, reason;
    try
      {
        std::tie(kind, reason) = classify(run);
      }
    catch (const std::exception &e)
      {
        kind   = "crash";
        reason = std::string("could not inspect the run: ") + e.what();
      }
    ++counts[kind];
    std::ostringstream line;
    line << "case " << run.index << " " << run.program << " ["
         << join(run.mutations, "; ") << "] " << kind << " ("
         << static_cast<int>(run.seconds * 10) / 10.0 << " s)";
    if (!reason.empty())
      line << ": " << reason;
    std::string err = read_file(run.folder / "stderr.txt");
    std::replace(err.begin(), err.end(), '\n', ' ');
    if (!err.empty())
      line << " | " << err.substr(0, 400);
    std::cout << line.str() << std::endl;
    if (log.is_open())
      log << line.str() << std::endl;
    const bool failure =
      kind != "refused" && kind != "accepted" && kind != "unproven";
    std::error_code ignore;
    if (failure)
      {
        const fs::path keep = options.work / "failures" / run.folder.filename();
        fs::remove_all(keep, ignore);
        fs::create_directories(keep.parent_path(), ignore);
        fs::rename(run.folder, keep, ignore);
      }
    else
      fs::remove_all(run.folder, ignore);
  };

  while (next < options.cases || !running.empty())
    {
      while (running.size() < options.jobs && next < options.cases)
        {
          Run            run = prepare(options, bases, next++);
          const fs::path step_file =
            bases[run.index % bases.size()].step_file.name;
          run.start = std::chrono::steady_clock::now();
          run.pid   = launch(fs::absolute(options.bin / run.program),
                           run.folder,
                           step_file.string());
          running.push_back(run);
        }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      for (auto it = running.begin(); it != running.end();)
        {
          int         status = 0;
          const pid_t done   = ::waitpid(it->pid, &status, WNOHANG);
          it->seconds        = std::chrono::duration<double>(
                          std::chrono::steady_clock::now() - it->start)
                          .count();
          if (done == 0 && it->seconds > options.timeout)
            {
              it->timed_out = true;
              ::kill(-it->pid, SIGKILL);
              ::kill(it->pid, SIGKILL);
              ::waitpid(it->pid, &status, 0);
            }
          else if (done == 0)
            {
              ++it;
              continue;
            }
          it->status = status;
          finish(*it);
          it = running.erase(it);
        }
    }

  std::ostringstream summary;
  summary << "fuzz summary (seed " << options.seed << ", " << options.cases
          << " cases):";
  for (const auto &[kind, n] : counts)
    summary << " " << kind << " " << n;
  std::cout << summary.str() << std::endl;
  if (log.is_open())
    log << summary.str() << std::endl;
  const unsigned int failures =
    counts["crash"] + counts["hang"] + counts["garbage"] + counts["unclear"];
  return failures == 0 ? 0 : 1;
}
