#!/usr/bin/env bash
# Installs the build into a temporary prefix, moves the prefix, and runs the moved copy from a
# folder of its own, where the source tree's assets are out of reach: the assets must be found
# through the program's own place (or BAIZE_DATA_DIR), never a compiled-in path.
# Usage: install_test.sh SOURCE_DIR BUILD_DIR WORK_DIR [no-program] (WORK_DIR is emptied and left
# holding WORK_DIR/moved, the moved prefix, for the consumer and Python tests; no-program: a build
# without the baize program, BAIZE_WITH_PROGRAM=OFF, whose installed files alone are checked).
set -uo pipefail
source_dir=$1 build_dir=$2 work=$3 program=${4:-with-program}
fail() { echo "FAIL: $*" >&2; exit 1; }

rm -rf "$work" && mkdir -p "$work" || fail "cannot make $work"
cmake --install "$build_dir" --prefix "$work/staged" >"$work/install.log" ||
  fail "cmake --install exited $? (see $work/install.log)"
mv "$work/staged" "$work/moved" || fail "cannot move the prefix"
prefix=$work/moved

expected=(include/baize/engine/sim/shot_simulator.h include/baize/physics/cloth_motion.h \
         share/baize/tables/pool-9ft.json share/baize/scenes/9-ball-break.json \
         lib/cmake/Baize/BaizeConfig.cmake lib/cmake/Baize/BaizeConfigVersion.cmake)
[[ "$program" == no-program ]] || expected+=(bin/baize)
for f in "${expected[@]}"; do
  [[ -e "$prefix/$f" ]] || fail "$f was not installed"
done
if [[ "$program" == no-program ]]; then
  [[ ! -e "$prefix/bin/baize" ]] || fail "bin/baize was installed by a build without it"
  echo "installed and moved to $prefix (no program to run)"
  exit 0
fi
# Nothing in the program points back at the source tree's assets.
if grep -qaF "$source_dir/assets" "$prefix/bin/baize"; then
  fail "bin/baize holds the source tree's assets path $source_dir/assets"
fi

version=$("$prefix/bin/baize" --version) || fail "--version exited $?"
# The project's version, as CMake has it (ctest sets BAIZE_EXPECTED_VERSION).
[[ "$version" == "baize ${BAIZE_EXPECTED_VERSION:?}" ]] ||
  fail "--version printed '$version', not 'baize $BAIZE_EXPECTED_VERSION'"

# A scene naming its table and ball set, run from an empty folder of its own.
run=$(mktemp -d) || fail "mktemp"
trap 'rm -rf "$run"' EXIT
cd "$run" || fail "cd $run"
cat > scene.json <<'JSON'
{"table": "pool-9ft", "ball_set": "pool",
 "balls": {"cue": [-0.6, 0.0], "1": [0.4, 0.0]},
 "shot": {"aim_at": "1", "speed_mps": 2.0}}
JSON
out=$("$prefix/bin/baize" simulate scene.json 2>&1) || fail "the moved baize exited $?: $out"
[[ "$out" == *"first ball hit: 1"* ]] || fail "the moved baize printed: $out"

# BAIZE_DATA_DIR points elsewhere: a copy of the assets, with the prefix's own taken away.
mv "$prefix/share/baize" "$run/assets" || fail "cannot move the assets away"
out=$("$prefix/bin/baize" simulate scene.json 2>&1) && fail "with no assets baize succeeded: $out"
[[ "$out" == *"BAIZE_DATA_DIR"* ]] || fail "with no assets baize printed: $out"
out=$(BAIZE_DATA_DIR="$run/assets" "$prefix/bin/baize" simulate scene.json 2>&1) ||
  fail "with BAIZE_DATA_DIR baize exited $?: $out"
[[ "$out" == *"first ball hit: 1"* ]] || fail "with BAIZE_DATA_DIR baize printed: $out"
out=$(BAIZE_DATA_DIR="$run/nowhere" "$prefix/bin/baize" simulate scene.json 2>&1) &&
  fail "a BAIZE_DATA_DIR with no assets was accepted: $out"
[[ "$out" == *"$run/nowhere"* ]] || fail "a bad BAIZE_DATA_DIR was not named: $out"
mv "$run/assets" "$prefix/share/baize" || fail "cannot put the assets back"
echo "installed, moved and ran from $prefix"
