// Multi-indices alpha in N^q, |alpha| <= n: the Taylor coefficients of an
// eigenpair with respect to q parameters or directions (eigen_derivatives.h).

#ifndef fuzzycontact_reanalysis_multi_index_set_h
#define fuzzycontact_reanalysis_multi_index_set_h

#include <map>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /**
   * All multi-indices alpha in N^q with |alpha| <= n, in graded order (all
   * of order 0, then 1, ...; lexicographic within an order), so that the
   * indices of order <= p are the first n_up_to_order(p).
   */
  class MultiIndexSet
  {
  public:
    MultiIndexSet(const unsigned int n_variables, const unsigned int max_order);

    unsigned int
    size() const;
    unsigned int
    n_variables() const;
    unsigned int
    max_order() const;
    const std::vector<unsigned int> &
    operator[](const unsigned int i) const;
    /** |alpha| of the i-th multi-index. */
    unsigned int
    order(const unsigned int i) const;
    /** Position of alpha; throws if alpha is not in the set. */
    unsigned int
    index(const std::vector<unsigned int> &alpha) const;
    /** Number of multi-indices of order <= p. */
    unsigned int
    n_up_to_order(const unsigned int p) const;
    /** alpha! = prod_k alpha_k!. */
    double
    factorial(const unsigned int i) const;
    /** Readable form, e.g. "(1,0,2)". */
    std::string
    to_string(const unsigned int i) const;

  private:
    unsigned int                                      n_variables_;
    unsigned int                                      max_order_;
    std::vector<std::vector<unsigned int>>            indices_;
    std::map<std::vector<unsigned int>, unsigned int> position_;
    std::vector<unsigned int>                         n_up_to_order_;
  };
} // namespace FuzzyContact

#endif
