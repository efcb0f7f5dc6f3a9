#!/usr/bin/env bash
# baize play, run the way a user runs it: whole frames deterministic per seed (the same log twice),
# the summary against the log, pictures per shot, player A's shots from a file, and bad input
# (an unknown game, a shot line with a bad key, an illegal placement, a bad flag): exit 2, a
# message naming what was written, no file half-written.
# Usage: play_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export GALLIUM_DRIVER=llvmpipe

# Whole frames: the same seed gives the same log byte for byte; every game ends or hits the limit.
for game in 9-ball 10-ball 8-ball snooker; do
  "$baize" play "$game" --seed 3 --log "$work/$game-a.jsonl" > "$work/$game-summary.txt"
  "$baize" play "$game" --seed 3 --log "$work/$game-b.jsonl" --quiet > "$work/quiet.txt"
  cmp -s "$work/$game-a.jsonl" "$work/$game-b.jsonl" || fail "$game: two runs with seed 3 differ"
  # --quiet drops notes only: the summary (the result) is the same.
  cmp -s "$work/quiet.txt" "$work/$game-summary.txt" || fail "$game: --quiet changed the summary"
  # The summary's shot count and winner agree with the log's last line.
  python3 - "$work/$game-a.jsonl" "$work/$game-summary.txt" "$game" <<'PY' || fail "$game: summary and log disagree"
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
summary = open(sys.argv[2]).read()
game = sys.argv[3]
assert summary.startswith("%s: %d shots, " % (game, len(lines))), summary
last = lines[-1]["next"]
for a, b in zip(lines, lines[1:]):
    assert a["next"] == b["state"], (a["index"], "next is not the following state")
if last["frame_over"]:
    assert "player %s won" % "AB"[last["winner"]] in summary, summary
else:
    assert "unfinished" in summary, summary
PY
done

# The log to standard output, and a different seed giving another frame.
"$baize" play 9-ball --seed 3 --log - > "$work/stdout.jsonl"
cmp -s "$work/stdout.jsonl" "$work/9-ball-a.jsonl" || fail "--log - differs from the file"
"$baize" play 9-ball --seed 4 --log "$work/seed4.jsonl" --quiet
! cmp -s "$work/seed4.jsonl" "$work/9-ball-a.jsonl" || fail "seeds 3 and 4 gave the same frame"
# No noise: the stroke is the shot intended.
"$baize" play 9-ball --noise 0 --max-shots 3 --log "$work/exact.jsonl" --quiet
python3 - "$work/exact.jsonl" <<'PY' || fail "--noise 0 changed a stroke"
import json, sys
for l in open(sys.argv[1]):
    d = json.loads(l)
    assert d["shot"] == d["executed"], d["index"]
PY

# One picture per shot that ran.
"$baize" play 9-ball --seed 3 --max-shots 3 --png-dir "$work/pictures" --quiet > "$work/pictures.txt"
grep -q "^9-ball: [0-9]* shots" "$work/pictures.txt" || fail "--quiet dropped the summary"
[ "$(ls "$work/pictures" | wc -l)" -ge 1 ] || fail "--png-dir wrote no picture"
ls "$work/pictures" | grep -qv '^shot_00[0-2]\.png$' && fail "--png-dir wrote an unexpected file"

# Player A's shots from a file: the break from the head spot, then the planner.
cat > "$work/shots.jsonl" <<'JSONL'
{"place": [-0.635, 0.1], "shot": {"aim_at": "1", "speed_mps": 6.0, "height": -0.1}}
JSONL
"$baize" play 9-ball --shots "$work/shots.jsonl" --max-shots 2 --log "$work/file.jsonl" --quiet
head -1 "$work/file.jsonl" | grep -q '"kind":"file"' || fail "the file's shot was not played first"
head -1 "$work/file.jsonl" | grep -q '"place_m":\[-0.635,0.1\]' || fail "the file's place was not used"

