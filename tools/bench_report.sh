#!/usr/bin/env bash
# Runs Baize's benchmarks and writes one report: the machine, the date and commit, and every table
# (whole shots, accuracy against run time, the cushion solvers, rendering, game play) with its
# charts. The
# README's headline line is taken from it. Every measured figure in the docs comes from here.
#
# Usage: tools/bench_report.sh [--quick] [--baize PATH] [--out FILE] [--images DIR] [--readme FILE]
#   --baize PATH   the program to measure (default build/baize)
#   --out FILE     the report (default docs/benchmarks.md)
#   --images DIR   where its charts go (default docs/images)
#   --readme FILE  the file whose headline line is replaced (default README.md; "none": no file)
#   --quick        tiny runs, for checking the report is made (the figures mean nothing)
# Run from the repository's root after building (build/baize). It takes some minutes in full.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

out=docs/benchmarks.md images=docs/images readme=README.md quick=0 baize=build/baize
while [[ $# -gt 0 ]]; do
  case "$1" in
    --quick) quick=1; shift ;;
    --out|--images|--readme|--baize)
      [[ $# -ge 2 && -n "$2" ]] || { echo "bench_report.sh: $1 needs a value" >&2; exit 2; }
      case "$1" in
        --out) out=$2 ;; --images) images=$2 ;; --readme) readme=$2 ;; --baize) baize=$2 ;;
      esac
      shift 2 ;;
    *) echo "bench_report.sh: unknown argument '$1' (allowed: --quick, --baize PATH, --out FILE," \
         "--images DIR, --readme FILE)" >&2
       exit 2 ;;
  esac
done
[[ -x "$baize" ]] || { echo "bench_report.sh: $baize not found: build first (see README)" >&2; exit 1; }
[[ -d "$images" ]] || { echo "bench_report.sh: --images $images is not a directory" >&2; exit 2; }
if [[ "$readme" != none ]]; then
  grep -q '<!-- benchmark-headline -->' "$readme" ||
    { echo "bench_report.sh: $readme has no '<!-- benchmark-headline -->' line to replace" >&2; exit 2; }
fi

if [[ $quick -eq 1 ]]; then
  shots_flags=(--repeat 1 --random-shots 30) accuracy_flags=(--shots 2 --repeat 1)
  cushion_flags=(--impacts 30 --repeat 1) render_flags=(--repeat 1 --width 320 --height 160)
  set_flags=(--impacts 30)
  pool_play_flags=(--racks 2 --noise 1) snooker_play_flags=(--racks 1 --noise 1)
else
  shots_flags=(--repeat 21 --random-shots 3000) accuracy_flags=()
  cushion_flags=() render_flags=() set_flags=()
  pool_play_flags=(--racks 200 --noise 0.5,1,2) snooker_play_flags=(--racks 20 --noise 0.5,1)
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
progress() { [[ -t 2 ]] && echo "bench_report.sh: $*" >&2 || true; }

progress "whole shots"
"$baize" bench shots "${shots_flags[@]}" --csv "$work/shots.csv" > "$work/shots.txt"
progress "accuracy against run time"
"$baize" bench accuracy "${accuracy_flags[@]}" --csv "$work/accuracy.csv" > "$work/accuracy.txt"
progress "cushion solvers"
"$baize" bench cushion "${cushion_flags[@]}" --csv "$work/cushion.csv" > "$work/cushion.txt"
progress "the 9-ball break's cushion impacts"
break_flags=()
[[ $quick -eq 1 ]] && break_flags=(--repeat 1)
"$baize" bench cushion --from-scene assets/scenes/9-ball-break.json "${break_flags[@]}" \
  --csv "$work/cushion-break.csv" > "$work/cushion-break.txt"
progress "the impacts of play (long: every impact is also solved at the reference tolerance)"
play_impacts_flags=(--from-shots 40000 --repeat 1)
[[ $quick -eq 1 ]] && play_impacts_flags=(--from-shots 20 --repeat 1)
"$baize" bench cushion "${play_impacts_flags[@]}" > "$work/cushion-play.txt"
progress "the spinning and grippy sets"
for set in spinning grippy; do
  "$baize" bench cushion --set "$set" "${set_flags[@]}" > "$work/cushion-$set.txt"
