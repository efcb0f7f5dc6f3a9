#!/usr/bin/env bash
# Runs the real `baize` program the way a user does and checks what it prints and writes:
#   bash tests/tools/cushion_cli_test.sh path/to/baize
# The physics itself is tested in tests/physics; here the values check that every flag reaches the
# model (closed-form frictionless rebounds, symmetry, linearity in V0) and that the outputs agree
# with each other (JSON, sweep CSVs, bench CSV).
set -euo pipefail

baize=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# json_of NAME ARGS...: runs `baize cushion --json - ARGS` into $work/NAME.json (the JSON alone on
# standard output: the report goes to standard error).
json_of() {
  local name=$1
  shift
  "$baize" cushion --json - "$@" >"$work/$name.json" 2>/dev/null || fail "baize cushion --json - $* exited $?"
}

# check_python CODE FILES...: runs CODE with the JSON/CSV helpers below and the files as argv.
check_python() {
  local code=$1
  shift
  python3 - "$@" <<EOF || fail "python check failed: see above"
import csv, json, math, sys
def load(path):
    with open(path) as f:
        return json.load(f)
def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))
def close(a, b, tol, what):
    assert abs(a - b) <= tol, f"{what}: {a!r} vs {b!r} (allowed {tol})"
$code
EOF
}

# ---- 1. The default run: the paper's head-on rolling shot, human-readable.
out=$("$baize" cushion) || fail "baize cushion exited $?"
for word in "rebound:" "speed ratio" "P_c =" "P_f =" "W_c =" "contacts:" "evaluations"; do
  grep -qF "$word" <<<"$out" || fail "default output lacks '$word':
$out"
done

# ---- 2. JSON: keys, self-consistency and the measured head-on rolling slope.
json_of default
# --json FILE: the same object in the file, written whole, and the report on standard output.
"$baize" cushion --json "$work/made/default.json" >"$work/report.txt" || fail "cushion --json FILE exited $?"
cmp -s "$work/made/default.json" "$work/default.json" || fail "--json FILE and --json - differ"
grep -q "^Ball-cushion impact" "$work/report.txt" || fail "--json FILE: no report: $(cat "$work/report.txt")"
json_of default_paper --solver paper
check_python '
d = load(sys.argv[1])
for key in ["v", "w", "speed", "angle_deg", "speed_ratio", "compression_impulse_Ns",
            "final_impulse_Ns", "compression_work_J", "contact_changes", "rhs_evaluations",
            "incoming", "params", "solver", "setting"]:
    assert key in d, "missing key " + key
assert d["solver"] == "exact" and d["setting"] == "default", (d["solver"], d["setting"])
vx, vy, vz = d["v"]
assert len(d["w"]) == 3 and vz == 0
close(d["speed"], math.hypot(vx, vy), 1e-15, "speed is |(v_x, v_y)|")
close(d["angle_deg"], math.degrees(math.atan2(-vy, vx)), 1e-12, "angle_deg is atan2(-v_y, v_x)")
close(d["speed_ratio"], d["speed"] / d["incoming"]["speed_mps"], 1e-15, "speed_ratio")
# Head-on rolling snooker shot: the measured low-speed rebound slope is about 0.91 (physics notes).
close(d["speed_ratio"], 0.91, 0.01, "head-on rolling speed ratio")
close(d["angle_deg"], 90.0, 1e-9, "head-on rebound angle")
assert 0 < d["compression_impulse_Ns"] < d["final_impulse_Ns"]
# Kinetic energy never grows (solid sphere, I = 2/5 M R^2).
p = d["params"]
def energy(v, w):
    I = 0.4 * p["mass_kg"] * p["radius_m"] ** 2
    return 0.5 * p["mass_kg"] * sum(x * x for x in v) + 0.5 * I * sum(x * x for x in w)
assert energy(d["v"], d["w"]) < energy(d["incoming"]["v"], d["incoming"]["w"])
# The incoming state follows the flags: V0 = 1 m/s head-on, rolling (w_x = -V0/R).
close(d["incoming"]["v"][1], 1.0, 1e-15, "incoming v_y")
close(d["incoming"]["w"][0], -1.0 / p["radius_m"], 1e-12, "incoming w_x (natural roll)")
# The default parameters are the paper snooker values, h = 7R/5.
assert (p["mass_kg"], p["radius_m"], p["restitution"], p["cushion_friction"], p["cloth_friction"]) \
    == (0.1406, 0.02625, 0.98, 0.14, 0.212), p
close(p["contact_height_m"], 1.4 * p["radius_m"], 1e-17, "h = 7R/5")
# The paper scheme (first order, N = 5000) agrees with the exact solver to about 1/N.
q = load(sys.argv[2])
assert q["solver"] == "paper" and q["setting"] == "N=5000" and q["contact_changes"] == []
close(q["speed_ratio"], d["speed_ratio"], 1e-3, "paper vs exact speed ratio")
' "$work/default.json" "$work/default_paper.json"

