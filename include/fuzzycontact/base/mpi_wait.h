// Waiting for the other MPI ranks without spinning. A blocking collective
// busy-polls while it waits: a rank that finished its share of the work
// (one body of the offline build, while another rank builds a body
// re-analysed by HPTP) would keep a core busy for nothing, which on a
// machine shared with other jobs takes CPU time from the ranks still
// working. Before such a wait, a rank calls wait_for_all_ranks().

#ifndef fuzzycontact_base_mpi_wait_h
#define fuzzycontact_base_mpi_wait_h

#include <deal.II/base/mpi.h>

namespace FuzzyContact
{
  /**
   * Returns when every rank of @p comm has called it (a barrier), testing
   * for the others' arrival and sleeping between the tests (at most a
   * fifth of a millisecond late). Nothing to wait for with one rank.
   * Collective.
   */
  void
  wait_for_all_ranks(const MPI_Comm comm);
} // namespace FuzzyContact

#endif
