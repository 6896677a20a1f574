#ifndef softopt_base_blas_kernels_h
#define softopt_base_blas_kernels_h

namespace softopt
{
  /**
   * Debian 12's OpenBLAS (0.3.21) does not know CPUs that came after it
   * (here Intel family 6 model 207) and falls back to its Prescott
   * kernels, whose matrix products run about five times slower than the
   * AVX-512 ones: MUMPS's dense fronts, most of a factorization, with them
   * (doc/benchmarks.md, session 47). OpenBLAS reads OPENBLAS_CORETYPE only
   * when it is loaded; so if it chose Prescott on a CPU with AVX-512 or
   * AVX2 and OPENBLAS_CORETYPE is unset, the program starts itself again
   * with OPENBLAS_CORETYPE=SkylakeX or Haswell. A user who sets
   * OPENBLAS_CORETYPE chooses. Call first in main, before MPI starts;
   * returns when there is nothing to do or the new start failed.
   */
  void
  use_the_cpus_blas_kernels(char **argv);
} // namespace softopt

#endif