# The contact log: a stun ball head-on into the 9 ft pool table's cushion (its shipped e_e 0.74)
# sticks at the nose before compression ends, and the stick is listed there at the default
# tolerance as at 1e-14 (tests/physics checks the log against an independent reference).
pool_stun=(--mass 0.17 --radius 0.028575 --h 0.03629 --mu-s 0.2 --e 0.74 --topspin 0)
json_of pool_stun "${pool_stun[@]}"
json_of pool_stun_converged "${pool_stun[@]}" --tolerance 1e-14
check_python '
fast, converged = load(sys.argv[1]), load(sys.argv[2])
def sticks(d):
    return [c["impulse_Ns"] for c in d["contact_changes"]
            if c["contact"] == "cushion" and c["mode"] == "stick"]
assert len(sticks(fast)) == 1, fast["contact_changes"]
assert 0 < sticks(fast)[0] < fast["compression_impulse_Ns"], fast["contact_changes"]
assert len(sticks(converged)) == 1, converged["contact_changes"]
close(sticks(fast)[0], sticks(converged)[0], 1e-6 * 0.17, "stick onset, default vs 1e-14")
' "$work/pool_stun.json" "$work/pool_stun_converged.json"
out=$("$baize" cushion "${pool_stun[@]}") || fail "baize cushion ${pool_stun[*]} exited $?"
grep -q "N s: cushion sticks" <<<"$out" || fail "the pool stun ball's stick is not listed:
$out"

# ---- 3. Flags reach the model.
# Frictionless cushion and cloth: the closed form v_x' = v_x, v_y' = -e v_y, spin unchanged.
json_of frictionless --solver exact --mu-w 0 --mu-s 0 --e 0.8 --angle 30 --speed 2 --topspin 0.5 --sidespin 1
# Linearity: doubling V0 (spins in units of V0/R follow) doubles every output velocity.
json_of slow --solver exact --speed 0.75 --angle 60 --topspin 2 --sidespin -1.5
json_of fast --solver exact --speed 1.5 --angle 60 --topspin 2 --sidespin -1.5
# Mirror symmetry x -> -x: alpha -> 180 - alpha and sidespin -> -sidespin mirror the rebound.
json_of mirror --solver exact --speed 0.75 --angle 120 --topspin 2 --sidespin 1.5
# --h defaults to 7R/5 of the radius in use; giving that value explicitly changes nothing.
json_of radius --solver exact --radius 0.0286 --mass 0.17
json_of radius_h --solver exact --radius 0.0286 --mass 0.17 --h 0.04004
# --steps and --tolerance reach the solvers: the answer moves by no more than their error.
json_of coarse --solver paper --steps 100
json_of loose --solver exact --tolerance 1e-6
check_python '
f, slow, fast, mirror, radius, radius_h, coarse, loose, exact = map(load, sys.argv[1:])
a = math.radians(30)
close(f["v"][0], 2 * math.cos(a), 1e-9, "frictionless v_x unchanged")
close(f["v"][1], -0.8 * 2 * math.sin(a), 1e-9, "frictionless v_y = -e v_y0")
for i in range(3):
    close(f["w"][i], f["incoming"]["w"][i], 1e-7, "frictionless spin unchanged")
for i in range(3):
    close(fast["v"][i], 2 * slow["v"][i], 1e-8, "linearity in V0 (v)")
    close(fast["w"][i], 2 * slow["w"][i], 1e-8 / 0.02625, "linearity in V0 (w)")
close(fast["angle_deg"], slow["angle_deg"], 1e-7, "rebound angle does not depend on V0")
close(mirror["v"][0], -slow["v"][0], 1e-9, "mirror v_x")
close(mirror["v"][1], slow["v"][1], 1e-9, "mirror v_y")
close(mirror["angle_deg"], 180 - slow["angle_deg"], 1e-7, "mirror rebound angle")
close(radius["params"]["contact_height_m"], 1.4 * 0.0286, 1e-17, "h follows --radius")
assert radius["v"] == radius_h["v"] and radius["w"] == radius_h["w"], "explicit --h = 7R/5"
assert radius["v"] != exact["v"], "--radius and --mass reach the model"
assert coarse["setting"] == "N=100", coarse["setting"]
close(coarse["speed_ratio"], exact["speed_ratio"], 0.02, "paper N=100 within its 1/N error")
assert coarse["speed_ratio"] != exact["speed_ratio"]
assert loose["setting"] == "tol=1e-06", loose["setting"]
close(loose["speed_ratio"], exact["speed_ratio"], 1e-5, "exact at 1e-6")
' "$work"/{frictionless,slow,fast,mirror,radius,radius_h,coarse,loose,default}.json

