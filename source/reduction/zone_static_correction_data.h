// The internals of ZoneStaticCorrection (zone_static_correction.h), shared
// by its files, and not a public header: zone_static_correction.cc (the
// dense algebra, and the constructor: the Krylov levels),
// zone_static_correction_basis.cc (the basis: blocks K0-orthogonalised,
// compressed and projected, snapshots) and zone_static_correction_split.cc
// (the active and inert parts: their matrices at a state and their errors
// against exact factorisations).

#ifndef fuzzycontact_reduction_zone_static_correction_data_h
#define fuzzycontact_reduction_zone_static_correction_data_h

#include <fuzzycontact/base/sparse_cholesky.h>
#include <fuzzycontact/reduction/zone_static_correction.h>

#include <deal.II/base/timer.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/vector.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace FuzzyContact
{
  // The dense algebra of these files (zone_static_correction.cc).
  namespace ZoneCorrectionAlgebra
  {
    // Blocks of full-length vectors are stored column-major (column j from
    // data[j * n]), as BLAS and CHOLMOD's multi-column solve read them.
    // FullMatrix is row-major: its data is the column-major transpose.
    using Block = std::vector<double>;

    // M X for a sparse M and a column-major block X with b columns; and
    // X := M X in place (a vector's worth of memory more, not a block's).
    Block
    sparse_product(const SparseMatrix<double> &M,
                   const Block                &X,
                   const unsigned int          b);
    void
    sparse_product_in_place(const SparseMatrix<double> &M,
                            Block                      &X,
                            const unsigned int          b);

    // Blocks of full-length vectors are worked on this many columns at a
    // time where a product with a sparse matrix or Psi would otherwise
    // make a second block of all the columns: on a large mesh one block is
    // gigabytes (966 columns of 371,522 DoFs: 2.9 GB).
    constexpr unsigned int chunk_columns = 64;

    // A := (A + A^T) / 2 for a square A.
    void
    symmetrise(FullMatrix<double> &A);

    // Eigenpairs of the symmetric row-major G, ascending.
    std::pair<std::vector<double>, FullMatrix<double>>
    eigen(const FullMatrix<double> &G);

    // L with A = L L^T; A := A L^{-T}.
    FullMatrix<double>
    cholesky(const FullMatrix<double> &A, const std::string &what);
    void
    right_solve(const FullMatrix<double> &L, FullMatrix<double> &A);

    // The columns [first, first + count) of A; A B, A^T B and A^T v.
    FullMatrix<double>
    columns(const FullMatrix<double> &A,
            const unsigned int        first,
            const unsigned int        count);
    FullMatrix<double>
    product(const FullMatrix<double> &A, const FullMatrix<double> &B);
    FullMatrix<double>
    transpose_product(const FullMatrix<double> &A, const FullMatrix<double> &B);
    Vector<double>
    transpose_product(const FullMatrix<double> &A, const Vector<double> &v);
  } // namespace ZoneCorrectionAlgebra
  using namespace ZoneCorrectionAlgebra;


  struct ZoneStaticCorrection::Data
  {
    Data(const Component &component, const std::vector<std::string> &names)
        : component(component)
        , model(component, names)
    {
    }

    const Component                        &component;
    ParameterModel                          model;
    std::shared_ptr<const ReducedComponent> psi;
    std::shared_ptr<const SparseCholesky>   factor;
    const SparseMatrix<double>             *C = nullptr;
    std::vector<types::global_dof_index>    observed, attachment, B;
    ZoneCorrectionSettings                  settings;
    types::blas_int                         n   = 0;
    unsigned int                            n_s = 0;
    // Psi = K0^{-1} F, F zero outside B, F_B (|B| x n_s).
    FullMatrix<double> F_B;

    // The explicit vectors Z (column-major n x r), K0-orthonormal and
    // K0-orthogonal to Psi.
    Block        Z;
    unsigned int r = 0;
    // V^T K_k V per parameter (k = n_s + r), C V, O V and V^T f (per load;
    // per zone for a prescribed displacement).
    std::vector<FullMatrix<double>>          A;
    FullMatrix<double>                       CV, OV;
    std::vector<std::vector<Vector<double>>> Vf;
    mutable std::vector<bool>                per_zone;
    // C Psi Psi^T C^T: the contact flexibility at the nominal point (C Z
    // vanishes), formed once.
    FullMatrix<double> W0;

    // The split (see the header): Q = [Q_a, Q_c] orthogonal (k x k, Q_a
    // its first n_active columns, diagonalising the one parameter's
    // projection), the active projections, and the blocks of both parts.
    unsigned int                             n_active = 0;
    FullMatrix<double>                       Q;
    std::vector<FullMatrix<double>>          A_active;
    std::vector<double>                      lambda;
    bool                                     diagonal = false;
    FullMatrix<double>                       H_a, O_a, H_c, O_c;
    std::vector<std::vector<Vector<double>>> f_a, f_c;

    // The corners of the box (relative changes), the largest |t|, and
    // their exact contact flexibilities and load gaps (made once).
    std::vector<std::vector<double>>         corners;
    double                                   t_max = 0;
    std::vector<FullMatrix<double>>          exact_W;
    std::vector<std::vector<Vector<double>>> exact_g;

    ZoneCorrectionCheck check;

    unsigned int
    k() const
    {
      return n_s + r;
    }

    // The loads' vectors at their reference forces: the load of each
    // component load l, one per zone for a prescribed displacement.
    std::vector<std::vector<Vector<double>>>
    load_vectors() const;

    // sum_z a_z f[z], a_z the zone modulus for a prescribed displacement
    // (load l), else 1.
    Vector<double>
    combine(const unsigned int                 l,
            const std::vector<Vector<double>> &f,
            const std::vector<double>         &moduli,
            const unsigned int                 size) const
    {
      Vector<double> v(size);
      for (unsigned int z = 0; z < f.size(); ++z)
        v.add(per_zone[l] ? moduli[z] : 1., f[z]);
      return v;
    }

    // X := K0^{-1} X (b columns), counted.
    void
    solve(Block &X, const unsigned int b)
    {
      factor->solve(X.data(), b);
      check.back_substitutions += b;
    }

    // Psi c for a row-major c (n_s x b): one back-substitution a column.
    Block
    psi_times(const FullMatrix<double> &c)
    {
      const unsigned int b = c.n();
      Block              X(std::size_t(n) * b, 0.);
      if (b == 0)
        return X;
      const FullMatrix<double> Fc = product(F_B, c); // |B| x b
      for (unsigned int j = 0; j < b; ++j)
        for (unsigned int i = 0; i < B.size(); ++i)
          X[std::size_t(j) * n + B[i]] = Fc(i, j);
      solve(X, b);
      return X;
    }

    // X -= Psi c (X with b columns, c row-major n_s x b), Psi c made
    // chunk_columns columns at a time.
    void
    subtract_psi_times(Block                    &X,
                       const unsigned int        b,
                       const FullMatrix<double> &c)
    {
      AssertDimension(c.n(), b);
      for (unsigned int first = 0; first < b; first += chunk_columns)
        {
          const unsigned int m = std::min(chunk_columns, b - first);
          const Block        P = psi_times(columns(c, first, m));
          double            *x = X.data() + std::size_t(first) * n;
          for (std::size_t i = 0; i < P.size(); ++i)
            x[i] -= P[i];
        }
    }

    // A^T K0 X (row-major a x b) for column-major blocks A (a columns) and
    // X (b columns), K0 X made chunk_columns columns at a time.
    FullMatrix<double>
    energy_products(const double      *A,
                    const unsigned int a,
                    const Block       &X,
                    const unsigned int b) const;

    // Psi^T K0 X = F_B^T X_B (no back-substitution): n_s x b.
    FullMatrix<double>
    psi_products(const Block &X, const unsigned int b) const
    {
      FullMatrix<double> XB(B.size(), b);
      for (unsigned int j = 0; j < b; ++j)
        for (unsigned int i = 0; i < B.size(); ++i)
          XB(i, j) = X[std::size_t(j) * n + B[i]];
      return transpose_product(F_B, XB);
    }

    // The candidates X (b columns) made K0-orthogonal to Psi and Z (twice)
    // and compressed: the directions of what is left whose K0-norm is at
    // least @p threshold are appended to Z (K0-orthonormal), and returned.
    Block
    add_block(Block X, const unsigned int b, const double threshold);

    // The projections of the new columns [first, r) of Z: V^T K_k z (with
    // Y_k = K0^{-1} K_k Z_new, returned: the next level's candidates), C z,
    // O z, z^T f.
    std::vector<Block>
    extend(const unsigned int first);

    // The split into active and inert parts, and their blocks.
    void
    split();

    // The reduced contact flexibility at t (the split's form), and its
    // relative errors against @p W and @p g (exact there).
    std::pair<double, double>
    errors(const std::vector<double>         &t,
           const FullMatrix<double>          &W,
           const std::vector<Vector<double>> &g) const;

    // The largest errors over the corners, into check.
    void
    measure(TimerOutput *timer);

    // The exact contact flexibility and load gaps at t (a factorisation).
    std::pair<FullMatrix<double>, std::vector<Vector<double>>>
    exact(const std::vector<double> &t) const;
  };
} // namespace FuzzyContact

#endif
