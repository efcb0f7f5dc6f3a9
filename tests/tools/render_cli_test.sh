#!/usr/bin/env bash
# baize render and baize simulate --png, run the way a user runs them: pictures of the shipped
# scenes and of a saved result, frames, animated GIFs, the bench in smoke size, and bad input.
# Usage: render_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export GALLIUM_DRIVER=llvmpipe  # one rasteriser: the same input gives the same bytes

# PNG width and height from the IHDR chunk.
png_size() {
  python3 - "$1" <<'PY'
import struct, sys
data = open(sys.argv[1], "rb").read(24)
assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
print(*struct.unpack(">II", data[16:24]))
PY
}

# simulate --png: the picture is written (parent folders made), named in the output, of the size asked.
scene="$root/assets/scenes/9-ball-break.json"
out=$("$baize" simulate "$scene" --png "$work/out/deeper/break.png" --width 640 --height 320) ||
  fail "simulate --png exited $?"
grep -q "^picture: $work/out/deeper/break.png (640 x 320 px, top view)$" <<<"$out" || fail "no picture line: $out"
[[ $(png_size "$work/out/deeper/break.png") == "640 320" ]] || fail "size $(png_size "$work/out/deeper/break.png")"

# render of the scene gives the same bytes as simulate --png, twice over (determinism).
"$baize" render "$scene" --png "$work/a.png" --width 640 --height 320 >/dev/null || fail "render exited $?"
"$baize" render "$scene" --png "$work/b.png" --width 640 --height 320 >/dev/null || fail "render exited $?"
cmp -s "$work/a.png" "$work/b.png" || fail "two renders of the same scene differ"
cmp -s "$work/a.png" "$work/out/deeper/break.png" || fail "render and simulate --png differ"

# A saved result renders to the same picture as its scene, from another working directory.
"$baize" simulate "$scene" --json "$work/result.json" >/dev/null || fail "simulate --json exited $?"
(cd / && "$baize" render "$work/result.json" --png "$work/from-result.png" --width 640 --height 320 >/dev/null) ||
  fail "render of a result exited $?"
cmp -s "$work/a.png" "$work/from-result.png" || fail "result and scene pictures differ"
# A result draws the paths with the cloth it ran with, even after its scene file changed.
python3 - "$scene" "$work/slow.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["physics"] = {"cloth": {"rolling_friction": 0.03}}
json.dump(s, open(sys.argv[2], "w"))
PY
"$baize" render "$work/slow.json" --png "$work/slow.png" --width 640 --height 320 >/dev/null
"$baize" simulate "$work/slow.json" --json "$work/slow-result.json" >/dev/null
python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); del s["physics"]; json.dump(s, open(sys.argv[1], "w"))' \
  "$work/slow.json"
"$baize" render "$work/slow-result.json" --png "$work/slow-from-result.png" --width 640 --height 320 \
  >/dev/null || fail "render of the slow result exited $?"
cmp -s "$work/slow.png" "$work/slow-from-result.png" || fail "the result was drawn with the scene's new cloth"
cmp -s "$work/slow.png" "$work/a.png" && fail "test setup: the slower cloth draws the same picture"

# A result is self-contained: it renders after its scene and the scene's own table file are gone.
mkdir "$work/own"
cp "$root/assets/tables/pool-9ft.json" "$work/own/my-table.json"
python3 - "$scene" "$work/own/scene.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
s["table"] = "my-table.json"
json.dump(s, open(sys.argv[2], "w"))
PY
"$baize" render "$work/own/scene.json" --png "$work/own.png" --width 640 --height 320 >/dev/null
"$baize" simulate "$work/own/scene.json" --json "$work/own-result.json" >/dev/null
rm -r "$work/own"
"$baize" render "$work/own-result.json" --png "$work/own-from-result.png" --width 640 --height 320 \
  >/dev/null || fail "render of a result whose scene is deleted exited $?"
cmp -s "$work/own.png" "$work/own-from-result.png" || fail "the self-contained result draws another picture"
# A line of baize batch is a result too (no trajectories: its embedded scene is simulated again).
python3 -c 'import json,sys; print(json.dumps(json.load(open(sys.argv[1]))))' "$scene" >"$work/one-line.jsonl"
"$baize" batch "$work/one-line.jsonl" >"$work/line-result.json" || fail "batch exited $?"
"$baize" render "$work/line-result.json" --png "$work/from-line.png" --width 640 --height 320 >/dev/null ||
  fail "render of a batch line exited $?"