# The speed dependence of e_e: no change below the knee; above it the rebound ratio falls while the
# rebound speed still rises; the JSON names the law as a scene does.
law=(--knee-speed 2.12 --falloff-exponent 0.31)
json_of law_slow --speed 1.5 "${law[@]}"
json_of plain_slow --speed 1.5
json_of law_fast --speed 5 "${law[@]}"
json_of law_faster --speed 8 "${law[@]}"
json_of plain_fast --speed 5
check_python '
law_slow, plain_slow, law_fast, law_faster, plain_fast = map(load, sys.argv[1:])
assert law_slow["v"] == plain_slow["v"] and law_slow["w"] == plain_slow["w"], "below the knee"
assert law_fast["speed_ratio"] < plain_fast["speed_ratio"], "above the knee e_e falls"
assert law_faster["speed_ratio"] < law_fast["speed_ratio"], "and falls further"
assert law_faster["speed"] > law_fast["speed"], "while the rebound still grows"
assert law_fast["params"]["restitution_speed_dependence"] == {"knee_speed_mps": 2.12, "falloff_exponent": 0.31}
assert "restitution_speed_dependence" not in plain_fast["params"]
' "$work"/{law_slow,plain_slow,law_fast,law_faster,plain_fast}.json

# ---- 4. Bad input: a message naming the flag, exit status 2 (usage) or 1 (failure), no output.
# expect_error STATUS TEXT ARGS...: baize ARGS must exit STATUS and print TEXT on stderr.
expect_error() {
  local status=$1 text=$2
  shift 2
  local actual=0
  "$baize" "$@" >"$work/stdout" 2>"$work/stderr" || actual=$?
  [[ $actual -eq $status ]] || fail "baize $* exited $actual, expected $status"
  grep -qF -- "$text" "$work/stderr" || fail "baize $*: stderr lacks '$text': $(cat "$work/stderr")"
  [[ ! -s "$work/stdout" ]] || fail "baize $* printed to stdout: $(cat "$work/stdout")"
}
expect_error 2 "--speed = -1 is not allowed" cushion --speed -1
expect_error 2 "--speed = nan is not allowed" cushion --speed nan
expect_error 2 "--speed = abc" cushion --speed abc
expect_error 2 "--angle = 180 is not allowed" cushion --angle 180
expect_error 2 "--angle = 0 is not allowed" cushion --angle 0
expect_error 2 "--topspin = inf is not allowed" cushion --topspin inf
expect_error 2 "--solver: foo" cushion --solver foo
expect_error 2 "--steps = 0 is not allowed" cushion --solver paper --steps 0
expect_error 2 "--tolerance = -1 is not allowed" cushion --tolerance -1
expect_error 2 "--tolerance = 1e-30 is not allowed" cushion --solver exact --tolerance 1e-30
expect_error 2 "--steps sets the paper solver's increments" cushion --steps 100
expect_error 2 "--tolerance sets the exact solver's accuracy" cushion --solver paper --tolerance 1e-6
expect_error 2 "--mu-w = 0.9 is not allowed" cushion --mu-w 0.9
expect_error 2 "--mass = -0.1 is not allowed" cushion --mass -0.1
expect_error 2 "--h = 0.01 is not allowed" cushion --h 0.01
expect_error 2 "baize cushion: error: --e = 1.5 is not allowed: it must lie in [1e-06, 1]" cushion --e 1.5
# Errors name the flag and the value as written, never the model's internal components.
expect_error 2 "baize cushion: error: --speed = 10000 is not allowed: it must lie in (0, 1000] m/s" \
  cushion --speed 1e4
expect_error 2 "--topspin = 1e+09 is not allowed: with --speed 1 and --radius 0.02625" cushion --topspin 1e9
expect_error 2 "--sidespin = -3e+06 is not allowed" cushion --sidespin -3e6
expect_error 2 "--knee-speed was given without --falloff-exponent" cushion --knee-speed 2
expect_error 2 "--falloff-exponent was given without --knee-speed" cushion --falloff-exponent 0.3
expect_error 2 "baize cushion: error: --falloff-exponent = 1.5 is not allowed: it must lie in [0, 1]" \
  cushion --knee-speed 2 --falloff-exponent 1.5
expect_error 2 "--knee-speed = -1 is not allowed: it must be a speed in (0, 1000] m/s" \
  cushion --knee-speed -1 --falloff-exponent 0.3
expect_error 2 "--knee-speed = nan is not allowed" cushion --knee-speed nan --falloff-exponent 0.3
expect_error 2 "--json excludes --sweep" cushion --sweep "$work/never" --json "$work/never.json"
expect_error 2 "--bogus" cushion --bogus
expect_error 2 "A subcommand is required" bench
expect_error 2 "--impacts = 0 is not allowed" bench cushion --impacts 0
expect_error 2 "--repeat = 0 is not allowed" bench cushion --repeat 0
expect_error 2 "--impacts = 2e+09 is not allowed: it must lie in [1, 1000000]" \
  bench cushion --impacts 2000000000
expect_error 2 "--steps = 2e+09 is not allowed: it must lie in [1, 10000000]" \
  cushion --solver paper --steps 2000000000
expect_error 2 "--mass = -1 is not allowed: it must lie in [0.001, 1000] (ball mass (kg))" \
  bench cushion --impacts 1 --repeat 1 --mass -1
expect_error 2 "--mu-s = nan is not allowed" bench cushion --impacts 1 --repeat 1 --mu-s nan
touch "$work/a-file"
expect_error 1 "--csv = $work/a-file/bench.csv: cannot create" \
  bench cushion --impacts 1 --repeat 1 --csv "$work/a-file/bench.csv"
