# The instruction set the kernels are compiled for. With KESSLER_NATIVE_ARCH (default ON) Kessler
# targets x86-64-v3 (AVX2 and FMA: four doubles per instruction, fused multiply-adds) when the
# compiler knows it and this machine runs it; elsewhere it keeps the compiler's default. Measured
# on hvi-100k: 1.99 -> 1.83 us per point-step on one thread (docs/performance.md). Results stay
# the same for any thread count; they differ from a default-architecture build at round-off (FMA).
# Off for binaries that must run on another, older machine than the one that built them.
option(KESSLER_NATIVE_ARCH "Compile for x86-64-v3 (AVX2, FMA) when this machine runs it" ON)
if(KESSLER_NATIVE_ARCH)
  include(CheckCXXSourceRuns)
  set(CMAKE_REQUIRED_FLAGS -march=x86-64-v3)
  check_cxx_source_runs("
    #include <cmath>
    int main(int argc, char**) { volatile double x = argc; return std::fma(x, x, x) == 2.0 ? 0 : 1; }"
    KESSLER_HAS_X86_64_V3)
  unset(CMAKE_REQUIRED_FLAGS)
  if(KESSLER_HAS_X86_64_V3)
    target_compile_options(kessler_options INTERFACE -march=x86-64-v3)
  endif()
endif()
