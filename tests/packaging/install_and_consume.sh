#!/usr/bin/env bash
# Installs the built semslam into a temporary prefix, then configures, builds and runs the consumer project
# against it with find_package(semslam). Usage: install_and_consume.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build_dir=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log"
test -x "$work/prefix/bin/semslam" || { echo "the CLI was not installed"; exit 1; }
test -f "$work/prefix/include/semslam/solve/Optimizer.h" || { echo "headers were not installed"; exit 1; }
cmake -S "$source_dir/tests/packaging/consumer" -B "$work/consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/consumer" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/consumer/consumer"