[[ ! -e "$work/never" && ! -e "$work/a-file/bench.csv" ]] || fail "a refused command left files behind"
# Missing parent folders are made, as for every output (docs/commands.md).
"$baize" bench cushion --impacts 1 --repeat 1 --csv "$work/missing/bench.csv" >/dev/null ||
  fail "bench cushion --csv in a missing folder exited $?"
[[ -s "$work/missing/bench.csv" ]] || fail "bench cushion --csv did not make its folder"
"$baize" --help >/dev/null || fail "baize --help exited $?"
"$baize" cushion --help | grep -qF -- "--mu-s" || fail "baize cushion --help does not list --mu-s"

# ---- 5. The sweep: four CSV files with their headers, consistent with one another and with
# single runs.
"$baize" cushion --solver exact --sweep "$work/sweep" >"$work/sweep.out" || fail "sweep exited $?"
rebound_header="speed_mps,topspin_k,sidespin_k,alpha_deg,rebound_speed_mps,rebound_angle_deg,speed_ratio"
slip_header="impulse_Ns,cushion_slip_mps,cushion_slip_angle_deg,cloth_slip_mps,cloth_slip_angle_deg"
for figure in fig6 fig7 fig8; do
  [[ $(head -n 1 "$work/sweep/$figure.csv") == "$rebound_header" ]] || fail "$figure.csv header"
done
[[ $(head -n 1 "$work/sweep/fig10.csv") == "$slip_header" ]] || fail "fig10.csv header"
[[ -z $(find "$work/sweep" -name '*.tmp') ]] || fail "the sweep left temporary files"
json_of fig10 --solver exact --speed 2 --angle 45 --sidespin 2 --topspin 1.5
json_of fig8_point --solver exact --speed 1 --angle 135 --sidespin -2
check_python '
fig6, fig7, fig8, fig10 = (rows(sys.argv[1] + "/" + name + ".csv")
                           for name in ("fig6", "fig7", "fig8", "fig10"))
single10, single8 = load(sys.argv[2]), load(sys.argv[3])
angles = [float(a) for a in range(1, 180)]
def curves(table, key):
    out = {}
    for r in table:
        out.setdefault(float(r[key]), []).append(r)
    return out
for table, key, values in ((fig6, "speed_mps", [0.5, 1, 1.5, 2, 2.5]),
                           (fig7, "topspin_k", [-1, 0, 1, 2, 3]),
                           (fig8, "sidespin_k", [-2, -1, 0, 1, 2])):
    c = curves(table, key)
    assert sorted(c) == values, (key, sorted(c))
    for curve in c.values():
        assert [float(r["alpha_deg"]) for r in curve] == angles
# Fig. 6: rolling, no side: the rebound angle and the speed ratio do not depend on V0.
c6 = curves(fig6, "speed_mps")
for r_slow, r_fast in zip(c6[0.5], c6[2.5]):
    close(float(r_slow["rebound_angle_deg"]), float(r_fast["rebound_angle_deg"]), 1e-6,
          "fig6 angle")
    close(float(r_slow["speed_ratio"]), float(r_fast["speed_ratio"]), 1e-8, "fig6 ratio")
    close(float(r_fast["rebound_speed_mps"]), 2.5 * float(r_fast["speed_ratio"]), 1e-12,
          "fig6 speed")
# The same shot (V0 = 1, rolling, no side) appears in all three families with the same values.
same = [curves(fig6, "speed_mps")[1.0], curves(fig7, "topspin_k")[1.0],
        curves(fig8, "sidespin_k")[0.0]]
assert same[0] == same[1] == same[2], "the shared rolling curve differs between fig6, fig7, fig8"
# Fig. 8 at alpha = 135, k = -2 is the single run with those flags.
point = [r for r in curves(fig8, "sidespin_k")[-2.0] if float(r["alpha_deg"]) == 135][0]
close(float(point["rebound_speed_mps"]), single8["speed"], 0, "fig8 point vs single run")
close(float(point["rebound_angle_deg"]), single8["angle_deg"], 0, "fig8 point vs single run")
# Fig. 10: P runs from 0 to P_f; it starts at the incoming slips (cushion: s_x = v_x +
# R (w_y sin th - w_z cos th), s_y = -v_y sin th + R w_x; cloth: v_x - R w_y, v_y + R w_x).
P = [float(r["impulse_Ns"]) for r in fig10]
assert P[0] == 0 and all(b >= a for a, b in zip(P, P[1:])) and len(P) > 100, "fig10 impulse column"
close(P[-1], single10["final_impulse_Ns"], 1e-12, "fig10 ends at P_f")
R = single10["params"]["radius_m"]
sin_th = (single10["params"]["contact_height_m"] - R) / R
cos_th = math.sqrt(1 - sin_th ** 2)
(vx, vy, _), (wx, wy, wz) = single10["incoming"]["v"], single10["incoming"]["w"]
sx, sy = vx + R * (wy * sin_th - wz * cos_th), -vy * sin_th + R * wx
cx, cy = vx - R * wy, vy + R * wx
first = fig10[0]
close(float(first["cushion_slip_mps"]), math.hypot(sx, sy), 1e-12, "s(0)")
close(float(first["cushion_slip_angle_deg"]), math.degrees(math.atan2(sy, sx)), 1e-9, "Phi(0)")
close(float(first["cloth_slip_mps"]), math.hypot(cx, cy), 1e-12, "s_prime(0)")
close(float(first["cloth_slip_angle_deg"]), math.degrees(math.atan2(cy, cx)), 1e-9, "Phi_prime(0)")
assert all(float(r["cushion_slip_mps"]) >= 0 and float(r["cloth_slip_mps"]) >= 0 for r in fig10)
' "$work/sweep" "$work/fig10.json" "$work/fig8_point.json"

