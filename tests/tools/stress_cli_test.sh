#!/usr/bin/env bash
# Runs `baize stress` the way a user does and checks what it prints:
#   bash tests/tools/stress_cli_test.sh path/to/baize
# The summary must count the shots asked for and some events; no shot may fail (exit status 0); the
# reproduction printed for a failing shot must parse as JSON and hold the scene; bad flags must be
# refused with status 2; and the same seed must give the same summary counts.
set -euo pipefail

baize=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

status=0
"$baize" stress --shots 2000 --seed 1 >"$work/out.txt" 2>"$work/err.txt" || status=$?
summary=$(grep '^stress: ' "$work/out.txt") || fail "no summary line in: $(cat "$work/out.txt")"
[[ $summary =~ ^stress:\ shots\ 2000,\ events\ ([0-9]+),\ failed\ shots\ ([0-9]+),\ failed\ shots\ by\ kind\ (.*),\ largest\ energy\ growth\ .*shots/s$ ]] ||
  fail "summary line not in the expected form: $summary"
events=${BASH_REMATCH[1]}
failed=${BASH_REMATCH[2]}
(( events > 2000 * 5 )) || fail "too few events ($events) for 2000 shots: the scenes must exercise the loop"
kinds=${BASH_REMATCH[3]}
if (( failed == 0 )); then
  [[ $status == 0 ]] || fail "no failed shots but exit status $status"
  [[ $kinds == none ]] || fail "no failed shots but failures listed: $kinds"
else
  [[ $status == 1 ]] || fail "$failed failed shots but exit status $status (want 1)"
  reported=$(grep -c '^FAILED SHOT ' "$work/out.txt" || true)
  (( reported == (failed < 10 ? failed : 10) )) || fail "$reported reproductions printed for $failed failed shots"
  grep '^FAILED SHOT ' "$work/out.txt" | sed 's/^FAILED SHOT //' | python3 -c '
import json, sys
for line in sys.stdin:
    r = json.loads(line)
    assert r["seed"] == 1 and isinstance(r["shot"], int) and r["first_failure"], r
    assert len(r["balls"]) >= 1
    for b in r["balls"]:
        assert len(b["position"]) == 2 and len(b["velocity"]) == 3 and len(b["angular_velocity"]) == 3, b
' || fail "a reproduction is not valid JSON with the scene"
  fail "$failed of 2000 shots failed ($kinds): $(grep '^FAILED SHOT ' "$work/out.txt" | head -1)"
fi

# The same seed gives the same counts (the time and rate may differ).
"$baize" stress --shots 300 --seed 5 >"$work/a.txt" || true
"$baize" stress --shots 300 --seed 5 >"$work/b.txt" || true
counts() { grep '^stress: ' "$1" | sed 's/, largest energy.*//'; }
[[ $(counts "$work/a.txt") == "$(counts "$work/b.txt")" ]] || fail "same seed, different counts"
cmp <(grep '^FAILED' "$work/a.txt") <(grep '^FAILED' "$work/b.txt") || fail "same seed, different failures"

# Bad flags are usage errors.
for bad in "--shots 0" "--balls 1" "--balls 99"; do
  status=0
  "$baize" stress $bad >/dev/null 2>"$work/err.txt" || status=$?
  [[ $status == 2 ]] || fail "baize stress $bad exited $status, want 2"
  grep -q "is not allowed" "$work/err.txt" || fail "baize stress $bad: no message naming the value"
done
echo "stress CLI checks passed"
