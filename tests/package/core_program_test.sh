#!/usr/bin/env bash
# Runs the baize program of a core build (BAIZE_WITH_RENDER=OFF) from its moved install prefix: it
# simulates a shipped scene as the full program does, writes its result file, and refuses what
# draws (a picture flag, a drawing command) by name, saying why, with exit status 2, before any
# work and without writing anything.
# Usage: core_program_test.sh PREFIX [REFERENCE_BAIZE]
#   REFERENCE_BAIZE: a baize built with rendering (the enclosing build's), whose report of the
#   same scene the core program's must equal, line for line but the wall time
set -uo pipefail
prefix=$1 reference=${2:-}
fail() { echo "FAIL: $*" >&2; exit 1; }
baize=$prefix/bin/baize
scene=$prefix/share/baize/scenes/one-cushion-bank.json
run=$(mktemp -d) || fail "mktemp"
trap 'rm -rf "$run"' EXIT
cd "$run" || fail "cd $run"

out=$("$baize" simulate "$scene" --json result.json 2>&1) || fail "simulate exited $?: $out"
events=$(sed -n 's/^events: \([0-9]*\), at rest after .* s$/\1/p' <<<"$out")
[[ "$events" =~ ^[0-9]+$ && "$events" -gt 0 ]] || fail "simulate reported no events: $out"
grep -q '^cue ball stopped at: \[-\?[0-9.]*, -\?[0-9.]*\] m$' <<<"$out" ||
  fail "simulate reported no final cue ball position: $out"
grep -q '"format"' result.json || fail "the result file has no format: $(head -c 300 result.json)"
if [[ -n "$reference" ]]; then
  expected=$("$reference" simulate "$scene" 2>&1) || fail "the reference baize exited $?"
  diff <(grep -v '^wall time' <<<"$expected") <(grep -v '^wall time' <<<"$out") ||
    fail "the core program's report differs from the full program's (above)"
fi

# refused CMD...: exits 2, names `named` and the build option ($option, rendering unless set),
# prints nothing on standard output and writes no file.
option=BAIZE_WITH_RENDER=OFF
refused() {
  local named=$1
  shift
  local stdout status
  stdout=$("$baize" "$@" 2>stderr.txt)
  status=$?
  [[ $status -eq 2 ]] || fail "baize $* exited $status, not 2"
  [[ -z "$stdout" ]] || fail "baize $* printed before refusing: $stdout"
  grep -qF -- "$named" stderr.txt && grep -qF "$option" stderr.txt ||
    fail "baize $* did not name $named and $option: $(cat stderr.txt)"
  [[ -z "$(ls -A | grep -v '^stderr.txt$\|^result.json$')" ]] ||
    fail "baize $* left files: $(ls -A)"
}
refused "'baize simulate --png'" simulate "$scene" --png shot.png
refused "'baize simulate --png'" simulate "$scene" --png ""  # refused before its value is checked
refused "'baize simulate --gif'" simulate "$scene" --gif shot.gif
refused "'baize simulate --width'" simulate "$scene" --width 800
refused "'baize sweep --png'" sweep "$scene" --vary speed=1:2:1 --png map.png
refused "'baize render'" render "$scene" --png shot.png
refused "'baize bench render'" bench render
refused "'baize render'" render --help  # a refused command's help is refused with it
refused "'baize simulate --legend'" simulate "$scene" --legend  # a flag without a value
refused "'baize chart'" chart sweep somewhere
refused "'baize check --png-dir'" check "$prefix/share/baize/suites/positional-drills.json" --png-dir pictures
option=BAIZE_WITH_BOX2D=OFF
refused "'baize bench accuracy' compares against Box2D" bench accuracy --shots 5
echo "the core program simulated $events events and refused what draws"
