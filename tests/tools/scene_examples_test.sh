#!/usr/bin/env bash
# Every scene of docs/scenes.md's "Examples, one per feature" runs through baize simulate:
# the documentation cannot drift from what the program accepts.
# Usage: scene_examples_test.sh path/to/baize
set -euo pipefail
baize=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

python3 - "$root/docs/scenes.md" "$work" <<'PY'
import json, re, sys
text = open(sys.argv[1]).read()
section = text.split("## Examples, one per feature", 1)[1].split("\n## ", 1)[0]
blocks = re.findall(r"```json\n(.*?)```", section, re.S)
assert len(blocks) >= 7, f"only {len(blocks)} examples"
for i, block in enumerate(blocks):
    scene = json.loads(block)  # each block is a complete scene
    open(f"{sys.argv[2]}/example{i}.json", "w").write(block)
PY
# The own-files example reads these next to it.
cp "$root/assets/tables/pool-9ft.json" "$work/my-9ft.json"
cp "$root/assets/balls/pool.json" "$work/my-balls.json"
count=0
for scene in "$work"/example*.json; do
  out=$("$baize" simulate "$scene" --json "$scene.out") || fail "$(cat "$scene") exited $?"
  grep -q "^first ball hit: " <<<"$out" || fail "no summary for $(cat "$scene"): $out"
  count=$((count + 1))
done
# The massé example: the cue ball's path curves while it slides. Its first event is its change to
# rolling (no contact before it), and by then its heading has turned well away from the cue's.
masse=$(grep -l '"elevation_deg": 70' "$work"/example*.json)
python3 - "$masse.out" <<'PY'
import json, math, sys
d = json.load(open(sys.argv[1]))
first = d["events"][0]
assert first["type"] == "state change" and first["ball"] == "cue", first
v0 = d["trajectories"]["cue"][0]["velocity_mps"]
v1 = first["before"][0]["velocity_mps"]
turn = math.degrees(math.atan2(v1[1], v1[0]) - math.atan2(v0[1], v0[0]))
turn = (turn + 180) % 360 - 180
assert abs(turn) > 20, f"the massé turned the cue ball by only {turn:.2f} deg while sliding"
PY
echo "scene examples: $count ran"
