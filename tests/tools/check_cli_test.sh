#!/usr/bin/env bash
# baize check, run the way a user runs it: the shipped suite, a failing case with its measured
# value, exit statuses, --junit (well-formed XML) and --noise (probabilities, reproducible).
# Usage: check_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# The shipped drills pass: one PASS line per case, the summary, exit 0.
out=$("$baize" check "$root/assets/suites/positional-drills.json") || fail "drills exited $?: $out"
cases=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["cases"]))' \
  "$root/assets/suites/positional-drills.json")
[[ $(grep -c "^PASS " <<<"$out") == "$cases" ]] || fail "expected $cases PASS lines: $out"
grep -q "^$cases passed, 0 failed$" <<<"$out" || fail "summary: $out"
grep -q "^PASS stop-shot | cue_ball_stops_in ok (cue ball at \[" <<<"$out" || fail "measured: $out"

# A suite with one passing and one failing case. The cue ball rolls straight along y = 0 from
# x = -0.8 and hits nothing: ball 1 sits off its line. The failing case expects a hit and a
# circle it does not reach; the line must give the measured values.
cat >"$work/suite.json" <<'JSON'
{"cases": [
  {"name": "rolls-alone", "scene": {"table": "pool-9ft", "ball_set": "pool",
     "balls": {"cue": [-0.8, 0.0], "1": [0.0, 0.4]},
     "shot": {"heading_deg": 0, "speed_mps": 0.5, "height": 0.4}},
   "expect": {"not_pocketed": ["1"], "cue_ball_stops_in": {"rectangle": [-0.8, -0.01, 0.8, 0.01]}}},
  {"name": "expects-a-hit", "scene": {"table": "pool-9ft", "ball_set": "pool",
     "balls": {"cue": [-0.8, 0.0], "1": [0.0, 0.4]},
     "shot": {"heading_deg": 0, "speed_mps": 0.5, "height": 0.4}},
   "expect": {"first_hit": "1", "no_foul": true, "cue_ball_stops_in": {"circle": [1.0, 0.3, 0.05]}}}
]}
JSON
set +e
out=$("$baize" check "$work/suite.json" --junit "$work/junit.xml")
status=$?
set -e
[[ $status == 1 ]] || fail "a failing case must exit 1, got $status: $out"
grep -q "^PASS rolls-alone " <<<"$out" || fail "rolls-alone: $out"
grep -q "^FAIL expects-a-hit " <<<"$out" || fail "expects-a-hit: $out"
grep -q "first_hit FAILED (expected first hit 1; measured first hit none)" <<<"$out" ||
  fail "first_hit's measured value: $out"
grep -q "no_foul FAILED (expected no foul; measured foul: no ball hit)" <<<"$out" ||
  fail "no_foul's measured value: $out"
grep -q "^1 passed, 1 failed$" <<<"$out" || fail "summary: $out"
# The stop point printed agrees with the rolling closed form: the ball leaves at
# v0 = 1.75 * 0.5 / (1 + 0.17/0.54 + 0.4) = 0.5103 m/s rolling, and stops after v0^2 / (2 mu_r g)
# = 1.3270 m, at x = 0.527.
grep -q "cue ball at \[0.527, 0.000\]" <<<"$out" || fail "stop point: $out"

python3 - "$work/junit.xml" <<'PY'
import sys
import xml.etree.ElementTree as ET
suite = ET.parse(sys.argv[1]).getroot()
assert suite.tag == "testsuite", suite.tag
assert suite.get("tests") == "2" and suite.get("failures") == "1", suite.attrib
cases = {c.get("name"): c for c in suite.findall("testcase")}
assert set(cases) == {"rolls-alone", "expects-a-hit"}, cases
assert cases["rolls-alone"].find("failure") is None
failure = cases["expects-a-hit"].find("failure")
assert failure is not None and "first_hit FAILED" in failure.get("message"), failure
assert "measured first hit none" in failure.get("message"), failure.get("message")
assert float(cases["rolls-alone"].get("time")) >= 0
PY
[[ -e "$work/junit.xml.tmp" ]] && fail "a temporary file was left behind"

# A scene by path (relative to the suite), a shot override, and a case name XML must escape. The
# override turns the shot onto ball 1 (the file's heading would miss it): a level centre hit at
# 1 m/s leaves at 1.75 / 1.3148 = 1.331 m/s, rolls after 0.221 m, meets the ball at 0.928 m/s and
# follows 0.333 m from the contact point at x = -0.057 (the follow closed form of
# tools/positional_suite.py): x = 0.276.
mkdir -p "$work/scenes"
cat >"$work/scenes/straight.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool", "balls": {"cue": [-0.5, 0.0], "1": [0.0, 0.0]},
 "shot": {"heading_deg": 90, "speed_mps": 0.2}}
