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
  WarmStarts::add(const std::vector<double>       &x,
                  const std::vector<ContactState> &states)
  {
    AssertThrow(widths.empty() || x.size() == widths.size(),
                ExcMessage("WarmStarts: a point of another dimension."));
    Entry entry;
    entry.x = x;
    for (const ContactState &s : states)
      {
        ContactState kept;
        kept.status    = s.status;
        kept.slip_sign = s.slip_sign;
        kept.p         = s.p;
        kept.rigid     = s.rigid;
        entry.states.push_back(std::move(kept));
      }
    if (entries.size() == capacity)
      entries.pop_front();
    entries.push_back(std::move(entry));
  }


  const std::vector<ContactState> *
  WarmStarts::nearest(const std::vector<double> &x) const
  {
    const Entry *best     = nullptr;
    double       distance = std::numeric_limits<double>::infinity();
    for (const Entry &e : entries)
      {
        if (e.x.size() != x.size())
          continue;
        double d = 0;
        for (unsigned int i = 0; i < x.size(); ++i)
          {
            const double w = widths.empty() ? 1. : widths[i];
            if (w > 0)
              d += (x[i] - e.x[i]) * (x[i] - e.x[i]) / (w * w);
          }
        if (d < distance)
          {
            distance = d;
            best     = &e;
          }
      }
    return best == nullptr ? nullptr : &best->states;
  }


  std::size_t
  WarmStarts::size() const
  {
    return entries.size();
  }
} // namespace FuzzyContact
