#!/usr/bin/env bash
# Runs `baize stress` the way a user does and checks what it prints and writes:
#   bash tests/tools/stress_cli_test.sh path/to/baize
# - 2600 shots (200 of each kind) pass every check (exit status 0), with many events and some balls
#   pocketed (the pocket tables are used);
# - the summary is the same for 1 and 2 threads, and --max-seconds stops after a first run of shots;
# - failing shots (forced: --max-events 20 makes most shots "hang") are written one file each:
#   scene files that `baize simulate` refuses with the same max_events error, state files that
#   `baize stress --replay` fails the same way; a passing shot replays as passing;
# - "on the table" with pockets: a ball beyond a corner has escaped, a ball in a pocket mouth has
#   not, and a table whose capture circles leave a pocket opening uncovered is refused;
# - bad flags and bad replay files are refused with status 2 and a message naming the value.
set -euo pipefail

baize=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

summary_re='^stress: shots ([0-9]+), events ([0-9]+), failed shots ([0-9]+), failed shots by kind (.*), largest energy growth .*shots/s$'

# ---- 1. A clean run over every kind of shot.
status=0
"$baize" stress --shots 2600 --seed 1 >"$work/out.txt" 2>"$work/err.txt" || status=$?
summary=$(grep '^stress: ' "$work/out.txt") || fail "no summary line in: $(cat "$work/out.txt")"
[[ $summary =~ $summary_re ]] || fail "summary line not in the expected form: $summary"
[[ ${BASH_REMATCH[1]} == 2600 ]] || fail "summary counts ${BASH_REMATCH[1]} shots, want 2600"
events=${BASH_REMATCH[2]}
failed=${BASH_REMATCH[3]}
(( events > 2600 * 10 )) || fail "too few events ($events) for 2600 shots: the scenes must exercise the loop"
(( failed == 0 )) || fail "$failed of 2600 shots failed: $(grep -A1 '^FAILED SHOT ' "$work/out.txt" | head -2)"
[[ $status == 0 ]] || fail "no failed shots but exit status $status"
[[ ${BASH_REMATCH[4]} == none ]] || fail "no failed shots but failures listed: ${BASH_REMATCH[4]}"
kinds=$(grep '^shots by kind:' "$work/out.txt") || fail "no 'shots by kind' line"
for kind in random "gap shot" "frozen line" "frozen triangle" "ball against a cushion" "tiny speed" \
  grazing near-simultaneous "in the mouth" "cue masse" "cue at pocket" "cue cluster" "cue tiny"; do
  [[ $kinds == *" $kind=200"* ]] || fail "kind '$kind' did not get 200 shots: $kinds"
done
pocketed=$(sed -n 's/^balls pocketed \([0-9]*\)$/\1/p' "$work/out.txt")
(( pocketed > 100 )) || fail "only '$pocketed' balls pocketed: the pocket tables are not exercised"

# ---- 2. Threads and the time budget do not change what a shot gives.
counts() { grep -E '^(stress|shots by kind|balls pocketed)' "$1" | sed 's/, largest energy.*//'; }
"$baize" stress --shots 400 --seed 5 --threads 1 >"$work/t1.txt"
"$baize" stress --shots 400 --seed 5 --threads 2 >"$work/t2.txt"
[[ $(counts "$work/t1.txt") == "$(counts "$work/t2.txt")" ]] ||
  fail "1 and 2 threads differ: $(counts "$work/t1.txt") / $(counts "$work/t2.txt")"
# The default, --threads 0, is the hardware concurrency: the same counts again.
"$baize" stress --shots 400 --seed 5 >"$work/t0.txt"
[[ $(counts "$work/t1.txt") == "$(counts "$work/t0.txt")" ]] ||
  fail "the default threads differ: $(counts "$work/t1.txt") / $(counts "$work/t0.txt")"
"$baize" stress --shots 100000000 --seed 5 --threads 2 --max-seconds 0.5 >"$work/budget.txt"
grep -q '^stopped by --max-seconds 0.5 after shots 0 to [0-9]* of 100000000$' "$work/budget.txt" ||
  fail "no budget line: $(cat "$work/budget.txt")"
