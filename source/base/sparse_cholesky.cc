#include <fuzzycontact/base/sparse_cholesky.h>

#include <deal.II/base/exceptions.h>
#include <deal.II/lac/lapack_templates.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <list>
#include <mutex>
#include <suitesparse/cholmod.h>
#include <type_traits>

namespace FuzzyContact
{
  using Index = SuiteSparse_long;

  struct SparseCholesky::Data
  {
    cholmod_common  common;
    cholmod_factor *factor = nullptr;
    // Workspace of cholmod_l_solve2, kept between solves.
    mutable cholmod_dense *x = nullptr, *y = nullptr, *e = nullptr;

    Data()
    {
      cholmod_l_start(&common);
      // Errors are reported through the return values and Common->status,
      // in our messages; CHOLMOD itself stays quiet.
      common.print = 0;
    }

    ~Data()
    {
      cholmod_l_free_dense(&x, &common);
      cholmod_l_free_dense(&y, &common);
      cholmod_l_free_dense(&e, &common);
      cholmod_l_free_factor(&factor, &common);
      cholmod_l_finish(&common);
    }
  };


  SparseCholesky::SparseCholesky()
      : data(std::make_unique<Data>())
  {
  }


  SparseCholesky::~SparseCholesky() = default;


  namespace
  {
    // The lower triangle of the symmetric @p A in CHOLMOD's compressed
    // columns: column j of it is the part of row j of A (compressed rows) on
    // and below the diagonal, sorted.
    struct LowerTriangle
    {
      std::vector<Index>  column_starts, rows;
      std::vector<double> values;
      cholmod_sparse      matrix;

      explicit LowerTriangle(const SparseMatrix<double> &A)
      {
        const Index n = A.m();
        column_starts.assign(1, 0);
        std::vector<std::pair<Index, double>> column;
        for (Index j = 0; j < n; ++j)
          {
            column.clear();
            for (auto it = A.begin(j); it != A.end(j); ++it)
              if (static_cast<Index>(it->column()) >= j)
                column.emplace_back(it->column(), it->value());
            std::sort(column.begin(), column.end());
            for (const auto &[i, value] : column)
              {
                rows.push_back(i);
                values.push_back(value);
              }
            column_starts.push_back(rows.size());
          }
        matrix        = cholmod_sparse();
        matrix.nrow   = n;
        matrix.ncol   = n;
        matrix.nzmax  = rows.size();
        matrix.p      = column_starts.data();
        matrix.i      = rows.data();
        matrix.stype  = -1;
        matrix.itype  = CHOLMOD_LONG;
        matrix.xtype  = CHOLMOD_REAL;
        matrix.dtype  = CHOLMOD_DOUBLE;
        matrix.sorted = 1;
        matrix.packed = 1;
        matrix.x      = values.data();
      }
    };

    // The symbolic analyses (CAMD ordering and supernodal structure) of the
    // last patterns factorised, each with the pattern of the lower triangle
    // and the DoFs ordered last that it was made for: a matrix of the same
    // pattern and the same DoFs last gets the same analysis (CAMD and
    // CHOLMOD's analysis are deterministic), so it is copied, not redone.
    // A component refactorised at new zone moduli (the exact solves of a
    // zone study) pays the numeric factorisation only.
    struct SymbolicAnalysis
    {
      std::vector<Index>        column_starts;
      std::vector<unsigned int> rows;
      std::vector<Index>        last; // member[] of the DoFs ordered last
      double                    lnz = 0, fl = 0;
      cholmod_factor           *symbolic = nullptr;
      cholmod_common            common;

      SymbolicAnalysis()
      {
        cholmod_l_start(&common);
        common.print = 0;
      }
      ~SymbolicAnalysis()
      {
        cholmod_l_free_factor(&symbolic, &common);
        cholmod_l_finish(&common);
      }

      bool
      matches(const LowerTriangle      &lower,
              const std::vector<Index> &member) const
      {
        return column_starts == lower.column_starts && last == member &&
               std::equal(rows.begin(),
                          rows.end(),
                          lower.rows.begin(),
                          lower.rows.end());
      }
    };

