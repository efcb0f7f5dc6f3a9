#!/usr/bin/env bash
# Runs `baize chart` the way a user does, on a real sweep and a real bench table, and checks the
# PNG files it writes (signature, chunk checksums, size from the IHDR chunk), that the same input
# gives the same bytes, and that bad input gets a clear error and leaves no file behind:
#   bash tests/tools/chart_cli_test.sh path/to/baize
# What is drawn where is tested in tests/render (pixels of known data).
set -euo pipefail

baize=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# check_png WIDTH HEIGHT FILES...: each file is a whole PNG (signature, every chunk's CRC, IHDR
# first, IEND last) of WIDTH x HEIGHT pixels.
check_png() {
  python3 - "$@" <<'EOF_PY' || fail "PNG check failed: see above"
import struct, sys, zlib
width, height = int(sys.argv[1]), int(sys.argv[2])
for path in sys.argv[3:]:
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path}: no PNG signature"
    offset, chunks = 8, []
    while offset < len(data):
        length, kind = struct.unpack(">I4s", data[offset:offset + 8])
        body = data[offset + 8:offset + 8 + length]
        (crc,) = struct.unpack(">I", data[offset + 8 + length:offset + 12 + length])
        assert zlib.crc32(kind + body) == crc, f"{path}: bad CRC in chunk {kind}"
        chunks.append((kind, body))
        offset += 12 + length
    assert offset == len(data), f"{path}: trailing bytes"
    assert chunks[0][0] == b"IHDR" and chunks[-1][0] == b"IEND", f"{path}: chunk order"
    w, h = struct.unpack(">II", chunks[0][1][:8])
    assert (w, h) == (width, height), f"{path}: {w} x {h}, expected {width} x {height}"
EOF_PY
}

# expect_error STATUS TEXT ARGS...: baize ARGS must exit STATUS, print TEXT on stderr and nothing
# on stdout.
expect_error() {
  local status=$1 text=$2
  shift 2
  local actual=0
  "$baize" "$@" >"$work/stdout" 2>"$work/stderr" || actual=$?
  [[ $actual -eq $status ]] || fail "baize $* exited $actual, expected $status: $(cat "$work/stderr")"
  grep -qF -- "$text" "$work/stderr" || fail "baize $*: stderr lacks '$text': $(cat "$work/stderr")"
  [[ ! -s "$work/stdout" ]] || fail "baize $* printed to stdout: $(cat "$work/stdout")"
}

charts=(fig6-rebound-speed fig6-rebound-angle fig7-rebound-speed fig7-rebound-angle
        fig8-rebound-speed fig8-rebound-angle fig10-slip-speed fig10-slip-angle)

# ---- 1. A sweep (the paper solver with few steps: quick, and the charts do not care) to PNGs.
"$baize" cushion --sweep "$work/sweep" --solver paper --steps 200 >/dev/null || fail "sweep exited $?"
"$baize" chart sweep "$work/sweep" --width 800 --height 500 >"$work/out" || fail "chart sweep exited $?"
for chart in "${charts[@]}"; do
  grep -qxF "wrote $work/sweep/$chart.png" "$work/out" || fail "no 'wrote' line for $chart"
done
pngs=()
for chart in "${charts[@]}"; do pngs+=("$work/sweep/$chart.png"); done
check_png 800 500 "${pngs[@]}"
[[ -z $(find "$work/sweep" -name '*.tmp') ]] || fail "chart sweep left temporary files"

# ---- 2. The same input gives the same bytes; the default size is 960 x 600.
mkdir "$work/again"
cp "$work"/sweep/*.csv "$work/again/"
"$baize" chart sweep "$work/again" --width 800 --height 500 >/dev/null || fail "second run exited $?"
for chart in "${charts[@]}"; do
  cmp -s "$work/sweep/$chart.png" "$work/again/$chart.png" || fail "$chart.png differs between runs"
done
"$baize" chart sweep "$work/again" >/dev/null || fail "default size run exited $?"
check_png 960 600 "$work/again/fig6-rebound-speed.png"
cmp -s "$work/sweep/fig6-rebound-speed.png" "$work/again/fig6-rebound-speed.png" &&
  fail "a different size gave the same bytes"

# ---- 3. The bench table (smoke size) to a log-log PNG.
"$baize" bench cushion --impacts 4 --repeat 1 --csv "$work/bench.csv" >/dev/null ||
  fail "bench exited $?"
"$baize" chart bench-cushion "$work/bench.csv" --png "$work/bench.png" >"$work/out" ||
  fail "chart bench-cushion exited $?"
grep -qxF "wrote $work/bench.png" "$work/out" || fail "no 'wrote' line for the bench chart"
check_png 960 600 "$work/bench.png"

# ---- 4. Bad input: a clear message, exit status 2 (usage) or 1 (failure), and no PNG at all.
mkdir "$work/bad"
cp "$work"/sweep/*.csv "$work/bad/"
# A non-number in the middle of fig7.csv (line 100, the rebound speed column).
python3 - "$work/bad/fig7.csv" <<'EOF_PY'
import sys
path = sys.argv[1]
lines = open(path).read().splitlines()
fields = lines[99].split(",")
fields[4] = "nan"
lines[99] = ",".join(fields)
open(path, "w").write("\n".join(lines) + "\n")
EOF_PY
expect_error 2 "$work/bad/fig7.csv line 100, column rebound_speed_mps = 'nan' is not allowed" \
  chart sweep "$work/bad"
[[ -z $(find "$work/bad" -name '*.png*') ]] || fail "a refused sweep chart left files: $(ls "$work/bad")"
rm "$work/bad/fig7.csv"
expect_error 2 "fig7.csv: the file cannot be opened" chart sweep "$work/bad"
[[ -z $(find "$work/bad" -name '*.png*') ]] || fail "a sweep with a missing file left PNG files"
expect_error 2 "chart width (px) = 10 is not allowed" chart sweep "$work/sweep" --width 10
expect_error 2 "(set by --height)" chart sweep "$work/sweep" --height 100000

# A zero error cannot go on a log axis: the message names the table, the series and the axis.
sed 's/^exact,tol=1e-06,\([^,]*\),.*/exact,tol=1e-06,\1,0/' "$work/bench.csv" >"$work/zero.csv"
grep -q ',0$' "$work/zero.csv" || fail "test setup: no zero error written"
expect_error 2 "$work/zero.csv: chart 'Cushion solvers" chart bench-cushion "$work/zero.csv" --png "$work/zero.png"
grep -qF "series 'exact'" "$work/stderr" || fail "the log-axis message does not name the series"
grep -qF "logarithmic" "$work/stderr" || fail "the log-axis message does not say why"
[[ ! -e "$work/zero.png" && ! -e "$work/zero.png.tmp" ]] || fail "a refused bench chart left a file"
expect_error 1 "$work/missing/bench.png" \
  chart bench-cushion "$work/bench.csv" --png "$work/missing/bench.png"
[[ ! -e "$work/missing" ]] || fail "an unwritable --png created something"
expect_error 2 "fig6.csv: no column 'solver'" chart bench-cushion "$work/sweep/fig6.csv" --png "$work/x.png"
expect_error 2 "--png is required" chart bench-cushion "$work/bench.csv"
[[ ! -e "$work/x.png" ]] || fail "a refused bench chart left a file"

echo "chart CLI: all checks passed"
