# Instrumented builds, each in its own build folder (tools/dev.sh asan|fuzz):
#   KESSLER_SANITIZE=ON  AddressSanitizer + UndefinedBehaviorSanitizer on everything (g++ or clang).
#   KESSLER_FUZZ=ON      clang only: coverage for libFuzzer plus ASan/UBSan on everything, and the
#                        fuzz targets of tests/fuzz linked with libFuzzer's driver.
#   KESSLER_TSAN=ON      clang only: ThreadSanitizer on everything (tools/dev.sh tsan runs it with LLVM's
#                        Archer, which tells TSan about OpenMP's synchronisation).
# Any undefined behaviour aborts (no recovery), so that tests and fuzzers fail on it.
option(KESSLER_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(KESSLER_FUZZ "Build the libFuzzer targets in tests/fuzz (needs clang)" OFF)
option(KESSLER_TSAN "Build with ThreadSanitizer (needs clang)" OFF)

if(KESSLER_FUZZ AND NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "KESSLER_FUZZ needs clang: configure with CC=clang CXX=clang++")
endif()
if(KESSLER_TSAN)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR KESSLER_SANITIZE OR KESSLER_FUZZ)
    message(FATAL_ERROR "KESSLER_TSAN needs clang (CC=clang CXX=clang++) and no other sanitizer")
  endif()
  target_compile_options(kessler_options INTERFACE -fsanitize=thread -fno-omit-frame-pointer)
  target_link_options(kessler_options INTERFACE -fsanitize=thread)
endif()
if(KESSLER_SANITIZE OR KESSLER_FUZZ)
  set(kessler_sanitizers address,undefined)
  if(KESSLER_FUZZ)
    set(kessler_sanitizers fuzzer-no-link,address,undefined)
  endif()
  # g++ 12 reports false -Wmaybe-uninitialized inside libstdc++ (std::regex, std::function) once the
  # sanitizers' instrumentation is in; the ordinary build keeps that warning as an error.
  target_compile_options(kessler_options INTERFACE -fsanitize=${kessler_sanitizers}
    -fno-sanitize-recover=undefined -fno-omit-frame-pointer $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
  target_link_options(kessler_options INTERFACE -fsanitize=address,undefined)
endif()
