#!/usr/bin/env bash
# baize simulate, run the way a user runs it: the shipped scenes, --json, and bad input.
# Usage: simulate_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# The 9-ball break: the summary names the first ball hit (the 1: the shot aims at it) and the rest.
out=$("$baize" simulate "$root/assets/scenes/9-ball-break.json") || fail "9-ball break exited $?"
grep -q "^first ball hit: 1$" <<<"$out" || fail "first ball hit: $out"
for line in "^pocketed: [0-9] ([a-z-]*)" "^cushion and jaw contacts: [0-9]* (cue ball [0-9]*)$" \
  "^foul: none$" "^events: [0-9]" "^predictions: [0-9]* solved, [0-9]* skipped$" "^wall time:"; do
  grep -q "$line" <<<"$out" || fail "missing '$line' in: $out"
done

# --cushion-model and --ball-ball-model: the registries' models by name, in place of the scene's.
flagged=$("$baize" simulate "$root/assets/scenes/9-ball-break.json" --cushion-model simple \
  --ball-ball-model mathavan2014) || fail "--cushion-model exited $?"
grep -q "^models: cushion simple, ball-ball mathavan2014$" <<<"$flagged" || fail "models: $flagged"
if msg=$("$baize" simulate "$root/assets/scenes/9-ball-break.json" --cushion-model rigid 2>&1); then
  fail "--cushion-model rigid was accepted"
fi
grep -q "rigid" <<<"$msg" || fail "message for --cushion-model rigid: $msg"

# --json: the events in time order and a final state for each of the 10 balls.
"$baize" simulate "$root/assets/scenes/9-ball-break.json" --json "$work/break.json" >/dev/null ||
  fail "--json exited $?"
python3 - "$work/break.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
assert d["format"] == "baize-result" and d["version"] == 1, (d["format"], d["version"])
assert d["source"].endswith("9-ball-break.json") and d["scene"]["rack"] == {"name": "9-ball"}, d["scene"]
times = [e["time_s"] for e in d["events"]]
assert times == sorted(times), "events in time order"
assert d["event_count"] == len(d["events"]), d["event_count"]
final = d["final_positions_m"]
assert set(final) == {"cue"} | {str(i) for i in range(1, 10)}, final
assert d["first_ball_hit"] == "1", d["first_ball_hit"]
# A pocketed ball is listed with its pocket, matching its pocket event, and has no final position.
names = ["bottom-left", "bottom-middle", "bottom-right", "top-right", "top-middle", "top-left"]
pocketed = {p["ball"]: p["pocket"] for p in d["pocketed"]}
for ball in final:
    falls = [e for e in d["events"] if e["type"] == "pocket" and e["ball"] == ball]
    assert (ball in pocketed) == bool(falls) == (final[ball] is None), ball
    if falls:
        assert pocketed[ball] == names[falls[0]["index"]], (ball, pocketed)
    contacts = [e for e in d["events"] if e["type"] in ("cushion", "jaw") and e["ball"] == ball]
    assert d["cushion_contacts"][ball] == len(contacts), ball
assert pocketed, "the break pockets a ball"
assert d["foul"] == "none", d["foul"]
assert d["predictions"]["solved"] > 0 and d["predictions"]["skipped"] > 0, d["predictions"]
assert "samples" not in d
# Trajectories: per ball, pieces starting at 0 in time order; the cue ball's first piece is the strike.
assert set(d["trajectories"]) == set(final)
for pieces in d["trajectories"].values():
    starts = [q["start_time_s"] for q in pieces]
    assert starts[0] == 0 and starts == sorted(starts), starts
assert d["trajectories"]["cue"][0]["velocity_mps"][0] > 5, "struck at break speed"
# The physics echo: the defaults of a pool table, in the scene format's keys.
p = d["physics"]
assert p["cushion"]["model"] == "tabulated" and p["ball_ball"]["model"] == "frictional", p
assert p["cloth"]["rolling_friction"] == 0.01 and "squirt_end_mass_kg" not in p["cue"], p
PY
grep -q "^models: cushion tabulated, ball-ball frictional$" <<<"$out" || fail "models line: $out"

# --sample BALL@TIME: the state at that time, as the trajectory's closed form gives it. At 0 the
# cue ball is where the scene put it, moving as struck (the printed line agrees with the JSON);
# after the end every ball is at rest where it stopped, or in its pocket; the JSON carries the
# same samples.
out=$("$baize" simulate "$root/assets/scenes/9-ball-break.json" --sample cue@0 --sample 9@1000 \
  --sample cue@0.05 --sample 6@1000 --json "$work/sampled.json") || fail "--sample exited $?"
