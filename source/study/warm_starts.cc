#include <fuzzycontact/study/warm_starts.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
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
    update_box(next / block_size);
    next = (next + 1) % capacity;
  }


  void
  WarmStarts::update_box(const std::size_t block)
  {
    if (dimension == 0)
      return;
    const std::size_t n_blocks = (states.size() + block_size - 1) / block_size;
    box_low.resize(n_blocks * dimension);
    box_high.resize(n_blocks * dimension);
    double *low  = &box_low[block * dimension],
           *high = &box_high[block * dimension];
    std::fill(low, low + dimension, std::numeric_limits<double>::infinity());
    std::fill(high, high + dimension, -std::numeric_limits<double>::infinity());
    const std::size_t end = std::min(states.size(), (block + 1) * block_size);
    for (std::size_t e = block * block_size; e < end; ++e)
      for (unsigned int i = 0; i < dimension; ++i)
        {
          low[i]  = std::min(low[i], coordinates[e * dimension + i]);
          high[i] = std::max(high[i], coordinates[e * dimension + i]);
        }
  }


  const std::vector<ContactState> *
  WarmStarts::nearest(const std::vector<double> &x) const
  {
    if (states.empty() || x.size() != dimension)
      return nullptr;
    scale(x, scaled_x);
    // The (squared) distance from x to each block's box.
    const std::size_t n_blocks = box_low.size() / std::max(1u, dimension);
    box_distance.resize(n_blocks);
    std::size_t first = 0;
    for (std::size_t b = 0; b < n_blocks; ++b)
      {
        const double *low  = &box_low[b * dimension],
                     *high = &box_high[b * dimension];
        double d           = 0;
        for (unsigned int i = 0; i < dimension; ++i)
          {
            const double outside =
              std::max({low[i] - scaled_x[i], scaled_x[i] - high[i], 0.});
            d += outside * outside;
          }
        box_distance[b] = d;
        if (d < box_distance[first])
          first = b;
      }
    // The nearest point, the first stored of equally near ones (as a scan
    // in storage order finds it): the nearest box first, then every box
    // not strictly farther than the nearest point found so far (no sort:
    // the distance only falls, so a box passed over stays too far).
    std::size_t best     = 0;
    double      distance = std::numeric_limits<double>::infinity();
    const auto  scan     = [&](const std::size_t b) {
      const std::size_t end = std::min(states.size(), (b + 1) * block_size);
      const double     *c   = &coordinates[b * block_size * dimension];
      for (std::size_t e = b * block_size; e < end; ++e, c += dimension)
        {
          double d = 0;
          for (unsigned int i = 0; i < dimension; ++i)
            d += (scaled_x[i] - c[i]) * (scaled_x[i] - c[i]);
          if (d < distance || (d == distance && e < best))
            {
              distance = d;
              best     = e;
            }
        }
    };
    scan(first);
    for (std::size_t b = 0; b < n_blocks; ++b)
      if (b != first && box_distance[b] <= distance)
        scan(b);
    return &states[best];
  }


  std::size_t
  WarmStarts::size() const
  {
    return states.size();
  }
} // namespace FuzzyContact
