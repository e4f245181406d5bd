// Work on n items dealt to the ranks of a communicator in contiguous
// blocks, its results gathered on every rank. Contiguous: neighbouring
// points of a study often share their stiffness, and with it an exact
// solver's factorisation, so they stay on one rank. A rank that finished
// its block waits without spinning (mpi_wait.h).

#ifndef fuzzycontact_base_rank_blocks_h
#define fuzzycontact_base_rank_blocks_h

#include <fuzzycontact/base/mpi_wait.h>

#include <deal.II/base/mpi.h>

#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>

#include <cstddef>
#include <utility>
#include <vector>

namespace FuzzyContact
{
  /**
   * work(i) for the items i < @p n of this rank's block, and every rank's
   * results in the order of the items (T must be serialisable by Boost).
   * Collective over @p comm; with one rank (or without MPI) just work(i)
   * for every item.
   */
  template <class T, class Work>
  std::vector<T>
  in_rank_blocks(const std::size_t n, const Work &work, const MPI_Comm comm)
  {
    using namespace dealii;
    const bool parallel = Utilities::MPI::job_supports_mpi() &&
                          Utilities::MPI::n_mpi_processes(comm) > 1;
    const unsigned int size =
      parallel ? Utilities::MPI::n_mpi_processes(comm) : 1;
    const unsigned int rank =
      parallel ? Utilities::MPI::this_mpi_process(comm) : 0;
    std::vector<std::pair<std::size_t, T>> mine;
    for (std::size_t i = n * rank / size; i < n * (rank + 1) / size; ++i)
      mine.emplace_back(i, work(i));
    std::vector<T> all(n);
    if (!parallel)
      for (auto &[i, t] : mine)
        all[i] = std::move(t);
    else
      {
        wait_for_all_ranks(comm); // (unevenly long work: without spinning)
        for (auto &part : Utilities::MPI::all_gather(comm, mine))
          for (auto &[i, t] : part)
            all[i] = std::move(t);
      }
    return all;
  }
} // namespace FuzzyContact

#endif
