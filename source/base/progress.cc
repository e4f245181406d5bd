#include <fuzzycontact/base/progress.h>

#include <deal.II/base/mpi.h>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <unistd.h>

namespace FuzzyContact
{
  namespace ProgressLines
  {
    namespace
    {
      Verbosity verbosity = Verbosity::automatic;

      // The elapsed time of the process's stages and when the last stage
      // line was printed.
      Timer &
      stage_timer()
      {
        static Timer timer;
        return timer;
      }
      double last_stage_line = 0;

      const double stage_interval = 2.;

      std::string
      seconds(const double t)
      {
        std::ostringstream out;
        out << std::fixed << std::setprecision(t < 10 ? 1 : 0) << t << " s";
        return out.str();
      }
    } // namespace


    void
    declare_parameters(ParameterHandler &prm)
    {
      prm.declare_entry("verbosity",
                        "auto",
                        Patterns::Selection("quiet|auto|progress"),
                        "Progress lines on long stages (offline build, "
                        "optimisation, reference sampling), on standard "
                        "error: 'quiet' "
                        "never, 'auto' when standard error is a terminal, "
                        "'progress' always (at most one line every few "
                        "seconds).");
    }


    void
    parse_parameters(const ParameterHandler &prm)
    {
      const std::string v = prm.get("verbosity");
      set_verbosity(v == "quiet"      ? Verbosity::quiet
                    : v == "progress" ? Verbosity::progress
                                      : Verbosity::automatic);
    }


    void
    set_verbosity(const Verbosity v)
    {
      verbosity = v;
    }


    bool
    enabled()
    {
      if (Utilities::MPI::job_supports_mpi() &&
          Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return false;
      switch (verbosity)
        {
          case Verbosity::quiet:
            return false;
          case Verbosity::progress:
            return true;
          default:
            return isatty(fileno(stderr)) == 1;
        }
    }


    void
    stage(const std::string &what,
          const unsigned int done,
          const unsigned int total)
    {
      note(what + " (" + std::to_string(done) + "/" + std::to_string(total) +
           ")");
    }


    void
    note(const std::string &what)
    {
      const double t = stage_timer().wall_time();
      if (!enabled() || t - last_stage_line < stage_interval)
        return;
      last_stage_line = t;
      std::cerr << "  ... " << what << ", " << seconds(t) << " elapsed"
                << std::endl;
    }


    std::string
    line(const std::string &what,
         const unsigned int done,
         const unsigned int total,
         const double       elapsed,
         const std::string &detail)
    {
      std::ostringstream out;
      out << "  ... " << what << ": " << done << "/" << total << " ("
          << (total == 0 ? 100 : 100 * done / total) << " %), "
          << (detail.empty() ? "" : detail + ", ") << seconds(elapsed)
          << " elapsed";
      if (done > 0 && done < total)
        out << ", about " << seconds(elapsed * (total - done) / done)
            << " left";
      return out.str();
    }
  } // namespace ProgressLines


  Progress::Progress(const std::string                  &what,
                     const unsigned int                  total,
                     const double                        interval,
                     const std::function<std::string()> &detail)
      : what(what)
      , detail(detail)
      , total(total)
      , interval(interval)
      , last_line(0)
  {
  }


  Progress::~Progress()
  {
    // The last line, if the loop was long enough to print any.
    if (printed)
      print();
  }


  void
  Progress::advance(const unsigned int n)
  {
    done += n;
    const double t = timer.wall_time();
    if (t - last_line >= interval && done < total && ProgressLines::enabled())
      {
        last_line = t;
        printed   = true;
        print();
      }
  }


  void
  Progress::print() const
  {
    std::cerr << ProgressLines::line(what,
                                     done,
                                     total,
                                     timer.wall_time(),
                                     detail ? detail() : std::string())
              << std::endl;
  }
} // namespace FuzzyContact
