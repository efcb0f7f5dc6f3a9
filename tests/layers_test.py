#!/usr/bin/env python3
"""The layer rule, checked: every #include in the source tree points down or sideways, never up.

    physics/  <-  engine/sim/  <-  engine/models/  <-  engine/io/  <-  engine/play/, engine/fit/, engine/baselines/  <-  render/  <-  tools/, python/

with one exception: engine/models/ reads its parameters with engine/io/json_reader (which
includes nothing of this project), so it may include that one file of engine/io/. Inside tools/,
the baize program's commands (tools/baize/) never include render/ or tools/baize/pictures/: only
pictures/ draws, so that the program builds without the renderer (BAIZE_WITH_RENDER=OFF).

and the outside libraries stay where they belong: Box2D in engine/baselines/box2d_pool only, SDL2
in tools/baize_view only, OSMesa in render/osmesa_context only. Usage: layers_test.py SOURCE_ROOT.
With --self-test it first checks that it catches a planted violation of each kind.
"""
import pathlib
import re
import sys
import tempfile

# What each folder may include from this project, by path prefix.
ALLOWED = {
    "physics/": ["physics/"],
    "engine/sim/": ["physics/", "engine/sim/"],
    "engine/models/": ["physics/", "engine/sim/", "engine/models/", "engine/io/json_reader.h"],
    "engine/io/": ["physics/", "engine/sim/", "engine/models/", "engine/io/"],
    "engine/fit/": ["physics/", "engine/sim/", "engine/models/", "engine/io/", "engine/fit/"],
    "engine/play/": ["physics/", "engine/sim/", "engine/models/", "engine/io/", "engine/play/"],
    "engine/baselines/": ["physics/", "engine/sim/", "engine/models/", "engine/io/", "engine/baselines/"],
    "render/": ["physics/", "engine/", "render/"],
    "tools/baize/pictures/": ["physics/", "engine/", "render/", "tools/baize/"],
    "tools/baize/": ["physics/", "engine/", "tools/baize/"],
    "tools/": ["physics/", "engine/", "render/", "tools/"],
    "python/": ["physics/", "engine/", "render/", "python/"],
}
# Prefixes a folder may not include although its ALLOWED list would let it.
EXCLUDED = {"tools/baize/": ["tools/baize/pictures/"]}
# Outside libraries (an include prefix) and the only files that may include them.
CONFINED = {
    "box2d/": ["engine/baselines/box2d_pool."],
    "SDL": ["tools/baize_view/"],
    "GL/osmesa.h": ["render/osmesa_context."],
}
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def violations(root, checked=None):
    found = []
    for path in sorted(root.rglob("*")):
        if path.suffix not in (".h", ".cpp") or not path.is_file():
            continue
        rel = path.relative_to(root).as_posix()
        folder = next((f for f in ALLOWED if rel.startswith(f)), None)
        if folder is None:
            continue  # tests/ and build trees may include anything
        if checked is not None:
            checked.append(rel)
        for kind, target in INCLUDE.findall(path.read_text(errors="replace")):
            if kind == '"' and "/" in target and target.split("/")[0] in ("physics", "engine", "render", "tools", "python"):
                if any(target.startswith(p) for p in EXCLUDED.get(folder, [])):
                    found.append(f"{rel}: includes {target}, which {folder} may not (only tools/baize/pictures/ draws)")
                elif not any(target.startswith(p) for p in ALLOWED[folder]):
                    found.append(f"{rel}: includes {target}, above its layer ({folder} may use {', '.join(ALLOWED[folder])})")
            for lib, homes in CONFINED.items():
                if target.startswith(lib) and not any(rel.startswith(h) for h in homes):
                    found.append(f"{rel}: includes {target}, which only {', '.join(homes)} may")
    return found


def self_test():
    planted = {
        "physics/a.cpp": '#include "engine/sim/x.h"\n',
        "engine/sim/b.h": '#include "engine/io/table.h"\n',
        "engine/io/c.cpp": '#include "engine/play/shot_suite.h"\n',
        "engine/models/h.cpp": '#include "engine/io/scene.h"\n',
        "engine/play/d.cpp": '#include "render/camera.h"\n',
        "render/e.cpp": '#include "tools/baize/cli_errors.h"\n',
        "engine/sim/f.cpp": "#include <box2d/box2d.h>\n",
        "render/g.cpp": "#include <SDL.h>\n",
        "engine/io/ok.cpp": '#include "engine/sim/shot_simulator.h"\n#include <vector>\n',
        "engine/models/ok.cpp": '#include "engine/io/json_reader.h"\n',
        "tools/baize/i.cpp": '#include "render/camera.h"\n',
        "tools/baize/j.cpp": '#include "tools/baize/pictures/shot_pictures.h"\n',
        "tools/baize/pictures/ok.cpp": '#include "render/camera.h"\n#include "tools/baize/drawing.h"\n',
    }
    with tempfile.TemporaryDirectory() as tmp:
        root = pathlib.Path(tmp)
        for rel, text in planted.items():
            (root / rel).parent.mkdir(parents=True, exist_ok=True)
            (root / rel).write_text(text)
        flagged = {v.split(":")[0] for v in violations(root)}
    expected = set(planted) - {"engine/io/ok.cpp", "engine/models/ok.cpp", "tools/baize/pictures/ok.cpp"}
    if flagged != expected:
        print(f"self-test failed: flagged {sorted(flagged)}, expected {sorted(expected)}")
        return False
    return True


def main():
    args = [a for a in sys.argv[1:] if a != "--self-test"]
    if len(args) != 1:
        print("usage: layers_test.py [--self-test] SOURCE_ROOT", file=sys.stderr)
        return 2
    if "--self-test" in sys.argv and not self_test():
        return 1
    checked = []
    found = violations(pathlib.Path(args[0]), checked)
    for v in found:
        print(v)
    print(f"layers: {len(found)} includes against the layer rule in {len(checked)} source files")
    if not checked:
        print("layers: no source file found under " + args[0])
        return 1
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
