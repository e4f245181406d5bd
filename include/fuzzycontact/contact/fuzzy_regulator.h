// A Mamdani fuzzy regulator with one input and one output, as the FL2C
// method of Massa et al. (2013) uses it: seven linguistic terms per
// variable, NL NM NS Z PS PM PL (large, medium, small negative; zero; small,
// medium, large positive).
//
// Input terms, from three transition points 0 < a1 < a2 < a3:
//   Z  = tri(-a1, 0, a1),  PS = tri(0, a1, a2),  PM = tri(a1, a2, a3),
//   PL = shoulder: 0 below a2, rising linearly on [a2, a3], 1 beyond a3;
//   NS, NM, NL mirrored. They form a partition of unity.
// Output terms, from 0 < b1 < b2 < b3: triangles centred at 0, +-b1, +-b2,
//   +-b3 whose feet are the neighbouring centres; the outermost feet are at
//   +-(2 b3 - b2), which bounds the universe of discourse.
// Rules: the output mirrors the input, NL -> PL, NM -> PM, NS -> PS, Z -> Z,
//   PS -> NS, PM -> NM, PL -> NL (a penetration asks for more compression,
//   an opening for less; a slip one way for friction the other way).
// Inference: min implication (each output term is clipped at the degree of
//   its rule), max aggregation, and centroid defuzzification computed
//   exactly: the aggregated membership function is piecewise linear, and
//   its area and first moment are integrated exactly between its
//   breakpoints (the term vertices, the clip points and the crossings of
//   neighbouring terms); no sampling.

#ifndef fuzzycontact_contact_fuzzy_regulator_h
#define fuzzycontact_contact_fuzzy_regulator_h

#include <array>
#include <string>

namespace FuzzyContact
{
  class MamdaniRegulator
  {
  public:
    /** Term order used by all arrays: NL, NM, NS, Z, PS, PM, PL. */
    static constexpr unsigned int n_terms = 7;
    using Degrees                         = std::array<double, n_terms>;

    /**
     * Throws, naming @p what, unless 0 < a1 < a2 < a3 and 0 < b1 < b2 < b3
     * (all finite).
     */
    MamdaniRegulator(const std::array<double, 3> &input_points,
                     const std::array<double, 3> &output_points,
                     const std::string           &what = "regulator");

    /** Degrees of membership of @p x in the seven input terms. */
    Degrees
    fuzzify(const double x) const;

    /** Degree of membership of @p y in output term @p k (unclipped). */
    double
    output_membership(const unsigned int k, const double y) const;

    /**
     * The aggregated output membership function at @p y for rule
     * strengths @p strengths (one per output term).
     */
    double
    aggregated_membership(const Degrees &strengths, const double y) const;

    /** Exact centroid of the aggregation for the given strengths. */
    double
    centroid(const Degrees &strengths) const;

    /** The crisp output for input @p x: fuzzify, infer, defuzzify. */
    double
    operator()(const double x) const;

    /** The rule strengths of the output terms for input @p x. */
    Degrees
    rule_strengths(const double x) const;

    const std::array<double, 3> &
    input_points() const;
    const std::array<double, 3> &
    output_points() const;
    /** Half-width 2 b3 - b2 of the output universe. */
    double
    output_bound() const;

  private:
    std::array<double, 3> a;
    std::array<double, 3> b;
    // The nine vertices of the output terms, -(2 b3 - b2) ... 2 b3 - b2:
    // term k has feet v[k], v[k + 2] and centre v[k + 1].
    std::array<double, 9> v;
  };
} // namespace FuzzyContact

#endif