cmp -s "$work/a.png" "$work/from-line.png" || fail "a batch line and its scene draw different pictures"

# --at: a picture of the shot under way differs from the end; the angled view differs from the top.
"$baize" render "$scene" --png "$work/at.png" --width 640 --height 320 --at 0.05 >/dev/null || fail "--at exited $?"
cmp -s "$work/a.png" "$work/at.png" && fail "--at 0.05 drew the end of the shot"
"$baize" render "$scene" --png "$work/angled.png" --width 640 --height 320 --view angled >/dev/null ||
  fail "--view angled exited $?"
cmp -s "$work/a.png" "$work/angled.png" && fail "the angled view drew the top view"

# --legend adds a legend (a different picture), the same bytes each time.
"$baize" render "$scene" --png "$work/legend.png" --width 640 --height 320 --legend >/dev/null ||
  fail "--legend exited $?"
"$baize" render "$scene" --png "$work/legend2.png" --width 640 --height 320 --legend >/dev/null
cmp -s "$work/a.png" "$work/legend.png" && fail "--legend drew no legend"
cmp -s "$work/legend.png" "$work/legend2.png" || fail "two legend pictures differ"

# --png-dir: one frame per 1/fps s of the shot and one at rest, numbered from 0, each of the size
# asked. Frames of an earlier run (Baize's frame_*.png names) are removed first.
end=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["end_time_s"])' "$work/result.json")
mkdir -p "$work/frames" && echo old >"$work/frames/frame_99999.png"
out=$("$baize" render "$work/result.json" --png-dir "$work/frames" --fps 2 --width 64 --height 32) ||
  fail "--png-dir exited $?"
expected=$(python3 -c 'import math,sys; print(math.ceil(float(sys.argv[1]) * 2) + 1)' "$end")
count=$(ls "$work/frames" | grep -c '^frame_[0-9]\{5\}\.png$')
[[ $count -eq $expected ]] || fail "$count frames for a shot of $end s at 2 fps, expected $expected"
[[ -f "$work/frames/frame_00000.png" ]] || fail "frames do not start at frame_00000.png"
[[ $(png_size "$work/frames/frame_00000.png") == "64 32" ]] || fail "frame size"
grep -q "^frames: $expected in $work/frames" <<<"$out" || fail "no frames line: $out"
[[ -e "$work/frames/frame_99999.png" ]] && fail "an earlier run's frame was left in --png-dir"
# A folder holding a file Baize did not write is refused before any drawing and left as it was.
echo mine >"$work/frames/notes.txt"
set +e
msg=$("$baize" render "$work/result.json" --png-dir "$work/frames" --fps 2 2>&1 >/dev/null); status=$?
set -e
[[ $status -eq 2 ]] || fail "--png-dir on a user's folder exited $status"
grep -q -- "--png-dir = $work/frames is not allowed: it holds 'notes.txt'" <<<"$msg" || fail "message: $msg"
[[ -e "$work/frames/frame_00000.png" ]] || fail "a refused --png-dir lost its frames"
# --quiet: the same frames, no note.
out=$("$baize" render "$work/result.json" --png-dir "$work/quiet" --fps 2 --width 64 --height 32 --quiet)
[[ -z $out ]] || fail "--quiet printed: $out"
cmp -s "$work/frames/frame_00001.png" "$work/quiet/frame_00001.png" || fail "--quiet drew another frame"

