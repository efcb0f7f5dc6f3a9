#!/usr/bin/env bash
# Runs `baize calibrate` the way a user does: on the shipped snooker measurements and on data made
# by `baize cushion` itself, checking the text, the JSON and the chart, and that bad input is
# refused naming where it is, with exit status 2 and no file left behind:
#   bash tests/tools/calibrate_cli_test.sh path/to/baize
set -euo pipefail

baize=$1
here=$(cd "$(dirname "$0")" && pwd)
assets="$here/../../assets"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# expect_refused WHAT...: the command after -- exits 2 and its error holds every WHAT.
expect_refused() {
  local pieces=()
  while [[ $1 != -- ]]; do pieces+=("$1"); shift; done
  shift
  set +e
  "$@" >"$work/out" 2>"$work/err"
  local status=$?
  set -e
  [[ $status == 2 ]] || fail "exit $status, expected 2: $* ($(cat "$work/err"))"
  for piece in "${pieces[@]}"; do
    grep -qF -- "$piece" "$work/err" || fail "'$piece' not in the error of $*: $(cat "$work/err")"
  done
}

# Data made by the model (e_e 0.8, mu_w 0.2 on the 9 ft pool table) at angles and spins that
# separate the two: fitted back close to them.
{
  echo "speed_mps,angle_deg,topspin,sidespin,rebound_speed_mps,rebound_angle_deg"
  for angle in 30 60 90; do
    for topspin in 0 1; do
      "$baize" cushion --json - --speed 1 --angle $angle --topspin $topspin --mass 0.17 \
        --radius 0.028575 --h 0.03629 --mu-s 0.2 --e 0.8 --mu-w 0.2 |
        python3 -c "import json,sys; d=json.load(sys.stdin); print(f\"1,$angle,$topspin,0,{d['speed']!r},{d['angle_deg']!r}\")"
    done
  done
} >"$work/model.csv"
"$baize" calibrate "$work/model.csv" --table pool-9ft --json "$work/fit.json" --png "$work/fit.png" \
  >"$work/text"
grep -q "restitution" "$work/text" || fail "no restitution in the text"
python3 - "$work/fit.json" <<'EOF_PY' || fail "JSON check failed"
import json, sys
fit = json.load(open(sys.argv[1]))
assert abs(fit["restitution"] - 0.8) < 1e-6, fit["restitution"]
assert abs(fit["friction"] - 0.2) < 1e-6, fit["friction"]
assert fit["restitution_sd"] is not None and fit["friction_sd"] is not None
assert fit["fitted"] == ["restitution", "friction"] and fit["not_separated"] == []
assert fit["points_fitted"] == 6 and fit["points_left_out"] == 0
assert "contact_height_m" not in fit  # not fitted
EOF_PY
head -c 8 "$work/fit.png" | od -An -c | grep -q "P   N   G" || fail "no PNG written"

# The same JSON on standard output, alone.
"$baize" calibrate "$work/model.csv" --json - | python3 -c "import json,sys; json.load(sys.stdin)" ||
  fail "--json - is not JSON alone"
# --quiet drops the notes ("wrote ...") and keeps the fit.
"$baize" calibrate "$work/model.csv" --json "$work/quiet.json" --quiet > "$work/quiet.txt"
grep -q "wrote" "$work/quiet.txt" && fail "--quiet printed a note"
cmp -s "$work/quiet.txt" <("$baize" calibrate "$work/model.csv") || fail "--quiet changed the fit's report"

# The paper's head-on rolling snooker data: points above 1.5 m/s left out and counted, and the two
# parameters reported as not separated.
"$baize" calibrate "$assets/measurements/snooker-head-on-rolling.csv" --table snooker-12ft >"$work/text"
grep -q "7 points .* 9 left out" "$work/text" || fail "left-out count: $(head -1 "$work/text")"
grep -q "cannot separate restitution and friction" "$work/text" || fail "no separation note"

# The speed dependence on the full snooker data: no point left out without --max-speed, the fitted
# values as the shipped file holds them (to its rounding), the law in the JSON's model; with
# --max-speed the fast points are left out again.
"$baize" calibrate "$assets/measurements/snooker-head-on-rolling.csv" --table snooker-12ft \
  --fit knee_speed_mps,falloff_exponent --json "$work/law.json" >"$work/text"