    // At most two (two bodies refactorised in turn), most recent first.
    constexpr unsigned int                       max_analyses = 2;
    std::mutex                                   analyses_mutex;
    std::list<std::shared_ptr<SymbolicAnalysis>> analyses;
    std::atomic<unsigned long>                   n_shared{0};
  } // namespace


  unsigned long
  SparseCholesky::n_shared_analyses()
  {
    return n_shared;
  }


  void
  SparseCholesky::factorize(const SparseMatrix<double>                 &A,
                            const std::vector<types::global_dof_index> &last,
                            const std::string                          &what)
  {
    AssertThrow(A.m() == A.n() && A.m() > 0,
                ExcMessage(what + " to factorise must be square and not "
                                  "empty."));
    data = std::make_unique<Data>();
    trailing.clear();
    cholmod_common &common = data->common;
    const Index     n      = A.m();
    LowerTriangle   lower(A);

    // The ordering: CAMD with the DoFs of @p last in a second constraint
    // set (ordered after the first), used as given: no postordering, which
    // could move them.
    std::vector<Index> member(n, 0), permutation(n);
    for (const types::global_dof_index dof : last)
      {
        AssertThrow(dof < A.m(),
                    ExcMessage(what +
                               ": a DoF to order last is out of range."));
        member[dof] = 1;
      }
    const Index m = std::count(member.begin(), member.end(), 1);
    {
      std::lock_guard<std::mutex> lock(analyses_mutex);
      for (auto it = analyses.begin(); it != analyses.end(); ++it)
        if ((*it)->matches(lower, member))
          {
            data->factor = cholmod_l_copy_factor((*it)->symbolic, &common);
            AssertThrow(data->factor != nullptr,
                        ExcMessage(what +
                                   " could not be analysed: "
                                   "CHOLMOD failed with status " +
                                   std::to_string(common.status) + "."));
            common.lnz = (*it)->lnz;
            common.fl  = (*it)->fl;
            analyses.splice(analyses.begin(), analyses, it);
            ++n_shared;
            break;
          }
    }
    if (data->factor == nullptr)
      {
        AssertThrow(cholmod_l_camd(&lower.matrix,
                                   nullptr,
                                   0,
                                   member.data(),
                                   permutation.data(),
                                   &common) == 1,
                    ExcMessage(what +
                               " could not be ordered: CHOLMOD's CAMD failed "
                               "with status " +
                               std::to_string(common.status) + "."));
        common.nmethods           = 1;
        common.method[0].ordering = CHOLMOD_GIVEN;
        common.postorder          = 0;
        common.supernodal         = CHOLMOD_SUPERNODAL;
        data->factor              = cholmod_l_analyze_p(&lower.matrix,
                                           permutation.data(),
                                           nullptr,
                                           0,
                                           &common);
        AssertThrow(data->factor != nullptr,
                    ExcMessage(what +
                               " could not be analysed: CHOLMOD failed with "
                               "status " +
                               std::to_string(common.status) +
                               (common.status == CHOLMOD_OUT_OF_MEMORY
                                  ? " (out of memory)."
                                  : ".")));
        auto analysis           = std::make_shared<SymbolicAnalysis>();
        analysis->column_starts = lower.column_starts;
        analysis->rows.assign(lower.rows.begin(), lower.rows.end());
        analysis->last = member;
        analysis->lnz  = common.lnz;
        analysis->fl   = common.fl;
        analysis->symbolic =
          cholmod_l_copy_factor(data->factor, &analysis->common);
        if (analysis->symbolic != nullptr)
          {
            std::lock_guard<std::mutex> lock(analyses_mutex);
            analyses.push_front(std::move(analysis));
            if (analyses.size() > max_analyses)
              analyses.pop_back();
          }
      }
    cholmod_l_factorize(&lower.matrix, data->factor, &common);
    const Index *perm = static_cast<const Index *>(data->factor->Perm);
    if (common.status == CHOLMOD_NOT_POSDEF)
      {
        const Index pivot = data->factor->minor;
        AssertThrow(false,
                    ExcMessage(
                      what + " is not positive definite (pivot " +
                      std::to_string(pivot) + " of " + std::to_string(n) +
                      ", DoF " + std::to_string(pivot < n ? perm[pivot] : -1) +
                      "). Either a rigid-body motion is not suppressed by the "
                      "supports, or a material value is not positive."));
      }
    AssertThrow(common.status == CHOLMOD_OK,
                ExcMessage(what +
                           " could not be factorised: CHOLMOD failed "
                           "with status " +
                           std::to_string(common.status) +
                           (common.status == CHOLMOD_OUT_OF_MEMORY
                              ? " (out of memory)."
                              : ".")));
    Assert(data->factor->is_super && data->factor->is_ll,
           ExcMessage("A supernodal LL^T factor was asked for."));

    for (Index k = n - m; k < n; ++k)
      {
        Assert(member[perm[k]] == 1,
               ExcMessage("CHOLMOD did not keep the given ordering."));
        trailing.push_back(perm[k]);
      }
  }


