// ReducedContactModel's flexibility operator (reduced_model.h): W as the
// contact solvers see it, its columns combined from the components' parts
// on demand. Not a public header: only reduced_model.cc builds it.

#ifndef fuzzycontact_reduction_reduced_model_flexibility_h
#define fuzzycontact_reduction_reduced_model_flexibility_h

#include <fuzzycontact/reduction/reduced_model.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_templates.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <vector>

namespace FuzzyContact
{
  // W as the solvers see it: columns combined from the parts on demand,
  // kept until the model changes.
  class ReducedContactModel::Flexibility : public FlexibilityOperator
  {
  public:
    explicit Flexibility(const ReducedContactModel &model)
        : model(model)
        , m(model.problem_.g_initial.size())
        , cache(m, m)
        , computed(m, false)
        , diagonal_(m)
    {
    }

    unsigned int
    size() const override
    {
      return m;
    }

    void
    prepare(const std::vector<unsigned int> &columns) override
    {
      // Many new columns of parts of low rank are combined at once,
      // W(:, J) = U U(J, :)^T as one matrix product (BLAS), not column by
      // column.
      std::vector<unsigned int> missing;
      for (const unsigned int j : columns)
        if (!computed[j] &&
            std::find(missing.begin(), missing.end(), j) == missing.end())
          missing.push_back(j);
      if (missing.size() < 8)
        {
          for (const unsigned int j : missing)
            column(j);
          return;
        }
      for (const unsigned int j : missing)
        {
          AssertIndexRange(j, m);
          std::fill(&cache(j, 0), &cache(j, 0) + m, 0.);
        }
      for (unsigned int c = 0; c < model.variable.size(); ++c)
        for (const Part *part : {&model.variable[c], &model.fixed[c]})
          if (part->present)
            {
              const double a = 1. / model.scales[c];
              if (!part->low_rank || part->U.n() == 0)
                {
                  for (const unsigned int j : missing)
                    part->add_column(j, a, &cache(j, 0));
                  continue;
                }
              FullMatrix<double> UJ(missing.size(), part->U.n()),
                Z(missing.size(), m);
              for (unsigned int r = 0; r < missing.size(); ++r)
                std::copy(&part->U(missing[r], 0),
                          &part->U(missing[r], 0) + part->U.n(),
                          &UJ(r, 0));
              UJ.mTmult(Z, part->U);
              for (unsigned int r = 0; r < missing.size(); ++r)
                {
                  double       *w = &cache(missing[r], 0);
                  const double *z = &Z(r, 0);
                  for (unsigned int i = 0; i < m; ++i)
                    w[i] += a * z[i];
                }
            }
      for (const unsigned int j : missing)
        {
          computed[j] = true;
          list.push_back(j);
        }
    }

    double
    operator()(const unsigned int i, const unsigned int j) const override
    {
      Assert(computed[j], ExcMessage("prepare() the column first."));
      return cache(j, i);
    }

    const double *
    column(const unsigned int j) override
    {
      AssertIndexRange(j, m);
      double *w = &cache(j, 0);
      if (!computed[j])
        {
          std::fill(w, w + m, 0.);
          for (unsigned int c = 0; c < model.variable.size(); ++c)
            for (const Part *part : {&model.variable[c], &model.fixed[c]})
              if (part->present)
                part->add_column(j, 1. / model.scales[c], w);
          computed[j] = true;
          list.push_back(j);
        }
      return w;
    }

    // The columns are side by side in the cache (column j at row j): a
    // run of consecutive columns is one matrix-vector product (BLAS).
    void
    add_columns(const std::vector<unsigned int> &columns,
                const Vector<double>            &p,
                Vector<double>                  &g) override
    {
      AssertDimension(g.size(), m);
      prepare(columns);
      const types::blas_int ld = m, one = 1;
      const double          alpha = 1;
      for (std::size_t r = 0; r < columns.size();)
        {
          std::size_t e = r + 1;
          while (e < columns.size() && columns[e] == columns[e - 1] + 1)
            ++e;
          const types::blas_int n = e - r;
          gemv("N",
               &ld,
               &n,
               &alpha,
               &cache(columns[r], 0),
               &ld,
               p.data() + columns[r],
               &one,
               &alpha,
               g.data(),
               &one);
          r = e;
        }
    }

    double
    diagonal(const unsigned int i) override
    {
      return diagonal_[i];
    }

    // Forgets the columns and combines the diagonal afresh; the state is
    // @p previous (W back to a value it had then) or a new one.
    void
    reset(const unsigned long previous = 0)
    {
      if (previous > 0)
        restored(previous);
      else
        changed();
      for (const unsigned int j : list)
        computed[j] = false;
      list.clear();
      diagonal_ = 0;
      for (unsigned int c = 0; c < model.variable.size(); ++c)
        for (const Part *part : {&model.variable[c], &model.fixed[c]})
          if (part->present)
            diagonal_.add(1. / model.scales[c], part->diagonal);
    }

  private:
    const ReducedContactModel &model;
    const unsigned int         m;
    FullMatrix<double>         cache; // row j: column j of W
    std::vector<bool>          computed;
    std::vector<unsigned int>  list;
    Vector<double>             diagonal_;
  };
} // namespace FuzzyContact

#endif
