#include <fuzzycontact/base/rank_timers.h>

#include <boost/serialization/map.hpp>
#include <boost/serialization/string.hpp>

#include <iomanip>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace FuzzyContact
{
  std::string
  sections_per_rank(const dealii::TimerOutput &timer, const MPI_Comm comm)
  {
    using namespace dealii;
    if (!Utilities::MPI::job_supports_mpi() ||
        Utilities::MPI::n_mpi_processes(comm) == 1)
      return "";
    const std::map<std::string, double> mine =
      timer.get_summary_data(TimerOutput::total_wall_time);
    const std::vector<std::map<std::string, double>> all =
      Utilities::MPI::gather(comm, mine, 0);
    if (Utilities::MPI::this_mpi_process(comm) != 0)
      return "";
    std::set<std::string> sections;
    std::size_t           width = 8;
    for (const auto &rank : all)
      for (const auto &[section, time] : rank)
        {
          sections.insert(section);
          width = std::max(width, section.size());
        }
    std::ostringstream out;
    out << "\nwall time per section and MPI rank [s]\n"
        << "  " << std::left << std::setw(width) << "section" << std::right;
    for (unsigned int r = 0; r < all.size(); ++r)
      out << std::setw(10) << ("rank " + std::to_string(r));
    out << "\n" << std::fixed << std::setprecision(4);
    for (const std::string &section : sections)
      {
        out << "  " << std::left << std::setw(width) << section << std::right;
        for (const auto &rank : all)
          {
            const auto found = rank.find(section);
            if (found == rank.end())
              out << std::setw(10) << "-";
            else
              out << std::setw(10) << found->second;
          }
        out << "\n";
      }
    return out.str();
  }
} // namespace FuzzyContact