# ---- 6. The bench in smoke mode: the table's columns and rows, and how the errors relate.
"$baize" bench cushion --impacts 20 --repeat 1 --csv "$work/bench.csv" >"$work/bench.out" ||
  fail "bench exited $?"
grep -qF "speed ratio" "$work/bench.out" || fail "bench prints no speed ratio"
grep -qF "accuracy ratio" "$work/bench.out" || fail "bench prints no accuracy ratio"
grep -qE "^exact default: [0-9]+\.[0-9] evaluations per impact; [0-9]+ of 30 impacts above 5e-10 V0, 0 above the promised 1e-9 V0 \(kept\)$" \
  "$work/bench.out" || fail "bench does not report the exact solver's promise: $(grep "exact default" "$work/bench.out")"
[[ ! -e "$work/bench.csv.tmp" ]] || fail "the bench left its temporary file"
check_python '
with open(sys.argv[1]) as f:
    lines = f.read().splitlines()
assert lines[0] == "solver,setting,median_ns,max_error", lines[0]
table = rows(sys.argv[1])
assert [(r["solver"], r["setting"]) for r in table] == [
    ("paper", "N=100"), ("paper", "N=1000"), ("paper", "N=5000"), ("paper", "N=50000"),
    ("exact", "default"), ("tabulated", "default"), ("exact", "tol=1e-06"), ("exact", "tol=1e-08"),
    ("exact", "tol=1e-10"), ("exact", "tol=1e-12")], table
error = {r["solver"] + " " + r["setting"]: float(r["max_error"]) for r in table}
assert all(float(r["median_ns"]) > 0 for r in table)
# The paper scheme is first order: 500 times the steps cut its error by well over 50.
paper = [error["paper N=" + n] for n in ("100", "1000", "5000", "50000")]
assert all(b < a for a, b in zip(paper, paper[1:])), paper
assert paper[3] < paper[0] / 50, paper
# The exact solver meets its documented accuracy (1e-9 V0 at the default tolerance) and tighter
# tolerances give smaller errors.
assert error["exact default"] <= 1e-9, error
assert error["exact tol=1e-12"] < error["exact tol=1e-08"] < error["exact tol=1e-06"], error
assert error["exact default"] < paper[3], error
# The default path keeps its promise (1e-6 V0); the tighter promise of its table is held by
# tests/physics/cushion_rolling_surface_test.cpp.
assert error["tabulated default"] <= 1e-6, error
# The stdout table is the CSV.
with open(sys.argv[2]) as f:
    printed = f.read()
for line in lines:
    assert line in printed, line
' "$work/bench.csv" "$work/bench.out"

# The bench on another cushion (the 9 ft pool table's ball and cloth): the header names the values
# in use (h = 7R/5 of the radius given), they reach every solver (the table differs from the
# snooker one above), and the exact solver keeps its accuracy there too.
"$baize" bench cushion --impacts 20 --repeat 1 --mass 0.17 --radius 0.028575 --mu-s 0.2 \
  --csv "$work/bench_pool.csv" >"$work/bench_pool.out" || fail "bench on the pool cushion exited $?"
grep -qF "cushion: M 0.17 kg, R 0.028575 m, h 0.040005 m, e_e 0.98, mu_w 0.14, mu_s 0.2" \
  "$work/bench_pool.out" || fail "the pool bench does not name its cushion: $(head -3 "$work/bench_pool.out")"
grep -qF "cushion: M 0.1406 kg, R 0.02625 m, h 0.03675 m" "$work/bench.out" ||
  fail "the default bench does not name the paper's snooker cushion"
"$baize" bench cushion --impacts 1 --repeat 1 --radius 0.028575 --h 0.03629 >"$work/bench_h.out" ||
  fail "bench with --h exited $?"
grep -qF "R 0.028575 m, h 0.03629 m," "$work/bench_h.out" ||
  fail "an explicit --h does not win over 7R/5: $(head -2 "$work/bench_h.out")"
check_python '
snooker = {r["setting"] + r["solver"]: float(r["max_error"]) for r in rows(sys.argv[1])}
pool = {r["setting"] + r["solver"]: float(r["max_error"]) for r in rows(sys.argv[2])}
assert snooker.keys() == pool.keys()
assert all(snooker[k] != pool[k] for k in pool), (snooker, pool)
assert pool["defaultexact"] <= 1e-9, pool
' "$work/bench.csv" "$work/bench_pool.csv"

