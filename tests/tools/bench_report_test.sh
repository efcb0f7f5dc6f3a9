#!/usr/bin/env bash
# tools/bench_report.sh in its quick mode: the report has the machine, the commit and every table,
# its charts are written, and the README's headline line is replaced by the report's (and only it).
# Usage: bench_report_test.sh path/to/baize
set -euo pipefail
baize=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

printf '# Title\n\n<!-- benchmark-headline -->\nan old headline\n\nthe rest\n' > "$work/README.md"
out=$(bash "$root/tools/bench_report.sh" --quick --baize "$baize" --out "$work/bench.md" \
  --images "$work" --readme "$work/README.md") || fail "bench_report.sh exited $?"
grep -q "^wrote $work/bench.md: Random single shots: " <<<"$out" || fail "output: $out"
for part in "- Commit: " "- Machine: " "## Whole shots" "| 9-ball-break |" "## Accuracy against run time" \
  "| event | exact |" "## The cushion solvers" "| exact | default |" "### The 9-ball break's impacts" \
  "impacts of assets/scenes/9-ball-break.json" "impacts answered from the table" "### The impacts of play" \
  "cushion and jaw impacts of 20 random single shots" "## Rendering" "bench-accuracy.png" \
  "## Game play" "| 9-ball | 1.00 | 2 |" "| snooker | 1.00 | 1 |" "## Python" "baize.simulate_many"; do
  grep -qF -- "$part" "$work/bench.md" || fail "the report has no '$part'"
done
[[ -s "$work/bench-accuracy.png" && -s "$work/bench-cushion.png" ]] || fail "charts not written"
python3 - "$work/README.md" "$work/bench.md" <<'PY'
import sys
readme = open(sys.argv[1]).read().split("\n")
report = open(sys.argv[2]).read()
assert readme[0] == "# Title" and readme[2] == "<!-- benchmark-headline -->", readme
assert readme[3].startswith("Random single shots: ") and "on one core" in readme[3], readme[3]
# The report carries the README's headline without the README's link to the report itself.
assert readme[3].endswith(" ([docs/benchmarks.md](docs/benchmarks.md))."), readme[3]
assert "**" + readme[3].split(" ([docs/")[0] + ".**" in report, "the README's headline is not the report's"
assert readme[4:] == ["", "the rest", ""], readme[4:]
PY
# A README without the marker is refused before anything runs; so is an unknown flag.
printf '# No marker\n' > "$work/plain.md"
set +e
msg=$(bash "$root/tools/bench_report.sh" --quick --baize "$baize" --out "$work/x.md" \
  --images "$work" --readme "$work/plain.md" 2>&1); status=$?
set -e
[[ $status -eq 2 && ! -e "$work/x.md" ]] || fail "a README without the marker: exit $status"
grep -q "no '<!-- benchmark-headline -->' line" <<<"$msg" || fail "message: $msg"
set +e
msg=$(bash "$root/tools/bench_report.sh" --fast 2>&1); status=$?
set -e
[[ $status -eq 2 ]] && grep -q "unknown argument '--fast'" <<<"$msg" || fail "--fast: $status $msg"
echo "bench_report_test: ok"