  types::global_dof_index
  SparseCholesky::n() const
  {
    return data->factor == nullptr ? 0 : data->factor->n;
  }


  void
  SparseCholesky::solve(Vector<double> &b) const
  {
    AssertDimension(b.size(), n());
    solve(b.data(), 1);
  }


  void
  SparseCholesky::solve(double *columns, const unsigned int n_columns) const
  {
    Assert(data->factor != nullptr, ExcMessage("factorize() first."));
    if (n_columns == 0)
      return;
    const std::size_t n = this->n();
    // At most so many columns per call: CHOLMOD's workspace, kept between
    // solves, holds as many vectors as the call has columns (a block of
    // 966 columns on 371,522 DoFs kept 2.9 GB after its solve), and blocks
    // of this many columns keep its substitutions in BLAS 3.
    constexpr unsigned int max_columns = 64;
    for (unsigned int first = 0; first < n_columns; first += max_columns)
      {
        const unsigned int m   = std::min(max_columns, n_columns - first);
        double            *b   = columns + n * first;
        cholmod_dense      rhs = cholmod_dense();
        rhs.nrow               = n;
        rhs.ncol               = m;
        rhs.nzmax              = n * m;
        rhs.d                  = n;
        rhs.x                  = b;
        rhs.xtype              = CHOLMOD_REAL;
        rhs.dtype              = CHOLMOD_DOUBLE;
        const int ok           = cholmod_l_solve2(CHOLMOD_A,
                                        data->factor,
                                        &rhs,
                                        nullptr,
                                        &data->x,
                                        nullptr,
                                        &data->y,
                                        &data->e,
                                        &data->common);
        AssertThrow(ok == 1,
                    ExcMessage("CHOLMOD's solve failed with status " +
                               std::to_string(data->common.status) + "."));
        const double *x = static_cast<const double *>(data->x->x);
        std::copy(x, x + n * m, b);
      }
  }


  void
  SparseCholesky::vmult(Vector<double> &dst, const Vector<double> &src) const
  {
    dst = src;
    solve(dst);
  }


  const std::vector<types::global_dof_index> &
  SparseCholesky::trailing_dofs() const
  {
    return trailing;
  }


  FullMatrix<double>
  SparseCholesky::trailing_factor() const
  {
    Assert(data->factor != nullptr, ExcMessage("factorize() first."));
    const cholmod_factor &L     = *data->factor;
    const Index           n     = L.n;
    const Index           m     = trailing.size();
    const Index           first = n - m;
    const Index          *super = static_cast<const Index *>(L.super);
    const Index          *pi    = static_cast<const Index *>(L.pi);
    const Index          *px    = static_cast<const Index *>(L.px);
    const Index          *rows  = static_cast<const Index *>(L.s);
    const double         *x     = static_cast<const double *>(L.x);

    // Each supernode holds columns super[s] .. super[s+1]-1 as a dense
    // column-major block whose rows are rows[pi[s] .. pi[s+1]).
    FullMatrix<double> L_BB(m, m);
    for (Index s = 0; s < static_cast<Index>(L.nsuper); ++s)
      {
        const Index k1 = super[s], k2 = super[s + 1];
        if (k2 <= first)
          continue;
        const Index n_rows = pi[s + 1] - pi[s];
        for (Index j = std::max(k1, first); j < k2; ++j)
          for (Index r = j - k1; r < n_rows; ++r)
            {
              const Index i = rows[pi[s] + r];
              if (i >= first)
                L_BB(i - first, j - first) = x[px[s] + (j - k1) * n_rows + r];
            }
      }
    return L_BB;
  }