# The bench on the impacts of `baize bench shots`' random single shots: the header counts them and
# names their table's cushion (the 9 ft pool table's), the rows are the same, and the exact solver
# keeps its accuracy there too.
"$baize" bench cushion --from-shots 4 --repeat 1 --csv "$work/bench_shots.csv" \
  >"$work/bench_shots.out" || fail "bench --from-shots exited $?"
grep -qE "^baize bench cushion: the [1-9][0-9]* cushion and jaw impacts of 4 random single shots" \
  "$work/bench_shots.out" || fail "the shots bench does not count its impacts: $(head -1 "$work/bench_shots.out")"
grep -qF "cushion: M 0.17 kg, R 0.028575 m, h 0.03629 m, e_e 0.74, mu_w 0.14, mu_s 0.2" \
  "$work/bench_shots.out" || fail "the shots bench does not name its table's cushion"
check_python '
pool = {r["setting"] + r["solver"]: float(r["max_error"]) for r in rows(sys.argv[1])}
shots = {r["setting"] + r["solver"]: float(r["max_error"]) for r in rows(sys.argv[2])}
assert shots.keys() == pool.keys()
assert shots["defaultexact"] <= 1e-9, shots
assert shots["defaultexact"] < shots["N=50000paper"] < shots["N=100paper"], shots
' "$work/bench_pool.csv" "$work/bench_shots.csv"
grep -qE "^exact default: [0-9]+\.[0-9] evaluations per impact; [0-9]+ of [0-9]+ impacts above 5e-10 V0, 0 above the promised 1e-9 V0 \(kept\)$" \
  "$work/bench_shots.out" || fail "the shots bench does not report the exact solver's promise: $(grep "exact default" "$work/bench_shots.out")"
grep -qE "^tabulated default \(the default path\): [1-9][0-9]* of [0-9]+ impacts answered from the table, the rest solved exactly at tolerance 1e-08 \([0-9.e+]+ rate evaluations each; the [0-9]+ with a stick phase take [0-9.e+-]+ % of them\); [0-9.e+-]+ ns median; largest error [0-9.e+-]+ V0, 99.9th percentile [0-9.e+-]+ V0; promised 1e-6 V0 \(kept\)$" \
  "$work/bench_shots.out" || fail "the shots bench does not report the default path's promise: $(grep "tabulated default" "$work/bench_shots.out")"
# The impacts left to the exact solver that have a stick phase: no more of them than were left, and
# their share of the evaluations a percentage.
check_python '
import re
line = next(l for l in open(sys.argv[1]) if l.startswith("tabulated default"))
m = re.search(r"(\d+) of (\d+) impacts answered from the table.*; the (\d+) with a stick phase take ([0-9.e+-]+) % of them\)", line)
assert m, line
answered, impacts, stuck, share = int(m[1]), int(m[2]), int(m[3]), float(m[4])
assert stuck <= impacts - answered and 0 <= share <= 100 and (share > 0) == (stuck > 0), line
' "$work/bench_shots.out"

# The bench on the impacts of one scene's shot: as many as the scene's result counts cushion and
# jaw contacts, its table's cushion, the default path's split between the table and the exact
# solver, and the scene's cushion overrides in force.
"$baize" bench cushion --from-scene "$root/assets/scenes/9-ball-break.json" --repeat 1 \
  --csv "$work/bench_scene.csv" >"$work/bench_scene.out" || fail "bench --from-scene exited $?"
"$baize" simulate "$root/assets/scenes/9-ball-break.json" --json "$work/break.json" --quiet >/dev/null ||
  fail "simulate of the break exited $?"
check_python '
import re
out = open(sys.argv[1]).read()
contacts = [e for e in load(sys.argv[2])["events"] if e["type"] in ("cushion", "jaw")]
header = re.search(r"^baize bench cushion: the (\d+) cushion and jaw impacts of .*9-ball-break.json", out, re.M)
assert header and int(header.group(1)) == len(contacts) > 0, (out[:200], len(contacts))
split = re.search(r"^tabulated default \(the default path\): (\d+) of (\d+) impacts answered", out, re.M)
assert split and 0 < int(split.group(1)) < int(split.group(2)) == len(contacts), out
# The stick count is not always zero: of the impacts the break leaves to the exact solver, one is
# an object ball whose nose sticks (as the contact log of its exact solution lists).
stuck = re.search(r"^tabulated default .*; the (\d+) with a stick phase take", out, re.M)
assert stuck and 1 <= int(stuck.group(1)) <= int(split.group(2)) - int(split.group(1)), out
assert "cushion: M 0.17 kg, R 0.028575 m, h 0.03629 m, e_e 0.74, mu_w 0.14, mu_s 0.2" in out, out
shots = {r["setting"] + r["solver"]: float(r["max_error"]) for r in rows(sys.argv[3])}
assert shots["defaultexact"] <= 1e-9 and shots["defaulttabulated"] <= 1e-6, shots
' "$work/bench_scene.out" "$work/break.json" "$work/bench_scene.csv"
cat >"$work/lively_break.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool", "rack": {"name": "9-ball"},
 "shot": {"aim_at": "1", "speed_mps": 6.0, "height": -0.1},
 "physics": {"cushion": {"model": "exact", "restitution": 0.9}}}
