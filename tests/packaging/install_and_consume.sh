#!/usr/bin/env bash
# The install, as a user gets it: installs the already built semslam (nothing is rebuilt) into a temporary prefix,
# checks that everything landed under that prefix and nowhere else (CLI, headers, CMake package, semslam.pc,
# plotting scripts, licence and citation) and that the package names no MPI, then builds and runs the same tiny consumer
# (tests/packaging/consumer/main.cpp) twice: with CMake's find_package(semslam) and with
# `pkg-config --cflags --libs semslam`; and, where the build made the Python module, imports it from the prefix.
# Usage: install_and_consume.sh BUILD_DIR SOURCE_DIR VERSION
set -euo pipefail
build_dir=$1
source_dir=$2
version=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
fail() { echo "install test: $*" >&2; exit 1; }

cmake --install "$build_dir" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; exit 1; }
# Under PREFIX only: every installed file (cmake's manifest of this install) lies inside the prefix.
outside=$(grep -v "^$prefix/" "$build_dir/install_manifest.txt" || true)
[ -z "$outside" ] || fail "installed outside the prefix: $outside"
for file in bin/semslam include/semslam/solve/Optimizer.h include/semslam/core/Version.h \
            lib/cmake/semslam/semslamConfig.cmake lib/cmake/semslam/semslamConfigVersion.cmake \
            lib/cmake/semslam/FindCHOLMOD.cmake lib/pkgconfig/semslam.pc share/semslam/python/plot_run.py \
            share/semslam/python/plot_methods.py share/semslam/python/paired_statistics.py share/semslam/python/hypotheses.py \
            share/doc/semslam/LICENSE share/doc/semslam/CITATION.cff; do
  [ -e "$prefix/$file" ] || fail "$file was not installed"
done
[ -x "$prefix/share/semslam/python/plot_run.py" ] || fail "the plotting scripts are not executable"
[ "$("$prefix/bin/semslam" --version)" = "semslam $version" ] || fail "the installed CLI does not print $version"
# MPI is the command-line tool's alone (docs/studies.md): the package a consumer builds against never names it.
! grep -lE "MPI::|libmpi|-lmpi" "$prefix"/lib/cmake/semslam/*.cmake "$prefix/lib/pkgconfig/semslam.pc" \
  || fail "the installed package names MPI"

# 1. CMake: find_package(semslam) finds semslam and its dependencies.
cmake -S "$source_dir/tests/packaging/consumer" -B "$work/cmake-consumer" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/cmake-consumer" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
"$work/cmake-consumer/consumer" "$version"

# 2. pkg-config: the flags alone build the same program.
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
[ "$(pkg-config --modversion semslam)" = "$version" ] || fail "semslam.pc does not say version $version"
flags=$(pkg-config --cflags --libs semslam) || fail "pkg-config cannot resolve semslam.pc"
"${CXX:-c++}" -std=c++20 -O1 "$source_dir/tests/packaging/consumer/main.cpp" $flags -o "$work/pkg-config-consumer" \
  > "$work/pkg-build.log" 2>&1 || { echo "c++ ... $flags"; cat "$work/pkg-build.log"; exit 1; }
"$work/pkg-config-consumer" "$version"

# 3. Python: where the build made the module (SEMSLAM_BUILD_PYTHON), the installed package imports from the prefix
# alone (docs/python.md), not from the build folder.
if [ -d "$build_dir/python/semslam" ]; then
  package=$(ls -d "$prefix"/lib/python3*/dist-packages/semslam 2>/dev/null) || fail "the Python package was not installed"
  [ -e "$package/__init__.py" ] || fail "the Python package has no __init__.py"
  imported=$(cd "$work" && PYTHONPATH="$(dirname "$package")" /usr/bin/python3 -B -c \
    "import semslam; print(semslam.__version__, semslam.__file__, semslam.SE2(1, 2, 0.5).compose(semslam.SE2()).x())") \
    || fail "import semslam from $(dirname "$package") failed"
  [ "$imported" = "$version $package/__init__.py 1.0" ] || fail "the installed module says '$imported'"
fi
