#!/usr/bin/env bash
# baize bench accuracy on a tiny configuration (the first two shots of the set, one timed run):
# the CSV has the documented columns and every configuration, the event loop scores 0 against
# itself (and keeps its own contacts), and the fixed-step integrator's error and contact-time shift
# fall as its step shrinks; on three shots the event loop's error grows with its cushion tolerance.
# Usage: bench_accuracy_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

out=$("$baize" bench accuracy --shots 2 --repeat 1 --csv "$work/accuracy.csv") ||
  fail "bench accuracy exited $?"
grep -q "^2 shots" <<<"$out" || fail "no shot count in: $out"
grep -q "wrote $work/accuracy.csv" <<<"$out" || fail "no 'wrote' line in: $out"
[[ -f "$work/accuracy.csv.tmp" ]] && fail "a temporary file was left behind"

python3 - "$work/accuracy.csv" <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
header = ["engine", "setting", "median_us", "position_error_m", "outcome_mismatch", "shots",
          "largest_position_error_m", "contact_mismatch", "largest_contact_shift_s", "failed"]
assert rows and list(rows[0].keys()) == header, rows[0].keys()
# Two shots of the set hold no break, so every row scores all of them.
assert all(r["shots"] == "all" for r in rows), rows
configs = [(r["engine"], r["setting"]) for r in rows]
assert configs == [("event", "exact"),
                   ("event", "tol=1e-10"), ("event", "tol=1e-08"), ("event", "tol=1e-06"),
                   ("event", "tabulated"), ("fixed-step", "dt=10ms"), ("fixed-step", "dt=1ms"),
                   ("fixed-step", "dt=100us"), ("fixed-step", "dt=10us"),
                   ("box2d", "dt=1/60s"), ("box2d", "dt=1/240s"), ("box2d", "dt=1ms"),
                   ("box2d", "dt=100us")], configs
for r in rows:
    t, e, m = float(r["median_us"]), float(r["position_error_m"]), float(r["outcome_mismatch"])
    assert t > 0 and math.isfinite(t), r
    assert e >= 0 and math.isfinite(e), r
    assert 0 <= m <= 1, r
    # The largest error over shots is at least their mean; a shift is given exactly when some shot
    # keeps the reference's contacts; nothing failed.
    columns = ("largest_position_error_m", "contact_mismatch", "largest_contact_shift_s")
    largest, cm, shift = (float(r[k]) for k in columns)
    assert largest >= e, r
    assert 0 <= cm <= 1, r
    assert (cm == 1) == math.isnan(shift), r
    assert math.isnan(shift) or shift >= 0, r
    assert r["failed"] == "0", r
event = rows[0]
assert float(event["position_error_m"]) == 0 and float(event["outcome_mismatch"]) == 0, event
assert float(event["contact_mismatch"]) == 0 and float(event["largest_contact_shift_s"]) == 0, event
fixed = [r for r in rows if r["engine"] == "fixed-step"]
# Each tenfold smaller step must cut the error, and the shift of the contacts' times, which the
# integrator keeps on these simple shots (first order: about tenfold).
for column in ("position_error_m", "largest_contact_shift_s"):
    values = [float(r[column]) for r in fixed]
    for coarse, fine in zip(values, values[1:]):
        assert fine < coarse, (column, values)
    assert values[0] > 10 * values[2], (column, values)
assert all(float(r["contact_mismatch"]) == 0 for r in fixed), fixed
PY

# The event loop with looser cushion tolerances, on the first three shots (the third, heavy sidespin,
# meets cushions): its error against the default grows with the tolerance and stays small, and its
# contacts stay the reference's, their times shifted more as the tolerance grows.
"$baize" bench accuracy --shots 3 --repeat 1 --csv "$work/tolerances.csv" >/dev/null ||
  fail "bench accuracy --shots 3 exited $?"
python3 - "$work/tolerances.csv" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["engine"] == "event"]
assert [r["setting"] for r in rows] == ["exact", "tol=1e-10", "tol=1e-08", "tol=1e-06", "tabulated"], rows
errors = [float(r["position_error_m"]) for r in rows]
assert errors[0] == 0, errors
assert 0 < errors[1] <= errors[2] <= errors[3] < 1e-3, errors
# The default path stays within a micrometre of the exact one. Its promise (1e-6 V0 per impact)
# alone would allow more over a few impacts and metres; its errors lie far below it.
assert errors[4] < 1e-6, errors
assert all(float(r["outcome_mismatch"]) == 0 for r in rows), rows
# Every looser setting and the default path keep the reference's contacts; their times move by
# more as the tolerance grows. A velocity error of a share d of V0 at an impact moves a contact a
# metre on at 1 m/s by about d seconds: the default path's shift stays within its promise's.
PROMISED_SHIFT_S = 1e-6  # physics::kTabulatedPathPromise (1e-6 V0) over a metre at 1 m/s
assert all(float(r["contact_mismatch"]) == 0 for r in rows), rows
shifts = [float(r["largest_contact_shift_s"]) for r in rows]
assert shifts[0] == 0 and 0 < shifts[1] <= shifts[2] <= shifts[3], shifts
assert shifts[4] < PROMISED_SHIFT_S, shifts
PY

# Bad flags: exit 2 with the flag named; nothing written.
set +e
msg=$("$baize" bench accuracy --repeat 0 --csv "$work/never.csv" 2>&1 >/dev/null); status=$?
set -e
[[ $status -eq 2 ]] || fail "--repeat 0 exited $status, expected 2"
grep -q -- "--repeat" <<<"$msg" || fail "message does not name --repeat: $msg"
[[ -e "$work/never.csv" ]] && fail "CSV written for a bad flag"
echo "bench accuracy CLI: ok"