done
progress "Python package"
python_bench=(/usr/bin/python3 tools/bench_python.py --baize "$baize")
[[ $quick -eq 1 ]] && python_bench+=(--quick)
if [[ -d "$(dirname "$baize")/python/baize" ]]; then
  PYTHONPATH="$(dirname "$baize")/python" "${python_bench[@]}" > "$work/python.md"
else
  printf '## Python\n\nNot measured: built with BAIZE_WITH_PYTHON=OFF.\n' > "$work/python.md"
fi
progress "rendering"
GALLIUM_DRIVER=llvmpipe "$baize" bench render "${render_flags[@]}" > "$work/render.txt"
progress "game play"
"$baize" bench play --game 9-ball "${pool_play_flags[@]}" --csv "$work/play-9-ball.csv" > /dev/null
"$baize" bench play --game snooker "${snooker_play_flags[@]}" --csv "$work/play-snooker.csv" > /dev/null
"$baize" chart bench-accuracy "$work/accuracy.csv" --png "$work/bench-accuracy.png" >/dev/null
"$baize" chart bench-cushion "$work/cushion.csv" --png "$work/bench-cushion.png" >/dev/null

commit=$(git rev-parse --short HEAD 2>/dev/null || echo unknown)
# The report's own outputs do not count as changes to what was measured.
changed=$(git status --porcelain -- . ":!$out" ":!$images" ":!$readme" 2>/dev/null || true)
[[ -z "$changed" ]] || commit="$commit (with uncommitted changes)"
python3 - "$work" "$out.tmp" "$commit" "$quick" "$images" <<'PY'
import csv, datetime, os, platform, sys
work, out, commit, quick, images = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4] == "1", sys.argv[5]

def table(path):
    rows = list(csv.reader(open(path)))
    lines = ["| " + " | ".join(rows[0]) + " |", "|" + "---|" * len(rows[0])]
    lines += ["| " + " | ".join(r) + " |" for r in rows[1:]]
    return "\n".join(lines)

def text(path, skip_prefix=None):
    return [l.rstrip() for l in open(path) if l.strip() and not (skip_prefix and l.startswith(skip_prefix))]

def promise_lines(name):
    """A `baize bench cushion` run's header and promise lines, as a code block."""
    return [f"    {l}" for l in text(f"{work}/{name}.txt")
            if l.startswith(("baize bench cushion:", "exact default:", "tabulated default"))]

cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), platform.processor())
load = open("/proc/loadavg").read().split()[:3]
shots = {r["scene"]: r for r in csv.DictReader(open(f"{work}/shots.csv"))}
shot_lines = text(f"{work}/shots.txt")
rate = next(l for l in shot_lines if l.startswith("random single shots:"))
per_core = rate.split(":")[1].split("shots/s")[0].strip()
ratio = float(shots["random-single-shots"]["one_core_us"]) / float(shots["random-single-shots-simple"]["one_core_us"])
ratio_line = next(l for l in shot_lines if l.startswith("random single shots with the full cushion model"))
total_ratio = float(ratio_line.split("of their total times:")[1].split("x")[0])
headline = (f"Random single shots: {float(per_core):,.0f} per second on one core "
            f"(full cushion model {ratio:.2f}x the simple rule's time for the median shot, "
            f"{total_ratio:.2f}x in total); "
            f"9-ball break: {float(shots['9-ball-break']['one_core_us']):.0f} us on one core "
            f"([docs/benchmarks.md](docs/benchmarks.md)).")