# Bad input: exit 2, the message names it, no log written.
expect_refusal() {  # expect_refusal TEXT ARGS...: exit 2, TEXT in the error, no log file
  local text=$1; shift
  local status=0
  "$baize" play "$@" --log "$work/bad.jsonl" 2> "$work/err.txt" > /dev/null || status=$?
  [ "$status" -eq 2 ] || fail "play $* exited $status, not 2: $(cat "$work/err.txt")"
  grep -qF -- "$text" "$work/err.txt" || fail "play $*: '$text' not in: $(cat "$work/err.txt")"
  [ ! -e "$work/bad.jsonl" ] || fail "play $* wrote a log"
  [ -z "$(ls "$work" | grep '\.tmp$' || true)" ] || fail "play $* left a temporary file"
}
expect_refusal "GAME = straight-pool is not allowed: the games are 9-ball, 10-ball, 8-ball, snooker" straight-pool
expect_refusal "--noise = -1 is not allowed" 9-ball --noise -1
expect_refusal "--max-shots = 0 is not allowed" 9-ball --max-shots 0
printf '{"shot": {"aim_at": "1", "speed_mps": 6.0}, "spin": 1}\n' > "$work/badkey.jsonl"
expect_refusal "badkey.jsonl line 1" 9-ball --shots "$work/badkey.jsonl"
grep -qF "spin" "$work/err.txt" || fail "the bad key is not named: $(cat "$work/err.txt")"
# The break-off placed on the brown (in the D, on the baulk line), after a blank line.
printf '\n{"place": [-1.0475, 0.01], "shot": {"aim_at": "red11", "speed_mps": 5.0}}\n' > "$work/onball.jsonl"
expect_refusal "onball.jsonl line 2: place" snooker --shots "$work/onball.jsonl"
grep -qF "touches ball brown" "$work/err.txt" || fail "the ball under the place is not named: $(cat "$work/err.txt")"
printf '{"place": [0.3, 0.0], "shot": {"aim_at": "1", "speed_mps": 6.0}}\n' > "$work/ahead.jsonl"
expect_refusal "not behind the head string" 9-ball --shots "$work/ahead.jsonl"
printf '{"place": [-0.8, 0.0], "shot": {"aim_at": "1", "speed_mps": 2.0}}\n{"place": [-0.8, 0.0], "shot": {"aim_at": "2", "speed_mps": 2.0}}\n' > "$work/twice.jsonl"
# The second line places the cue ball again: refused unless the first shot gave the cue ball in hand.
status=0
"$baize" play 9-ball --noise 0 --shots "$work/twice.jsonl" --log "$work/twice-log.jsonl" 2> "$work/err.txt" > /dev/null || status=$?
if [ "$status" -ne 0 ]; then
  [ "$status" -eq 2 ] || fail "a refused second line exited $status"
  grep -qF "twice.jsonl line 2" "$work/err.txt" || fail "the refusal does not name line 2: $(cat "$work/err.txt")"
  [ ! -e "$work/twice-log.jsonl" ] || fail "a refused file left a log"
fi
# bench play: a tiny run writes its CSV; bad flags exit 2 and write nothing.
"$baize" bench play --racks 1 --noise 0,1 --csv "$work/bench.csv" > "$work/bench.txt"
[ "$(wc -l < "$work/bench.csv")" -eq 3 ] || fail "bench play --csv has not a header and two rows"
grep -q "^9-ball noise 1.00: 1 frames, 1 finished, break and run" "$work/bench.txt" || fail "bench play output: $(cat "$work/bench.txt")"
for bad in "--game straight-pool" "--noise 1,x" "--noise -1" "--racks 0"; do
  status=0
  # shellcheck disable=SC2086
  "$baize" bench play $bad --csv "$work/bad.csv" > /dev/null 2> "$work/err.txt" || status=$?
  [ "$status" -eq 2 ] || fail "bench play $bad exited $status"
  grep -qF -- "${bad%% *}" "$work/err.txt" || fail "bench play $bad: the flag is not named: $(cat "$work/err.txt")"
  [ ! -e "$work/bad.csv" ] || fail "bench play $bad wrote a CSV"
done
# The examples of docs/games.md's "Playing a frame" run as written (into the work folder).
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
python3 - "$root/docs/games.md" > "$work/examples.sh" <<'PY'
import re, sys
section = open(sys.argv[1]).read().split("## Playing a frame", 1)[1].split("\n## ", 1)[0]
commands = [l for b in re.findall(r"```sh\n(.*?)```", section, re.S) for l in b.splitlines()]
assert len(commands) == 3 and all(c.startswith("build/baize play ") for c in commands), commands
print("\n".join(commands))
PY
while read -r example; do
  command=${example//build\/baize/$baize}
  command=${command//out\//$work/docs-out/}
  eval "$command" > /dev/null || fail "docs/games.md example failed: $example"
done < "$work/examples.sh"
[ -s "$work/docs-out/snooker.jsonl" ] || fail "the snooker example wrote no log"
ls "$work/docs-out/8-ball"/shot_000.png > /dev/null || fail "the 8-ball example drew no picture"
echo "play CLI tests passed"