python3 - "$work/sampled.json" "$out" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
s = d["samples"]
assert [(x["ball"], x["time_s"]) for x in s] == [("cue", 0), ("9", 1000), ("cue", 0.05), ("6", 1000)], s
final = d["final_positions_m"]
pocketed = {p["ball"]: p["pocket"] for p in d["pocketed"]}
line = [l for l in sys.argv[2].splitlines() if l.startswith("sample cue@0:")][0]
expected = "sample cue@0: position [%.4f, %.4f] m, velocity [%.4f, %.4f, %.4f] m/s" % (
    *s[0]["position_m"], *s[0]["velocity_mps"])
assert line.startswith(expected), (line, expected)
assert s[0]["position_m"] == d["trajectories"]["cue"][0]["position_m"], s[0]
assert s[0]["velocity_mps"] == d["trajectories"]["cue"][0]["velocity_mps"], s[0]
assert final["9"] is not None and not s[1]["pocketed"], (final["9"], s[1])
assert s[1]["position_m"] == final["9"] and s[1]["velocity_mps"] == [0, 0, 0], s[1]
# The 6 falls in the break: its sample says where and since when, as its pocket event does.
fall = [e for e in d["events"] if e["type"] == "pocket" and e["ball"] == "6"][0]
assert s[3]["pocketed"] and s[3]["pocket"] == pocketed["6"], s[3]
assert s[3]["fell_at_s"] == fall["time_s"] and "velocity_mps" not in s[3], s[3]
assert "sample 6@1000: in the %s pocket since" % pocketed["6"] in sys.argv[2]
# Before the first collision the cue ball (struck below centre: it slides, its slip along +x)
# slows at mu_s g: v = v0 - mu_s g t, x = x0 + v0 t - mu_s g t^2 / 2, with the run's mu_s and
# g = 9.81 m/s^2 (physics::ClothParams).
v0, t, a = s[0]["velocity_mps"][0], 0.05, d["physics"]["cloth"]["sliding_friction"] * 9.81
assert abs(s[2]["velocity_mps"][0] - (v0 - a * t)) < 1e-9, s[2]
assert abs(s[2]["position_m"][0] - (s[0]["position_m"][0] + v0 * t - a * t * t / 2)) < 1e-9, s[2]
PY
for bad in "cue" "ghost@1" "cue@-1" "cue@nan" "cue@1s"; do
  set +e
  msg=$("$baize" simulate "$root/assets/scenes/stun-shot.json" --sample "$bad" 2>&1 >/dev/null)
  status=$?
  set -e
  [[ $status -eq 2 ]] || fail "--sample $bad exited $status, expected 2"
  grep -q -- "--sample '$bad' is not allowed" <<<"$msg" || fail "message for $bad: $msg"
done

# A scene choosing other models: the summary and the echo say so.
cat >"$work/simple.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool", "balls": {"cue": [0.6, 0]},
 "shot": {"heading_deg": 0, "speed_mps": 0.8, "side": 0.2},
 "physics": {"cushion": {"model": "simple", "simple_restitution": 0.6},
             "cue": {"squirt_end_mass_kg": 0.01}}}
JSON
out=$("$baize" simulate "$work/simple.json" --json "$work/simple-out.json") ||
  fail "simple-cushion scene exited $?"
grep -q "^models: cushion simple, ball-ball frictional, squirt$" <<<"$out" || fail "models: $out"
# The speed-dependent restitution is named in the models line.
python3 -c "import json; print(json.dumps({'table': 'snooker-12ft', 'ball_set': 'snooker', 'balls': {'cue': [-1.2, 0.0]}, 'shot': {'heading_deg': 0, 'speed_mps': 3.5, 'height': 0.4}, 'physics': {'cushion': json.load(open('$root/assets/measurements/snooker-speed-dependence.json'))['cushion']}}))" >"$work/law.json"
out=$("$baize" simulate "$work/law.json")
grep -q "^models: cushion tabulated with speed-dependent restitution, ball-ball frictional$" <<<"$out" ||
  fail "models with a law: $out"
python3 - "$work/simple-out.json" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))["physics"]
assert p["cushion"] == {"model": "simple", "simple_restitution": 0.6}, p["cushion"]
assert p["cue"]["squirt_end_mass_kg"] == 0.01, p["cue"]
PY
[[ -f "$work/break.json.tmp" ]] && fail "a temporary file was left behind"