JSON
"$baize" bench cushion --from-scene "$work/lively_break.json" --repeat 1 >"$work/bench_lively.out" ||
  fail "bench --from-scene with overrides exited $?"
grep -qF "cushion: M 0.17 kg, R 0.028575 m, h 0.03629 m, e_e 0.9, mu_w 0.14, mu_s 0.2" \
  "$work/bench_lively.out" || fail "the scene bench does not take the scene's cushion overrides"
cat >"$work/simple_break.json" <<'JSON'
{"table": "pool-9ft", "ball_set": "pool", "rack": {"name": "9-ball"},
 "shot": {"aim_at": "1", "speed_mps": 6.0}, "physics": {"cushion": {"model": "simple"}}}
JSON
expect_error 2 "simple_break.json: its cushion model is \"simple\" (physics.cushion.model)" \
  bench cushion --from-scene "$work/simple_break.json"
expect_error 2 "draw-shot.json: its shot meets no cushion" \
  bench cushion --from-scene "$root/assets/scenes/draw-shot.json"
expect_error 2 "the file cannot be opened" bench cushion --from-scene "$work/no_such_scene.json"
expect_error 2 "--from-shots excludes --from-scene" bench cushion --from-scene x --from-shots 2
expect_error 2 "--from-scene excludes --set" bench cushion --from-scene x --set spinning
expect_error 2 "--mass excludes --from-scene" bench cushion --from-scene x --mass 0.2

# ---- 7. The sets that check the exact solver's promise alone: spin about every axis, and grippy
# cushions and cloth drawn per impact. One row each, the same for the same seed, another for
# another seed; the promise kept on these small draws.
for run in spin_a spin_b; do
  "$baize" bench cushion --set spinning --impacts 30 --mass 0.17 --radius 0.028575 --h 0.03629 \
    --mu-s 0.2 --csv "$work/$run.csv" >"$work/$run.out" || fail "bench --set spinning exited $?"
done
"$baize" bench cushion --set spinning --impacts 30 --seed 2 --mass 0.17 --radius 0.028575 \
  --h 0.03629 --mu-s 0.2 --csv "$work/spin_c.csv" >"$work/spin_c.out" || fail "seed 2 exited $?"
"$baize" bench cushion --set grippy --impacts 10 --seed 3 --csv "$work/grippy.csv" \
  >"$work/grippy.out" || fail "bench --set grippy exited $?"
grep -qF "the spinning set, 30 impacts (seed 1;" "$work/spin_a.out" ||
  fail "the spinning bench does not name its set and seed: $(head -1 "$work/spin_a.out")"
grep -qF "mu_w and mu_s drawn per impact" "$work/grippy.out" ||
  fail "the grippy bench does not say its frictions are drawn: $(head -2 "$work/grippy.out")"
grep -qF "0 above the promised 1e-9 V0 (kept)" "$work/grippy.out" || fail "grippy: promise line"
# Grippy contacts leave the table nothing: the default path solves each impact with the exact
# solver at its own, looser tolerance, in fewer evaluations per impact.
check_python '
import re
text = open(sys.argv[1]).read()
exact = float(re.search(r"^exact default: ([0-9.]+) evaluations per impact", text, re.M).group(1))
path = re.search(r"^tabulated default \(the default path\): 0 of 10 impacts answered from the "
                 r"table, the rest solved exactly at tolerance 1e-08 \(([0-9.e+]+) rate "
                 r"evaluations each; the \d+ with a stick phase take [0-9.e+-]+ % of them\)",
                 text, re.M)
assert path, text
assert 0 < float(path.group(1)) < exact, ("evaluations each, path vs exact", path.group(1), exact)
' "$work/grippy.out"
# The default path keeps its own promise on both sets, at its looser tolerance.
for run in spin_a grippy; do
  grep -qE "^tabulated default \(the default path\): .*; promised 1e-6 V0 \(kept\)$" "$work/$run.out" ||
    fail "$run: the default path's promise line: $(grep '^tabulated default' "$work/$run.out")"
done
check_python '
import re
# The worst impact is one of the set, drawn as documented: V0 in [0.1, 2.5] m/s, alpha in [1, 179]
# deg; spinning: spin about each axis in [-3, 3] V0/R, none zero, on the flags cushion; grippy:
# mu_w in [0, 0.4), mu_s in [0.35, 0.425), topspin in [0.8, 1.05] and no spin about the travel.
number = r"(-?[0-9.]+(?:e-?[0-9]+)?)"
pattern = (r"^largest error: impact ([0-9]+), V0 N m/s, alpha N deg, spin \(N, N, N\) V0/R, "
           r"mu_w N, mu_s N$").replace("N", number)
def worst(path):
    with open(path) as f:
        (line,) = [l.strip() for l in f if l.startswith("largest error")]
    match = re.match(pattern, line)
    assert match, line
    return [float(x) for x in match.groups()]
