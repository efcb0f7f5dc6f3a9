#!/usr/bin/env bash
# baize batch, run the way a user runs it: JSON lines in, one result line per shot out in input
# order, identical for 1 and 2 threads; bad lines reported with their line number without stopping
# the batch; standard input and scene paths.
# Usage: batch_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

python3 "$root/tools/batch_shots.py" 300 --seed 5 >"$work/shots.jsonl"
# The docs' example as written: 2000 shots of the default seed, every one a shot batch runs (none
# starts in a pocket), exit 0.
python3 "$root/tools/batch_shots.py" 2000 | "$baize" batch --threads 2 >"$work/docs.jsonl" ||
  fail "the docs' batch example (batch_shots.py 2000 | baize batch) exited $?"
[[ $(grep -c '"error"' "$work/docs.jsonl") == 0 && $(wc -l <"$work/docs.jsonl") == 2000 ]] ||
  fail "the docs' batch example: $(grep -m1 '"error"' "$work/docs.jsonl")"
"$baize" batch "$work/shots.jsonl" --threads 1 >"$work/one.jsonl" || fail "--threads 1 exited $?"
"$baize" batch "$work/shots.jsonl" --threads 2 >"$work/two.jsonl" || fail "--threads 2 exited $?"
cmp -s "$work/one.jsonl" "$work/two.jsonl" || fail "1 and 2 threads give different output"
# Standard input gives the same results too, but for where each scene came from ("source").
"$baize" batch --threads 2 <"$work/shots.jsonl" >"$work/stdin.jsonl" || fail "stdin exited $?"
python3 - "$work/one.jsonl" "$work/stdin.jsonl" "$work/shots.jsonl" <<'PY' || fail "standard input gives different output"
import json, sys
one, stdin = ([json.loads(l) for l in open(f)] for f in sys.argv[1:3])
assert len(one) == len(stdin) > 0
for n, (a, b) in enumerate(zip(one, stdin), start=1):
    assert a.pop("source") == "%s:%d" % (sys.argv[3], n) and b.pop("source") == "stdin:%d" % n
    assert a == b, (a, b)
PY

python3 - "$work/shots.jsonl" "$work/one.jsonl" <<'PY'
import json, sys
shots = [json.loads(l) for l in open(sys.argv[1])]
results = [json.loads(l) for l in open(sys.argv[2])]
assert len(results) == len(shots), (len(results), len(shots))
for n, (shot, r) in enumerate(zip(shots, results), start=1):
    assert r["line"] == n and r["id"] == shot["id"], r
    assert "error" not in r, r
    assert r["format"] == "baize-result" and r["version"] == 1, r
    assert r["source"] == "%s:%d" % (sys.argv[1], n), r["source"]
    # The scene is embedded as read (the line without its id): a result is self-contained.
    assert r["scene"] == {k: v for k, v in shot.items() if k != "id"}, r["scene"]
    final = r["final_positions_m"]
    assert set(final) == {"cue", "1"} == set(r["cushion_contacts"]), r
    pocketed = {p["ball"] for p in r["pocketed"]}
    # A pocketed ball has no final position; one on the table has one inside the cushions.
    for ball, at in final.items():
        assert (at is None) == (ball in pocketed), r
        if at is not None:
            assert abs(at[0]) <= 1.27 and abs(at[1]) <= 0.635, r
    foul = "cue ball pocketed" if "cue" in pocketed else (
        "no ball hit" if r["first_ball_hit"] is None else "none")
    assert r["foul"] == foul, r
    assert r["first_ball_hit"] in (None, "1") and r["event_count"] >= 1, r
    assert "trajectories" not in r and "events" not in r, r
PY

