/*
** tests/unit/testhelp.h -- the whole test framework: check, count, report
** See LICENSE for copyright and license.
**
** PT_CHECK(descr, cond) counts one check and prints descr when cond is false.
** pt_test_report() prints "N passed, N failed" and returns the exit status
** (1 when anything failed).  tests/run.sh adds up these lines over all programs.
*/
#ifndef PT_TESTHELP_H
#define PT_TESTHELP_H

#include <stdio.h>

static int pt_test_passed, pt_test_failed;

#define PT_CHECK(descr, cond) do {                                        \
        if (cond) pt_test_passed++;                                       \
        else { pt_test_failed++;                                          \
               printf("FAIL %s:%d: %s\n", __FILE__, __LINE__, (descr)); } \
    } while (0)

static inline int pt_test_report(void)
{
    printf("%d passed, %d failed\n", pt_test_passed, pt_test_failed);
    return pt_test_failed ? 1 : 0;
}

#endif
