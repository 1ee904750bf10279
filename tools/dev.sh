#!/usr/bin/env bash
# Kessler's developer entry point. Installs the Debian packages it needs (as root), builds, and
#   tools/dev.sh example   runs the default example into results/
#   tools/dev.sh test      runs the whole test suite (unit, verification, regression)
#   tools/dev.sh build     only builds
#   tools/dev.sh asan      AddressSanitizer + UBSan build with clang (build-asan): unit tests and a short impact
#   tools/dev.sh tsan      ThreadSanitizer build with clang and LLVM's Archer (build-tsan): the threaded
#                          kernels on 2 threads (thread-determinism, a short impact); fails on any race
#   tools/dev.sh fuzz      libFuzzer on the same build (build-asan): each fuzzer for KESSLER_FUZZ_SECONDS
#                          (default 90) on a copy of its seed corpus; fails on any finding
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config libeigen3-dev libyaml-cpp-dev libfmt-dev libcli11-dev
          libhdf5-dev libgmsh-dev nlohmann-json3-dev googletest libgtest-dev python3 python3-numpy
          python3-h5py python3-matplotlib libbenchmark-dev libopenmpi-dev openmpi-bin libtrilinos-zoltan-dev
          libptscotch-dev python3-dev pybind11-dev python3-pytest paraview python3-paraview xvfb xauth python3-yaml)
# Only for `asan`, `fuzz` and `tsan`: clang with its sanitizer and libFuzzer runtimes, and its OpenMP (with Archer).
fuzz_packages=(clang libclang-rt-14-dev libomp-dev)