# Bad lines: each gets an error result naming its line, the others still run, exit status 1.
scene='{"table": "pool-9ft", "ball_set": "pool", "balls": {"cue": [0, 0], "1": [0.5, 0]}, "shot": {"aim_at": "1", "speed_mps": 1}}'
mkdir -p "$work/scenes"
echo "$scene" >"$work/scenes/straight.json"
{
  echo "{\"id\": \"first\", ${scene:1}"
  echo '{"id": 7, "table": "pool-9ft"'
  echo ''
  echo '{"id": "typo", "table": "pool-9ft", "ball_set": "pool", "balls": {"cue": [0, 0]}, "shot": {"speed_mps": 1, "heading_deg": 0, "spin": 1}}'
  echo '{"scene": "scenes/straight.json", "shot": {"aim_at": "1", "speed_mps": 2}, "id": "by-path"}'
  echo '[1, 2]'
  echo '{"scene": "scenes/missing.json"}'
  echo '{"scene": "scenes/straight.json", "scene": "scenes/straight.json"}'
  echo '{"scene": "scenes/straight.json", "shot": {"aim_at": "1", "speed_mps": -2}}'
} >"$work/mixed.jsonl"
set +e
"$baize" batch "$work/mixed.jsonl" --threads 2 >"$work/mixed-out.jsonl" 2>"$work/mixed-err.txt"
status=$?
set -e
[[ $status == 1 ]] || fail "bad lines must give exit status 1, got $status"
grep -q "6 of 8 lines failed" "$work/mixed-err.txt" || fail "stderr: $(cat "$work/mixed-err.txt")"
python3 - "$work/mixed-out.jsonl" <<'PY'
import json, sys
r = [json.loads(l) for l in open(sys.argv[1])]
assert [x["line"] for x in r] == [1, 2, 4, 5, 6, 7, 8, 9], [x["line"] for x in r]  # line 3 is blank
ok = {x["line"]: x for x in r if "error" not in x}
assert set(ok) == {1, 5}, r
assert ok[1]["id"] == "first" and ok[1]["first_ball_hit"] == "1"
assert ok[5]["id"] == "by-path" and ok[5]["first_ball_hit"] == "1"
# A line naming a scene file embeds that file's scene with the line's own shot.
assert ok[5]["scene"]["shot"] == {"aim_at": "1", "speed_mps": 2} and ok[5]["scene"]["table"] == "pool-9ft"
assert all(x["format"] == "baize-result" and x["version"] == 1 for x in r), r
err = {x["line"]: x["error"] for x in r if "error" in x}
assert "mixed.jsonl:2: not valid JSON" in err[2], err[2]
assert r[1]["id"] == 7 if "id" in r[1] else True
assert "mixed.jsonl:4" in err[4] and "spin" in err[4], err[4]
assert "mixed.jsonl:6" in err[6], err[6]
assert "missing.json" in err[7], err[7]
assert "mixed.jsonl:8: scene appears twice" in err[8], err[8]
# A line's own shot is named where it stands, not in the scene file it replaces the shot of.
assert "mixed.jsonl:9: shot.speed_mps" in err[9] and "straight.json" not in err[9], err[9]
PY

# A bad flag or input: exit 2.
set +e
"$baize" batch "$work/nope.jsonl" >/dev/null 2>&1; status=$?
set -e
[[ $status == 2 ]] || fail "a missing input must exit 2, got $status"
set +e
"$baize" batch "$work/shots.jsonl" --threads -1 >/dev/null 2>&1; status=$?
set -e
[[ $status == 2 ]] || fail "--threads -1 must exit 2, got $status"
# A line that is not UTF-8 gets its own error line (the parser's message quotes the byte, replaced
# in the output); the other lines' results are kept, with one thread or two.
printf '%s\n{"scene":"\xff.json"}\n' "$(head -1 "$work/shots.jsonl")" >"$work/bytes.jsonl"
for threads in 1 2; do
  set +e
  "$baize" batch "$work/bytes.jsonl" --threads $threads >"$work/bytes.out" 2>/dev/null; status=$?
  set -e
  [[ $status == 1 ]] || fail "a line that is not UTF-8 must exit 1, got $status"
  python3 - "$work/bytes.out" <<'PY'
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1], encoding="utf-8")]
assert len(lines) == 2 and "error" not in lines[0] and "not valid JSON" in lines[1]["error"], lines
PY
done
# A directory as the input is refused (exit 2), naming it.
set +e
msg=$("$baize" batch "$work" 2>&1 >/dev/null); status=$?
set -e
[[ $status == 2 ]] || fail "batch DIRECTORY must exit 2, got $status"
grep -qF "input $work is a directory" <<<"$msg" || fail "message: $msg"
# An input with no line ends is refused at the line limit (exit 2), not read until memory runs out.
set +e
msg=$(timeout 60 "$baize" batch /dev/zero 2>&1 >/dev/null); status=$?
set -e
[[ $status == 2 ]] || fail "batch /dev/zero must exit 2, got $status"
grep -qF "input /dev/zero: line 1 is longer than 16 MiB" <<<"$msg" || fail "message: $msg"
echo "batch CLI: ok"