  FullMatrix<double>
  SparseCholesky::trailing_inverse() const
  {
    // LAPACK's dpotri on L_BB. FullMatrix is row-major: its data is L_BB^T
    // in column-major order, an upper triangle.
    FullMatrix<double>    G = trailing_factor();
    const types::blas_int m = G.m();
    if (m == 0)
      return G;
    types::blas_int info = 0;
    potri("U", &m, &G(0, 0), &m, &info);
    AssertThrow(info == 0,
                ExcMessage("LAPACK's dpotri failed on the Schur complement "
                           "(info " +
                           std::to_string(info) + ")."));
    // dpotri wrote the upper triangle in column-major order, the lower one
    // of the row-major G.
    for (types::blas_int i = 0; i < m; ++i)
      for (types::blas_int j = i + 1; j < m; ++j)
        G(i, j) = G(j, i);
    return G;
  }


  namespace
  {
    // Starts the broadcast of @p n entries of @p data from @p root (in
    // pieces that an int counts), adding its requests to @p requests.
    template <typename T>
    void
    start_broadcast(T                        *data,
                    const std::size_t         n,
                    const unsigned int        root,
                    const MPI_Comm            comm,
                    std::vector<MPI_Request> &requests)
    {
      static_assert(std::is_same<T, double>::value || sizeof(T) == 8,
                    "64-bit integers or doubles");
      const MPI_Datatype type =
        std::is_same<T, double>::value ? MPI_DOUBLE : MPI_INT64_T;
      constexpr std::size_t piece = std::size_t(1) << 30;
      for (std::size_t begin = 0; begin < n; begin += piece)
        {
          requests.emplace_back();
          const int ierr =
            MPI_Ibcast(data + begin,
                       static_cast<int>(std::min(piece, n - begin)),
                       type,
                       root,
                       comm,
                       &requests.back());
          AssertThrowMPI(ierr);
        }
    }
  } // namespace


