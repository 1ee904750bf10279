#!/usr/bin/env bash
# Kessler's developer entry point. Installs the Debian packages it needs (as root), builds, and
#   tools/dev.sh example   runs the default example into results/
#   tools/dev.sh test      runs the whole test suite (unit, verification, regression)
#   tools/dev.sh build     only builds
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(build-essential cmake ninja-build pkg-config libeigen3-dev libyaml-cpp-dev libfmt-dev libcli11-dev
          libhdf5-dev libgmsh-dev nlohmann-json3-dev googletest libgtest-dev python3 python3-numpy
          python3-h5py python3-matplotlib)

install_missing() {
  local missing=()
  for p in "${packages[@]}"; do
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
}

case "${1:-}" in
  example)
    install_missing
    build
    build/src/app/kessler run examples/elastic-sphere-plate.yaml
    ;;
  test)
    install_missing
    build
    ctest --test-dir build --output-on-failure
    ;;
  build)
    install_missing
    build
    ;;
  *)
    echo "usage: tools/dev.sh example|test|build" >&2
    exit 2
    ;;
esac
