// LAPACK routines the project calls that deal.II does not wrap: declared
// once here for every file that calls them.

#ifndef fuzzycontact_base_lapack_extras_h
#define fuzzycontact_base_lapack_extras_h

#include <deal.II/lac/lapack_support.h>

extern "C"
{
  // Hager and Higham's estimate of a matrix's 1-norm by reverse
  // communication (the core of LAPACK's condition estimates): called until
  // *kase == 0, each call asks for x := A x (kase 1) or A^T x (kase 2).
  void
  dlacn2_(const dealii::types::blas_int *n,
          double                        *v,
          double                        *x,
          dealii::types::blas_int       *isgn,
          double                        *est,
          dealii::types::blas_int       *kase,
          dealii::types::blas_int       *isave);

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
