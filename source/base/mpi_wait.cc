#include <fuzzycontact/base/mpi_wait.h>

#include <deal.II/base/exceptions.h>

#include <chrono>
#include <thread>

namespace FuzzyContact
{
  void
  wait_for_all_ranks(const MPI_Comm comm)
  {
    using namespace dealii;
    if (!Utilities::MPI::job_supports_mpi() ||
        Utilities::MPI::n_mpi_processes(comm) == 1)
      return;
    MPI_Request request;
    int         ierr = MPI_Ibarrier(comm, &request);
    AssertThrowMPI(ierr);
    // A few quick tests first (the others are often there already).
    int done = 0;
    for (unsigned int test = 0; !done; ++test)
      {
        ierr = MPI_Test(&request, &done, MPI_STATUS_IGNORE);
        AssertThrowMPI(ierr);
        if (!done && test >= 100)
          std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
  }
} // namespace FuzzyContact