# Bad input: exit 2, a message naming the key; nothing written.
cat >"$work/bad.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool", "rack": {"name": "9-ball"},
 "shot": {"aim_at": "1", "speed_mps": 6, "spin": 3}}
JSON
set +e
msg=$("$baize" simulate "$work/bad.json" --json "$work/never.json" 2>&1 >/dev/null); status=$?
set -e
[[ $status -eq 2 ]] || fail "bad scene exited $status, expected 2"
grep -q "shot.spin" <<<"$msg" || fail "message does not name shot.spin: $msg"
[[ -e "$work/never.json" || -e "$work/never.json.tmp" ]] && fail "output written for a bad scene"
# The audit's reproductions: each refused with exit 2 naming the file, the key and the value as
# written, and nothing written.
refuse() {  # refuse NAME SCENE-TEXT EXPECTED-PART...
  local name=$1 text=$2
  shift 2
  printf '%s\n' "$text" >"$work/$name.json"
  set +e
  msg=$("$baize" simulate "$work/$name.json" --json "$work/$name-out.json" 2>&1 >/dev/null)
  status=$?
  set -e
  [[ $status -eq 2 ]] || fail "$name exited $status, expected 2: $msg"
  for part in "$name.json: " "$@"; do
    grep -qF -- "$part" <<<"$msg" || fail "$name: message lacks '$part': $msg"
  done
  [[ -e "$work/$name-out.json" || -e "$work/$name-out.json.tmp" ]] && fail "$name: output written"
  return 0
}
base='"table": "pool-9ft", "ball_set": "pool", "rack": {"name": "9-ball"}'
refuse fast "{$base, \"shot\": {\"aim_at\": \"1\", \"speed_mps\": 800}}" \
  "shot.speed_mps = 800 is not allowed" "(0, 12.3] m/s"
refuse steep "{$base, \"shot\": {\"aim_at\": \"1\", \"speed_mps\": 6, \"elevation_deg\": 95}}" \
  "shot.elevation_deg = 95 is not allowed" "[0, 90) deg"
refuse miscue "{$base, \"shot\": {\"aim_at\": \"1\", \"speed_mps\": 6, \"side\": 0.7}}" \
  "shot.side = 0.7 is not allowed" "miscues"
refuse jitter '{"table": "pool-9ft", "ball_set": "pool",
 "rack": {"name": "9-ball", "jitter_seed": 7, "jitter_m": 0.01},
 "shot": {"aim_at": "1", "speed_mps": 6}}' "rack.jitter_m = 0.01 is not allowed" "[0, 5e-04] m"
refuse twice '{"table": "pool-9ft", "ball_set": "pool", "balls": {"cue": [-0.6, 0], "cue": [0, 0]},
 "shot": {"heading_deg": 0, "speed_mps": 1}}' "balls.cue appears twice"

set +e
msg=$("$baize" simulate "$work/missing.json" 2>&1 >/dev/null); status=$?
set -e
[[ $status -ne 0 ]] || fail "a missing scene file was accepted"
grep -q "missing.json" <<<"$msg" || fail "message does not name the file: $msg"
# An endless input is refused at the size limit (exit 2, naming it), not read until memory ends.
set +e
msg=$(timeout 60 "$baize" simulate /dev/zero 2>&1 >/dev/null); status=$?
set -e
[[ $status -eq 2 ]] || fail "simulate /dev/zero exited $status: $msg"
grep -q "/dev/zero: the file is larger than 256 MiB" <<<"$msg" || fail "message: $msg"
# A table file whose corner capture circle sits far behind the mouth (or is too small) would let
# the cue ball run out through the corner pocket: the scene is refused (exit 2) naming the table
# file, the key and its value, instead of a ball stopping metres off the table with exit 0.
for change in "capture_offset_m 0.5" "capture_radius_m 0.02"; do
  set -- $change
  python3 - "$root/assets/tables/pool-9ft.json" "$work/leaky.json" "$1" "$2" <<'PY'
import json, sys
table = json.load(open(sys.argv[1]))
table["corner_pocket"][sys.argv[3]] = float(sys.argv[4])
json.dump(table, open(sys.argv[2], "w"))
PY
  cat >"$work/leaky-scene.json" <<'JSON'
{"table": "leaky.json", "ball_set": "pool", "balls": {"cue": [0.9, 0.3]},
 "shot": {"heading_deg": 45, "speed_mps": 3}}
