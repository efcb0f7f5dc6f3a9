#!/usr/bin/env bash
# baize plan, sweep --png and check --png-dir, run the way a user runs them: a plan's report and
# picture, bad flags (exit 2, a message naming the flag, no file written), the position map's PNG
# and pictures of failing suite cases only.
# Usage: plan_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export GALLIUM_DRIVER=llvmpipe

# PNG width and height from its IHDR chunk.
png_size() { python3 -c 'import struct,sys; d=open(sys.argv[1],"rb").read(24); assert d[:8]==b"\x89PNG\r\n\x1a\n"; print("%dx%d" % struct.unpack(">II", d[16:24]))' "$1"; }

# How many pixels of a PNG lie within 12 (0-255, per channel) of the colour R,G,B (an 8-bit RGBA
# PNG as render/png_writer writes it, decoded here with zlib and the five row filters).
count_colour() {
  python3 - "$@" <<'PY'
import struct, sys, zlib
path, r, g, b = sys.argv[1], *map(int, sys.argv[2:5])
data = open(path, "rb").read()
pos, idat = 8, b""
while pos < len(data):
    (length,) = struct.unpack(">I", data[pos:pos + 4])
    kind = data[pos + 4:pos + 8]
    body = data[pos + 8:pos + 8 + length]
    if kind == b"IHDR":
        width, height, depth, colour = struct.unpack(">IIBB", body[:10])
        assert depth == 8 and colour == 6, (depth, colour)
    elif kind == b"IDAT":
        idat += body
    pos += 12 + length
raw = zlib.decompress(idat)
stride = width * 4
previous = bytearray(stride)
count = 0
for y in range(height):
    f = raw[y * (stride + 1)]
    row = bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = row[i - 4] if i >= 4 else 0
        up = previous[i]
        c = previous[i - 4] if i >= 4 else 0
        if f == 1: row[i] = (row[i] + a) & 255
        elif f == 2: row[i] = (row[i] + up) & 255
        elif f == 3: row[i] = (row[i] + (a + up) // 2) & 255
        elif f == 4:
            p = a + up - c
            pa, pb, pc = abs(p - a), abs(p - up), abs(p - c)
            row[i] = (row[i] + (a if pa <= pb and pa <= pc else up if pb <= pc else c)) & 255
    for x in range(0, stride, 4):
        if abs(row[x] - r) <= 12 and abs(row[x + 1] - g) <= 12 and abs(row[x + 2] - b) <= 12:
            count += 1
    previous = row
print(count)
PY
}
# The region outline's magenta (tools/baize/overlay_pictures.cpp) and the map's colour scale ends
# (render/overlay_items.cpp: plasma at 0 and 1).
magenta="255 51 217"
scale_first="13 8 135"
scale_last="240 249 33"

# Ball 1 straight in to the top-right corner along its 45 deg axis (the positional drills' layout).
cat >"$work/straight.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool",
 "balls": {"cue": [0.1689, -0.4661], "1": [0.5629, -0.0721]},
 "shot": {"aim_at": "1", "speed_mps": 1.0}}
JSON

# A plan with its picture. The stop region: 5 cm around the ghost-ball position.
"$baize" plan "$work/straight.json" --ball 1 --pocket top-right \
  --region circle:0.5225,-0.1125,0.05 --budget 2500 --noise-samples 100 --png "$work/plan.png" \
  >"$work/plan.txt" || fail "plan exited $?"
grep -q "^planner: .* shots simulated" "$work/plan.txt" || fail "no planner line: $(cat "$work/plan.txt")"
grep -q "^  1\. speed .* tip height -" "$work/plan.txt" || fail "the best shot is no stun: $(cat "$work/plan.txt")"
[ "$(png_size "$work/plan.png")" = 1600x800 ] || fail "plan.png is $(png_size "$work/plan.png")"
[ -z "$(ls "$work" | grep '\.tmp$' || true)" ] || fail "a temporary file was left"
# The region is drawn: a 5 cm circle 3 px wide is some hundreds of magenta pixels.
[ "$(count_colour "$work/plan.png" $magenta)" -gt 100 ] || fail "plan.png shows no region"

# Bad flags: exit 2, the flag named, no picture written.
expect_usage() {
  local what=$1; shift
  set +e
  "$baize" plan "$work/straight.json" "$@" --png "$work/bad.png" >/dev/null 2>"$work/err.txt"
  local status=$?
  set -e
  [ $status -eq 2 ] || fail "$what: exit $status, not 2"
  grep -q -- "$what" "$work/err.txt" || fail "$what: message $(cat "$work/err.txt")"
  [ ! -e "$work/bad.png" ] || fail "$what: a picture was written"
}
expect_usage "--budget" --ball 1 --pocket 3 --budget 10
expect_usage "--region" --ball 1 --pocket 3 --region circle:0.5,0.1
expect_usage "--region" --ball 1 --pocket 3 --region rectangle:0.5,0.1,0.4,0.2
# Regions wholly off the table (the cue ball's centre stops within the noses less a radius).
expect_usage "--region circle:5,5,0.1 is not allowed: it lies wholly off the table" \
  --ball 1 --pocket 3 --region circle:5,5,0.1
