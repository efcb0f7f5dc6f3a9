#!/usr/bin/env bash
# Every shell command the README and docs show runs, and every relative link in them leads to a
# file. The commands are the lines of each ```sh block (a line ending in "\" continues, a here
# document runs whole), run from a scratch folder that sees the repository's assets/ and tools/ and
# the build under test as build/, so their outputs (out/...) land there and nothing in the
# repository changes. A command is skipped only when marked, with the reason in the doc itself:
#   - a comment line "# not run by the docs test: REASON" skips the command after it;
#   - a line "<!-- not run by the docs test: REASON -->" just before a block skips the block.
# Usage: docs_examples_test.sh path/to/build/baize
set -euo pipefail
baize=$1
build=$(cd "$(dirname "$baize")" && pwd)
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
export GALLIUM_DRIVER=llvmpipe

ln -s "$root/assets" "$work/assets"
ln -s "$root/tools" "$work/tools"
ln -s "$build" "$work/build"

docs=("$root/README.md" "$root"/docs/*.md "$root"/docs/design/*.md)
existing=()
for doc in "${docs[@]}"; do [[ -e $doc ]] && existing+=("$doc"); done

# Writes each command to $work/commands/NNNN.sh (with its origin on the first line, as a comment)
# and each skip to $work/skipped.txt; checks the relative links on the way.
python3 - "$root" "$work" "${existing[@]}" <<'PY'
import os, re, sys
root, work, docs = sys.argv[1], sys.argv[2], sys.argv[3:]
marker = "not run by the docs test:"
os.makedirs(os.path.join(work, "commands"))
count, skipped, broken = 0, [], []
for doc in docs:
    name = os.path.relpath(doc, root)
    lines = open(doc, encoding="utf-8").read().split("\n")
    # Relative links: [text](path) or [text](path#anchor), outside code blocks.
    fenced = False
    for number, line in enumerate(lines, 1):
        if line.startswith("```"):
            fenced = not fenced
            continue
        if fenced:
            continue
        for target in re.findall(r"\]\(([^)\s]+)\)", line):
            if re.match(r"[a-z]+:", target) or target.startswith("#"):
                continue
            path = os.path.normpath(os.path.join(os.path.dirname(doc), target.split("#")[0]))
            if not os.path.exists(path):
                broken.append(f"{name}:{number}: link to {target}, which does not exist")
    i = 0
    while i < len(lines):
        if lines[i].strip() != "```sh":
            i += 1
            continue
        start = i + 1
        end = lines.index("```", start)
        before = lines[i - 1] if i > 0 else ""
        block = lines[start:end]
        i = end + 1
        if marker in before:
            skipped.append(f"{name}:{start}: block: {before.split(marker, 1)[1].strip(' ->')}")
            continue
        k, skip_reason = 0, None
        while k < len(block):
            line = block[k]
            if not line.strip():
                k += 1
                continue
            if line.lstrip().startswith("#"):
                if marker in line:
                    skip_reason = line.split(marker, 1)[1].strip()
                k += 1
                continue
            first = k
            command = [line]
            heredoc = re.search(r"<<-?\s*'?\"?(\w+)", line)
            while command[-1].endswith("\\") and k + 1 < len(block):
                k += 1
                command.append(block[k])
            if heredoc:
                while k + 1 < len(block) and block[k].strip() != heredoc.group(1):
                    k += 1
                    command.append(block[k])
            k += 1
            where = f"{name}:{start + first + 1}"
            if skip_reason:
                skipped.append(f"{where}: {skip_reason}")
                skip_reason = None
                continue
            count += 1
            with open(os.path.join(work, "commands", f"{count:04d}.sh"), "w") as out:
                out.write(f"# {where}\n" + "\n".join(command) + "\n")
with open(os.path.join(work, "skipped.txt"), "w") as out:
    out.write("".join(s + "\n" for s in skipped))
if broken:
    sys.exit("\n".join(broken))
if count == 0:
    sys.exit("no commands found: the docs test reads ```sh blocks")
PY

# The longest a docs example may take (s): the slowest runs a few seconds; far above that, stop.
command_limit_s=120
ran=0
for command in "$work"/commands/*.sh; do
  where=$(head -1 "$command" | cut -c3-)
  status=0
  started=$(date +%s%N)
  # A docs example that waits for ever (a server, a window) is a broken example, not a hang.
  (cd "$work" && timeout "$command_limit_s" bash -eo pipefail "$command") >"$work/output.txt" 2>&1 </dev/null ||
    status=$?
  echo "$(( ($(date +%s%N) - started) / 1000000 )) ms $where" >>"$work/times.txt"
  # A check that finds a failing case exits 1 by design; the docs' suites all pass, so any
  # non-zero status is a broken example.
  [[ $status -eq 0 ]] || fail "$where exited $status: $(sed -n 2,99p "$command")
$(tail -20 "$work/output.txt")"
  ran=$((ran + 1))
done
echo "docs examples: $ran commands ran (slowest first):"
sort -rn "$work/times.txt" | head -5 | sed 's/^/  /'
echo "skipped by their docs' markers:"
sed 's/^/  /' "$work/skipped.txt"
