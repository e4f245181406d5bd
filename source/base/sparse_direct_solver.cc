#include <fuzzycontact/base/sparse_direct_solver.h>

#include <deal.II/base/exceptions.h>

#include <algorithm>
#include <string>
#include <umfpack.h>
#include <utility>

namespace FuzzyContact
{
  SparseDirectSolver::~SparseDirectSolver()
  {
    clear();
  }


  void
  SparseDirectSolver::clear()
  {
    if (numeric != nullptr)
      umfpack_dl_free_numeric(&numeric);
    numeric = nullptr;
    analysis_.reset();
    row_starts.clear();
    columns.clear();
    values.clear();
  }


  void
  SparseDirectSolver::copy_rows(const SparseMatrix<double> &A)
  {
    AssertThrow(A.m() == A.n(),
                ExcMessage("SparseDirectSolver: the matrix must be square."));
    clear();
    const long n = A.m();
    row_starts.assign(1, 0);
    std::vector<std::pair<long, double>> row;
    for (long i = 0; i < n; ++i)
      {
        row.clear();
        for (auto it = A.begin(i); it != A.end(i); ++it)
          row.emplace_back(it->column(), it->value());
        // deal.II stores the diagonal first; UMFPACK wants sorted indices.
        std::sort(row.begin(), row.end());
        for (const auto &[j, value] : row)
          {
            columns.push_back(j);
            values.push_back(value);
          }
        row_starts.push_back(columns.size());
      }
    control.resize(UMFPACK_CONTROL);
    umfpack_dl_defaults(control.data());
    control[UMFPACK_IRSTEP] = 0; // no iterative refinement in solve()
  }


  void
  SparseDirectSolver::factorize(const SparseMatrix<double> &A)
  {
    factorize(A, nullptr);
  }


  void
  SparseDirectSolver::factorize(const SparseMatrix<double>            &A,
                                const std::shared_ptr<const Analysis> &analysis)
  {
    copy_rows(A);
    if (analysis != nullptr && analysis->row_starts == row_starts &&
        analysis->columns == columns)
      analysis_ = analysis;
    else
      {
        const long          n = A.m();
        std::vector<double> info(UMFPACK_INFO);
        void               *symbolic = nullptr;
        const long          status   = umfpack_dl_symbolic(n,
                                                n,
                                                row_starts.data(),
                                                columns.data(),
                                                values.data(),
                                                &symbolic,
                                                control.data(),
                                                info.data());
        AssertThrow(status == UMFPACK_OK,
                    ExcMessage("UMFPACK's symbolic factorisation failed with "
                               "status " +
                               std::to_string(status) + "."));
        auto made = std::make_shared<Analysis>();
        made->symbolic.reset(symbolic, [](void *p) {
          umfpack_dl_free_symbolic(&p);
        });
        made->row_starts = row_starts;
        made->columns    = columns;
        analysis_        = std::move(made);
      }
    factorize_numeric();
  }


  std::shared_ptr<const SparseDirectSolver::Analysis>
  SparseDirectSolver::analysis() const
  {
    return analysis_;
  }


  void
  SparseDirectSolver::factorize_numeric()
  {
    std::vector<double> info(UMFPACK_INFO);
    const long          status = umfpack_dl_numeric(row_starts.data(),
                                           columns.data(),
                                           values.data(),
                                           analysis_->symbolic.get(),
                                           &numeric,
                                           control.data(),
                                           info.data());
    AssertThrow(status == UMFPACK_OK,
                ExcMessage("UMFPACK's numeric factorisation failed with "
                           "status " +
                           std::to_string(status) +
                           (status == UMFPACK_WARNING_singular_matrix
                              ? " (the matrix is singular)."
                              : ".")));
  }


  void
  SparseDirectSolver::solve(Vector<double> &b) const
  {
    Assert(numeric != nullptr, ExcMessage("factorize() first."));
    AssertDimension(b.size(), n());
    Vector<double>      x(b.size());
    std::vector<double> info(UMFPACK_INFO);
    const long          status = umfpack_dl_solve(UMFPACK_At,
                                         row_starts.data(),
                                         columns.data(),
                                         values.data(),
                                         x.data(),
                                         b.data(),
                                         numeric,
                                         control.data(),
                                         info.data());
    AssertThrow(status == UMFPACK_OK,
                ExcMessage("UMFPACK's solve failed with status " +
                           std::to_string(status) + "."));
    b.swap(x);
  }


  void
  SparseDirectSolver::vmult(Vector<double>       &dst,
                            const Vector<double> &src) const
  {
    dst = src;
    solve(dst);
  }


  types::global_dof_index
  SparseDirectSolver::n() const
  {
    return row_starts.empty() ? 0 : row_starts.size() - 1;
  }
} // namespace FuzzyContact