  std::vector<std::shared_ptr<const SparseCholesky>>
  SparseCholesky::broadcast(
    const std::vector<std::shared_ptr<const SparseCholesky>> &factorisations,
    const std::vector<unsigned int>                          &roots,
    const MPI_Comm                                            comm)
  {
    AssertDimension(factorisations.size(), roots.size());
    const unsigned int rank = Utilities::MPI::this_mpi_process(comm);
    const std::size_t  n_f  = roots.size();
    // The sizes and flags of every factor (supernodal LL^T, factorize()).
    std::vector<std::vector<Index>> headers(n_f, std::vector<Index>(12));
    for (std::size_t f = 0; f < n_f; ++f)
      if (rank == roots[f])
        {
          const auto &F = factorisations[f];
          AssertThrow(F != nullptr && F->data->factor != nullptr,
                      ExcMessage("SparseCholesky::broadcast: the root has "
                                 "no factorisation to send."));
          const cholmod_factor &L = *F->data->factor;
          Assert(L.is_super && L.is_ll && L.xtype == CHOLMOD_REAL,
                 ExcInternalError());
          headers[f] = {static_cast<Index>(L.n),
                        static_cast<Index>(L.minor),
                        static_cast<Index>(L.nsuper),
                        static_cast<Index>(L.ssize),
                        static_cast<Index>(L.xsize),
                        static_cast<Index>(L.maxcsize),
                        static_cast<Index>(L.maxesize),
                        L.ordering,
                        L.is_monotonic,
                        static_cast<Index>(F->data->common.lnz),
                        static_cast<Index>(F->trailing.size()),
                        static_cast<Index>(F->data->common.fl)};
        }
    std::vector<MPI_Request> requests;
    for (std::size_t f = 0; f < n_f; ++f)
      start_broadcast(headers[f].data(), 12, roots[f], comm, requests);
    int ierr =
      MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
    AssertThrowMPI(ierr);
    requests.clear();

    // Every factor's arrays at once: the roots send while they receive.
    std::vector<std::shared_ptr<const SparseCholesky>> result(n_f);
    std::vector<std::vector<Index>>                    trailing(n_f);
    for (std::size_t f = 0; f < n_f; ++f)
      {
        const std::vector<Index> &h = headers[f];
        const std::size_t n = h[0], nsuper = h[2], ssize = h[3], xsize = h[4];
        trailing[f].resize(h[10]);
        cholmod_factor *L;
        if (rank == roots[f])
          {
            result[f] = factorisations[f];
            L         = factorisations[f]->data->factor;
            std::copy(factorisations[f]->trailing.begin(),
                      factorisations[f]->trailing.end(),
                      trailing[f].begin());
          }
        else
          {
            // An empty factor of CHOLMOD's own allocation, made
            // supernodal LL^T with arrays of the root's sizes (freed by
            // CHOLMOD).
            auto            copy   = std::make_shared<SparseCholesky>();
            cholmod_common &common = copy->data->common;
            L                      = cholmod_l_allocate_factor(n, &common);
            AssertThrow(L != nullptr,
                        ExcMessage("CHOLMOD could not allocate a factor of " +
                                   std::to_string(n) + " rows."));
            copy->data->factor  = L;
            const auto allocate = [&](const std::size_t count,
                                      const std::size_t size) {
              void *p = cholmod_l_malloc(count, size, &common);
              AssertThrow(p != nullptr || count == 0,
                          ExcMessage("CHOLMOD could not allocate a factor "
                                     "received from another MPI rank (out "
                                     "of memory)."));
              return p;
            };
            L->super        = allocate(nsuper + 1, sizeof(Index));
            L->pi           = allocate(nsuper + 1, sizeof(Index));
            L->px           = allocate(nsuper + 1, sizeof(Index));
            L->s            = allocate(ssize, sizeof(Index));
            L->x            = allocate(xsize, sizeof(double));
            L->minor        = h[1];
            L->nsuper       = nsuper;
            L->ssize        = ssize;
            L->xsize        = xsize;
            L->maxcsize     = h[5];
            L->maxesize     = h[6];
            L->ordering     = h[7];
            L->is_monotonic = h[8];
            L->is_super     = 1;
            L->is_ll        = 1;
            L->xtype        = CHOLMOD_REAL;
            L->dtype        = CHOLMOD_DOUBLE;
            common.lnz      = h[9];
            common.fl       = h[11];
            result[f]       = copy;
          }
        const unsigned int r = roots[f];
        start_broadcast(static_cast<Index *>(L->Perm), n, r, comm, requests);
        start_broadcast(static_cast<Index *>(L->ColCount),
                        n,
                        r,
                        comm,
                        requests);
        start_broadcast(static_cast<Index *>(L->super),
                        nsuper + 1,
                        r,
                        comm,
                        requests);
        start_broadcast(static_cast<Index *>(L->pi),
                        nsuper + 1,
                        r,
                        comm,
                        requests);
        start_broadcast(static_cast<Index *>(L->px),
                        nsuper + 1,
                        r,
                        comm,
                        requests);
        start_broadcast(static_cast<Index *>(L->s), ssize, r, comm, requests);
        start_broadcast(static_cast<double *>(L->x), xsize, r, comm, requests);
        start_broadcast(trailing[f].data(),
                        trailing[f].size(),
                        r,
                        comm,
                        requests);
      }
    ierr = MPI_Waitall(requests.size(), requests.data(), MPI_STATUSES_IGNORE);
    AssertThrowMPI(ierr);
    for (std::size_t f = 0; f < n_f; ++f)
      if (rank != roots[f])
        std::const_pointer_cast<SparseCholesky>(result[f])
          ->trailing.assign(trailing[f].begin(), trailing[f].end());
    return result;
  }


  double
  SparseCholesky::n_factor_entries() const
  {
    return data->factor == nullptr ? 0. : data->common.lnz;
  }


  double
  SparseCholesky::n_factor_flops() const
  {
    return data->factor == nullptr ? 0. : data->common.fl;
  }


  std::size_t
  SparseCholesky::memory_consumption() const
  {
    if (data->factor == nullptr)
      return 0;
    const cholmod_factor &L = *data->factor;
    return L.xsize * sizeof(double) +
           (L.ssize + 2 * L.n + 3 * L.nsuper) * sizeof(Index);
  }
} // namespace FuzzyContact