i, v0, alpha, sx, sy, sz, mu_w, mu_s = worst(sys.argv[1])
assert 0 <= i < 30 and 0.1 <= v0 < 2.5 and 1 <= alpha < 179, (i, v0, alpha)
assert all(0 < abs(x) <= 3 for x in (sx, sy, sz)), (sx, sy, sz)
assert (mu_w, mu_s) == (0.14, 0.2), (mu_w, mu_s)
i, v0, alpha, sx, sy, sz, mu_w, mu_s = worst(sys.argv[2])
assert 0 <= i < 10 and 0.1 <= v0 < 2.5 and 1 <= alpha < 179, (i, v0, alpha)
assert 0 <= mu_w < 0.4 and 0.35 <= mu_s < 0.425, (mu_w, mu_s)
assert mu_w != 0.14 and mu_s != 0.212, (mu_w, mu_s)  # drawn, not the default cushion
# Near-rolling: topspin k in [0.8, 1.05] about the axis along the cushion turned by alpha.
topspin = math.hypot(sx, sy)
assert 0.8 - 1e-9 <= topspin <= 1.05 + 1e-9 and abs(sz) <= 1.5, (sx, sy, sz)
' "$work/spin_a.out" "$work/grippy.out"
cmp -s "$work/spin_a.csv" "$work/spin_b.csv" || fail "the same seed gave another spinning set"
check_python '
header = "set,impacts,evaluations_per_impact,above_half_promise,above_promise,max_error"
for path, name, n in ((sys.argv[1], "spinning", 30), (sys.argv[3], "grippy", 10)):
    with open(path) as f:
        assert f.readline().strip() == header, path
    (row,) = rows(path)
    assert row["set"] == name and int(row["impacts"]) == n, row
    assert float(row["evaluations_per_impact"]) > 12, row  # at least one Runge-Kutta step
    assert int(row["above_promise"]) == 0 <= int(row["above_half_promise"]), row
    assert 0 < float(row["max_error"]) <= 1e-9, row
(a,) = rows(sys.argv[1]); (c,) = rows(sys.argv[2])
assert a["max_error"] != c["max_error"], (a, c)
' "$work/spin_a.csv" "$work/spin_c.csv" "$work/grippy.csv"
# The grippy set's worst impact, run again by `baize cushion` as the bench prints it, has exactly
# the error the bench reports: the bench solved it with that impact's own frictions.
same_impact=$(sed -n 's/^the same impact: baize //p' "$work/grippy.out")
[[ -n "$same_impact" ]] || fail "the grippy bench does not print its worst impact as a command"
# shellcheck disable=SC2086  # the printed flags, split as a shell splits words
"$baize" $same_impact --json - 2>/dev/null >"$work/worst.json" || fail "baize $same_impact exited $?"
# shellcheck disable=SC2086
"$baize" $same_impact --json - --tolerance 1e-14 2>/dev/null >"$work/worst_ref.json" ||
  fail "baize $same_impact --tolerance 1e-14 exited $?"
check_python '
solved, reference = load(sys.argv[1]), load(sys.argv[2])
radius, speed = solved["params"]["radius_m"], solved["incoming"]["speed_mps"]
error = max(max(abs(a - b) for a, b in zip(solved["v"], reference["v"])),
            radius * max(abs(a - b) for a, b in zip(solved["w"], reference["w"]))) / speed
(row,) = rows(sys.argv[3])
assert error == float(row["max_error"]), (error, row["max_error"])
' "$work/worst.json" "$work/worst_ref.json" "$work/grippy.csv"
expect_error 2 "--set: foo not in {drawn,spinning,grippy}" bench cushion --set foo
expect_error 2 "--seed draws the spinning or grippy set" bench cushion --seed 3 --impacts 1
expect_error 2 "--seed" bench cushion --set spinning --seed -1
expect_error 2 "the grippy set draws mu_w up to 0.4 and mu_s up to 0.425, which this cushion" \
  bench cushion --set grippy --mass 0.17 --radius 0.028575 --h 0.03629
expect_error 2 "--mu-w and --mu-s: the grippy set draws its own" \
  bench cushion --set grippy --mu-w 0.05
expect_error 2 "--repeat times the drawn sets; the grippy set is not timed" \
  bench cushion --set grippy --repeat 2
expect_error 2 "--from-shots excludes --set" bench cushion --set spinning --from-shots 2
expect_error 2 "--from-shots = 0 is not allowed" bench cushion --from-shots 0
expect_error 2 "--mass excludes --from-shots" bench cushion --from-shots 1 --mass 0.2
expect_error 2 "--impacts excludes --from-shots" bench cushion --from-shots 1 --impacts 3
# The paper scheme with too few increments hands back more energy than the ball brought: refused
# naming --steps and both energies, as scenes refuse it; enough increments pass.
expect_error 2 "--steps 1: the paper scheme made this impact gain energy (0.09842 J in" \
  cushion --solver paper --steps 1
"$baize" cushion --solver paper --steps 50 >/dev/null || fail "--steps 50 was refused"

echo "cushion CLI: all checks passed"