JSON
cat >"$work/by-path.json" <<'JSON'
{"cases": [{"name": "a<b & \"c\" 'd'", "scene": "scenes/straight.json",
            "shot": {"aim_at": "1", "speed_mps": 1.0},
            "expect": {"first_hit": "1", "cue_ball_stops_in": {"rectangle": [0.26, -0.01, 0.29, 0.01]}}}]}
JSON
out=$("$baize" check "$work/by-path.json" --junit "$work/by-path.xml") || fail "by-path exited $?: $out"
grep -q "^PASS a<b & \"c\" 'd' | " <<<"$out" || fail "by-path: $out"
python3 - "$work/by-path.xml" <<'PY'
import sys
import xml.etree.ElementTree as ET
(case,) = ET.parse(sys.argv[1]).getroot().findall("testcase")
assert case.get("name") == "a<b & \"c\" 'd'", case.get("name")
PY

# --noise: probabilities with intervals under each case, the same for the same seed, and the
# pass/fail verdict still the noise-free shot's.
noisy() { "$baize" check "$root/assets/suites/positional-drills.json" --noise 20 --seed "$1"; }
a=$(noisy 3) || fail "--noise exited $?"
b=$(noisy 3)
[[ "$a" == "$b" ]] || fail "--noise with the same seed differs"
grep -q "^  noise: whole case [01]\.[0-9]* \[[01]\.[0-9]*, [01]\.[0-9]*\] ([0-9]*/20)" <<<"$a" ||
  fail "noise lines: $a"
grep -q "^  noise: pocketed " <<<"$a" || fail "per-expectation noise lines: $a"
grep -q "^$cases passed, 0 failed$" <<<"$a" || fail "noise changed the verdict: $a"
# With every sigma 0 each sample is the noise-free shot: every probability is 1.
z=$("$baize" check "$root/assets/suites/positional-drills.json" --noise 5 --sigma-tip-mm 0 \
  --sigma-elevation-deg 0 --sigma-aim-deg 0 --sigma-speed-mps 0)
[[ $(grep -c "^  noise: whole case 1.000 \[" <<<"$z") == "$cases" ]] || fail "zero noise: $z"

# Bad input: exit 2 with the file, the case and the key; a bad flag likewise.
cat >"$work/bad.json" <<'JSON'
{"cases": [{"name": "typo", "scene": "../x.json", "expect": {"no_foul": true}},
           {"name": "b", "scene": {}, "expect": {}}]}
JSON
set +e
err=$("$baize" check "$work/bad.json" 2>&1 >/dev/null); status=$?
set -e
[[ $status == 2 ]] || fail "a bad suite must exit 2, got $status"
grep -q "bad.json: case \"typo\".scene" <<<"$err" || fail "message: $err"
sed -i 's/"no_foul": true/"no_fowl": true/; s|"../x.json"|{"table": "pool-9ft", "ball_set": "pool", "balls": {"cue": [0, 0]}, "shot": {"heading_deg": 0, "speed_mps": 1}}|' \
  "$work/bad.json"
set +e
err=$("$baize" check "$work/bad.json" 2>&1 >/dev/null); status=$?
set -e
[[ $status == 2 ]] || fail "an unknown expectation must exit 2, got $status"
grep -q "case \"typo\".expect.no_fowl" <<<"$err" || fail "message: $err"
set +e
err=$("$baize" check "$root/assets/suites/positional-drills.json" --noise -3 2>&1); status=$?
set -e
[[ $status == 2 ]] || fail "--noise -3 must exit 2, got $status"
grep -q -- "--noise" <<<"$err" || fail "message: $err"
# --png-dir must be a folder: a file there is refused, naming the path given.
touch "$work/a-file"
set +e
err=$("$baize" check "$root/assets/suites/positional-drills.json" --png-dir "$work/a-file" 2>&1); status=$?
set -e
[[ $status == 2 ]] || fail "--png-dir FILE must exit 2, got $status"
grep -q -- "--png-dir = $work/a-file is not allowed: it must be a folder" <<<"$err" || fail "message: $err"
# The execution error's flags need --noise: refused alone, naming both.
for flag in "--seed 3" "--sigma-aim-deg 0.2"; do
  set +e
  err=$("$baize" check "$root/assets/suites/positional-drills.json" $flag 2>&1); status=$?
  set -e
  [[ $status == 2 ]] || fail "$flag without --noise must exit 2, got $status"
  grep -q -- "${flag% *} requires --noise" <<<"$err" || fail "$flag without --noise: $err"
done
# Each sigma flag is named as it was given, in its own units.
for flag in --sigma-tip-mm --sigma-elevation-deg --sigma-aim-deg --sigma-speed-mps; do
  set +e
  err=$("$baize" check "$root/assets/suites/positional-drills.json" --noise 1 $flag -1 2>&1); status=$?
  set -e
  [[ $status == 2 ]] || fail "$flag -1 must exit 2, got $status"
  grep -q -- "$flag = -1 is not allowed: it must be >= 0" <<<"$err" || fail "message: $err"
done
echo "check CLI: ok"
