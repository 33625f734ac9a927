#!/usr/bin/env bash
# Installs the Debian packages dashbed needs (only the missing ones; silent when all are there)
# and builds it (Release, ccache when available).
#
#   tools/setup.sh              build into build/
#   tools/setup.sh --sanitize   build into build-asan/ with AddressSanitizer + UBSan
#   tools/setup.sh --fuzz       build the libFuzzer harnesses (tests/fuzz) into build-fuzz/ with clang
set -euo pipefail

root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build_dir="$root/build"
# DASHBED_MPI: `mpirun -np K dashbed stress ...` shares a campaign among K ranks
cmake_args=(-DCMAKE_BUILD_TYPE=Release -DDASHBED_MPI=ON)
if [[ "${1:-}" == "--sanitize" ]]; then
  build_dir="$root/build-asan"
  # -O1 with line tables: readable sanitizer reports at a fraction of -O2 -g's compile time;
  # no MPI: OpenMPI's allocations trip LeakSanitizer (the MPI smoke test runs in build/)
  # no Python module: Python itself is not built with ASan (the Python tests run in build/)
  cmake_args=(-DCMAKE_BUILD_TYPE=None "-DCMAKE_CXX_FLAGS=-O1 -g1" -DDASHBED_SANITIZE=ON -DDASHBED_MPI=OFF
              -DDASHBED_PYTHON=OFF)
fi
build_target=all
fuzz_packages=()
if [[ "${1:-}" == "--fuzz" ]]; then
  build_dir="$root/build-fuzz"
  cmake_args=(-DCMAKE_BUILD_TYPE=None "-DCMAKE_CXX_FLAGS=-O1 -g1" -DCMAKE_CXX_COMPILER=clang++ -DDASHBED_FUZZ=ON
              -DDASHBED_PYTHON=OFF)
  build_target=dashbed_fuzzers
  fuzz_packages=(clang libclang-rt-dev)     # libFuzzer and clang's sanitizers
fi

packages=(
  cmake g++ make pkg-config ccache          # toolchain
  libeigen3-dev                             # linear algebra
  liburdfdom-dev                            # URDF parsing
  libassimp-dev                             # mesh loading
  libyaml-cpp-dev                           # world files
  nlohmann-json3-dev                        # plans, reports, --json
  libcli11-dev                              # command line
  libbullet-dev                             # physics (the double-precision bullet-float64 build)
  libfcl-dev                                # planner collision checking
  libosmesa6-dev libpng-dev                 # offscreen rendering, PNG frames
  ffmpeg                                    # MP4 video (ffprobe in the tests)
  catch2                                    # tests (Catch2 v2)
  python3                                   # tests: the folder map check
  libopenmpi-dev openmpi-bin                # stress campaigns across machines (mpirun)
  chromium                                  # the HTML replay's browser tests
  pybind11-dev python3-dev                  # the Python package (build/python)
  python3-numpy python3-pytest python3-matplotlib  # its arrays, its tests, the examples' plots
  "${fuzz_packages[@]}"
)
# node and npm: the HTML replay's three.js and its tests' puppeteer-core (any recent node will do)
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if ((${#missing[@]} > 0)); then
  if [[ $(id -u) -ne 0 ]]; then
    echo "setup: missing Debian packages: ${missing[*]} (run as root, or: sudo apt-get install ${missing[*]})" >&2
    exit 1
  fi
  echo "setup: installing ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  apt-get update -qq
  apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# the replay's npm packages, at the versions of assets/web/package-lock.json
web="$root/assets/web"
if [[ "$build_target" == all && ( ! -d "$web/node_modules" || "$web/package-lock.json" -nt "$web/node_modules" ) ]]; then
  npm ci --prefix "$web" --no-audit --no-fund --loglevel=error
  touch "$web/node_modules"
fi

cmake -S "$root" -B "$build_dir" "${cmake_args[@]}" >/dev/null
cmake --build "$build_dir" -j"$(nproc)" --target "$build_target"
