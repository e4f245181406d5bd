// Sampling methods: interval methods that evaluate the response at a set of
// points fixed in advance and take, per output and level, the smallest and
// largest value over the points inside the level's box.
//
// The points are dealt to the ranks of the MPI communicator in contiguous
// blocks (neighbouring samples often share the exact solver's
// factorisation) and the outputs of all points are gathered on every rank,
// so the bounds do not depend on the number of ranks.
//
// Two are provided: VertexMethod (vertex_method.h) and ExtensionPrinciple
// (extension_principle.h). To add one: derive from SamplingMethod and
// implement name() and points(); the evaluation, the bounds, the count and
// the timing are done here.

#ifndef fuzzycontact_fuzzy_sampling_method_h
#define fuzzycontact_fuzzy_sampling_method_h

#include <fuzzycontact/fuzzy/interval_method.h>

#include <vector>

namespace FuzzyContact
{
  class SamplingMethod : public IntervalMethod
  {
  public:
    /**
     * Evaluates the samples() of this method and takes the extremes of
     * every output over the samples inside each level's box.
     */
    FuzzyOutputBounds
    bounds(const std::vector<FuzzyNumber> &parameters,
           const std::vector<double>      &alpha,
           const Response                 &response,
           const std::vector<std::string> &output_names,
           const MPI_Comm                  comm) const final;

    /** The distinct points of points(), each once, in the order given. */
    std::vector<std::vector<double>>
    samples(const std::vector<FuzzyNumber> &parameters,
            const std::vector<double>      &alpha) const;

  protected:
    /**
     * The points to evaluate for the levels @p alpha (repeats are allowed:
     * samples() keeps each point once).
     */
    virtual std::vector<std::vector<double>>
    points(const std::vector<FuzzyNumber> &parameters,
           const std::vector<double>      &alpha) const = 0;
  };
} // namespace FuzzyContact

#endif
