#!/usr/bin/env python3
"""Fails when a layer includes a layer above it (README "Architecture").

Usage: check_layers.py ROOT            checks the tree at ROOT; prints one line per violation
       check_layers.py --self-test     checks a small tree with a known violation, which must be found

Layers and what each may include (besides itself and the standard and third-party headers allowed
below): the folder of a source file (src/LAYER, include/mobb/LAYER, bench/, python/) gives its layer. A quoted
include "mobb/LAYER/x.h" names its layer; a quoted include "x.h" is looked up in the including file's
folder, then in every layer's source folder (a name held by two layers is itself an error: the
layer could not be told). Angle-bracket includes are checked against the headers a layer must not use
(core knows no files and no OpenGL; only render, viewer and app touch OpenGL or ImGui).

Inside crowd, the folders (src/crowd/F, include/mobb/crowd/F) are in one order, CROWD_ORDER: a file uses
only its own folder and those before it. Its quoted includes name the folder: "mobb/crowd/F/x.h" (public)
or "F/x.h" (private, from src/crowd). The crowd's top holds only the files CROWD_TOP names."""
import os
import re
import sys
import tempfile

ALLOWED = {
    "util": set(),
    "core": set(),
    "io": {"core", "util"},
    "crowd": {"io", "core", "util"},
    "render": {"io", "core", "util"},
    "bench": {"crowd", "io", "core", "util"},
    "viewer": {"render", "crowd", "io", "core", "util"},
    "app": {"viewer", "bench", "render", "crowd", "io", "core", "util"},
    "bench-tools": {"bench", "crowd", "io", "core", "util"},  # bench/: micro-benchmarks, callgrind driver
    "python": {"crowd", "io", "core", "util"},  # python/: the Python module (pybind11)
}
GRAPHICS = ("glad/", "GL/", "GLFW/", "imgui", "stb_image", "stb/", "tiny_gltf")
FORBIDDEN_SYSTEM = {
    "core": ("fstream", "filesystem", "cstdio", "iostream", "nlohmann/") + GRAPHICS,
    "util": GRAPHICS,
    "io": ("glad/", "GL/", "GLFW/", "imgui", "stb"),
    "crowd": GRAPHICS,
    "python": GRAPHICS,
    "bench": ("glad/", "GL/", "GLFW/", "imgui", "tiny_gltf"),
}
# The crowd's folders, each using only those before it: the numbers, the ground, the motion graph, records,
# metrics, poses and export, policies, a run's options, broad and narrow phase, plans (what agents reserve,
# the state a choice point reads, its queries), the rules of the choice point, the choice point, the
# simulation, scenarios.
CROWD_ORDER = ["tuning", "world", "graph", "record", "metrics", "motion", "policy", "options", "collision",
               "plan", "rules", "choice", "sim", "scenario"]
CROWD_TOP = {"tuning.h": "tuning", "tuning.cpp": "tuning", "options.h": "options", "CMakeLists.txt": None}
SOURCE = (".h", ".hpp", ".cpp", ".cc")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')


def layer_of(rel):
    parts = rel.split("/")
    if parts[0] == "src" and len(parts) > 2 and parts[1] in ALLOWED:
        return parts[1]
    if parts[:2] == ["include", "mobb"] and len(parts) > 3 and parts[2] in ALLOWED:
        return parts[2]
    if parts[0] == "bench":
        return "bench-tools"
    if parts[0] == "python":
        return "python"
    return None


def sources(root):
    for top in ("src", "include", "bench", "python"):
        for folder, _, files in os.walk(os.path.join(root, top)):
            for f in files:
                if f.endswith(SOURCE):
                    path = os.path.join(folder, f)
                    yield os.path.relpath(path, root).replace(os.sep, "/")


def header_layers(root):
    """Flat header name -> layers whose source folder holds it."""
    out = {}
    for rel in sources(root):
        layer = layer_of(rel)
        if layer and rel.startswith("src/"):
            out.setdefault(os.path.basename(rel), set()).add(layer)
    return out


def quoted_layer(root, rel, name, flat):
    m = re.match(r"mobb/([a-z_]+)/", name)
    if m:
        return m.group(1), None
    here = os.path.join(root, os.path.dirname(rel), name)
    if os.path.exists(here):
        return layer_of(os.path.relpath(here, root).replace(os.sep, "/")), None
    layers = flat.get(os.path.basename(name), set())
    if len(layers) > 1:
        return None, "held by " + " and ".join(sorted(layers)) + ": rename one"
    return (next(iter(layers)), None) if layers else (None, None)