expect_usage "--region rectangle:2,0,3,1 is not allowed: it lies wholly off the table" \
  --ball 1 --pocket 3 --region rectangle:2,0,3,1
expect_usage "--pocket" --ball 1 --pocket nowhere
expect_usage "ball 9" --ball 9 --pocket 3
expect_usage "ball cue" --ball cue --pocket 3
expect_usage "--noise-samples" --ball 1 --pocket 3 --noise-samples 0

# sweep --png: the map at 1600 x 800, with --noise too; the CSV is unchanged by --png.
"$baize" sweep "$work/straight.json" --vary speed=0.5:2:0.5 --vary tip-height=-0.3:0.3:0.3 \
  --noise 5 --csv "$work/a.csv" --png "$work/map.png" 2>/dev/null || fail "sweep --png exited $?"
[ "$(png_size "$work/map.png")" = 1600x800 ] || fail "map.png is $(png_size "$work/map.png")"
"$baize" sweep "$work/straight.json" --vary speed=0.5:2:0.5 --vary tip-height=-0.3:0.3:0.3 \
  --noise 5 --csv "$work/b.csv" || fail "sweep exited $?"
cmp -s "$work/a.csv" "$work/b.csv" || fail "--png changed the CSV"
# The first and the last speed are both on the map, in the scale's two end colours.
[ "$(count_colour "$work/map.png" $scale_first)" -gt 20 ] || fail "map.png lacks the first speed"
[ "$(count_colour "$work/map.png" $scale_last)" -gt 20 ] || fail "map.png lacks the last speed"
# An unwritable --png: exit 2 before any work, and no CSV.
set +e
"$baize" sweep "$work/straight.json" --vary speed=0.5:1:0.5 --csv "$work/c.csv" \
  --png "$work/a.csv/map.png" 2>"$work/err.txt"
status=$?
set -e
[ $status -eq 2 ] || fail "sweep with a bad --png exited $status"
grep -q -- "--png" "$work/err.txt" || fail "sweep --png message: $(cat "$work/err.txt")"
[ ! -e "$work/c.csv" ] || fail "sweep with a bad --png wrote its CSV"

# check --png-dir: only the failing case gets a picture.
cat >"$work/suite.json" <<'JSON'
{"cases": [
  {"name": "pots", "scene": "straight.json", "shot": {"aim_at": "1", "speed_mps": 1.5},
   "expect": {"pocketed": ["1"]}},
  {"name": "stops/too far", "scene": "straight.json", "shot": {"aim_at": "1", "speed_mps": 1.5},
   "expect": {"pocketed": ["1"], "cue_ball_stops_in": {"circle": [-1.0, 0.4, 0.05]}}},
  {"name": "leave", "scene": "straight.json", "shot": {"aim_at": "1", "speed_mps": 0.2},
   "expect": {"cue_ball_stops_in": {"straight_shot_at": "1", "into_pocket": "top-right"},
              "pocketed": ["1"]}}
]}
JSON
set +e
# An earlier run's picture (Baize's case_*.png name) is removed first: the folder shows this run.
mkdir -p "$work/failed" && echo old >"$work/failed/case_fixed_since.png"
"$baize" check "$work/suite.json" --png-dir "$work/failed" >"$work/check.txt"
status=$?
set -e
[ $status -eq 1 ] || fail "check exited $status, not 1: $(cat "$work/check.txt")"
ls "$work/failed" | sort >"$work/pictures.txt"
printf 'case_leave.png\ncase_stops_too_far.png\n' | cmp -s - "$work/pictures.txt" ||
  fail "check --png-dir wrote $(cat "$work/pictures.txt")"
# A folder holding a file Baize did not write is refused before any case runs, and left as it was.
echo mine >"$work/failed/notes.txt"
set +e
err=$("$baize" check "$work/suite.json" --png-dir "$work/failed" 2>&1 >/dev/null); status=$?
set -e
[ $status -eq 2 ] || fail "check --png-dir on a user's folder exited $status, not 2"
grep -q -- "--png-dir = $work/failed is not allowed: it holds 'notes.txt'" <<<"$err" || fail "message: $err"
[ -e "$work/failed/case_leave.png" ] || fail "a refused folder lost its pictures"
rm "$work/failed/notes.txt"
[ "$(png_size "$work/failed/case_stops_too_far.png")" = 1600x800 ] || fail "case picture size"
[ "$(count_colour "$work/failed/case_stops_too_far.png" $magenta)" -gt 100 ] ||
  fail "the failing case's picture shows no region"
# A soft roll that leaves ball 1 on the table fails "pocketed" but keeps the straight shot: its
# picture shows the ghost-ball ring and the two paths.
grep -q "^FAIL leave | cue_ball_stops_in ok" "$work/check.txt" || fail "leave: $(cat "$work/check.txt")"
[ "$(count_colour "$work/failed/case_leave.png" $magenta)" -gt 100 ] ||
  fail "the straight shot's ghost ball and paths are not drawn"
echo "ok"