done_shots=$(sed -n 's/^stress: shots \([0-9]*\),.*/\1/p' "$work/budget.txt")
(( done_shots > 0 && done_shots < 100000000 )) || fail "budget run did $done_shots shots"
"$baize" stress --shots "$done_shots" --seed 5 >"$work/prefix.txt"
[[ $(counts "$work/budget.txt") == "$(counts "$work/prefix.txt")" ]] ||
  fail "the budget run is not the first $done_shots shots: $(counts "$work/budget.txt") / $(counts "$work/prefix.txt")"

# ---- 3. Failing shots and their reproductions.
mkdir "$work/failures"
status=0
"$baize" stress --shots 52 --seed 3 --max-events 20 --failures "$work/failures" >"$work/f.txt" 2>&1 ||
  status=$?
[[ $status == 1 ]] || fail "forced failures exited $status, want 1: $(cat "$work/f.txt")"
summary=$(grep '^stress: ' "$work/f.txt")
[[ $summary =~ $summary_re ]] || fail "summary line not in the expected form: $summary"
failed=${BASH_REMATCH[3]}
(( failed >= 10 )) || fail "only $failed shots hit --max-events 20"
[[ ${BASH_REMATCH[4]} == "hang=$failed" ]] || fail "failures by kind: ${BASH_REMATCH[4]}"
(( $(ls "$work/failures" | wc -l) == failed )) || fail "$(ls "$work/failures" | wc -l) files for $failed failed shots"
grep -q "^reproductions: $failed written to $work/failures, $failed fail the same way on replay$" \
  "$work/f.txt" || fail "no reproduction line: $(grep reproductions "$work/f.txt")"
(( $(grep -c '^FAILED SHOT ' "$work/f.txt") == (failed < 10 ? failed : 10) )) ||
  fail "wrong number of FAILED SHOT lines"
