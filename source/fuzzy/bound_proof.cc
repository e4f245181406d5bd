#include <fuzzycontact/base/rank_blocks.h>
#include <fuzzycontact/fuzzy/bound_proof.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/base/timer.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace FuzzyContact
{
  using namespace dealii;

  BoundProofs
  prove_bounds(const FuzzyOutputBounds &bounds,
               const Response          &exact,
               const MPI_Comm           comm)
  {
    Timer timer;
    // The distinct arguments, in a fixed order.
    std::map<std::vector<double>, unsigned long> index;
    for (const auto *args : {&bounds.argmin, &bounds.argmax})
      for (const auto &output : *args)
        for (const std::vector<double> &p : output)
          index.emplace(p, 0);
    std::vector<std::vector<double>> points;
    for (auto &[p, i] : index)
      {
        i = points.size();
        points.push_back(p);
      }

    // Each rank takes a contiguous block of the points (sorted): points
    // that share their stiffness follow each other, so an exact solver
    // that keeps its factorisation while the stiffness does not change
    // factorises as seldom as with one process.
    const std::vector<std::vector<double>> values =
      in_rank_blocks<std::vector<double>>(
        points.size(),
        [&](const std::size_t i) {
          return exact(points[i]);
        },
        comm);

    BoundProofs        proofs;
    const unsigned int n_outputs = bounds.bounds.size();
    proofs.lower.resize(n_outputs);
    proofs.upper.resize(n_outputs);
    for (unsigned int k = 0; k < n_outputs; ++k)
      for (unsigned int l = 0; l < bounds.bounds[k].size(); ++l)
        {
          const auto &lo = values[index.at(bounds.argmin[k][l])];
          const auto &hi = values[index.at(bounds.argmax[k][l])];
          AssertThrow(lo.size() == n_outputs && hi.size() == n_outputs,
                      ExcMessage("The exact response returned the wrong "
                                 "number of outputs."));
          proofs.lower[k].push_back({bounds.bounds[k][l].lower, lo[k]});
          proofs.upper[k].push_back({bounds.bounds[k][l].upper, hi[k]});
        }
    proofs.n_evaluations = points.size();
    proofs.wall_time     = timer.wall_time();
    if (Utilities::MPI::job_supports_mpi() &&
        Utilities::MPI::n_mpi_processes(comm) > 1)
      proofs.wall_time = Utilities::MPI::max(proofs.wall_time, comm);
    return proofs;
  }


  ReferenceComparison
  compare_with_reference(const double bound,
                         const double exact,
                         const double reference,
                         const bool   upper,
                         const double range,
                         const double tolerance)
  {
    // Signed so that positive means "beyond the reference's interval".
    const double        sign   = upper ? 1. : -1.;
    const double        scale  = range > 0 ? range : 1.;
    const double        beyond = sign * (bound - reference) / scale;
    const double        truly  = sign * (exact - reference) / scale;
    ReferenceComparison c;
    if (beyond < -tolerance)
      c.short_of_reference = -beyond;
    else if (beyond > tolerance)
      {
        if (truly > tolerance)
          c.reference_missed = truly;
        else
          c.outside_not_verified = beyond;
      }
    return c;
  }
} // namespace FuzzyContact
