#include <fuzzycontact/output/report.h>

#include <deal.II/base/timer.h>

#include <cmath>
#include <iomanip>

namespace FuzzyContact
{
  Report::Report(std::ostream &out, const bool active)
      : out(out)
      , active(active)
  {
  }


  void
  Report::say(const std::string &text)
  {
    if (active)
      out << text << std::flush;
    kept << text;
  }


  std::string
  Report::text() const
  {
    return kept.str();
  }


  namespace Format
  {
    std::string
    scientific(const double value, const int digits)
    {
      if (!std::isfinite(value))
        return "-";
      std::ostringstream s;
      s << std::scientific << std::setprecision(digits) << value;
      return s.str();
    }


    std::string
    fixed(const double value, const int digits)
    {
      if (!std::isfinite(value))
        return "-";
      std::ostringstream s;
      s << std::fixed << std::setprecision(digits) << value;
      return s.str();
    }


    std::string
    percent(const double relative, const int digits)
    {
      std::ostringstream s;
      s << std::showpos << std::fixed << std::setprecision(digits)
        << 100 * relative << "%";
      return s.str();
    }
  } // namespace Format


  double
  relative_error(const double a, const double b)
  {
    if (b == 0)
      return a == 0 ? 0. : 1.;
    return std::abs(a - b) / std::abs(b);
  }


  double
  time_per_call(const std::function<void()> &f, const double min_seconds)
  {
    dealii::Timer timer;
    unsigned int  calls = 0;
    do
      {
        f();
        ++calls;
      }
    while (timer.wall_time() < min_seconds);
    return timer.wall_time() / calls;
  }
} // namespace FuzzyContact
