#!/bin/sh
# tests/repo/paths.sh -- run tests/repo/paths.py (the tests/ files named exist), or say it is skipped
# See LICENSE for copyright and license.
if ! command -v python3 >/dev/null 2>&1; then
    echo "  skipped: python3 not installed"
    echo "0 passed, 0 failed"
    exit 0
fi
exec python3 tests/repo/paths.py
