// Every bound carries its proof: the argument of each bound of an interval
// method (each output, level and side) is evaluated once more with an
// exact model, so that the reduction error at the bound is known without a
// reference study, and a bound found outside a sampled reference's
// interval can be told apart from a reduction error.
//
// Many bounds share their argument (a vertex is the bound of several
// outputs and levels): each distinct point is evaluated once, the points
// (sorted) dealt in contiguous blocks to the ranks of the communicator (so
// that points sharing their stiffness stay on one rank, and with them the
// exact solver's factorisation) and the values gathered on all of them.

#ifndef fuzzycontact_fuzzy_bound_proof_h
#define fuzzycontact_fuzzy_bound_proof_h

#include <fuzzycontact/fuzzy/interval_method.h>

#include <deal.II/base/mpi.h>

#include <vector>

namespace FuzzyContact
{
  /** One bound, and the exact value at its argument. */
  struct BoundProof
  {
    /** The bound (the reduced model's value at the argument). */
    double reduced = 0;
    /** The exact model's value at the same point. */
    double exact = 0;
    /** reduced - exact: the reduction error at the bound. */
    double
    difference() const
    {
      return reduced - exact;
    }
  };

  struct BoundProofs
  {
    /** [output][level] */
    std::vector<std::vector<BoundProof>> lower, upper;
    /** Distinct points evaluated (over all ranks). */
    unsigned long n_evaluations = 0;
    /** Wall time [s] (the longest over the ranks). */
    double wall_time = 0;
  };

  /**
   * Evaluates @p exact at the distinct arguments of @p bounds (argmin and
   * argmax of every output and level), each once.
   */
  BoundProofs
  prove_bounds(const FuzzyOutputBounds &bounds,
               const Response          &exact,
               const MPI_Comm           comm);

  /**
   * How a method's bound compares with a sampled reference's, at one side
   * of one level, measured relative to @p range (the output's range over
   * the support, from the reference).
   */
  struct ReferenceComparison
  {
    /** How far the method's bound lies inside the reference's interval. */
    double short_of_reference = 0;
    /**
     * How far the exact value at the method's argument lies outside the
     * reference's interval (a point the reference's samples missed).
     */
    double reference_missed = 0;
    /**
     * How far the method's bound lies outside the reference's interval
     * while the exact value at its argument does not (a reduction error).
     */
    double outside_not_verified = 0;
  };

  /**
   * Compares the lower (@p upper = false) or upper bound @p bound of a
   * method, whose argument has the exact value @p exact, with the
   * reference's bound @p reference; differences below @p tolerance (of
   * @p range) count as agreement: the exact solvers of the proofs and of
   * the reference (factorisations reused or not) agree to about 1e-9.
   */
  ReferenceComparison
  compare_with_reference(const double bound,
                         const double exact,
                         const double reference,
                         const bool   upper,
                         const double range,
                         const double tolerance = 1e-8);
} // namespace FuzzyContact

#endif