now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
rel = os.path.relpath(images, os.path.dirname(os.path.abspath(out)) or ".")
doc = [
    "# Benchmarks",
    "",
    "Made by `tools/bench_report.sh`" + (" --quick (tiny runs: these figures mean nothing)" if quick else "") +
    "; run it again to measure your machine. Times are medians; per-core figures ran on one core.",
    "",
    f"- Date: {now}",
    f"- Commit: {commit}",
    f"- Machine: {cpu}, {os.cpu_count()} cores, load {' '.join(load)} (1, 5, 15 min) at the end",
    "",
    "**" + headline.split(" ([docs/benchmarks.md]")[0] + ".**",  # the README's line, without its link here
    "",
    "## Whole shots (`baize bench shots`)",
    "",
    "`one_core_us`: the shot on one core. `two_core_wall_us`: with a worker thread solving cushion",
    "impacts ahead on a second core (`nan` where there is none).",
    "",
    table(f"{work}/shots.csv"),
    "",
] + [f"    {l}" for l in shot_lines if "," not in l and not l.startswith("wrote ")] + [
    "",
    "## Accuracy against run time (`baize bench accuracy`)",
    "",
    "Error of each engine's final positions and contacts against the exact event loop, and its "
    "time per shot.",
    "",
    table(f"{work}/accuracy.csv"),
    "",
    f"![Run time against error]({rel}/bench-accuracy.png)",
    "",
    "## The cushion solvers (`baize bench cushion`)",
    "",
    "Time per impact and the largest velocity error relative to V0 against a converged reference.",
    "",
    table(f"{work}/cushion.csv"),
    "",
    f"![Cushion solvers: time against error]({rel}/bench-cushion.png)",
    "",
    "### The 9-ball break's impacts (`--from-scene assets/scenes/9-ball-break.json`)",
    "",
    "The same rows on the cushion and jaw impacts of the 9-ball break, and how many of them the",
    "default path answers from its table of rolling balls.",
    "",
    table(f"{work}/cushion-break.csv"),
    "",
] + promise_lines("cushion-break") + [
    "",
    "### The impacts of play (`--from-shots`)",
    "",
    "Every cushion and jaw impact of the first of `baize bench shots`' random single shots (the",
    "first line says how many), each also solved at the reference tolerance: the default path's",
    "largest error and 99.9th percentile against its promise.",
    "",
] + promise_lines("cushion-play") + [
    "",
    "### Spin about every axis, grippy cushions (`--set spinning`, `--set grippy`)",
    "",
    "The promises on impacts the table cannot answer: the exact solver at its default, and the",
    "default path at its own tolerance, against the converged reference (not timed).",
    "",
] + promise_lines("cushion-spinning") + promise_lines("cushion-grippy") + [
    "",
    "## Rendering (`baize bench render`)",
    "",
] + [f"    {l}" for l in text(f"{work}/render.txt")] + [
    "",
    "## Game play (`baize bench play`)",
    "",
    "Frames between two game players from the break, frame r with seed 1 + r, at execution noise",
    "scales (multiples of the default sigmas). 9-ball: `break_and_run`, the breaker wins without the",
    "opponent playing; `first_visit_run_out`, the player of the first shot after the break clears",
    "the table in that visit (95 % Wilson intervals). Snooker: the mean break over scoring visits",
    "(95 % interval). `ms_per_shot`: the median time of one shot, the player's decision and its",
    "stroke, on one core.",
    "",
    table(f"{work}/play-9-ball.csv"),
    "",
    table(f"{work}/play-snooker.csv"),
    "",
] + text(f"{work}/python.md") + [""]
open(out, "w").write("\n".join(doc))
open(out + ".headline", "w").write(headline + "\n")
PY
cp "$work/bench-accuracy.png" "$images/bench-accuracy.png"
cp "$work/bench-cushion.png" "$images/bench-cushion.png"
headline=$(cat "$out.tmp.headline")
rm -f "$out.tmp.headline"
mv "$out.tmp" "$out"
if [[ "$readme" != none ]]; then
  python3 - "$readme" "$headline" <<'PY'
import sys
path, headline = sys.argv[1], sys.argv[2]
lines = open(path).read().split("\n")
i = next(k for k, l in enumerate(lines) if l.strip() == "<!-- benchmark-headline -->")
# The line after the marker is the headline.
if i + 1 < len(lines) and lines[i + 1].strip():
    lines[i + 1] = headline
else:
    lines.insert(i + 1, headline)
open(path + ".tmp", "w").write("\n".join(lines))
PY
  mv "$readme.tmp" "$readme"
fi
echo "wrote $out: $headline"