scenes=("$work"/failures/*.scene.json)
states=("$work"/failures/*.state.json)
[[ -e ${scenes[0]} && -e ${states[0]} ]] || fail "want both scene and state files: $(ls "$work/failures")"
for scene in "${scenes[@]}"; do
  status=0
  "$baize" simulate "$scene" >/dev/null 2>"$work/err.txt" || status=$?
  [[ $status == 1 ]] || fail "baize simulate $scene exited $status, want 1 (the hang)"
  grep -q "did not come to rest within max_events = 20 events" "$work/err.txt" ||
    fail "baize simulate $scene: $(cat "$work/err.txt")"
done
for file in "${scenes[0]}" "${states[@]}"; do
  status=0
  "$baize" stress --replay "$file" >"$work/r.txt" 2>&1 || status=$?
  [[ $status == 1 ]] || fail "replay of $file exited $status, want 1"
  grep -q "FAILED hang: the shot did not come to rest within max_events = 20 events" "$work/r.txt" ||
    fail "replay of $file: $(cat "$work/r.txt")"
done
python3 - "${states[0]}" "$work/pass.state.json" <<'EOF_PY'
import json, sys
state = json.load(open(sys.argv[1]))
assert state["format"] == "baize stress state" and state["first_failure"].startswith("hang: "), state
for b in state["balls"]:
    assert len(b["position"]) == 2 and len(b["velocity"]) == 3 and len(b["angular_velocity"]) == 3, b
state["max_events"] = 100000  # the same shot with room to finish passes
json.dump(state, open(sys.argv[2], "w"))
EOF_PY
"$baize" stress --replay "$work/pass.state.json" >"$work/r.txt" || fail "replay with room failed: $(cat "$work/r.txt")"
grep -q "passed every check" "$work/r.txt" || fail "replay did not pass: $(cat "$work/r.txt")"

# ---- 4. "On the table" with pockets: a ball resting beyond a corner, where no cushion's contact
# range reaches it (so the event loop takes it as input), has escaped; a ball in a corner pocket's
# mouth, hit by another, is on the table.
python3 - "$work" <<'EOF_PY'
import json, math, sys
rest = [0, 0, 0]
def state(path, balls):
    json.dump({"format": "baize stress state", "table": "pool-9ft", "max_events": 1000,
               "balls": [{"position": p, "velocity": v, "angular_velocity": rest} for p, v in balls]},
              open(sys.argv[1] + "/" + path, "w"))
state("outside.json", [([1.5, 0.8], rest)])
# The +x +y corner pocket's mouth centre: halfway between the jaw tips, 0.116 m apart at 45 deg.
inset = 0.116 / 2 / math.sqrt(2)
state("mouth.json", [([1.27 - inset, 0.635 - inset], rest), ([1.0, 0.3], [0.5, 0.3, 0])])
EOF_PY
status=0
"$baize" stress --replay "$work/outside.json" >"$work/r.txt" 2>&1 || status=$?
[[ $status == 1 ]] || fail "a ball outside the outline replayed with status $status, want 1"
# The event loop refuses a ball beyond the table's extent before the first event (the stress
# program's own escape check would catch it at t = 0 otherwise).
grep -q "FAILED rejected: ball 0 is off the table: its x (m) = 1.5 is not allowed" "$work/r.txt" ||
  fail "a ball outside the outline: $(cat "$work/r.txt")"
"$baize" stress --replay "$work/mouth.json" >"$work/r.txt" || fail "a ball in the mouth failed: $(cat "$work/r.txt")"
grep -q "passed every check" "$work/r.txt" || fail "a ball in the mouth: $(cat "$work/r.txt")"

# A table whose corner capture circles are too small to cover the pocket openings: a ball could
# pass the facings' ends unpocketed, so the escape check cannot work there; the engine refuses the
# scene's table (engine/io/table.h, checkCapturesCoverOpenings).
python3 - "$work" "$(dirname "$0")/../../assets/tables/pool-9ft.json" <<'EOF_PY'
import json, sys
table = json.load(open(sys.argv[2]))
table["name"] = "small-capture"
table["corner_pocket"]["capture_radius_m"] = 0.005
json.dump(table, open(sys.argv[1] + "/small-capture.json", "w"))
json.dump({"table": "small-capture.json", "ball_set": "pool", "balls": {"cue": [0, 0]},
           "shot": {"speed_mps": 1, "heading_deg": 0}}, open(sys.argv[1] + "/small-capture-scene.json", "w"))
EOF_PY
status=0
"$baize" stress --replay "$work/small-capture-scene.json" >/dev/null 2>"$work/err.txt" || status=$?
[[ $status == 2 ]] || fail "a table with uncovered pocket openings replayed with status $status, want 2"
grep -q "small-capture.json: corner_pocket.capture_radius_m = 0.005 is not allowed" "$work/err.txt" ||
  fail "uncovered pocket openings: $(cat "$work/err.txt")"

# ---- 5. Bad flags and files are usage errors.
for bad in "--shots 0" "--balls 1" "--balls 99" "--threads -1" "--threads 1025" "--max-seconds -1" "--max-events 0"; do
  status=0
  "$baize" stress $bad >/dev/null 2>"$work/err.txt" || status=$?
  [[ $status == 2 ]] || fail "baize stress $bad exited $status, want 2"
  grep -q "is not allowed" "$work/err.txt" || fail "baize stress $bad: no message naming the value"
done
# --failures follows the output-folder rule (docs/commands.md): made if missing, a folder holding a
# file Baize did not write there refused before any shot, the file left alone.
"$baize" stress --shots 10 --failures "$work/new/failures" >/dev/null || fail "--failures in a new folder"
[[ -d "$work/new/failures" ]] || fail "--failures did not make its folder"
echo mine >"$work/new/failures/notes.txt"
status=0
"$baize" stress --shots 10 --failures "$work/new/failures" >/dev/null 2>"$work/err.txt" || status=$?
[[ $status == 2 ]] || fail "--failures on a folder with a user's file exited $status, want 2"
grep -q -- "--failures = $work/new/failures is not allowed: it holds 'notes.txt'" "$work/err.txt" ||
  fail "--failures on a user's folder: $(cat "$work/err.txt")"
[[ $(cat "$work/new/failures/notes.txt") == mine ]] || fail "the user's file was touched"
echo '{"format": "baize stress state", "table": "billiards", "max_events": 5, "balls": []}' >"$work/bad.json"
status=0
"$baize" stress --replay "$work/bad.json" >/dev/null 2>"$work/err.txt" || status=$?
[[ $status == 2 ]] || fail "a replay file with an unknown table exited $status, want 2"
grep -q "table = \"billiards\" is not allowed" "$work/err.txt" || fail "bad table: $(cat "$work/err.txt")"
# A state file is read strictly: an unknown key in a ball, an unknown kind, an empty ball list.
python3 - "$work" <<'PY'
import json, sys
base = {"format": "baize stress state", "table": "pool-9ft", "max_events": 1000, "seed": 1,
        "shot": 3, "kind": "random",
        "balls": [{"position": [0, 0], "velocity": [1, 0, 0], "angular_velocity": [0, 0, 0]}]}
bad = {"ballkey": ("balls", 0, "spin", 1), "kind": ("kind", "x"), "empty": ("balls", [])}
for name, edit in bad.items():
    d = json.loads(json.dumps(base))
    if len(edit) == 4:
        d[edit[0]][edit[1]][edit[2]] = edit[3]
    else:
        d[edit[0]] = edit[1]
    json.dump(d, open(f"{sys.argv[1]}/state-{name}.json", "w"))
PY
for case in "ballkey:balls\[0\].spin = 1 is not allowed" "kind:kind = \"x\" is not allowed" \
  "empty:balls = \[\] is not allowed"; do
  status=0
  "$baize" stress --replay "$work/state-${case%%:*}.json" >/dev/null 2>"$work/err.txt" || status=$?
  [[ $status == 2 ]] || fail "state ${case%%:*} exited $status, want 2"
  grep -q -- "${case#*:}" "$work/err.txt" || fail "state ${case%%:*}: $(cat "$work/err.txt")"
done
# A seed is a whole number in [0, 2^64 - 1]: "-1" is refused, not read as 2^64 - 1, and a larger
# number is refused, not wrapped (the same check serves the --seed of check, sweep and plan).
status=0
"$baize" stress --shots 1 --seed 18446744073709551616 >/dev/null 2>"$work/err.txt" || status=$?
[[ $status == 2 ]] || fail "--seed 2^64 exited $status, want 2"
status=0
"$baize" stress --shots 1 --seed -1 >/dev/null 2>"$work/err.txt" || status=$?
[[ $status == 2 ]] || fail "--seed -1 exited $status, want 2"
grep -q -- "--seed: -1 is not allowed: it must be a whole number in \[0, 2^64 - 1\]" "$work/err.txt" ||
  fail "--seed -1: $(cat "$work/err.txt")"
# Progress (tools/baize/progress): on standard error only when it is a terminal, counting up to the
# shots asked; none into a file or pipe, none under --quiet. `script` gives the run a terminal.
script -qec "'$baize' stress --shots 3000 --threads 1" /dev/null >"$work/tty.txt" </dev/null ||
  fail "stress on a terminal exited $?"
grep -q "3000 / 3000 shots (100 %)" "$work/tty.txt" || fail "no progress on a terminal: $(od -c "$work/tty.txt" | head)"
script -qec "'$baize' stress --shots 3000 --threads 1 --quiet" /dev/null >"$work/quiet.txt" </dev/null ||
  fail "stress --quiet on a terminal exited $?"
grep -q "shots (" "$work/quiet.txt" && fail "--quiet showed progress"
grep -q "^stress: shots 3000," "$work/quiet.txt" || fail "--quiet lost the results: $(cat "$work/quiet.txt")"
"$baize" stress --shots 3000 --threads 1 >/dev/null 2>"$work/pipe.txt" || fail "stress into a file exited $?"
[[ ! -s "$work/pipe.txt" ]] || fail "progress went into a file: $(cat "$work/pipe.txt")"
echo "stress CLI checks passed"
