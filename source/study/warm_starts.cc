#include <fuzzycontact/study/warm_starts.h>

#include <deal.II/base/exceptions.h>

#include <limits>

namespace FuzzyContact
{
  WarmStarts::WarmStarts(const std::vector<double> &widths,
                         const std::size_t          capacity)
      : widths(widths)
      , capacity(capacity)
  {
    Assert(capacity > 0, ExcMessage("A warm start archive keeps some points."));
  }


  void
  WarmStarts::scale(const std::vector<double> &x,
                    std::vector<double>       &scaled) const
  {
    scaled.resize(x.size());
    for (unsigned int i = 0; i < x.size(); ++i)
      {
        const double w = widths.empty() ? 1. : widths[i];
        scaled[i]      = w > 0 ? x[i] / w : 0.;
      }
  }


  void
  WarmStarts::add(const std::vector<double>       &x,
                  const std::vector<ContactState> &states_of_x)
  {
    AssertThrow(widths.empty() || x.size() == widths.size(),
                ExcMessage("WarmStarts: a point of another dimension."));
    if (states.empty())
      dimension = x.size();
    AssertThrow(x.size() == dimension,
                ExcMessage("WarmStarts: a point of another dimension."));
    std::vector<ContactState> kept(states_of_x.size());
    for (unsigned int k = 0; k < states_of_x.size(); ++k)
      {
        kept[k].status    = states_of_x[k].status;
        kept[k].slip_sign = states_of_x[k].slip_sign;
        kept[k].p         = states_of_x[k].p;
        kept[k].rigid     = states_of_x[k].rigid;
      }
    scale(x, scaled_x);
    if (states.size() < capacity)
      {
        coordinates.insert(coordinates.end(), scaled_x.begin(), scaled_x.end());
        states.push_back(std::move(kept));
      }
    else
      {
        std::copy(scaled_x.begin(),
                  scaled_x.end(),
                  coordinates.begin() + next * dimension);
        states[next] = std::move(kept);
      }
    next = (next + 1) % capacity;
  }


  const std::vector<ContactState> *
  WarmStarts::nearest(const std::vector<double> &x) const
  {
    if (states.empty() || x.size() != dimension)
      return nullptr;
    scale(x, scaled_x);
    std::size_t   best     = 0;
    double        distance = std::numeric_limits<double>::infinity();
    const double *c        = coordinates.data();
    for (std::size_t e = 0; e < states.size(); ++e, c += dimension)
      {
        double d = 0;
        for (unsigned int i = 0; i < dimension; ++i)
          d += (scaled_x[i] - c[i]) * (scaled_x[i] - c[i]);
        if (d < distance)
          {
            distance = d;
            best     = e;
          }
      }
    return &states[best];
  }


  std::size_t
  WarmStarts::size() const
  {
    return states.size();
  }
} // namespace FuzzyContact
