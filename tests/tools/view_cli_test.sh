#!/usr/bin/env bash
# baize-view without a person or a display: SDL's offscreen driver (EGL), N frames, a screenshot.
# Usage: view_cli_test.sh path/to/baize (baize-view sits next to it)
set -euo pipefail
baize=$1
view="$(dirname "$baize")/baize-view"
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export SDL_VIDEODRIVER=offscreen GALLIUM_DRIVER=llvmpipe

# Fraction of the screenshot's pixels within 6 of the colour "#rrggbb" in every channel, and its size.
# (A small PNG decoder: 8-bit RGBA, non-interlaced, as the viewer writes.)
colour_share() {
  python3 - "$1" "$2" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n"
pos, idat = 8, b""
while pos < len(data):
    length, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + length]
    if kind == b"IHDR":
        w, h, depth, colour_type = struct.unpack(">IIBB", body[:10])
        assert depth == 8 and colour_type == 6, "8-bit RGBA"
    elif kind == b"IDAT":
        idat += body
    pos += 12 + length
raw, stride, rows, prev = zlib.decompress(idat), w * 4, [], bytearray(w * 4)
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):
        a = line[i - 4] if i >= 4 else 0
        b = prev[i]
        c = prev[i - 4] if i >= 4 else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c
            pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line)
    prev = line
want = [int(sys.argv[2][k:k + 2], 16) for k in (1, 3, 5)]
hits = sum(1 for line in rows for x in range(w)
           if all(abs(line[4 * x + k] - want[k]) <= 6 for k in range(3)))
print(w, h, round(hits / (w * h), 3))
PY
}

# A scene: 30 frames (half a second of the break), the last saved; most of it is pool cloth (#1c6fa8).
out=$("$view" "$root/assets/scenes/9-ball-break.json" --frames 30 --screenshot "$work/shot.png" \
  --width 320 --height 180) || fail "baize-view exited $?"
grep -q "^screenshot: $work/shot.png (320 x 180 px, frame 30, t = 0.500 s)$" <<<"$out" || fail "output: $out"
read -r w h share <<<"$(colour_share "$work/shot.png" "#1c6fa8")"
[[ "$w $h" == "320 180" ]] || fail "screenshot is $w x $h"
python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) > 0.4 else 1)" "$share" ||
  fail "only $share of the screenshot is cloth"

# A result file plays too (snooker: green cloth #1f6b35).
"$baize" simulate "$root/assets/scenes/snooker-break-off.json" --json "$work/snooker.json" >/dev/null
"$view" "$work/snooker.json" --frames 3 --screenshot "$work/snooker.png" --width 200 --height 120 \
  --view angled >/dev/null || fail "baize-view on a result exited $?"
read -r w h share <<<"$(colour_share "$work/snooker.png" "#1f6b35")"
python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) > 0.2 else 1)" "$share" ||
  fail "only $share of the snooker screenshot is cloth"

# Bad input: exit 2, no screenshot.
set +e
msg=$("$view" "$work/missing.json" --frames 1 --screenshot "$work/no.png" 2>&1); status=$?
set -e
[[ $status -eq 2 ]] || fail "missing input exited $status"
grep -q "missing.json" <<<"$msg" || fail "message does not name the file: $msg"
[[ -e "$work/no.png" ]] && fail "a screenshot was written for a missing input"
set +e
msg=$("$view" "$root/assets/scenes/stun-shot.json" --screenshot "$work/no.png" 2>&1); status=$?
set -e
[[ $status -eq 2 ]] || fail "--screenshot without --frames exited $status"

# No display and no --frames: refused at once naming the way out, not a window nobody sees that
# spins a core forever (exit 2, within a bounded time).
set +e
out=$(timeout 20 "$view" "$root/assets/scenes/9-ball-break.json" 2>&1)
status=$?
set -e
[[ $status -eq 2 ]] || fail "baize-view with no display exited $status (2 expected): $out"
grep -q "there is no display to show a window on (SDL video driver 'offscreen')" <<<"$out" ||
  fail "no display message: $out"
grep -q -- "--frames N --screenshot FILE" <<<"$out" || fail "no way out named: $out"

# --screenshot follows the rule of every output (docs/commands.md): missing parent folders made; a
# path under a file refused before any drawing (exit 2, the flag and the path named).
"$view" "$root/assets/scenes/9-ball-break.json" --frames 2 --width 64 --height 64 \
  --screenshot "$work/new/deeper/view.png" >/dev/null || fail "--screenshot in a new folder exited $?"
[[ -s "$work/new/deeper/view.png" ]] || fail "--screenshot did not make its folder"
touch "$work/a-file"
set +e
out=$("$view" "$root/assets/scenes/9-ball-break.json" --frames 2 --screenshot "$work/a-file/v.png" 2>&1)
status=$?
set -e
[[ $status -eq 2 ]] || fail "--screenshot under a file exited $status (2 expected): $out"
grep -q -- "--screenshot = $work/a-file/v.png is not allowed" <<<"$out" || fail "message: $out"
echo "view CLI: all checks passed"
