#!/usr/bin/env bash
# Installs the build into a temporary prefix and builds and runs a consumer that uses
# find_package(sweepcdt): the install/export rules must work for an installed copy.
# Usage: check_install.sh BUILD_DIR CONSUMER_SOURCE_DIR
set -euo pipefail
build="$1"; consumer="$2"
work="$(mktemp -d)"; trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/consumer" > "$work/build.log"
output="$("$work/consumer/consumer")"
echo "$output"
[ "$output" = "valid" ]
