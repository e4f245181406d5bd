// Fuzzy numbers and their alpha-cuts.
//
// A fuzzy number is described by its membership function mu(x) in [0, 1]:
// a crisp value (mu = 1 at one point), a triangle (a, m, b) or a trapezoid
// (a, m1, m2, b), with a <= m1 <= m2 <= b. Its alpha-cut is the interval
// {x : mu(x) >= alpha}; alpha-cuts are nested, from the support [a, b] at
// alpha = 0 to the core [m1, m2] at alpha = 1. The fuzzy propagation works on
// n_alpha of them at once: one interval problem per level.

#ifndef fuzzycontact_fuzzy_fuzzy_number_h
#define fuzzycontact_fuzzy_fuzzy_number_h

#include <array>
#include <string>
#include <vector>

namespace FuzzyContact
{
  /**
   * A closed interval [lower, upper].
   */
  struct Interval
  {
    double lower;
    double upper;

    double
    width() const;
    double
    midpoint() const;
    /** True if lower - tolerance <= x <= upper + tolerance. */
    bool
    contains(const double x, const double tolerance = 0) const;

    template <class Archive>
    void
    serialize(Archive &ar, const unsigned int)
    {
      ar &lower &upper;
    }
  };

  class FuzzyNumber
  {
  public:
    enum class Shape
    {
      crisp,
      triangular,
      trapezoidal
    };

    /** A crisp zero. */
    FuzzyNumber();

    static FuzzyNumber
    crisp(const double value);
    /**
     * The triangle with support [a, b] and peak m. Throws (naming @p what)
     * unless a <= m <= b, all finite, and a < b.
     */
    static FuzzyNumber
    triangular(const double       a,
               const double       m,
               const double       b,
               const std::string &what = "fuzzy number");
    /**
     * The trapezoid with support [a, b] and core [m1, m2]. Throws unless
     * a <= m1 <= m2 <= b, all finite, and a < b.
     */
    static FuzzyNumber
    trapezoidal(const double       a,
                const double       m1,
                const double       m2,
                const double       b,
                const std::string &what = "fuzzy number");

    /**
     * Reads a shape name ("crisp", "triangular", "trapezoidal") and its
     * values (1, 3 or 4 of them), with the checks above.
     */
    static FuzzyNumber
    from(const std::string         &shape,
         const std::vector<double> &values,
         const std::string         &what);

    Shape
    shape() const;
    /** The four points (a, m1, m2, b); a crisp value repeats itself. */
    const std::array<double, 4> &
    points() const;

    /**
     * The alpha-cut, for alpha in [0, 1] (alpha = 0 gives the support).
     */
    Interval
    alpha_cut(const double alpha) const;

    /** mu(x). */
    double
    membership(const double x) const;

    /** The same fuzzy number with every point multiplied by @p factor > 0. */
    FuzzyNumber
    scaled(const double factor) const;

    /** For instance "triangular(1.995e+11, 2.1e+11, 2.205e+11)". */
    std::string
    to_string() const;

  private:
    FuzzyNumber(const Shape shape, const std::array<double, 4> &points);

    Shape                 shape_;
    std::array<double, 4> points_;
  };

  /**
   * @p n_alpha equally spaced membership levels 0, 1/(n-1), ..., 1 (n >= 2).
   */
  std::vector<double>
  alpha_levels(const unsigned int n_alpha);
} // namespace FuzzyContact

#endif