# --gif: a valid GIF89a of the size asked, one image per frame (the same count as --png-dir), its
# delays adding up to the frames' time at the rate asked, looping; the same bytes twice over;
# simulate writes the same animation as render of its result.
gif_facts() {  # prints: width height frames total-delay-in-hundredths loops
  python3 - "$1" <<'PY'
import struct, sys
d = open(sys.argv[1], "rb").read()
assert d[:6] == b"GIF89a", "not a GIF89a"
w, h, packed = struct.unpack("<HHB", d[6:11])
i = 13 + (3 * 2 ** ((packed & 7) + 1) if packed & 0x80 else 0)
def skip_blocks(i):
    while d[i]:
        i += d[i] + 1
    return i + 1
frames = delay = 0
loops = False
while True:
    b = d[i]
    if b == 0x3B:
        break
    if b == 0x21:
        label = d[i + 1]
        if label == 0xF9:
            delay += struct.unpack("<H", d[i + 4:i + 6])[0]
        if label == 0xFF and d[i + 3:i + 14] == b"NETSCAPE2.0":
            loops = True
        i = skip_blocks(i + 2)
    elif b == 0x2C:
        x, y, fw, fh, fp = struct.unpack("<HHHHB", d[i + 1:i + 10])
        assert (x, y, fw, fh) == (0, 0, w, h), "a frame that does not cover the picture"
        i += 10 + (3 * 2 ** ((fp & 7) + 1) if fp & 0x80 else 0)
        i = skip_blocks(i + 1)  # after the LZW minimum code size
        frames += 1
    else:
        raise SystemExit("unexpected block 0x%02x at %d" % (b, i))
assert i == len(d) - 1, "bytes after the trailer"
print(w, h, frames, delay, int(loops))
PY
}
out=$("$baize" render "$work/result.json" --gif "$work/out/shot.gif" --fps 4 --width 120 --height 60) ||
  fail "--gif exited $?"
gif_expected=$(python3 -c 'import math,sys; print(math.ceil(float(sys.argv[1]) * 4) + 1)' "$end")
read -r gw gh gframes gdelay gloops <<<"$(gif_facts "$work/out/shot.gif")"
[[ "$gw $gh" == "120 60" ]] || fail "GIF size $gw x $gh"
[[ $gframes -eq $gif_expected ]] || fail "$gframes GIF frames for a shot of $end s at 4 fps, expected $gif_expected"
[[ $gdelay -eq $((gif_expected * 25)) ]] || fail "GIF delays add up to $gdelay hundredths, expected $((gif_expected * 25))"
[[ $gloops -eq 1 ]] || fail "the GIF does not loop"
grep -q "^animation: $work/out/shot.gif ($gif_expected frames, 120 x 60 px, 4 per second)$" <<<"$out" ||
  fail "no animation line: $out"
"$baize" render "$work/result.json" --gif "$work/again.gif" --fps 4 --width 120 --height 60 >/dev/null
cmp -s "$work/out/shot.gif" "$work/again.gif" || fail "two GIFs of the same shot differ"
"$baize" simulate "$scene" --gif "$work/simulated.gif" --fps 4 --width 120 --height 60 >/dev/null
cmp -s "$work/out/shot.gif" "$work/simulated.gif" || fail "simulate --gif and render --gif differ"
# 30 fps is no whole number of hundredths: the delays (3 or 4) keep real time.
"$baize" render "$work/result.json" --gif "$work/thirty.gif" --fps 30 --width 32 --height 16 >/dev/null
read -r gw gh gframes gdelay gloops <<<"$(gif_facts "$work/thirty.gif")"
python3 -c 'import sys; f, d = int(sys.argv[1]), int(sys.argv[2]); sys.exit(abs(d - f * 100 / 30) > 1)' \
  "$gframes" "$gdelay" || fail "$gframes frames at 30 fps last $gdelay hundredths"
# --png -: the picture on standard output alone (the note goes to standard error).
"$baize" render "$scene" --png - --width 640 --height 320 >"$work/stdout.png" 2>/dev/null
cmp -s "$work/a.png" "$work/stdout.png" || fail "--png - wrote another picture to standard output"

