#!/usr/bin/env bash
# Configures, builds and runs tests/package/consumer against the moved install prefix that
# install_test.sh left (find_package(Baize 0.2 CONFIG REQUIRED), a scene built in code); with
# rendering in the package, its render_consumer too, which draws a PNG and checks it with libpng.
# Usage: consumer_test.sh SOURCE_DIR WORK_DIR with-render|no-render [CMAKE_ARGUMENTS...]
#   with-render|no-render: whether the package holds Baize::render (and so render_consumer is built)
#   CMAKE_ARGUMENTS: passed on to the consumer's configuration
set -uo pipefail
source_dir=$1 work=$2 render=$3
shift 3
fail() { echo "FAIL: $*" >&2; exit 1; }
[[ "$render" == with-render || "$render" == no-render ]] ||
  fail "the third argument is '$render': with-render or no-render"
prefix=$work/moved
[[ -d "$prefix" ]] || fail "no install prefix at $prefix (the install test runs first)"
build=$work/consumer-build
rm -rf "$build"
cmake -S "$source_dir/tests/package/consumer" -B "$build" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release "$@" >"$work/consumer-configure.log" 2>&1 ||
  fail "configuring the consumer failed: $(tail -20 "$work/consumer-configure.log")"
cmake --build "$build" -j2 >"$work/consumer-build.log" 2>&1 ||
  fail "building the consumer failed: $(tail -30 "$work/consumer-build.log")"
# Run from a folder of its own: the consumer sits outside the prefix, so it is told where the
# installed assets are, as the package configuration's Baize_DATA_DIR says.
cd "$work" || fail "cd $work"
BAIZE_DATA_DIR="$prefix/share/baize" "$build/consumer" || fail "the consumer's checks failed"
if [[ "$render" == no-render ]]; then
  [[ ! -e "$build/render_consumer" ]] || fail "render_consumer was built without Baize::render"
  exit 0
fi
[[ -x "$build/render_consumer" ]] || fail "the package has Baize::render but render_consumer was not built"
rm -f "$work/consumer.png"
# OSMesa's software rasteriser, as the other picture tests use.
GALLIUM_DRIVER=${GALLIUM_DRIVER:-llvmpipe} BAIZE_DATA_DIR="$prefix/share/baize" \
  "$build/render_consumer" "$work/consumer.png" ||
  fail "the render consumer's checks failed"
