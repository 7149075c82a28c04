#!/usr/bin/env bash
# Installs every Debian 12 package sweepcdt needs (idempotent), then configures and builds it.
# Usage: scripts/setup.sh [--deps-only] [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  build-essential cmake g++ pkg-config
  libgmp-dev            # exact predicate fallback
  libgtest-dev googletest libgmock-dev   # tests
  libbenchmark-dev      # bench/
  libcgal-dev           # tests and benchmarks only (reference Delaunay/CDT, peer predicates)
  tetgen time           # bench/run_sweep.sh: the peer mesher, and /usr/bin/time for peak memory
  openscad              # tests/data/scad: 3D-print parts exported as users export them (CliCad, bench/run_cad.py --scad)
  libdraco-dev draco    # io: Draco .drc and KHR_draco_mesh_compression; draco_encoder for round-trip tests
  libtinygltf-dev nlohmann-json3-dev   # io: glTF 2.0 (tinygltf is compiled in io/src/tinygltf_impl.cpp)
  clang-14 libclang-rt-14-dev   # tests/fuzz: libFuzzer targets (cmake -DSWEEPCDT_FUZZ=ON with clang)
  python3-meshio gmsh calculix-ccx   # tests/io: independent readers of the volume meshes written (and tetgen above)
  python3-dev python3-numpy pybind11-dev python3-pytest   # plugin/python: the module for Debian's /usr/bin/python3, its tests
  freecad-python3 xvfb xauth   # plugin/freecad: FreeCAD 0.20 (FEM, CalculiX via calculix-ccx above); GUI test under Xvfb
  meshlab qtbase5-dev libqt5opengl5-dev libglew-dev libeigen3-dev python3 xz-utils   # plugin/meshlab, its tests (xvfb-run), the SDK fetch; Eigen also for bench/cgal_delaunay_dd
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  $sudo_cmd apt-get update -qq
  $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# MeshLab 2020.09 headers from Debian's source package, for plugin/meshlab (idempotent).
scripts/fetch_meshlab_sdk.sh

deps_only=0
if [ "${1:-}" = "--deps-only" ]; then deps_only=1; shift; fi
((deps_only)) && exit 0

build_dir="${1:-build}"
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release
cmake --build "$build_dir" -j "$(nproc)"
