#!/usr/bin/env python3
# tests/repo/docs_write.py -- rewrite the output shown in the docs' console blocks
# See LICENSE for copyright and license.
#
# Usage: python3 tests/repo/docs_write.py PIPETRACE FILE.md...  (that is `make docs`)
# Runs each "$ " command of every ```console block, as tests/repo/docs.sh does, and
# replaces the output shown under it with what it printed.  Do it on purpose
# and read the diff: tests/repo/docs.sh is what checks the docs.
import subprocess
import sys

exe, files = sys.argv[1], sys.argv[2:]
for path in files:
    out, block, skipping = [], False, False
    for line in open(path, encoding="utf-8").read().split("\n"):
        if not block and line.rstrip() == "```console":
            block = True
        elif block and line.startswith("```"):
            block, skipping = False, False
        elif block and line.startswith("$ "):
            cmd = line[2:].replace("build/pipetrace", exe)
            got = subprocess.run(["sh", "-c", cmd], stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT).stdout.decode("utf-8")
            out.append(line)
            if got:         # a command that prints nothing has no lines under it
                out.extend(got.split("\n")[:-1] if got.endswith("\n") else got.split("\n"))
            skipping = True
            continue
        elif block and skipping:
            continue
        out.append(line)
    open(path, "w", encoding="utf-8").write("\n".join(out))
