// The vertex method: the response at the 2^n corners of every level's box
// (n fuzzy parameters), its extremes taken as the bounds. Exact for
// responses that are monotone in each parameter over the box, wrong (the
// interval too narrow) otherwise: an optimum inside the box is never seen.
//
// It is one of the interval methods of interval_method.h (see there for
// the others and for where to add one); the evaluation over MPI ranks is
// SamplingMethod's (sampling_method.h).

#ifndef fuzzycontact_fuzzy_vertex_method_h
#define fuzzycontact_fuzzy_vertex_method_h

#include <fuzzycontact/fuzzy/sampling_method.h>

namespace FuzzyContact
{
  class VertexMethod : public SamplingMethod
  {
  public:
    /** "vertex method". */
    std::string
    name() const override;

  protected:
    /** The corners of every level's box. */
    std::vector<std::vector<double>>
    points(const std::vector<FuzzyNumber> &parameters,
           const std::vector<double>      &alpha) const override;
  };
} // namespace FuzzyContact

#endif
