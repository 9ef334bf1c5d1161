/*
** src/cli.c -- what every pipetrace command does with its arguments
** See LICENSE for copyright and license.
*/
#include <stdio.h>
#include <string.h>
#include "cli.h"
#include "builtin.h"

int pt_cli_load(pt_scene *s, const char *path)
{
    char err[PT_ERRLEN];
    int rc = path ? pt_scene_load(s, path, err, sizeof err)
                  : pt_scene_parse(s, "<builtin>", pt_builtin_scene,
                                   strlen(pt_builtin_scene), err, sizeof err);

    if (rc == 0) return 0;
    fprintf(stderr, "%s\n", err);
    return PT_EXIT_INPUT;
}

const pt_model *pt_cli_vertex_model(const pt_scene *s, const char *cmd,
                                    const char *name, uint64_t v)
{
    size_t k;

    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        if (name ? strcmp(name, m->name) != 0 : m->nv < v) continue;
        if (m->nv >= v) return m;
        break;                              /* the named model is too small */
    }
    if (name && k == s->nmodels)
        fprintf(stderr, "pipetrace %s: %s has no model '%s'\n", cmd, s->path, name);
    else
        fprintf(stderr, "pipetrace %s: %s: no model%s%s has a vertex %llu\n", cmd, s->path,
                name ? " " : "", name ? name : "", (unsigned long long)v);
    return NULL;
}

int pt_cli_count(const char *text, uint64_t lo, uint64_t hi, uint64_t *out)
{
    uint64_t v = 0;
    const char *p = text;

    if (*p < '0' || *p > '9') return -1;
    for (; *p >= '0' && *p <= '9'; p++) {
        unsigned d = (unsigned)(*p - '0');
        if (v > (UINT64_MAX - d) / 10) return -1;   /* would overflow */
        v = v * 10 + d;
    }
    if (*p || v < lo || v > hi) return -1;
    *out = v;
    return 0;
}