JSON
  set +e
  msg=$("$baize" simulate "$work/leaky-scene.json" 2>&1 >/dev/null); status=$?
  set -e
  [[ $status -eq 2 ]] || fail "a table letting balls out ($change) exited $status, expected 2"
  grep -q "leaky.json: corner_pocket.$1 = $2 is not allowed" <<<"$msg" ||
    fail "message does not name the table file, key and value ($change): $msg"
done
set --

# baize bench shots, smoke size: one row per shipped scene plus the random set, the CSV as printed.
out=$("$baize" bench shots --repeat 1 --random-shots 20 --csv "$work/shots.csv") ||
  fail "bench shots exited $?"
# The full cushion model's time over the simple rule's on the same shots, as the two rows give it.
ratio=$(grep -oP "^random single shots with the full cushion model / with the simple rule at every cushion: \K[0-9.e+]+(?=x)" <<<"$out") ||
  fail "no ratio line in: $out"
# The same ratio of the shots' total times, beside it (a positive number).
total_ratio=$(grep -oP "^random single shots with the full cushion model .* of their total times: \K[0-9.e+]+(?=x)" <<<"$out") ||
  fail "no ratio of total times in: $out"
python3 -c "import sys; assert float(sys.argv[1]) > 0, sys.argv[1]" "$total_ratio" ||
  fail "ratio of total times not a positive number: $total_ratio"
python3 - "$work/shots.csv" "$root/assets/scenes" "$ratio" <<'PY'
import csv, os, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert list(rows[0]) == ["scene", "one_core_us", "two_core_wall_us", "events"], list(rows[0])
scenes = sorted(f[:-5] for f in os.listdir(sys.argv[2]) if f.endswith(".json"))
assert [r["scene"] for r in rows] == scenes + ["random-single-shots", "random-single-shots-simple"], [r["scene"] for r in rows]
assert all(float(r["one_core_us"]) > 0 and float(r["events"]) >= 1 for r in rows), rows
# Two cores where a second core is there to hand over, "nan" (and said so) where it is not.
two = [float(r["two_core_wall_us"]) for r in rows]
assert all(t > 0 for t in two) or all(t != t for t in two), two
by_scene = {r["scene"]: float(r["one_core_us"]) for r in rows}
ratio = by_scene["random-single-shots"] / by_scene["random-single-shots-simple"]
assert abs(ratio / float(sys.argv[3]) - 1) < 1e-2, (ratio, sys.argv[3])
PY
# --cushion-tolerance: the runs use it and say so; a value outside the solver's range is refused
# (exit 2, the flag named, nothing written).
out=$("$baize" bench shots --repeat 1 --random-shots 5 --cushion-tolerance 1e-8 \
  --csv "$work/tolerance.csv") || fail "bench shots --cushion-tolerance 1e-8 exited $?"
grep -q "cushion impacts solved to tolerance 1e-08" <<<"$out" || fail "no tolerance line in: $out"
python3 - "$work/tolerance.csv" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert list(rows[0]) == ["scene", "one_core_us", "two_core_wall_us", "events", "cushion_tolerance"], rows[0]
assert all(float(r["cushion_tolerance"]) == 1e-8 for r in rows), rows
PY
for bad in 1e-5 0 -1 nan ""; do
  set +e
  msg=$("$baize" bench shots --repeat 1 --random-shots 5 --cushion-tolerance "$bad" \
    --csv "$work/never.csv" 2>&1 >/dev/null)
  status=$?
  set -e
  [[ $status -eq 2 ]] || fail "--cushion-tolerance $bad exited $status, expected 2"
  grep -q -- "--cushion-tolerance" <<<"$msg" || fail "message does not name the flag: $msg"
  [[ -e "$work/never.csv" ]] && fail "CSV written for --cushion-tolerance $bad"
done
# Outputs: a symbolic link is followed (the file it names is replaced, the link stays), a directory
# is refused before any work (exit 2, nothing written), and output that cannot be written (a full
# device) fails the command (exit 1).
scene="$root/assets/scenes/stun-shot.json"
echo old >"$work/real.json"
ln -s real.json "$work/link.json"
"$baize" simulate "$scene" --json "$work/link.json" >/dev/null || fail "--json through a link exited $?"
[[ -L "$work/link.json" ]] || fail "the link was replaced"
python3 -c "import json, sys; json.load(open(sys.argv[1]))['events']" "$work/real.json" ||
  fail "the link's file does not hold the result"