# Bad input: exit 2, a message naming what is wrong, no file (and no temporary) left behind.
expect_refused() {  # expect_refused WHAT-TO-FIND OUTPUT-THAT-MUST-NOT-EXIST ARGS...
  local needle=$1 output=$2 msg status
  shift 2
  set +e
  msg=$("$baize" "$@" 2>&1 >/dev/null); status=$?
  set -e
  [[ $status -eq 2 ]] || fail "'$*' exited $status, expected 2 ($msg)"
  grep -q -- "$needle" <<<"$msg" || fail "'$*': message does not name '$needle': $msg"
  [[ -e "$output" || -e "$output.tmp" ]] && fail "'$*' left $output behind"
  return 0
}
expect_refused "missing.json" "$work/x.png" render "$work/missing.json" --png "$work/x.png"
expect_refused "--width" "$work/x.png" render "$scene" --png "$work/x.png" --width 0
expect_refused "--height" "$work/x.png" render "$scene" --png "$work/x.png" --height 100000
expect_refused "--view" "$work/x.png" render "$scene" --png "$work/x.png" --view side
expect_refused "--at" "$work/x.png" render "$scene" --png "$work/x.png" --at -1
expect_refused "--fps" "$work/f/frame_00000.png" render "$scene" --png-dir "$work/f" --fps 0
expect_refused "--fps = 101 is not allowed" "$work/x.gif" render "$scene" --gif "$work/x.gif" --fps 101
# A flag that would do nothing is refused, naming it and what it needs.
expect_refused "--fps sets the frame rate of --png-dir and --gif" "$work/x.png" \
  render "$scene" --png "$work/x.png" --fps 10
expect_refused "--at sets the time of the one picture of --png" "$work/x.gif" \
  render "$scene" --gif "$work/x.gif" --at 1
expect_refused "--legend shapes a picture: give --png, --png-dir or --gif" "$work/y.json" \
  simulate "$scene" --json "$work/y.json" --legend
expect_refused "both name standard output" "$work/x.png" simulate "$scene" --json - --png -
touch "$work/a-file"
expect_refused "--png" "$work/a-file/x.png" render "$scene" --png "$work/a-file/x.png"
expect_refused "--png" "$work/x.png" render "$scene"
expect_refused "--width" "$work/y.png" simulate "$scene" --png "$work/y.png" --width 0
expect_refused "--width" "$work/y.png" simulate "$scene" --width 0  # checked without a picture too
# A result written before the format was versioned (it names its scene by path) is named as such.
echo '{"scene": "nowhere.json", "trajectories": {}}' >"$work/bad-result.json"
expect_refused 'bad-result.json: format is missing: it must be "baize-result"' "$work/x.png" \
  render "$work/bad-result.json" --png "$work/x.png"
# A result edited by hand: one change each to the saved result above, each refused naming the key.
edit_result() {  # edit_result NAME PYTHON-STATEMENT-ON-r
  python3 - "$work/result.json" "$work/$1.json" "$2" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
exec(sys.argv[3])
json.dump(r, open(sys.argv[2], "w"))
PY
}
# Each row: a name, the edit, and what the refusal must say.
while IFS='|' read -r name change needle; do
  edit_result "$name" "$change"
  expect_refused "$needle" "$work/x.png" render "$work/$name.json" --png "$work/x.png"
done <<'ROWS'
far|r["trajectories"]["cue"][0]["position_m"] = [1e6, 1e6]|trajectories.cue\[0\].position_m = \[1000000.0,1000000.0\] is not allowed
fast|r["trajectories"]["cue"][0]["velocity_mps"] = [1e6, 0, 0]|trajectories.cue\[0\].velocity_mps = \[1000000.0,0,0\] is not allowed: each component must be of magnitude at most 20 m/s
endless|r["end_time_s"] = 1e9|end_time_s = 1000000000.0 is not allowed: a shot must end within 3600 s
unknown|r["zzz"] = 1|zzz = 1 is not allowed: unknown key
version|r["version"] = 2|version = 2 is not allowed: this baize reads version 1
table|r["scene"]["table"] = "mine.json"|scene.table = "mine.json" is not allowed: a result's scene holds its table
extra|r["trajectories"]["ghost"] = r["trajectories"]["cue"]|trajectories.ghost = .* is not allowed: unknown ball
physics|r["physics"]["max_events"] = -1|physics.max_events = -1 is not allowed
late|r["end_time_s"] = -1|end_time_s = -1 is not allowed: it must be a finite number >= 0
ROWS

# bench render, smoke size: one line with the median.
out=$("$baize" bench render --width 64 --height 32 --repeat 2) || fail "bench render exited $?"
grep -q "^median of 2 renders: [0-9.]* ms" <<<"$out" || fail "bench render output: $out"
echo "render CLI: all checks passed"
