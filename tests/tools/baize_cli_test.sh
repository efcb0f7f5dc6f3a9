#!/usr/bin/env bash
# The program's own conventions: --version, `baize help CMD`, and a mistyped command named with the
# nearest one suggested (exit 2), at the top level and under `bench`.
# Usage: baize_cli_test.sh path/to/baize
set -euo pipefail
baize=$1
fail() { echo "FAIL: $*" >&2; exit 1; }

out=$("$baize" --version) || fail "--version exited $?"
[[ "$out" =~ ^baize\ [0-9]+\.[0-9]+ ]] || fail "--version printed: $out"

out=$("$baize" help simulate) || fail "help simulate exited $?"
grep -q -- "--json" <<<"$out" || fail "help simulate does not list --json: $out"
out=$("$baize" help bench shots) || fail "help bench shots exited $?"
grep -q -- "--random-shots" <<<"$out" || fail "help bench shots: $out"
out=$("$baize" help) || fail "help exited $?"
grep -q "baize help COMMAND" <<<"$out" || fail "help does not say how to get a command's help"

expect_unknown() {  # words... then the expected message part in $expected
  set +e
  msg=$("$baize" "$@" 2>&1 >/dev/null); status=$?
  set -e
  [[ $status -eq 2 ]] || fail "baize $*: exit $status, not 2"
  grep -qF -- "$expected" <<<"$msg" || fail "baize $*: message: $msg"
}
expected="unknown command 'simulat'; did you mean 'simulate'?"; expect_unknown simulat x.json
expected="unknown command 'bench shot'; did you mean 'bench shots'?"; expect_unknown bench shot
expected="unknown command 'xyzzy'. The commands are: batch bench"; expect_unknown xyzzy
expected="unknown command 'nope'."; expect_unknown help nope
# Words past a command without subcommands are not command names: refused, not a crash.
expected="'baize help' takes command names only: 'foo' is not a command of 'baize simulate'"
expect_unknown help simulate foo
expected="'extra' is not a command of 'baize bench cushion'"; expect_unknown help bench cushion extra
echo "baize_cli_test: ok"
