#include <softopt/base/blas_kernels.h>

#include <dlfcn.h>
#include <strings.h>
#include <unistd.h>

#include <cstdlib>

namespace softopt
{
  namespace
  {
    /** The OpenBLAS kernels for this CPU's vector instructions, or nullptr
     * where Prescott's are the best it has. */
    const char *
    kernels_for_this_cpu()
    {
      __builtin_cpu_init();
      // OpenBLAS's SKYLAKEX kernels use these five AVX-512 subsets.
      if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512cd") &&
          __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512dq") &&
          __builtin_cpu_supports("avx512vl"))
        return "SkylakeX";
      if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
        return "Haswell";
      return nullptr;
    }
  } // namespace



  void
  use_the_cpus_blas_kernels(char **argv)
  {
    if (std::getenv("OPENBLAS_CORETYPE") != nullptr)
      return; // the user's choice, or this is the new start
    // Looked up, not linked: the BLAS may be another library.
    using CoreName       = char *(*)();
    const auto core_name = reinterpret_cast<CoreName>(dlsym(RTLD_DEFAULT, "openblas_get_corename"));
    if (core_name == nullptr)
      return;
    const char *core = core_name();
    if (core == nullptr || strcasecmp(core, "prescott") != 0)
      return;
    const char *kernels = kernels_for_this_cpu();
    if (kernels == nullptr)
      return;
    setenv("OPENBLAS_CORETYPE", kernels, 1);
    execv("/proc/self/exe", argv);
    unsetenv("OPENBLAS_CORETYPE"); // not started again: go on as before
  }
} // namespace softopt
