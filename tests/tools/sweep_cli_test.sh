#!/usr/bin/env bash
# baize sweep, run the way a user runs it: grids of one and two parameters, the CSV's shape, a
# physical relation along the grid (more top, more follow), miscue rows and bad --vary specs.
# Usage: sweep_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# The follow drill of assets/suites/positional-drills.json: a full hit along the top-right
# corner's 45 deg axis.
cat >"$work/follow.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool",
 "balls": {"cue": [0.1689, -0.4661], "1": [0.5629, -0.0721]},
 "shot": {"aim_at": "1", "speed_mps": 1.0268, "height": 0.4}}
JSON
"$baize" sweep "$work/follow.json" --vary tip-height=-0.4:0.4:0.1 --csv "$work/height.csv" ||
  fail "one-parameter sweep exited $?"
python3 - "$work/height.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert list(rows[0])[:2] == ["tip-height", "cue_x_m"], list(rows[0])
heights = [float(r["tip-height"]) for r in rows]
assert len(rows) == 9 and abs(heights[0] + 0.4) < 1e-12 and abs(heights[-1] - 0.4) < 1e-9, heights
for r in rows:
    assert r["error"] == "" and r["first_hit"] == "1", r
# With top (h >= 0) the object ball reaches the pocket; heavy draw slows the cue ball too much.
assert all(r["object_pocketed"] == "1" for r in rows if float(r["tip-height"]) >= 0), rows
# Along the line of the shot, from full draw to stun, the cue ball ends further forward for each
# step up: less backspin, and a faster ball too (the strike gives more speed nearer the centre).
# (Above the centre it is not monotonic at a fixed cue speed: the ball leaves slower.)
along = [(float(r["cue_x_m"]) + float(r["cue_y_m"])) / 2 ** 0.5 for r in rows]
draw_to_stun = [a for a, h in zip(along, heights) if h <= 1e-9]
assert all(b > a for a, b in zip(draw_to_stun, draw_to_stun[1:])), along
# h = 0.4 is the drill itself: the closed form (tools/positional_suite.py) puts the stop 0.394 m
# past the contact point [0.5225, -0.1125] along the 45 deg line: [0.8009, 0.1659].
x, y = float(rows[-1]["cue_x_m"]), float(rows[-1]["cue_y_m"])
assert ((x - 0.8009) ** 2 + (y - 0.1659) ** 2) ** 0.5 < 0.05, (x, y)
PY

# The issue's example grid: 15 speeds x 11 tip heights, speed outer.
"$baize" sweep "$work/follow.json" --vary speed=0.5:4:0.25 --vary tip-height=-0.5:0.5:0.1 \
  >"$work/grid.csv" || fail "two-parameter sweep exited $?"
python3 - "$work/grid.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 15 * 11, len(rows)
assert [float(r["speed"]) for r in rows[:12:11]] == [0.5, 0.75], rows[:12:11]
assert all(r["error"] == "" for r in rows), [r["error"] for r in rows if r["error"]]
PY

# Past the miscue limit the row says so and carries no values; the sweep goes on.
"$baize" sweep "$work/follow.json" --vary tip-height=0.3:0.6:0.1 >"$work/miscue.csv" ||
  fail "miscue sweep exited $?"
python3 - "$work/miscue.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 4, len(rows)
assert rows[1]["error"] == "" and rows[1]["cue_x_m"] != "", rows[1]
assert "miscue" in rows[3]["error"] and rows[3]["cue_x_m"] == "", rows[3]
PY

# --noise: the spread of a lone cue ball's roll. Struck at 0.3 m/s with natural roll it leaves at
# v0 = 1.75 * 0.3 / 1.7148 = 0.3061 m/s and rolls d = v0^2 / (2 mu_r g) = 0.478 m. The speed error
# (0.075 m/s on the cue, 0.0765 m/s on the ball, e = 0.25 of v0) spreads d = d0 (1 + e)^2 along the
# line: sd = d0 sqrt(4 e^2 + 2 e^4) = 0.243 m; the aim error (0.125 deg) across it: about
# 0.125 deg * sqrt(E[d^2]) = 1.13 mm. The tip errors add nothing on a level cue without squirt.
cat >"$work/roll.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool", "balls": {"cue": [-0.8, 0.0]},
 "shot": {"heading_deg": 0, "speed_mps": 0.3, "height": 0.4}}
JSON
"$baize" sweep "$work/roll.json" --vary speed=0.3:0.3:1 --noise 400 --seed 4 >"$work/noise-a.csv" ||
  fail "--noise exited $?"
"$baize" sweep "$work/roll.json" --vary speed=0.3:0.3:1 --noise 400 --seed 4 >"$work/noise-b.csv"
cmp -s "$work/noise-a.csv" "$work/noise-b.csv" || fail "--noise with the same seed differs"
python3 - "$work/noise-a.csv" <<'PY'
import csv, math, sys
(r,) = list(csv.DictReader(open(sys.argv[1])))
# 400 samples: the sample standard deviation has a relative standard error of about 5 % (more for
# the skewed (1 + e)^2); 15 % allows three of them.
tolerance = 0.15
major, minor = float(r["cue_sd_major_m"]), float(r["cue_sd_minor_m"])
assert abs(major / 0.243 - 1) < tolerance, major
assert abs(minor / 0.00113 - 1) < tolerance, minor
assert abs(float(r["cue_major_axis_deg"])) < 1, r  # along the roll, the x axis
assert float(r["p_cue_pocketed"]) == 0 and float(r["p_miscue"]) == 0, r
PY

for bad in "--vary spin=0:1:0.1" "--vary speed=2:1:0.1" "--vary speed=1:2:0" "--vary speed=1:2" \
  "--vary speed=1:2:1 --vary speed=1:2:1" "" "--vary speed=1:20:5" "--vary speed=0:1:0.5" \
  "--vary aim=0:1e300:1e299"; do
  set +e
  # shellcheck disable=SC2086
  "$baize" sweep "$work/follow.json" $bad >/dev/null 2>"$work/err.txt"
  status=$?
  set -e
  [[ $status == 2 ]] || fail "'$bad' must exit 2, got $status"
  grep -q -- "--vary" "$work/err.txt" || fail "'$bad': $(cat "$work/err.txt")"
done
echo "sweep CLI: ok"
