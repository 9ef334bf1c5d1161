/*
** tests/unit/refcases.h -- the reference cases of a directory, by name
** See LICENSE for copyright and license.
**
** pt_ref_cases(dir, names, max) lists the NAME of each NAME.scene in dir,
** sorted, into names[] (each malloc'ed; the caller frees them) and returns
** how many, at most max; -1 when dir does not open.  Used by the tests that
** run every reference case (test_reference.c, test_catalogue.c).
** pt_ref_run(argc, argv, prog, run_case) calls run_case(dir, NAME) for each
** case of the directory argv[1] (default tests/reference), with the checks
** that it opens and holds cases, then prints "PROG: N cases from DIR";
** pt_ref_load() loads one case, checking that it does.
** Include after testhelp.h.
*/
#ifndef PT_REFCASES_H
#define PT_REFCASES_H

#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core/pipetrace.h"

static int pt_ref_by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static long pt_ref_cases(const char *dir, char **names, size_t max)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    size_t n = 0;

    if (!d) return -1;
    while ((e = readdir(d)) != NULL && n < max) {
        size_t len = strlen(e->d_name);
        if (len > 6 && strcmp(e->d_name + len - 6, ".scene") == 0 &&
            (names[n] = malloc(len - 5)) != NULL) {
            memcpy(names[n], e->d_name, len - 6);
            names[n][len - 6] = '\0';
            n++;
        }
    }
    closedir(d);
    qsort(names, n, sizeof names[0], pt_ref_by_name);
    return (long)n;
}

/* Load case NAME of dir into *s; on failure check "TAG NAME: loads (why)"
** as failed and return -1.  Needs core/pipetrace.h. */
static int pt_ref_load(pt_scene *s, const char *dir, const char *name, const char *tag)
{
    char path[4096], err[PT_ERRLEN], descr[PT_ERRLEN + 4200];

    snprintf(path, sizeof path, "%s/%s.scene", dir, name);
    if (pt_scene_load(s, path, err, sizeof err) == 0) return 0;
    snprintf(descr, sizeof descr, "%s %s: loads (%s)", tag, name, err);
    PT_CHECK(descr, 0);
    return -1;
}

static void pt_ref_run(int argc, char **argv, const char *prog,
                       void (*run_case)(const char *dir, const char *name))
{
    const char *dir = argc > 1 ? argv[1] : "tests/reference";
    char *names[4096];
    long n = pt_ref_cases(dir, names, 4096), k;

    PT_CHECK("reference directory opens", n >= 0);
    PT_CHECK("reference cases found", n > 0);
    for (k = 0; k < n; k++) { run_case(dir, names[k]); free(names[k]); }
    printf("%s: %ld cases from %s\n", prog, n < 0 ? 0 : n, dir);
}

#endif
