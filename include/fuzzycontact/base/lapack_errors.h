// LAPACK's and BLAS's error handler, replaced.
//
// When a LAPACK or BLAS routine is called with an illegal argument, it calls
// XERBLA, whose reference version prints "On entry to DLASCL parameter
// number 4 had an illegal value" and ends the program with exit status 0
// (the library's STOP). That happens, for instance, inside ARPACK when a
// matrix entry has overflowed. This file defines xerbla_ for the
// executables of FuzzyContact instead: it records the error, and the
// routine returns to its caller with its error code (LAPACK routines return
// right after calling XERBLA).
//
// Recording, not throwing: an exception from xerbla_ would have to unwind
// through Fortran (ARPACK, LAPACK) and C (UMFPACK) frames that were not
// compiled for it. The caller of a LAPACK-based computation checks after it
// returns (LapackErrors::check); every program checks before it writes
// output (OutputFiles) and when it ends (run_program), so that a result
// computed after such an error is never written and never ends with exit
// status 0.
//
// The shared LAPACK refers to xerbla_, so the linker exports the
// executable's definition (`nm -D build/step-3` lists `T xerbla_`), and the
// installed LAPACK calls it through its procedure linkage table instead of
// its own (tests/hardening.cc checks it with a real LAPACK call, in a child
// process).

#ifndef fuzzycontact_base_lapack_errors_h
#define fuzzycontact_base_lapack_errors_h

#include <string>

namespace FuzzyContact
{
  namespace LapackErrors
  {
    /**
     * Makes sure this file's xerbla_ is linked into the executable (a
     * static library only contributes the objects something refers to).
     * run_program() calls it.
     */
    void
    install();

    /** True if a LAPACK or BLAS routine reported an illegal argument. */
    bool
    pending();

    /**
     * The recorded errors as one sentence ("LAPACK routine DLASCL was called
     * with an illegal value of its argument 4"), and forgets them; empty if
     * there are none.
     */
    std::string
    take();

    /**
     * Throws an ExcMessage naming @p context, the routine and the argument
     * if an error was recorded (and forgets it); does nothing otherwise.
     */
    void
    check(const std::string &context);
  } // namespace LapackErrors
} // namespace FuzzyContact

#endif
