// Where each MPI rank's time went: the wall time of every TimerOutput
// section on every rank, side by side. A rank's TimerOutput prints on the
// first rank only, so the other ranks' sections are gathered here.

#ifndef fuzzycontact_base_rank_timers_h
#define fuzzycontact_base_rank_timers_h

#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <string>

namespace FuzzyContact
{
  /**
   * The wall time of every section of @p timer on every rank of @p comm, a
   * table with one column per rank (a section a rank never entered: "-"),
   * after an empty line, on the first rank (empty on the others, and with
   * one rank). Collective.
   */
  std::string
  sections_per_rank(const dealii::TimerOutput &timer, const MPI_Comm comm);
} // namespace FuzzyContact

#endif
