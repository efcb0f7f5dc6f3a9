#!/usr/bin/env bash
# Builds Baize's core alone (no rendering, viewer, Box2D or Python; no tests) in a folder of its
# own, with every optional dependency but CLI11 (the baize program's, header-only) made
# unfindable, installs it, runs its baize program (core_program_test.sh), and builds and runs the
# C++ consumer against it, the consumer's configuration finding only what the core's package asks
# for: the core needs Eigen and nlohmann-json and nothing else. A configuration without the
# program (BAIZE_WITH_PROGRAM=OFF) must succeed with CLI11 unfindable too.
# Usage: core_only_test.sh SOURCE_DIR WORK_DIR GENERATOR [COMPILER_LAUNCHER [REFERENCE_BAIZE]]
#   GENERATOR, COMPILER_LAUNCHER: the enclosing build's (ccache, when it uses it)
#   REFERENCE_BAIZE: the enclosing build's baize when it draws, whose reports the core's must equal
set -uo pipefail
source_dir=$1 work=$2 generator=$3 launcher=${4:-} reference=${5:-}
fail() { echo "FAIL: $*" >&2; exit 1; }
here=$(dirname "${BASH_SOURCE[0]}")

# find_package of each of these fails as if the package were not installed.
optional=(PNG Freetype Fontconfig GIF PkgConfig CLI11 SDL2 box2d GTest Python pybind11)
not_findable=()
for package in "${optional[@]}"; do not_findable+=("-DCMAKE_DISABLE_FIND_PACKAGE_$package=ON"); done

rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
core_options=(-DBAIZE_BUILD_TESTS=OFF -DBAIZE_WITH_RENDER=OFF -DBAIZE_WITH_VIEWER=OFF
              -DBAIZE_WITH_BOX2D=OFF -DBAIZE_WITH_PYTHON=OFF)
cmake -S "$source_dir" -B "$work/library-build" -G "$generator" "${core_options[@]}" \
  -DBAIZE_WITH_PROGRAM=OFF "${not_findable[@]}" >"$work/library-configure.log" 2>&1 ||
  fail "configuring the core without the program failed: $(tail -20 "$work/library-configure.log")"
rm -rf "$work/library-build"
build=$work/core-build
program_findable=()  # the program's CLI11 only
for option in "${not_findable[@]}"; do
  [[ "$option" == *_CLI11=ON ]] || program_findable+=("$option")
done
cmake -S "$source_dir" -B "$build" -G "$generator" -DCMAKE_BUILD_TYPE=Release \
  ${launcher:+"-DCMAKE_CXX_COMPILER_LAUNCHER=$launcher"} "${core_options[@]}" \
  "${program_findable[@]}" >"$work/configure.log" 2>&1 ||
  fail "configuring the core alone failed: $(tail -20 "$work/configure.log")"
cmake --build "$build" -j2 >"$work/build.log" 2>&1 ||
  fail "building the core alone failed: $(tail -30 "$work/build.log")"

config=$build/BaizeConfig.cmake
grep -qx 'set(Baize_WITH_RENDER OFF)' "$config" || fail "$config does not say Baize_WITH_RENDER OFF"
grep -qx 'set(Baize_WITH_BOX2D OFF)' "$config" || fail "$config does not say Baize_WITH_BOX2D OFF"

bash "$here/install_test.sh" "$source_dir" "$build" "$work/package" ||
  fail "installing the core alone failed"
bash "$here/core_program_test.sh" "$work/package/moved" ${reference:+"$reference"} ||
  fail "the core's baize program failed"
# Nothing the installed targets link names a render, viewer or Box2D library.
if grep -lE 'PkgConfig::|PNG::|Freetype::|Fontconfig::|GIF::|box2d|SDL2|CLI11' \
     "$work/package/moved/lib/cmake/Baize/"BaizeTargets*.cmake; then
  fail "the core's installed targets link a library the core should not need (files above)"
fi
[[ ! -e "$work/package/moved/include/baize/render" ]] || fail "the render headers were installed"
bash "$here/consumer_test.sh" "$source_dir" "$work/package" no-render "${not_findable[@]}" ||
  fail "the consumer against the core alone failed"
rm -rf "$work"  # kept only when something failed, with its logs
echo "the core alone built, installed and served the consumer"
