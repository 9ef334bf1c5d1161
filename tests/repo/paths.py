#!/usr/bin/env python3
# tests/repo/paths.py -- every tests/ file the sources and docs name exists
# See LICENSE for copyright and license.
#
# Usage: python3 tests/repo/paths.py [ROOT].  Reads the C sources, headers,
# scripts, the Makefile, .ci/run and the Markdown docs, and checks that each
# path under tests/ they name with a file's ending (tests/unit/test_raster.c,
# tests/teach/student.sh) is there: a moved test leaves no comment or command
# pointing at where it was.  Names made to be filled in (NAME, TARGET) or
# made not to exist (no_such, no-such) are passed over.  Prints "N passed, N
# failed".
import os
import re
import sys

root = sys.argv[1] if len(sys.argv) > 1 else "."
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
from checks import check, finish  # noqa: E402

ENDINGS = (".c", ".h", ".sh", ".py", ".html", ".md", ".scene", ".obj", ".jsonl", ".csv",
           ".txt", ".ppm", ".png", ".log", ".svg")
PLACEHOLDER = re.compile(r"NAME|TARGET|no_such|no-such|\*")
TOKEN = re.compile(r"\btests/[A-Za-z0-9_./*-]*[A-Za-z0-9_*]")


def sources():
    for top in ("src", "stages", "docs", "tests"):
        for d, dirs, files in os.walk(os.path.join(root, top)):
            dirs[:] = [x for x in dirs if x not in ("corpus",)]
            for f in sorted(files):
                if f.endswith((".c", ".h", ".sh", ".py", ".md", ".html")):
                    yield os.path.relpath(os.path.join(d, f), root)
    for f in ("README.md", "Makefile", ".ci/run"):
        if os.path.exists(os.path.join(root, f)):
            yield f


def named_in(line):
    """The tests/ files line names, placeholders left out."""
    out = []
    for tok in TOKEN.findall(line):
        tok = tok.rstrip(".")
        if tok.endswith(ENDINGS) and not PLACEHOLDER.search(tok):
            out.append(tok)
    return out


named = missing = 0
for path in sources():
    with open(os.path.join(root, path), encoding="utf-8", errors="replace") as fh:
        for n, line in enumerate(fh, 1):
            for tok in named_in(line):
                named += 1
                if not os.path.exists(os.path.join(root, tok)):
                    missing += 1
                    check("paths-1.1 %s:%d names %s, which is not there" % (path, n, tok), 0)
check("paths-1.2 every tests/ file named (%d) is there" % named, named > 20 and not missing)
# the check can fail: it sees a path, and passes over a placeholder
absent = "tests" + "/unit/absent.c"         # (spelled apart: not a path of this file)
check("paths-2.1 a path is seen", named_in("(%s checks)" % absent) == [absent])
check("paths-2.2 a placeholder is not", named_in("tests/cli/NAME.sh") == [])
finish()
