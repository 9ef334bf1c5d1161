/*
** tests/unit/test_nameset.c -- tests of the model-name table (src/core/nameset.c) and
** of the scene parser's duplicate check, which asks it
** See LICENSE for copyright and license.
**
** Ids:
**   nameset-1  the table: what it finds, what it does not, how much it compares
**   nameset-2  the parser: 200,000 models read, a late duplicate named with the
**            line of the first
** The work is counted, never timed: the table counts its string comparisons
** (before it, 80,000 `model` lines took 3.2e9 comparisons and 15 s; issue 14).
*/
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "testhelp.h"
#include "core/nameset.h"
#include "core/scene.h"

#define N 200000

int main(void)
{
    static char name[N][12];
    pt_nameset t = {NULL, 0, 0, 0};
    char err[PT_ERRLEN], *text, *p;
    size_t k, wrong = 0, len;
    pt_scene s;
    int ok = 1;

    for (k = 0; k < N; k++) {
        snprintf(name[k], sizeof name[k], "m%zu", k);
        ok &= pt_nameset_find(&t, name[k], strlen(name[k])) == SIZE_MAX;
        ok &= pt_nameset_add(&t, name[k], strlen(name[k]), k) == 0;
    }
    PT_CHECK("nameset-1.1 200000 new names: none found before it is added, all added", ok);
    PT_CHECK("nameset-1.2 ... about one comparison a name, not one per earlier name",
             t.compares <= N / 100);
    t.compares = 0;
    for (k = 0; k < N; k++)
        wrong += pt_nameset_find(&t, name[k], strlen(name[k])) != k;
    PT_CHECK("nameset-1.3 each name finds its own index", wrong == 0);
    PT_CHECK("nameset-1.4 ... with at most a few comparisons each", t.compares <= N + N / 100);
    PT_CHECK("nameset-1.5 a prefix, a longer name, the empty name are not there",
             pt_nameset_find(&t, "m1", 1) == SIZE_MAX
             && pt_nameset_find(&t, "m1999999", 8) == SIZE_MAX
             && pt_nameset_find(&t, "", 0) == SIZE_MAX);
    PT_CHECK("nameset-1.6 names are bytes: a NUL inside counts",
             pt_nameset_find(&t, "m1\0", 3) == SIZE_MAX);
    pt_nameset_free(&t);
    PT_CHECK("nameset-1.7 freed: empty", t.slot == NULL && t.cap == 0 && t.n == 0
             && pt_nameset_find(&t, "m1", 2) == SIZE_MAX);

    /* 200,000 models, one vertex each, then m7 again */
    text = malloc((size_t)N * 24 + 64);
    p = text;
    for (k = 0; k < N; k++) p += sprintf(p, "model m%zu\nv 0 0 -1\n", k);
    p += sprintf(p, "model m7\n");
    len = (size_t)(p - text);
    PT_CHECK("nameset-2.1 a scene of 200000 models and a late duplicate is refused",
             pt_scene_parse(&s, "many.scene", text, len, err, sizeof err) == -1);
    PT_CHECK("nameset-2.2 ... at the duplicate, naming the first's line",
             strcmp(err, "many.scene:400001:7: error: duplicate model name 'm7' "
                    "(first at line 15)") == 0);
    len -= strlen("model m7\n");
    PT_CHECK("nameset-2.3 without it, all 200000 are read",
             pt_scene_parse(&s, "many.scene", text, len, err, sizeof err) == 0
             && s.nmodels == N && strcmp(s.models[N - 1].name, "m199999") == 0);
    pt_scene_free(&s);
    free(text);
    return pt_test_report();
}
