# tests/lib/checks.py -- check() and the closing count for the Python tests
# See LICENSE for copyright and license.
#
#   sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lib"))
#   from checks import check, finish
#   check("x-1.1 what it asserts", ok, "detail printed when it fails")
#   finish()        prints "N passed, N failed", exits 1 when anything failed
import sys

passed = failed = 0


def check(descr, ok, detail=""):
    global passed, failed
    if ok:
        passed += 1
    else:
        failed += 1
        print("FAIL " + descr)
        if detail:
            print("  " + detail)


def finish():
    print("%d passed, %d failed" % (passed, failed))
    sys.exit(1 if failed else 0)
