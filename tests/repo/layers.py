#!/usr/bin/env python3
# tests/repo/layers.py -- the layers include only downward, and no header cycle
# See LICENSE for copyright and license.
#
# Usage: python3 tests/repo/layers.py [ROOT]  (default: the current directory).
# Reads the #include "..." lines of stages/ and src/ and checks the rules of
# docs/architecture.md:
#   stages/     includes only stages/ headers, by plain name (a student's stage
#               file is compiled with -Istages and nothing else)
#   src/core/   includes stages/ and src/core/ headers, nothing of io or tools
#   src/io/     includes core/pipetrace.h (the core's one public header) and
#               src/io/ headers; no other core or stage header, no tool header
#   src/tools/  includes core/pipetrace.h, src/io/ and src/tools/ headers
#   src/wasm/   (the journey page's WebAssembly module, built without libc)
#               includes stages/ and src/wasm/ headers; nothing includes it
# and that every included file exists and no chain of includes comes back to
# where it started; and that docs/architecture.md names every folder.  Prints
# "N passed, N failed".
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else "."
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from checks import check, finish  # noqa: E402


def sources(top):
    for d, _, files in os.walk(os.path.join(root, top)):
        for f in sorted(files):
            if f.endswith((".c", ".h")):
                yield os.path.relpath(os.path.join(d, f), root)


def includes(path):
    """The quoted includes of path, as repository paths, with line numbers."""
    out = []
    with open(os.path.join(root, path), encoding="utf-8") as f:
        for n, line in enumerate(f, 1):
            m = re.match(r'\s*#\s*include\s+"([^"]+)"', line)
            if not m:
                continue
            name = m.group(1)
            if path.startswith("stages/") and "/" not in name:
                target = "stages/" + name
                here = os.path.join(os.path.dirname(path), name)   # stages/wasm/
                if os.path.exists(os.path.join(root, here)):
                    target = here
            elif name.startswith("stages/"):
                target = name
            else:
                target = "src/" + name
            out.append((n, name, target))
    return out


def layer(path):
    if path.startswith("stages/"):
        return "stages"
    parts = path.split("/")
    return parts[1] if len(parts) > 2 else "src"


def allowed(path, name, target):
    """None when path may include target, else the rule it breaks."""
    lay = layer(path)
    tl = layer(target)
    if tl == "wasm" and lay != "wasm":
        return "only the WebAssembly module includes src/wasm/"
    if lay == "stages":
        return None if tl == "stages" and "/" not in name else \
            "a stage includes only stages/ headers, by plain name"
    if lay == "core":
        return None if tl in ("stages", "core") else \
            "the core includes nothing of io or tools"
    if lay == "wasm":
        return None if tl in ("stages", "wasm") else \
            "the WebAssembly module includes only stages/ and src/wasm/ headers"
    if lay in ("io", "tools"):
        if target == "src/core/pipetrace.h":
            return None
        if tl in ("stages", "core"):
            return "above the core only core/pipetrace.h is included"
        if lay == "io" and tl == "tools":
            return "io includes no tool header"
        return None
    return "a file of src/ belongs to core, io, tools or wasm"


graph = {}
files = list(sources("stages")) + list(sources("src"))
check("layers-1.0 there are sources to check", len(files) > 20)
for path in files:
    bad = []
    edges = []
    for n, name, target in includes(path):
        if not os.path.exists(os.path.join(root, target)):
            bad.append('%s:%d: "%s" does not exist' % (path, n, name))
            continue
        rule = allowed(path, name, target)
        if rule:
            bad.append('%s:%d: "%s": %s' % (path, n, name, rule))
        edges.append(target)
    graph[path] = edges
    check("layers-1.1 %s includes only downward" % path, not bad, "\n  ".join(bad))

# no cycles: depth-first search, colouring the nodes on the current path
def find_cycle(g):
    state, cycle = {}, []

    def visit(p, stack):
        state[p] = 1
        stack.append(p)
        for q in sorted(g.get(p, ())):
            if state.get(q) == 1 and not cycle:
                cycle.extend(stack[stack.index(q):] + [q])
            elif q not in state:
                visit(q, stack)
        stack.pop()
        state[p] = 2

    for p in sorted(g):
        if p not in state:
            visit(p, [])
    return cycle


cycle = find_cycle(graph)
check("layers-2.1 no include cycle", not cycle, " -> ".join(cycle))

# no cycle between modules either (a module: x.c with its header x.h), so
# that each can be read knowing only those below it
mgraph = {}
for p, edges in graph.items():
    mod = os.path.splitext(p)[0]
    for q in edges:
        other = os.path.splitext(q)[0]
        if other != mod:
            mgraph.setdefault(mod, set()).add(other)
cycle = find_cycle(mgraph)
check("layers-2.2 no cycle between modules", not cycle, " -> ".join(cycle))

# the checks can fail: a core file that included io would be refused
check("layers-3.1 the rules refuse core -> io",
      allowed("src/core/pipeline.c", "io/trace.h", "src/io/trace.h") is not None)
check("layers-3.2 ... a tool reaching past core/pipetrace.h",
      allowed("src/tools/cmd_step.c", "core/raster.h", "src/core/raster.h") is not None)
check("layers-3.3 ... a stage including src/",
      allowed("stages/s1_model2camera.c", "core/scene.h", "src/core/scene.h") is not None)
check("layers-3.4 ... the WebAssembly module including the core",
      allowed("src/wasm/pt_wasm.c", "core/pipetrace.h", "src/core/pipetrace.h") is not None)
check("layers-3.5 ... a tool including the WebAssembly module",
      allowed("src/tools/journey/journey_wasm.c", "wasm/pt_wasm_libm.h",
              "src/wasm/pt_wasm_libm.h") is not None)

# docs/architecture.md is the map: it names every folder of src/ and stages/
arch = os.path.join(root, "docs", "architecture.md")
text = open(arch, encoding="utf-8").read() if os.path.exists(arch) else ""
folders = ["stages/"] + sorted(
    os.path.relpath(d, root) + "/" for d, _, _ in os.walk(os.path.join(root, "src"))
    if os.path.relpath(d, root) != "src")
missing = [f for f in folders if f not in text]
check("layers-4.1 docs/architecture.md names every folder of src/ and stages/",
      text and not missing, "missing: " + ", ".join(missing))

finish()
