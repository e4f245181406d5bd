// LAPACK routines the project calls that deal.II does not wrap: declared
// once here for every file that calls them.

#ifndef fuzzycontact_base_lapack_extras_h
#define fuzzycontact_base_lapack_extras_h

#include <deal.II/lac/lapack_support.h>

extern "C"
{
  // The condition estimate of an LU factorisation.
  void
  dgecon_(const char                    *norm,
          const dealii::types::blas_int *n,
          const double                  *a,
          const dealii::types::blas_int *lda,
          const double                  *anorm,
          double                        *rcond,
          double                        *work,
          dealii::types::blas_int       *iwork,
          dealii::types::blas_int       *info);

  // The pivoted Cholesky factorisation.
  void
  dpstrf_(const char                    *uplo,
          const dealii::types::blas_int *n,
          double                        *a,
          const dealii::types::blas_int *lda,
          dealii::types::blas_int       *piv,
          dealii::types::blas_int       *rank,
          const double                  *tol,
          double                        *work,
          dealii::types::blas_int       *info);
}

#endif
