// Start-up of a process: OpenBLAS's kernels for the processor it runs on.
//
// Debian 12's OpenBLAS 0.3.21 (DYNAMIC_ARCH) picks its kernels from the CPU's family and model.
// A virtual machine that names no model ("Intel(R) Xeon(R) Processor", as this project's
// development and CI machines do) is taken for a Prescott, and every BLAS call runs the generic
// SSE3 kernels although the processor has AVX2 and AVX-512 — MUMPS' factorizations and solves
// spend most of their time in dgemm. Measured 2026-12-06 on such a machine (the fast model's
// helical built-in pair, 32 positions, 2 ranks, one sitting): 29.95 s (median of 31.26, 29.95,
// 29.55; factorization 9.8 s, coefficients 17.0 s, dgemm_kernel_PRESCOTT 53 % of a profile)
// against 20.6 s with OPENBLAS_CORETYPE=SkylakeX (6.3 s, 10.8 s), every k equal.
//
// OpenBLAS reads OPENBLAS_CORETYPE when the library loads. Where it reports the Prescott fallback
// and the processor has the instructions of a later kernel set, this sets OPENBLAS_CORETYPE to it
// and has OpenBLAS choose again (its gotoblas_dynamic_quit and gotoblas_dynamic_init, which read
// the variable; the library is single-threaded, so no BLAS call is under way). Called first
// thing by the command, the test mains and the Python module, so that the command line and
// `import gearstiff` compute with the same kernels (their results are compared digit for digit).
// A value the user set is kept; another BLAS, or OpenBLAS that recognised the processor, is left
// alone.
#pragma once

#include <cstdlib>
#include <cstring>
#include <dlfcn.h>

namespace gearstiff::fem
{
inline void select_blas_kernels()
{
  if (std::getenv("OPENBLAS_CORETYPE") != nullptr)
    return;
  // The loaded OpenBLAS itself: a library Python loaded (RTLD_LOCAL) is not in the global scope.
  void* library = dlopen("libopenblas.so.0", RTLD_LAZY | RTLD_NOLOAD);
  const auto find = [library](const char* name)
  { return library != nullptr ? dlsym(library, name) : dlsym(RTLD_DEFAULT, name); };
  using CoreName = char* (*)();
  using Call = void (*)();
  const auto core_name = reinterpret_cast<CoreName>(find("openblas_get_corename"));
  const auto quit = reinterpret_cast<Call>(find("gotoblas_dynamic_quit"));
  const auto init = reinterpret_cast<Call>(find("gotoblas_dynamic_init"));
  if (library != nullptr)
    dlclose(library); // NOLOAD took a reference; the library stays loaded
  if (core_name == nullptr || quit == nullptr || init == nullptr ||
      std::strcmp(core_name(), "Prescott") != 0)
    return;
  __builtin_cpu_init();
  const char* kernels = nullptr;
  if (__builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
      __builtin_cpu_supports("avx512dq") && __builtin_cpu_supports("avx512vl"))
    kernels = "SkylakeX";
  else if (__builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    kernels = "Haswell";
  else if (__builtin_cpu_supports("avx"))
    kernels = "Sandybridge";
  if (kernels == nullptr)
    return;
  setenv("OPENBLAS_CORETYPE", kernels, 1);
  quit();
  init();
}
} // namespace gearstiff::fem
