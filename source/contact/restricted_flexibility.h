// W restricted to some of its rows, the problem of FL2C's coarse
// correction (fl2c.h). Not a public header: only fl2c.cc builds it.

#ifndef fuzzycontact_contact_restricted_flexibility_h
#define fuzzycontact_contact_restricted_flexibility_h

#include <fuzzycontact/contact/contact_problem.h>

#include <vector>

namespace FuzzyContact
{
  // W restricted to some of its rows (two per node of the coarse
  // correction's nodes), the problem of the coarse correction. With
  // @p lasting, rows that only ever grow by appending (a workspace's
  // coarse nodes): then the restriction has W's state, so that factors
  // made for it at this W serve the next, larger one.
  class RestrictedFlexibility : public FlexibilityOperator
  {
  public:
    RestrictedFlexibility(FlexibilityOperator             &W,
                          const std::vector<unsigned int> &rows,
                          const bool                       lasting)
        : W(W)
        , rows(rows)
    {
      if (lasting)
        restored(W.state());
    }

    unsigned int
    size() const override
    {
      return rows.size();
    }

    void
    prepare(const std::vector<unsigned int> &columns) override
    {
      global.clear();
      for (const unsigned int j : columns)
        global.push_back(rows[j]);
      W.prepare(global);
    }

    double
    operator()(const unsigned int i, const unsigned int j) const override
    {
      return W(rows[i], rows[j]);
    }

    const double *
    column(const unsigned int j) override
    {
      const double *w = W.column(rows[j]);
      gathered.resize(rows.size());
      for (unsigned int i = 0; i < rows.size(); ++i)
        gathered[i] = w[rows[i]];
      return gathered.data();
    }

    double
    diagonal(const unsigned int i) override
    {
      return W.diagonal(rows[i]);
    }

  private:
    FlexibilityOperator             &W;
    const std::vector<unsigned int> &rows;
    std::vector<unsigned int>        global;
    std::vector<double>              gathered;
  };
} // namespace FuzzyContact

#endif