install_missing() {
  local missing=()
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return
  echo "installing: ${missing[*]}"
  local sudo=""
  [ "$(id -u)" -ne 0 ] && sudo="sudo"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

build() {
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build -j"$(nproc)"
  install_python_path
}

# `import kessler` with no further step: a kessler.pth in the user site folder of each python3 that
# has one (Debian's /usr/bin/python3, and a different python3 first in PATH) names the package's
# folder (python/) and the compiled module's (build/python/). Python 3.11 of both shares the folder.
install_python_path() {
  [ -d build/python ] || return 0
  local interpreter site
  for interpreter in /usr/bin/python3 "$(command -v python3 || true)"; do
    [ -x "$interpreter" ] || continue
    site=$("$interpreter" -c "import site; print(site.getusersitepackages())" 2>/dev/null) || continue
    mkdir -p "$site"
    printf '%s\n%s\n' "$PWD/python" "$PWD/build/python" >"$site/kessler.pth"
  done
}

# Any sanitizer report fails the program. Gmsh's own small leaks are suppressed (tests/lsan.supp).
sanitizer_environment() {
  export ASAN_OPTIONS=detect_leaks=1:strict_string_checks=1:check_initialization_order=1
  export LSAN_OPTIONS=suppressions=$PWD/tests/lsan.supp:print_suppressions=0
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
}

# The sanitizer builds compile at -O1 with line tables only (-g1): the reports keep their file:line
# stacks, and an ASan build takes half the time it takes at RelWithDebInfo's -O2 -g (the slowest
# file: 75 s against 164 s), which is most of CI's time in this stage.
# The Python module is left out: an instrumented module would need the sanitizer's runtime preloaded
# into python3.
sanitizer_flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG"
                 "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DKESSLER_PYTHON=OFF)

# One AddressSanitizer + UBSan build with clang (build-asan) serves the unit tests and the fuzzers:
# libFuzzer's coverage is compiled into everything (KESSLER_FUZZ), and only the fuzz targets link its
# driver. Warnings stay warnings here (clang's differ from g++'s, which the main build holds to
# -Werror); MPI is left out (the multi-rank tests are not run here, and the fuzzed readers never
# reach it). One build instead of a g++ ASan build and a clang fuzz build saves CI a whole build.
configure_asan() {
  CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja "${sanitizer_flags[@]}" -DKESSLER_FUZZ=ON \
    -DKESSLER_WERROR=OFF -DKESSLER_MPI=OFF >/dev/null
}

asan() {
  sanitizer_environment
  configure_asan
  # Only what the unit tests, the impact run and the fuzzers need: not the benches.
  cmake --build build-asan -j"$(nproc)" --target unit_tests fuzz_deck fuzz_sesame
  # VolumeStabilisation.ConservesMomentumAndBooksItsEnergy (three impacts at cfl 0.1) takes 197 s here,
  # against 65 s in g++'s ASan build and 1 s in the release build that `test` runs: its code paths
  # are the other volume tests', so it is left to `test`.
  OMP_WAIT_POLICY=passive ctest --test-dir build-asan -L unit -j"$(nproc)" --output-on-failure \
    -E '^VolumeStabilisation\.ConservesMomentumAndBooksItsEnergy$'
  build-asan/src/app/kessler run tests/data/decks/elastic-sphere-plate.yaml --out build-asan/example-1us \
    --set solver.end_time="1 us" --set output.every="0.5 us" --quiet
  echo "asan: unit tests and a 1 us impact ran clean"
}

# Archer (in libomp-dev) is an OpenMP tool that tells ThreadSanitizer about OpenMP's barriers and
# locks; without it every parallel region reports false races. MPI is left out (not instrumented).
tsan() {
  local archer=/usr/lib/llvm-14/lib/libarcher.so
  [ -f "$archer" ] || { echo "tsan: $archer is missing (libomp-dev)" >&2; exit 1; }
  CC=clang CXX=clang++ cmake -S . -B build-tsan -G Ninja "${sanitizer_flags[@]}" -DKESSLER_TSAN=ON \
    -DKESSLER_MPI=OFF -DKESSLER_WERROR=OFF -DKESSLER_BUILD_TESTS=OFF >/dev/null
  cmake --build build-tsan -j"$(nproc)" --target kessler
  export OMP_TOOL_LIBRARIES=$archer OMP_NUM_THREADS=2
  export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ignore_noninstrumented_modules=1"
  build-tsan/src/app/kessler verify thread-determinism
  build-tsan/src/app/kessler verify --method sph thread-determinism flyer-plate
  build-tsan/src/app/kessler run examples/whipple.yaml --out build-tsan/whipple-short --threads 2 --quiet \
    --set solver.end_time="1.5 us" --set output.every="0.5 us" --set bodies.0.mesh_size="0.7 mm" \
    --set bodies.1.mesh_size="0.8 mm" --set bodies.2.mesh_size="1.94 mm"
  # RKPM: its kernels, and its contact with a surface built again as the rod erodes (21 g of debris).
  build-tsan/src/app/kessler verify --method rkpm thread-determinism
  build-tsan/src/app/kessler run examples/rod-steel-plate.yaml --out build-tsan/rod-short --threads 2 --quiet \
    --set solver.method=rkpm --set solver.end_time="15 us" --set bodies.0.mesh_size="3 mm" \
    --set bodies.1.mesh_size="3 mm" --set "bodies.0.velocity=[0, 0.26048 km/s, -1.47722 km/s]"
  echo "tsan: thread-determinism (OTM, SPH and RKPM), SPH's flyer plate, a 1.5 us whipple impact and a 15 us" \
    "RKPM rod impact on 2 threads ran without a race"
}

fuzz() {
  sanitizer_environment
  local seconds=${KESSLER_FUZZ_SECONDS:-90}
  configure_asan  # the build of `asan` (nothing to do after it)
  cmake --build build-asan -j"$(nproc)" --target fuzz_deck fuzz_sesame
  local -A seeds=([deck]="tests/fuzz/corpus/deck tests/data/decks examples"
                  [sesame]="tests/fuzz/corpus/sesame tests/data/sesame")
  for target in deck sesame; do
    # New inputs go to a scratch copy (the first folder); the seed folders are only read.
    local corpus=build-asan/corpus/$target artifacts=build-asan/artifacts/$target/
    mkdir -p "$corpus" "$artifacts"
    local log=build-asan/fuzz_$target.log status=0
    # shellcheck disable=SC2086
    build-asan/tests/fuzz/fuzz_$target "$corpus" ${seeds[$target]} -dict="tests/fuzz/$target.dict" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=8192 -print_final_stats=1 \
      -artifact_prefix="$artifacts" >"$log" 2>&1 || status=$?
    grep -E "^(INFO: Seed|#[0-9]+ +DONE|Done [0-9]+ runs|stat::number_of_executed_units|stat::peak_rss)" \
      "$log" || true
    if [ "$status" -ne 0 ]; then
      tail -40 "$log" >&2
      echo "fuzz_$target found a problem (exit $status): the input is in $artifacts" >&2
      exit 1
    fi
  done
  echo "fuzz: no findings in ${seconds} s per target"
}

case "${1:-}" in
  example)
    install_missing "${packages[@]}"
    build
    build/src/app/kessler run examples/sphere-plate.yaml
    ;;
  test)
    install_missing "${packages[@]}"
    build
    # Tests run side by side, each with OpenMP threads: waiting threads must sleep, not spin, or
    # two tests on the same cores stall each other at every barrier (minutes instead of seconds).
    OMP_WAIT_POLICY=passive ctest --test-dir build -j"$(nproc)" -LE long --output-on-failure
    ;;
  build)
    install_missing "${packages[@]}"
    build
    ;;
  asan)
    install_missing "${packages[@]}" "${fuzz_packages[@]}"
    asan
    ;;
  tsan)
    install_missing "${packages[@]}" "${fuzz_packages[@]}"
    tsan
    ;;
  fuzz)
    install_missing "${packages[@]}" "${fuzz_packages[@]}"
    fuzz
    ;;
  *)
    echo "usage: tools/dev.sh example|test|build|asan|tsan|fuzz" >&2
    exit 2
    ;;
esac
