#!/usr/bin/env bash
# Configures, builds and runs tests/package/consumer against the moved install prefix that
# install_test.sh left (find_package(Baize 0.2 CONFIG REQUIRED), a scene built in code).
# Usage: consumer_test.sh SOURCE_DIR WORK_DIR
set -uo pipefail
source_dir=$1 work=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
prefix=$work/moved
[[ -d "$prefix" ]] || fail "no install prefix at $prefix (the install test runs first)"
build=$work/consumer-build
rm -rf "$build"
cmake -S "$source_dir/tests/package/consumer" -B "$build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release >"$work/consumer-configure.log" 2>&1 ||
  fail "configuring the consumer failed: $(tail -20 "$work/consumer-configure.log")"
cmake --build "$build" -j2 >"$work/consumer-build.log" 2>&1 ||
  fail "building the consumer failed: $(tail -30 "$work/consumer-build.log")"
# Run from a folder of its own: the consumer sits outside the prefix, so it is told where the
# installed assets are, as the package configuration's Baize_DATA_DIR says.
cd "$work" || fail "cd $work"
BAIZE_DATA_DIR="$prefix/share/baize" "$build/consumer" || fail "the consumer's checks failed"