mkdir "$work/folder"
set +e
msg=$("$baize" simulate "$scene" --json "$work/folder" 2>&1 >/dev/null); status=$?
set -e
[[ $status -eq 2 ]] || fail "--json DIRECTORY exited $status, expected 2"
grep -qF -- "--json = $work/folder is not allowed: it is a directory" <<<"$msg" || fail "message: $msg"
[[ -z "$(ls -A "$work/folder")" ]] || fail "something was written into the directory"
# An empty path is refused, not taken for "no output" (every path flag has the same check).
set +e
msg=$("$baize" simulate "$scene" --json '' 2>&1 >/dev/null); status=$?
set -e
[[ $status -eq 2 ]] || fail "--json '' exited $status, expected 2"
grep -qF -- "--json: an empty value is not allowed" <<<"$msg" || fail "message: $msg"
# /dev/stdout is written straight: into a pipe, and appended to a file the shell opened (what the
# file held is kept).
piped=$("$baize" simulate "$scene" --json /dev/stdout | cat) || fail "--json /dev/stdout into a pipe exited $?"
grep -q '"events"' <<<"$piped" || fail "--json /dev/stdout wrote nothing into the pipe"
echo kept >"$work/log"
"$baize" simulate "$scene" --json /dev/stdout >>"$work/log" || fail "--json /dev/stdout >> log exited $?"
[[ "$(head -1 "$work/log")" == kept ]] || fail "--json /dev/stdout replaced the log"
grep -q '"events"' "$work/log" || fail "--json /dev/stdout wrote nothing into the log"
# A named pipe that no program reads is refused (writing would wait forever); a loop of links too.
mkfifo "$work/pipe"
ln -s loop-b "$work/loop-a"
ln -s loop-a "$work/loop-b"
for target in pipe:"it is a named pipe that no program reads" loop-a:"it is a loop of symbolic links"; do
  set +e
  msg=$(timeout 20 "$baize" simulate "$scene" --json "$work/${target%%:*}" 2>&1 >/dev/null); status=$?
  set -e
  [[ $status -eq 2 ]] || fail "--json ${target%%:*} exited $status, expected 2"
  grep -qF "${target#*:}" <<<"$msg" || fail "message: $msg"
done
if [[ -w /dev/full ]]; then
  set +e
  msg=$("$baize" simulate "$scene" 2>&1 >/dev/full); status=$?
  set -e
  [[ $status -eq 1 ]] || fail "simulate > /dev/full exited $status, expected 1"
  grep -qF "standard output could not be written" <<<"$msg" || fail "message: $msg"
  set +e
  "$baize" --help >/dev/full 2>/dev/null; status=$?
  set -e
  [[ $status -eq 1 ]] || fail "--help > /dev/full exited $status, expected 1"
fi
# Impacts beyond the cushion model's range: the summary line counts the result's
# "beyond_model_range" (cushion and jaw events faster than the limit); the scene's limit changes it.
out=$("$baize" simulate "$root/assets/scenes/8-ball-break.json" --json "$work/range.json") ||
  fail "8-ball break exited $?"
line=$(grep "^beyond the cushion model's range: " <<<"$out") || fail "no range line: $out"
python3 - "$work/range.json" "$line" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
beyond = d["beyond_model_range"]
assert beyond, "a break hits cushions above 2.5 m/s"
assert sys.argv[2] == f"beyond the cushion model's range: {len(beyond)} impact{'s' if len(beyond) != 1 else ''} (normal speed above 2.5 m/s)", sys.argv[2]
for i in beyond:
    e = d["events"][i]
    assert e["type"] in ("cushion", "jaw"), e
    assert math.hypot(*e["before"][0]["velocity_mps"][:2]) > 2.5, e  # faster than its normal part
PY
python3 - "$root/assets/scenes/8-ball-break.json" "$work/range-high.json" "$work/range-bad.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
d["physics"] = {"cushion": {"valid_normal_speed_mps": 100}}
json.dump(d, open(sys.argv[2], "w"))
d["physics"]["cushion"]["valid_normal_speed_mps"] = -1
json.dump(d, open(sys.argv[3], "w"))
PY
out=$("$baize" simulate "$work/range-high.json") || fail "raised limit exited $?"
grep -qx "beyond the cushion model's range: 0 impacts (normal speed above 100 m/s)" <<<"$out" ||
  fail "raised limit: $out"
set +e
msg=$("$baize" simulate "$work/range-bad.json" 2>&1 >/dev/null); status=$?
set -e
[[ $status -ne 0 ]] || fail "a negative limit was accepted"
grep -qF "physics.cushion.valid_normal_speed_mps = -1 is not allowed" <<<"$msg" || fail "message: $msg"

echo "simulate CLI: all checks passed"
