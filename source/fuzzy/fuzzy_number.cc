#include <fuzzycontact/fuzzy/fuzzy_number.h>

#include <deal.II/base/exceptions.h>

#include <cmath>
#include <sstream>

namespace FuzzyContact
{
  using namespace dealii;

  double
  Interval::width() const
  {
    return upper - lower;
  }

  double
  Interval::midpoint() const
  {
    return 0.5 * (lower + upper);
  }

  bool
  Interval::contains(const double x, const double tolerance) const
  {
    return x >= lower - tolerance && x <= upper + tolerance;
  }


  namespace
  {
    // @p n_values: 3 for a triangle (its peak is p[1] = p[2]), 4 for a
    // trapezoid; the message lists them as they were given.
    void
    check_points(const std::array<double, 4> &p,
                 const std::string           &what,
                 const unsigned int           n_values)
    {
      for (const double x : p)
        AssertThrow(std::isfinite(x),
                    ExcMessage(what + ": every value must be a finite "
                                      "number."));
      std::ostringstream values;
      values << p[0] << ", " << p[1] << ", ";
      if (n_values == 4)
        values << p[2] << ", ";
      values << p[3];
      AssertThrow(p[0] <= p[1] && p[1] <= p[2] && p[2] <= p[3],
                  ExcMessage(what +
                             ": the values must not decrease (lower end of "
                             "the support <= core <= upper end), got " +
                             values.str() + " (a reversed interval)."));
      AssertThrow(p[0] < p[3],
                  ExcMessage(what + ": the support [" + std::to_string(p[0]) +
                             ", " + std::to_string(p[3]) +
                             "] is empty (zero width); declare the value "
                             "crisp if it is not uncertain."));
    }
  } // namespace


  FuzzyNumber::FuzzyNumber()
      : FuzzyNumber(Shape::crisp, {{0., 0., 0., 0.}})
  {
  }

  FuzzyNumber::FuzzyNumber(const Shape shape, const std::array<double, 4> &p)
      : shape_(shape)
      , points_(p)
  {
  }

  FuzzyNumber
  FuzzyNumber::crisp(const double value)
  {
    AssertThrow(std::isfinite(value),
                ExcMessage("A crisp value must be a finite number."));
    return FuzzyNumber(Shape::crisp, {{value, value, value, value}});
  }

  FuzzyNumber
  FuzzyNumber::triangular(const double       a,
                          const double       m,
                          const double       b,
                          const std::string &what)
  {
    check_points({{a, m, m, b}}, what, 3);
    return FuzzyNumber(Shape::triangular, {{a, m, m, b}});
  }

  FuzzyNumber
  FuzzyNumber::trapezoidal(const double       a,
                           const double       m1,
                           const double       m2,
                           const double       b,
                           const std::string &what)
  {
    check_points({{a, m1, m2, b}}, what, 4);
    return FuzzyNumber(Shape::trapezoidal, {{a, m1, m2, b}});
  }

  FuzzyNumber
  FuzzyNumber::from(const std::string         &shape,
                    const std::vector<double> &v,
                    const std::string         &what)
  {
    const auto expect = [&](const std::size_t n) {
      AssertThrow(v.size() == n,
                  ExcMessage(what + ": a " + shape + " fuzzy number needs " +
                             std::to_string(n) + " values, got " +
                             std::to_string(v.size()) + "."));
    };
    if (shape == "crisp")
      {
        expect(1);
        AssertThrow(std::isfinite(v[0]),
                    ExcMessage(what + ": the value must be finite."));
        return crisp(v[0]);
      }
    if (shape == "triangular")
      {
        expect(3);
        return triangular(v[0], v[1], v[2], what);
      }
    if (shape == "trapezoidal")
      {
        expect(4);
        return trapezoidal(v[0], v[1], v[2], v[3], what);
      }
    AssertThrow(false,
                ExcMessage(what + ": unknown shape <" + shape +
                           ">; use crisp, triangular or trapezoidal."));
    return FuzzyNumber();
  }

  FuzzyNumber::Shape
  FuzzyNumber::shape() const
  {
    return shape_;
  }

  const std::array<double, 4> &
  FuzzyNumber::points() const
  {
    return points_;
  }

  Interval
  FuzzyNumber::alpha_cut(const double alpha) const
  {
    AssertThrow(alpha >= 0 && alpha <= 1,
                ExcMessage("An alpha level must lie in [0, 1]."));
    const auto &[a, m1, m2, b] = points_;
    // Linear flanks; at alpha = 1 exactly the core, at 0 exactly the support.
    return Interval{alpha == 1 ? m1 : a + alpha * (m1 - a),
                    alpha == 1 ? m2 : b - alpha * (b - m2)};
  }

  double
  FuzzyNumber::membership(const double x) const
  {
    const auto &[a, m1, m2, b] = points_;
    if (x < a || x > b)
      return 0;
    if (x >= m1 && x <= m2)
      return 1;
    if (x < m1)
      return (x - a) / (m1 - a);
    return (b - x) / (b - m2);
  }

  FuzzyNumber
  FuzzyNumber::scaled(const double factor) const
  {
    AssertThrow(factor > 0 && std::isfinite(factor),
                ExcMessage("A fuzzy number can only be scaled by a positive "
                           "factor."));
    std::array<double, 4> p = points_;
    for (double &x : p)
      x *= factor;
    return FuzzyNumber(shape_, p);
  }

  std::string
  FuzzyNumber::to_string() const
  {
    std::ostringstream s;
    s.precision(6);
    switch (shape_)
      {
        case Shape::crisp:
          s << "crisp(" << points_[0] << ")";
          break;
        case Shape::triangular:
          s << "triangular(" << points_[0] << ", " << points_[1] << ", "
            << points_[3] << ")";
          break;
        case Shape::trapezoidal:
          s << "trapezoidal(" << points_[0] << ", " << points_[1] << ", "
            << points_[2] << ", " << points_[3] << ")";
          break;
      }
    return s.str();
  }


  std::vector<double>
  alpha_levels(const unsigned int n_alpha)
  {
    AssertThrow(n_alpha >= 2,
                ExcMessage("number of alpha levels must be at least 2 (the "
                           "support and the core), got " +
                           std::to_string(n_alpha) + "."));
    std::vector<double> levels(n_alpha);
    for (unsigned int i = 0; i < n_alpha; ++i)
      levels[i] = static_cast<double>(i) / (n_alpha - 1);
    levels.back() = 1.0;
    return levels;
  }
} // namespace FuzzyContact
