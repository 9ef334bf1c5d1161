/*
** tests/fuzz/fuzz_common.c -- what the fuzz targets share: the message check
** See LICENSE for copyright and license.
*/
#include <string.h>
#include "fuzz.h"

int pt_fuzz_message_ok(const char *err, const char *name)
{
    size_t n = strlen(name);
    const char *p = err + n;
    int k;

    if (strncmp(err, name, n) != 0 || strchr(err, '\n') != NULL) return 0;
    for (k = 0; k < 2; k++) {           /* ":LINE" then ":COL", each >= 1 */
        if (*p++ != ':' || *p < '1' || *p > '9') return 0;
        while (*p >= '0' && *p <= '9') p++;
    }
    return strncmp(p, ": error: ", 9) == 0 && p[9] != '\0';
}