grep -q "16 points .* 0 left out" "$work/text" || fail "speed dependence left points out: $(head -1 "$work/text")"
python3 - "$work/law.json" "$assets/measurements/snooker-speed-dependence.json" <<'EOF_PY' || fail "law JSON check failed"
import json, sys
fit = json.load(open(sys.argv[1]))
shipped = json.load(open(sys.argv[2]))["cushion"]["restitution_speed_dependence"]
assert fit["fitted"] == ["knee_speed_mps", "falloff_exponent"], fit["fitted"]
assert fit["knee_speed_mps_sd"] > 0 and fit["falloff_exponent_sd"] > 0
for key in ("knee_speed_mps", "falloff_exponent"):
    assert abs(fit[key] - shipped[key]) < 0.005, (key, fit[key], shipped[key])
    assert fit["model"]["restitution_speed_dependence"][key] == fit[key]
assert fit["model"]["restitution"] == 0.98 and fit["points_left_out"] == 0
EOF_PY
"$baize" calibrate "$assets/measurements/snooker-head-on-rolling.csv" --table snooker-12ft \
  --fit restitution --knee-speed 2.12 --falloff-exponent 0.31 --max-speed 1.5 >"$work/text"
grep -q "7 points .* 9 left out" "$work/text" || fail "--max-speed with a law: $(head -1 "$work/text")"
expect_refused "knee_speed_mps = -2" "--knee-speed" -- "$baize" calibrate "$work/model.csv" --knee-speed -2
expect_refused "knee_speed_mps, falloff_exponent" -- "$baize" calibrate "$work/model.csv" --fit knee

# Bad input: named by line and column, flag and value.
printf 'speed_mps,angle_deg,rebound_speed_mps\n1,90,0.7\n1,abc,0.7\n' >"$work/bad.csv"
expect_refused "bad.csv line 3" "column angle_deg" "abc" -- "$baize" calibrate "$work/bad.csv"
printf 'speed_mps,rebound_speed_mps\n1,0.7\n' >"$work/bad.csv"
expect_refused "no column 'angle_deg'" -- "$baize" calibrate "$work/bad.csv"
printf 'speed_mps,angle_deg,rebound_speed_mps\n-1,90,0.7\n' >"$work/bad.csv"
expect_refused "line 2" "speed_mps = -1" -- "$baize" calibrate "$work/bad.csv"
printf 'speed_mps,angle_deg,rebound_speed_mps\n1,200,0.7\n' >"$work/bad.csv"
expect_refused "line 2" "angle_deg = 200" -- "$baize" calibrate "$work/bad.csv"
printf 'speed_mps,angle_deg,rebound_speed_mps\n1,90,2\n' >"$work/bad.csv"
expect_refused "line 2" "rebound_speed_mps = 2" "energy" -- "$baize" calibrate "$work/bad.csv"
printf 'speed_mps,angle_deg,rebound_speed_mps\n1,90,0.7\n' >"$work/bad.csv"
expect_refused "fewer than the 2 parameters" -- "$baize" calibrate "$work/bad.csv"
expect_refused "--fit" "bounce" -- "$baize" calibrate "$work/model.csv" --fit restitution,bounce
expect_refused "--max-speed = -1" -- "$baize" calibrate "$work/model.csv" --max-speed -1
expect_refused "mu_w" "--mu-w" -- "$baize" calibrate "$work/model.csv" --mu-w 5
expect_refused "no-such-table" -- "$baize" calibrate "$work/model.csv" --table no-such-table
mkdir "$work/dir"
expect_refused "--png" -- "$baize" calibrate "$work/bad.csv" --png "$work/dir"
[[ ! -e "$work/fit2.json" ]] || fail "a refused run wrote its JSON"
expect_refused "fewer" -- "$baize" calibrate "$work/bad.csv" --json "$work/fit2.json"
[[ ! -e "$work/fit2.json" && ! -e "$work/fit2.json.tmp" ]] || fail "a refused run left a JSON file"
echo "calibrate CLI: all checks passed"
