// A solver built for AVX2 or AVX-512F (fast_solver/simd.h: the build machine ran it) stops with a
// message, instead of an illegal instruction, when started on a processor without it. This file is
// compiled without those instruction sets, told the width by COMPLIANT_BUILT_FOR_SIMD_BITS
// (solver/fe/CMakeLists.txt), and the check runs as a
// constructor before the program's own static initialisers.
#include <cstdio>
#include <cstdlib>

#if defined(COMPLIANT_BUILT_FOR_SIMD_BITS) && COMPLIANT_BUILT_FOR_SIMD_BITS > 0
__attribute__((constructor(101))) static void require_the_build_machines_simd()
{
  __builtin_cpu_init();
  const bool runs = COMPLIANT_BUILT_FOR_SIMD_BITS >= 512 ? __builtin_cpu_supports("avx512f") :
                                                       __builtin_cpu_supports("avx2");
  if (!runs)
    {
      std::fprintf(stderr, "compliant: this build uses %s (the machine that built it runs it; this one does "
                           "not): build it here (bash scripts/setup.sh), or configure with -DCOMPLIANT_SIMD=OFF\n",
                   COMPLIANT_BUILT_FOR_SIMD_BITS >= 512 ? "AVX-512F" : "AVX2");
      std::_Exit(2);
    }
}
#endif
