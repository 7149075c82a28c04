#!/usr/bin/env bash
# Builds the libFuzzer targets with clang-14 (AddressSanitizer + UndefinedBehaviorSanitizer on all of
# sweepcdt), seeds one corpus per reader from ../shared/data, and runs each target for SECONDS.
# Usage: tests/fuzz/run_fuzzers.sh [SECONDS=60] [TARGET...]     (build in build-fuzz/)
# Crashes are written to build-fuzz/crashes/<target>/; turn each into a regression test in tests/io.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds="${1:-60}"
shift || true
targets=("$@")
((${#targets[@]})) || targets=(off stl_ascii stl_binary obj ply gltf glb draco medit vtu gmsh inp plc)

sanitizers="-fsanitize=address,undefined -fsanitize=fuzzer-no-link"
# Undefined behaviour is fatal except for the known cases listed in ubsan.supp.
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$PWD/tests/fuzz/ubsan.supp"
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_CXX_FLAGS="$sanitizers" -DSWEEPCDT_FUZZ=ON -DSWEEPCDT_BUILD_BENCH=OFF > /dev/null
cmake --build build-fuzz -j "$(nproc)" --target $(printf 'fuzz_%s ' "${targets[@]}") > build-fuzz/build.log

data=../shared/data
seed() {  # seed TARGET FILES...
  local dir="build-fuzz/corpus/$1"; shift
  mkdir -p "$dir"
  for f in "$@"; do [ -f "$f" ] && cp "$f" "$dir/"; done
  return 0
}
seed off "$data"/off/*.off "$data"/bad/*.off
seed stl_ascii "$data"/stl_ascii/*.stl "$data"/bad/*.stl
seed stl_binary "$data"/stl_binary/torus.stl
seed gltf "$data"/gltf/*.gltf
seed glb "$data"/glb/*.glb
seed draco "$data"/drc/*.drc "$data"/bad/*.drc
# OBJ and PLY have no shared samples: small hand-made seeds.
mkdir -p build-fuzz/corpus/obj build-fuzz/corpus/ply
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n' > build-fuzz/corpus/obj/tetra.obj
printf 'v 0 0 0\nv 2 0 0\nv 2 1 0\nv 1 1 0\nv 1 2 0\nv 0 2 0\nf 1/1/1 2//1 3 4 5 -1\n' > build-fuzz/corpus/obj/l.obj
printf 'ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > build-fuzz/corpus/ply/tetra.ply

# Volume meshes and .plc: small files written by sweepcdt itself (tests/fuzz/seeds/).
for t in medit vtu gmsh inp plc; do seed "$t" tests/fuzz/seeds/"$t"/*; done

for t in "${targets[@]}"; do
  mkdir -p "build-fuzz/crashes/$t"
  echo "== fuzz_$t for ${seconds}s"
  build-fuzz/tests/fuzz/fuzz_$t "build-fuzz/corpus/$t" -max_total_time="$seconds" -max_len=65536 -rss_limit_mb=2048 \
    -timeout=10 -artifact_prefix="build-fuzz/crashes/$t/" -print_final_stats=1 2>&1 | grep -E "^#[0-9]+ *DONE|stat::number_of_executed_units|stat::peak_rss|ERROR|SUMMARY|Test unit written" || true
done
