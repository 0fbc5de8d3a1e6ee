#!/usr/bin/env bash
# Installs the Debian packages rodshape builds, tests and benchmarks with.
# Usage: scripts/install-deps.sh [PACKAGE...]   (as root, or with sudo available)
# Extra Debian packages may be named after it (.ci/run adds clang's for its sanitizer builds).
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libeigen3-dev            # core linear algebra
  libboost-dev             # Boost.Math's Brent minimiser (solvers/stability.cpp), header-only
  libyaml-cpp-dev          # task files
  nlohmann-json3-dev       # results
  libcli11-dev             # command line
  libgtest-dev             # tests
  libbenchmark-dev         # bench/
  coinor-libipopt-dev      # shape optimisation (interior point)
  liborocos-kdl-dev liburdfdom-dev  # robot arms
  python3                  # test helpers
  pybind11-dev python3-dev # the Python package (python/)
  python3-numpy python3-pytest python3-matplotlib  # its arrays, tests and figures
  python3-distributed      # docs/batch.md: many tasks on a Dask cluster (its test)
  libnanoflann-dev         # feedback/: nearest points of a cloud to the model rod (k-d tree)
  libzstd-dev              # plan.mcap's compressed chunks (io/mcap_writer)
  libjs-three              # plan.html, validation.html: three.js, inlined when a page is written
  chromium chromium-driver python3-selenium  # the pages' test in a real browser (.ci/run, 3b)
  "$@"
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps: installed ${missing[*]}"
