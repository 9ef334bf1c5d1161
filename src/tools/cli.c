/*
** src/tools/cli.c -- what every pipetrace command does with its arguments
** See LICENSE for copyright and license.
*/
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "tools/cli.h"
#include "core/pipetrace.h"

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

const pt_model *pt_cli_model(const pt_scene *s, const char *cmd, const char *name)
{
    size_t k;

    for (k = 0; k < s->nmodels; k++)
        if (!strcmp(name, s->models[k].name)) return &s->models[k];
    fprintf(stderr, "pipetrace%s%s: --model %s: %s has no model '%s' (", cmd ? " " : "",
            cmd ? cmd : "", name, s->path, name);
    for (k = 0; k < s->nmodels; k++)
        fprintf(stderr, "%s%s", k ? ", " : "its models: ", s->models[k].name);
    fprintf(stderr, "%s)\n", s->nmodels ? "" : "it has no models");
    return NULL;
}

const pt_model *pt_cli_vertex_model(const pt_scene *s, const char *cmd,
                                    const char *name, uint64_t v)
{
    const pt_model *m;
    size_t k, most = 0;

    if (name) {
        if (!(m = pt_cli_model(s, cmd, name))) return NULL;
        if (m->nv >= v) return m;
        fprintf(stderr, "pipetrace%s%s: --vertex %llu: model %s of %s has no vertex %llu "
                "(it has %zu)\n", cmd ? " " : "", cmd ? cmd : "", (unsigned long long)v, m->name, s->path,
                (unsigned long long)v, m->nv);
        return NULL;
    }
    for (k = 0; k < s->nmodels; k++) {
        if (s->models[k].nv >= v) return &s->models[k];
        if (s->models[k].nv > most) most = s->models[k].nv;
    }
    fprintf(stderr, "pipetrace%s%s: --vertex %llu: no model of %s has a vertex %llu "
            "(the largest has %zu)\n", cmd ? " " : "", cmd ? cmd : "", (unsigned long long)v, s->path,
            (unsigned long long)v, most);
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

int pt_cli_value(const char *cmd, int argc, char **argv, int *k, const char **val)
{
    if (*k + 1 >= argc) return pt_cli_usage(cmd, "option needs a value: %s", argv[*k]);
    *val = argv[++*k];
    return -1;
}

int pt_cli_arg(pt_cli_args *a, int argc, char **argv, int *k)
{
    const char *o = argv[*k], *val = NULL;
    int rc;

    if (!strcmp(o, "--help") || !strcmp(o, "-h")) { fputs(a->usage, stdout); return 0; }
    if (a->takes_vertex && (!strcmp(o, "--vertex") || !strcmp(o, "--model"))) {
        if ((rc = pt_cli_value(a->cmd, argc, argv, k, &val)) >= 0) return rc;
        if (!strcmp(o, "--model")) a->model = val;
        else if (pt_cli_count(val, 1, 4294967295u, &a->vertex) != 0)
            return pt_cli_usage(a->cmd, "--vertex takes a vertex number >= 1, not %s", val);
        return -1;
    }
    if (o[0] == '-' && o[1] != '\0') return pt_cli_usage(a->cmd, "unknown option %s", o);
    if (a->path) return pt_cli_usage(a->cmd, "more than one scene given: %s", o);
    a->path = o;
    return -1;
}

int pt_cli_usage(const char *cmd, const char *fmt, ...)
{
    va_list ap;

    fprintf(stderr, "pipetrace%s%s: ", cmd ? " " : "", cmd ? cmd : "");
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fprintf(stderr, "\nTry 'pipetrace%s%s --help'.\n", cmd ? " " : "", cmd ? cmd : "");
    return PT_EXIT_USAGE;
}

int pt_cli_student_note(char *buf, size_t n)
{
    char names[256], vars[512];
    const char *p = pt_student_stages, *sep;
    size_t ln = 0, lv = 0;
    int k = 0, count = 0;

    for (sep = p; *sep; sep++) count += *sep != ' ' && (sep == p || sep[-1] == ' ');
    names[0] = vars[0] = '\0';
    while (*p) {
        size_t len;
        while (*p == ' ') p++;
        len = strcspn(p, " ");
        if (!len) break;
        k++;
        ln += (size_t)snprintf(names + ln, sizeof names - ln, "%s%.*s",
                               k == 1 ? "" : k == count ? " and " : ", ", (int)len, p);
        lv += (size_t)snprintf(vars + lv, sizeof vars - lv,
                               "%sSTAGE_%.*s=...", k == 1 ? "" : " ", (int)len, p);
        if (ln >= sizeof names || lv >= sizeof vars) break;
        p += len;
    }
    if (!k || !n) { if (n) buf[0] = '\0'; return 0; }
    snprintf(buf, n, "student build: the %s stage%s %s yours (make %s)", names,
             k > 1 ? "s" : "", k > 1 ? "are" : "is", vars);
    return 1;
}

int pt_cli_read_line(char *b, size_t n, int echo)
{
    return pt_cli_read_line_from(stdin, b, n, echo);
}

int pt_cli_read_line_from(FILE *f, char *b, size_t n, int echo)
{
    size_t len;

    if (!fgets(b, (int)n, f)) return -1;
    len = strlen(b);
    if (len && b[len - 1] == '\n') b[--len] = '\0';
    else { int ch; while ((ch = getc(f)) != EOF && ch != '\n') {} }
    if (len && b[len - 1] == '\r') b[--len] = '\0';
    if (echo) printf("%s\n", b);
    return 0;
}
