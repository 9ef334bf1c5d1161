#!/bin/sh
# tests/course79/course79.sh -- renderers 7 and 9 against the course's own logs and images
# See LICENSE for copyright and license.
#
# Usage: sh tests/course79/course79.sh PIPETRACE, from the repository root.
# The checks are in check.py (Python 3, its gzip module reads the .gz files).
exe=${1:-build/pipetrace}
if ! command -v python3 >/dev/null 2>&1; then
    echo "  skipped: no python3"
    echo "0 passed, 0 failed"
    exit 0
fi
exec python3 tests/course79/check.py "$exe"
