#pragma once

// The LAPACK and BLAS routines glissade calls, declared once (Fortran
// names, arguments by address). Linked from the system's LAPACK (OpenBLAS
// on the project machine): CMakeLists.txt, LAPACK_LIBRARIES.

extern "C" void
dgecon_(const char   *norm,
        const int    *n,
        const double *a,
        const int    *lda,
        const double *anorm,
        double       *rcond,
        double       *work,
        int          *iwork,
        int          *info);

extern "C" void
dgemm_(const char   *transa,
       const char   *transb,
       const int    *m,
       const int    *n,
       const int    *k,
       const double *alpha,
       const double *a,
       const int    *lda,
       const double *b,
       const int    *ldb,
       const double *beta,
       double       *c,
       const int    *ldc);

extern "C" void
dgemv_(const char   *trans,
       const int    *m,
       const int    *n,
       const double *alpha,
       const double *a,
       const int    *lda,
       const double *x,
       const int    *incx,
       const double *beta,
       double       *y,
       const int    *incy);

extern "C" void
dgelsy_(const int    *m,
        const int    *n,
        const int    *nrhs,
        double       *a,
        const int    *lda,
        double       *b,
        const int    *ldb,
        int          *jpvt,
        const double *rcond,
        int          *rank,
        double       *work,
        const int    *lwork,
        int          *info);

extern "C" void
dgetrf_(const int *m,
        const int *n,
        double    *a,
        const int *lda,
        int       *ipiv,
        int       *info);

extern "C" void
dgetrs_(const char   *trans,
        const int    *n,
        const int    *nrhs,
        const double *a,
        const int    *lda,
        const int    *ipiv,
        double       *b,
        const int    *ldb,
        int          *info);

extern "C" double
dlange_(const char   *norm,
        const int    *m,
        const int    *n,
        const double *a,
        const int    *lda,
        double       *work);

extern "C" void
dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);

extern "C" void
dpotri_(const char *uplo, const int *n, double *a, const int *lda, int *info);

extern "C" void
dpotrs_(const char   *uplo,
        const int    *n,
        const int    *nrhs,
        const double *a,
        const int    *lda,
        double       *b,
        const int    *ldb,
        int          *info);

extern "C" void
dsyev_(const char *jobz,
       const char *uplo,
       const int  *n,
       double     *a,
       const int  *lda,
       double     *w,
       double     *work,
       const int  *lwork,
       int        *info);