def crowd_folder(rel):
    """The crowd folder of a repository path; None outside crowd; "?" for a file the crowd's top does not name."""
    for top in ("src/crowd/", "include/mobb/crowd/"):
        if rel.startswith(top):
            rest = rel[len(top):]
            return rest.split("/")[0] if "/" in rest else CROWD_TOP.get(rest, "?")
    return None


def crowd_problem(root, rel, name):
    """Why a quoted include of a crowd file breaks CROWD_ORDER, or None."""
    mine = crowd_folder(rel)
    if mine is None:
        return None
    if name.startswith("mobb/crowd/"):
        target = crowd_folder("include/" + name)
    elif os.path.exists(os.path.join(root, "src/crowd", name)):
        target = crowd_folder("src/crowd/" + name)
    elif os.path.exists(os.path.join(root, os.path.dirname(rel), name)):
        target = crowd_folder(os.path.relpath(os.path.join(os.path.dirname(rel), name)).replace(os.sep, "/"))
    else:
        return None
    for folder in (mine, target):
        if folder not in CROWD_ORDER:
            return "crowd/%s is not in CROWD_ORDER" % folder
    if CROWD_ORDER.index(target) > CROWD_ORDER.index(mine):
        return "crowd/%s includes crowd/%s, a folder after it" % (mine, target)
    return None


def check(root):
    flat = header_layers(root)
    problems = []
    for rel in sorted(sources(root)):
        layer = layer_of(rel)
        if not layer:
            continue
        if crowd_folder(rel) == "?":
            problems.append(rel + ": at the crowd's top: move it into a folder, or name it in CROWD_TOP")
        with open(os.path.join(root, rel), encoding="utf-8", errors="replace") as f:
            for n, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                kind, name = m.groups()
                where = "%s:%d: %s includes %s" % (rel, n, layer, name)
                if kind == "<":
                    for bad in FORBIDDEN_SYSTEM.get(layer, ()):
                        if name.startswith(bad):
                            problems.append(where + ": not in this layer")
                    continue
                target, why = quoted_layer(root, rel, name, flat)
                crowd_why = crowd_problem(root, rel, name)
                if crowd_why:
                    problems.append(where + ": " + crowd_why)
                if why:
                    problems.append(where + ": " + why)
                elif target and target != layer and target not in ALLOWED[layer]:
                    problems.append(where + " (" + target + "): a lower layer includes a higher one")
    return problems


def self_test():
    files = {
        "src/core/a.cpp": '#include "mobb/core/b.h"\n#include <fstream>\n',
        "include/mobb/core/b.h": "#pragma once\n",
        "src/crowd/c.cpp": '#include "report.h"\n#include "mobb/core/b.h"\n',
        "src/bench/report.h": "#pragma once\n",
        "src/viewer/v.cpp": '#include "cli.h"\n',
        "src/app/cli.h": "#pragma once\n",
        "src/app/main.cpp": '#include "cli.h"\n#include "report.h"\n',
        "src/crowd/record/r.cpp": '#include "record/r.h"\n#include "choice/choice.h"\n',
        "src/crowd/record/r.h": "#pragma once\n",
        "src/crowd/choice/choice.h": '#pragma once\n#include "record/r.h"\n#include "mobb/crowd/sim/crowd.h"\n',
        "include/mobb/crowd/sim/crowd.h": '#pragma once\n#include "mobb/crowd/options.h"\n',
        "include/mobb/crowd/options.h": "#pragma once\n",
        "src/crowd/extra.cpp": "",
    }
    with tempfile.TemporaryDirectory() as root:
        for rel, text in files.items():
            os.makedirs(os.path.join(root, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(root, rel), "w") as f:
                f.write(text)
        found = check(root)
    expected = ["src/core/a.cpp:2", "src/crowd/c.cpp:1", "src/crowd/c.cpp: at", "src/crowd/extra.cpp: at", "src/viewer/v.cpp:1", "src/crowd/record/r.cpp:2",
                "src/crowd/choice/choice.h:3"]
    ok = len(found) == len(expected) and all(any(p.startswith(e) for p in found) for e in expected)
    print("\n".join(found))
    print("self-test " + ("passed" if ok else "FAILED: expected violations at " + ", ".join(expected)))
    return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    problems = check(sys.argv[1])
    print("\n".join(problems) if problems else "layers: every include points down or sideways")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
