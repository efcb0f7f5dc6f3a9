#!/usr/bin/env bash
# baize plan, sweep --png and check --png, run the way a user runs them: a plan's report and
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

# Ball 1 straight in to the top-right corner along its 45 deg axis (the positional drills' layout).
cat >"$work/straight.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool",
 "balls": {"cue": [0.1689, -0.4661], "1": [0.5629, -0.0721]},
 "shot": {"aim_at": "1", "speed_mps": 1.0}}
JSON

# A plan with its picture. The stop region: 5 cm around the ghost-ball position.
"$baize" plan "$work/straight.json" --ball 1 --pocket top-right \
  --region circle:0.5225,-0.1125,0.05 --budget 1000 --noise-samples 100 --png "$work/plan.png" \
  >"$work/plan.txt" || fail "plan exited $?"
grep -q "^planner: .* shots simulated" "$work/plan.txt" || fail "no planner line: $(cat "$work/plan.txt")"
grep -q "^  1\. speed .* tip height -" "$work/plan.txt" || fail "the best shot is no stun: $(cat "$work/plan.txt")"
[ "$(png_size "$work/plan.png")" = 1600x800 ] || fail "plan.png is $(png_size "$work/plan.png")"
[ -z "$(ls "$work" | grep '\.tmp$' || true)" ] || fail "a temporary file was left"

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
# An unwritable --png: exit 2 before any work, and no CSV.
set +e
"$baize" sweep "$work/straight.json" --vary speed=0.5:1:0.5 --csv "$work/c.csv" \
  --png "$work/a.csv/map.png" 2>"$work/err.txt"
status=$?
set -e
[ $status -eq 2 ] || fail "sweep with a bad --png exited $status"
grep -q -- "--png" "$work/err.txt" || fail "sweep --png message: $(cat "$work/err.txt")"
[ ! -e "$work/c.csv" ] || fail "sweep with a bad --png wrote its CSV"

# check --png: only the failing case gets a picture.
cat >"$work/suite.json" <<'JSON'
{"cases": [
  {"name": "pots", "scene": "straight.json", "shot": {"aim_at": "1", "speed_mps": 1.5},
   "expect": {"pocketed": ["1"]}},
  {"name": "stops/too far", "scene": "straight.json", "shot": {"aim_at": "1", "speed_mps": 1.5},
   "expect": {"pocketed": ["1"], "cue_ball_stops_in": {"circle": [-1.0, 0.4, 0.05]}}},
  {"name": "leave", "scene": "straight.json", "shot": {"aim_at": "1", "speed_mps": 1.5},
   "expect": {"cue_ball_stops_in": {"straight_shot_at": "1", "into_pocket": "top-left"}}}
]}
JSON
set +e
"$baize" check "$work/suite.json" --png "$work/failed" >"$work/check.txt"
status=$?
set -e
[ $status -eq 1 ] || fail "check exited $status, not 1: $(cat "$work/check.txt")"
ls "$work/failed" | sort >"$work/pictures.txt"
printf 'leave.png\nstops_too_far.png\n' | cmp -s - "$work/pictures.txt" ||
  fail "check --png wrote $(cat "$work/pictures.txt")"
[ "$(png_size "$work/failed/stops_too_far.png")" = 1600x800 ] || fail "case picture size"
echo "ok"
