#!/usr/bin/env bash
# Runs `baize chart` the way a user does, on a real sweep and real bench tables, and checks the
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

# count_palette_colours EXPECTED FILES...: each PNG (8-bit RGB, as Cairo writes an opaque image)
# shows exactly EXPECTED of the chart palette's colours (render/line_chart.cpp), i.e. holds that
# many series: every series draws its colour at least in the legend, and nothing else uses them.
count_palette_colours() {
  python3 - "$@" <<'EOF_PY' || fail "colour count check failed: see above"
import struct, sys, zlib
palette = [(0x00, 0x72, 0xB2), (0xD5, 0x5E, 0x00), (0x00, 0x9E, 0x73), (0xCC, 0x79, 0xA7),
           (0xE6, 0x9F, 0x00), (0x56, 0xB4, 0xE9)]
def pixels(path):
    data, offset, idat = open(path, "rb").read(), 8, b""
    while offset < len(data):
        length, kind = struct.unpack(">I4s", data[offset:offset + 8])
        body = data[offset + 8:offset + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour_type = struct.unpack(">IIBB", body[:10])
            assert (depth, colour_type) == (8, 2), f"{path}: not 8-bit RGB"
        elif kind == b"IDAT":
            idat += body
        offset += 12 + length
    raw, stride, previous, seen = zlib.decompress(idat), width * 3, bytearray(width * 3), set()
    for row in range(height):  # undo the PNG row filters (None, Sub, Up, Average, Paeth)
        start = row * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            b = previous[i]
            c = previous[i - 3] if i >= 3 else 0
            if kind == 1: line[i] = (line[i] + a) & 255
            elif kind == 2: line[i] = (line[i] + b) & 255
            elif kind == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        seen.update(zip(line[0::3], line[1::3], line[2::3]))
        previous = line
    return seen
expected = int(sys.argv[1])
for path in sys.argv[2:]:
    found = [c for c in palette if c in pixels(path)]
    assert len(found) == expected, f"{path}: {len(found)} series colours, expected {expected}"
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
"$baize" chart sweep "$work/sweep" --width 480 --height 320 >"$work/out" || fail "chart sweep exited $?"
for chart in "${charts[@]}"; do
  grep -qxF "wrote $work/sweep/$chart.png" "$work/out" || fail "no 'wrote' line for $chart"
done
pngs=()
for chart in "${charts[@]}"; do pngs+=("$work/sweep/$chart.png"); done
check_png 480 320 "${pngs[@]}"
[[ -z $(find "$work/sweep" -name '*.tmp') ]] || fail "chart sweep left temporary files"
# One series per curve of the sweep (5 in figures 6-8), one per contact in figure 10.
count_palette_colours 5 "$work"/sweep/fig{6,7,8}-rebound-{speed,angle}.png
count_palette_colours 2 "$work"/sweep/fig10-slip-{speed,angle}.png

# ---- 2. The same input gives the same bytes; the default size is 960 x 600.
mkdir "$work/again"
cp "$work"/sweep/*.csv "$work/again/"
"$baize" chart sweep "$work/again" --width 480 --height 320 >/dev/null || fail "second run exited $?"
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
"$baize" chart bench-cushion "$work/bench.csv" --png "$work/bench-small.png" --width 480 \
  --height 320 >/dev/null || fail "chart bench-cushion --width 480 exited $?"
count_palette_colours 3 "$work/bench-small.png"  # paper, exact and tabulated
# The same file with CRLF line ends (from Windows) draws the same chart.
sed 's/$/\r/' "$work/bench.csv" >"$work/bench-crlf.csv"
"$baize" chart bench-cushion "$work/bench-crlf.csv" --png "$work/bench-crlf.png" --width 480 \
  --height 320 >/dev/null || fail "chart bench-cushion of a CRLF file exited $?"
cmp -s "$work/bench-small.png" "$work/bench-crlf.png" || fail "a CRLF file draws another chart"

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
expect_error 2 "--width = 10 is not allowed" chart sweep "$work/sweep" --width 10
expect_error 2 "--height = 1e+05 is not allowed" chart sweep "$work/sweep" --height 100000

# A zero error cannot go on a log axis: the message names the table, the series and the axis.
sed 's/^exact,tol=1e-06,\([^,]*\),.*/exact,tol=1e-06,\1,0/' "$work/bench.csv" >"$work/zero.csv"
grep -q ',0$' "$work/zero.csv" || fail "test setup: no zero error written"
expect_error 2 "$work/zero.csv: chart 'Cushion solvers" chart bench-cushion "$work/zero.csv" --png "$work/zero.png"
grep -qF "series 'exact'" "$work/stderr" || fail "the log-axis message does not name the series"
grep -qF "logarithmic" "$work/stderr" || fail "the log-axis message does not say why"
# A directory as the output is refused before any work, naming --png.
expect_error 2 "--png = $work is not allowed: it is a directory" \
  chart bench-cushion "$work/bench.csv" --png "$work"
# A value too small for a log axis: the message names the file too.
sed 's/^exact,tol=1e-06,\([^,]*\),.*/exact,tol=1e-06,\1,5e-324/' "$work/bench.csv" >"$work/tiny.csv"
expect_error 2 "$work/tiny.csv: log axis low end = 5e-324 is not allowed" \
  chart bench-cushion "$work/tiny.csv" --png "$work/tiny.png"
[[ ! -e "$work/zero.png" && ! -e "$work/zero.png.tmp" ]] || fail "a refused bench chart left a file"
# Missing parent folders are made (docs/commands.md); a path under a file is refused before work.
"$baize" chart bench-cushion "$work/bench.csv" --png "$work/missing/bench.png" >/dev/null ||
  fail "chart --png in a missing folder exited $?"
[[ -s "$work/missing/bench.png" ]] || fail "chart --png did not make its folder"
touch "$work/a-file"
expect_error 2 "--png = $work/a-file/bench.png is not allowed" \
  chart bench-cushion "$work/bench.csv" --png "$work/a-file/bench.png"
expect_error 2 "$work: a directory is not allowed: it must be a CSV file" chart bench-cushion "$work" \
  --png "$work/x.png"
printf 'solver,setting,median_ns,max_error\nexact,default,5\0,1e-10\n' >"$work/nul.csv"
expect_error 2 "$work/nul.csv: a NUL byte is not allowed" chart bench-cushion "$work/nul.csv" \
  --png "$work/x.png"
expect_error 2 "fig6.csv: no column 'solver'" chart bench-cushion "$work/sweep/fig6.csv" --png "$work/x.png"
expect_error 2 "--png is required" chart bench-cushion "$work/bench.csv"
[[ ! -e "$work/x.png" ]] || fail "a refused bench chart left a file"

# ---- 5. The accuracy bench table (one shot, one timed run) to a log-log PNG: one series per
# engine; the event loop's error of 0 is drawn on a floor, so the table is accepted as it is.
"$baize" bench accuracy --shots 1 --repeat 1 --csv "$work/accuracy.csv" >/dev/null ||
  fail "bench accuracy exited $?"
grep -q '^event,exact,[^,]*,0,0,all,' "$work/accuracy.csv" || fail "test setup: the event row has no error 0"
"$baize" chart bench-accuracy "$work/accuracy.csv" --png "$work/accuracy.png" --width 480 \
  --height 320 >"$work/out" || fail "chart bench-accuracy exited $?"
grep -qxF "wrote $work/accuracy.png" "$work/out" || fail "no 'wrote' line for the accuracy chart"
check_png 480 320 "$work/accuracy.png"
count_palette_colours 3 "$work/accuracy.png"  # event, fixed-step, box2d
"$baize" chart bench-accuracy "$work/accuracy.csv" --png "$work/accuracy-again.png" --width 480 \
  --height 320 >/dev/null || fail "second chart bench-accuracy exited $?"
cmp -s "$work/accuracy.png" "$work/accuracy-again.png" || fail "accuracy chart differs between runs"
# With the "shots" column the rows of each subset make their own series: 3 engines x 2 subsets.
python3 - "$work/accuracy.csv" "$work/subsets.csv" <<'EOF_PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
with open(sys.argv[2], "w") as out:
    out.write("engine,setting,median_us,position_error_m,outcome_mismatch,shots\n")
    for subset, scale in (("all", 1.0), ("no-breaks", 0.5)):
        for r in rows:
            error = float(r["position_error_m"]) * scale
            out.write(f'{r["engine"]},{r["setting"]},{r["median_us"]},{error},{r["outcome_mismatch"]},{subset}\n')
EOF_PY
"$baize" chart bench-accuracy "$work/subsets.csv" --png "$work/subsets.png" --width 480 \
  --height 320 >/dev/null || fail "chart bench-accuracy with subsets exited $?"
count_palette_colours 6 "$work/subsets.png"
# Only the event loop's rows: every error is 0, and the chart still draws them (on the default floor).
head -2 "$work/accuracy.csv" >"$work/event-only.csv"
"$baize" chart bench-accuracy "$work/event-only.csv" --png "$work/event-only.png" >/dev/null ||
  fail "an all-zero error table was refused"
count_palette_colours 1 "$work/event-only.png"
# A negative error is refused with the file, line and column; nothing is written.
sed 's/^fixed-step,dt=1ms,\([^,]*\),[^,]*,/fixed-step,dt=1ms,\1,-0.5,/' "$work/accuracy.csv" >"$work/negative.csv"
line=$(grep -n ',-0.5,' "$work/negative.csv" | cut -d: -f1)
[[ -n "$line" ]] || fail "test setup: no negative error written"
expect_error 2 "$work/negative.csv line $line, column position_error_m = -0.5 is not allowed" \
  chart bench-accuracy "$work/negative.csv" --png "$work/negative.png"
[[ ! -e "$work/negative.png" && ! -e "$work/negative.png.tmp" ]] || fail "a refused accuracy chart left a file"
expect_error 2 "no column 'engine'" chart bench-accuracy "$work/bench.csv" --png "$work/x.png"
expect_error 2 "--png is required" chart bench-accuracy "$work/accuracy.csv"

echo "chart CLI: all checks passed"
