/*
** src/tools/cli.c -- what every pipetrace command does with its arguments
** See LICENSE for copyright and license.
*/
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <unistd.h>
#include "tools/cli.h"
#include "io/outfile.h"
#include "io/tread79.h"
#include "core/pipetrace.h"

int pt_cli_stdout(const char *cmd, int rc)
{
    int e;

    errno = 0;
    if (fflush(stdout) == 0 && !ferror(stdout)) return rc;
    e = errno;
    if (e == 0 && fputc('\n', stdout) != EOF && fflush(stdout) != 0)
        e = errno;                  /* the reason, from one more try */
    if (rc == PT_EXIT_INPUT) return rc;     /* already told */
    fprintf(stderr, "pipetrace%s%s: cannot write to standard output: %s\n", cmd ? " " : "",
            cmd ? cmd : "", e != 0 ? strerror(e) : "write error");
    return PT_EXIT_INPUT;
}

int pt_cli_load(pt_scene *s, const char *path)
{
    char err[PT_ERRLEN];
    int rc = path && !strcmp(path, "-") ? pt_scene_read(s, stdin, "<stdin>", err, sizeof err)
           : path ? pt_scene_load(s, path, err, sizeof err)
                  : pt_scene_parse(s, "<builtin>", pt_builtin_scene,
                                   strlen(pt_builtin_scene), err, sizeof err);

    if (rc == 0) return 0;
    fprintf(stderr, "%s\n", err);
    return PT_EXIT_INPUT;
}

int pt_cli_course_text(const char *path, const char *buf, size_t len, const char *cmd)
{
    int r = pt_t79_renderer(buf, len);          /* io/tread79.c tells them apart */

    if (r != 7 && r != 9) return 0;
    fprintf(stderr, "pipetrace %s: %s: error: %s does not read the traces and logs of "
            "scenes of the course's renderer 7 or 9\n", cmd, path, cmd);
    return PT_EXIT_INPUT;
}

int pt_cli_course(pt_scene *s, const char *cmd)
{
    if (s->renderer != 7 && s->renderer != 9) return 0;
    fprintf(stderr, "pipetrace %s: %s: error: %s does not take scenes of the course's "
            "renderer %d (render it with 'pipetrace %s': its image, log and trace)\n",
            cmd, s->path, cmd, s->renderer, s->path);
    pt_scene_free(s);
    return PT_EXIT_INPUT;
}

int pt_cli_outputs(const char *scene, const char *const *out, const char *const *opt, int n)
{
    const char *in = scene && !strcmp(scene, "-") ? "/dev/stdin" : scene;
    int k, i;

    for (k = 0; k < n; k++) {
        if (!out[k]) continue;
        if (in && pt_outfile_same(out[k], in)) {
            fprintf(stderr, "%s: error: %s names the scene file%s; writing it would "
                    "destroy the scene\n", out[k], opt[k], in == scene ? "" : " (standard input)");
            return PT_EXIT_INPUT;
        }
        for (i = 0; i < k; i++)
            if (out[i] && pt_outfile_same(out[i], out[k])) {
                fprintf(stderr, "%s: error: %s and %s name the same file; one would "
                        "overwrite the other\n", out[k], opt[i], opt[k]);
                return PT_EXIT_INPUT;
            }
    }
    return 0;
}

int pt_cli_outputs_objs(const pt_scene *s, const char *const *out, const char *const *opt,
                        int n)
{
    const char *const *objs = (const char *const *)s->objs;
    size_t j;
    int k;

    for (k = 0; k < n; k++)
        if (out[k] && (j = pt_outfile_among(out[k], objs, s->nobjs)) < s->nobjs) {
            fprintf(stderr, "%s: error: %s names '%s', an OBJ file the scene reads; "
                    "writing it would destroy it\n", out[k], opt[k], objs[j]);
            return PT_EXIT_INPUT;
        }
    return 0;
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
    if (!s->nmodels) {
        fprintf(stderr, "pipetrace%s%s: --vertex %llu: %s has no models\n", cmd ? " " : "",
                cmd ? cmd : "", (unsigned long long)v, s->path);
        return NULL;
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

    int big = 0;

    if (*p < '0' || *p > '9') return -1;
    for (; *p >= '0' && *p <= '9'; p++) {
        unsigned d = (unsigned)(*p - '0');
        if (big || v > (UINT64_MAX - d) / 10) big = 1;  /* would overflow: too large */
        else v = v * 10 + d;
    }
    if (*p) return -1;
    if (big || v < lo || v > hi) return -2;
    *out = v;
    return 0;
}

int pt_cli_vertex(const char *cmd, const char *val, uint64_t *out)
{
    int r = pt_cli_count(val, 1, PT_MAX_VERTEX, out);

    if (r == 0) return 0;
    if (r == -2 && strspn(val, "0") == strlen(val))
        return pt_cli_usage(cmd, "--vertex %s is out of range: vertices are numbered from 1", val);
    if (r == -2)
        return pt_cli_usage(cmd, "--vertex %.40s%s is out of range: vertex numbers go from 1 "
                            "to %u (indices are 32-bit)", val, strlen(val) > 40 ? "..." : "",
                            PT_MAX_VERTEX);
    return pt_cli_usage(cmd, "--vertex takes a vertex number from 1 to %u, not '%.40s%s'",
                        PT_MAX_VERTEX, val, strlen(val) > 40 ? "..." : "");
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
        else if (pt_cli_vertex(a->cmd, val, &a->vertex) != 0)
            return PT_EXIT_USAGE;
        return -1;
    }
    if (o[0] == '-' && o[1] != '\0') return pt_cli_unknown(a->cmd, a->usage, o);
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

/* Edit distance of a[0..na) and b[0..nb) (both < 64): insertions, deletions,
** changes, and swaps of two neighbours (optimal string alignment). */
static size_t distance(const char *a, size_t na, const char *b, size_t nb)
{
    size_t d[64][64], i, j;

    for (i = 0; i <= na; i++) d[i][0] = i;
    for (j = 0; j <= nb; j++) d[0][j] = j;
    for (i = 1; i <= na; i++)
        for (j = 1; j <= nb; j++) {
            size_t c = d[i - 1][j - 1] + (a[i - 1] != b[j - 1]);
            if (d[i - 1][j] + 1 < c) c = d[i - 1][j] + 1;
            if (d[i][j - 1] + 1 < c) c = d[i][j - 1] + 1;
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1] &&
                d[i - 2][j - 2] + 1 < c)
                c = d[i - 2][j - 2] + 1;
            d[i][j] = c;
        }
    return d[na][nb];
}

int pt_cli_nearest(const char *arg, const char *text, char *out, size_t n)
{
    const char *p = text, *best = NULL;
    size_t na = strlen(arg), nbest = 0, dbest = 3, letters;
    int opt = arg[0] == '-';

    letters = na - strspn(arg, "-");
    if (n) out[0] = '\0';
    if (na >= 64) return 0;
    while (*p) {
        size_t len;
        if (opt ? !(p[0] == '-' && p[1] == '-' && (p == text || p[-1] != '-'))
                : !(*p >= 'a' && *p <= 'z') || (p > text && p[-1] >= 'a' && p[-1] <= 'z')) {
            p++;
            continue;
        }
        len = opt ? 2 + strspn(p + 2, "abcdefghijklmnopqrstuvwxyz0123456789-")
                  : strspn(p, "abcdefghijklmnopqrstuvwxyz");
        if (len < 64 && (!opt || len > 2)) {
            size_t d = distance(arg, na, p, len);
            if (d < dbest) { dbest = d; best = p; nbest = len; }
        }
        p += len;
    }
    if (!best || dbest >= letters || dbest == 0 || nbest >= n) return 0;
    memcpy(out, best, nbest);
    out[nbest] = '\0';
    return 1;
}

int pt_cli_unknown(const char *cmd, const char *usage, const char *arg)
{
    char near[64];

    if (pt_cli_nearest(arg, usage, near, sizeof near))
        return pt_cli_usage(cmd, "unknown option '%s' (did you mean '%s'?)", arg, near);
    return pt_cli_usage(cmd, "unknown option '%s'", arg);
}

/* ===== output wrapped to the terminal's width ===== */

int pt_cli_width(void)
{
    const char *c = getenv("COLUMNS");
    uint64_t w;
#ifdef TIOCGWINSZ
    struct winsize ws;
#endif

    if (c && pt_cli_count(c, 20, 100000, &w) == 0) return (int)w;
#ifdef TIOCGWINSZ
    if (isatty(STDOUT_FILENO) && ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) == 0 && ws.ws_col >= 20)
        return ws.ws_col;
#endif
    return 0;
}

void pt_cli_wrap_line(FILE *f, const char *line, size_t n, int width)
{
    size_t lead = 0, cont, col, at, w = width > 0 ? (size_t)width : 0;

    if (!w || n <= w) { fwrite(line, 1, n, f); return; }
    while (lead < n && line[lead] == ' ') lead++;
    cont = lead + 4;                        /* the second column, else 4 in */
    for (col = lead; col + 2 < n; col++)
        if (line[col] == ' ' && line[col + 1] == ' ') {
            while (col < n && line[col] == ' ') col++;
            if (col < n && col < w / 2) cont = col;
            break;
        }
    if (cont >= w / 2) cont = lead < w / 2 ? lead : 0;
    at = 0;
    while (at < n) {
        size_t room = w - (at ? cont : 0), end = 0, k;
        if (at) { fputc('\n', f); fprintf(f, "%*s", (int)cont, ""); }
        if (n - at <= room) { fwrite(line + at, 1, n - at, f); return; }
        /* the last space within the room that is a good break: not after "=" */
        for (k = at + 1; k <= at + room && k < n; k++)
            if (line[k] == ' ' && line[k - 1] != ' ' && line[k - 1] != '=' &&
                (k < 2 || line[k - 1] != '-' || line[k - 2] != ' '))
                end = k;
        if (!end)                           /* one long word: let it run over */
            for (end = at + 1; end < n && line[end] != ' '; end++) ;
        fwrite(line + at, 1, end - at, f);
        at = end;
        while (at < n && line[at] == ' ') at++;
    }
}

void pt_cli_out_open(pt_cli_out *o)
{
    o->buf = NULL;
    o->len = 0;
    o->width = pt_cli_width();
    o->f = stdout;
    if (o->width && !(o->f = open_memstream(&o->buf, &o->len))) {
        o->f = stdout;                      /* out of memory: unwrapped, then */
        o->width = 0;
    }
}

int pt_cli_out_flush(pt_cli_out *o)
{
    const char *p, *e, *nl;

    if (o->width) {
        if (fflush(o->f) != 0) return -1;
        for (p = o->buf, e = o->buf + o->len; p < e; p = nl + 1) {
            nl = memchr(p, '\n', (size_t)(e - p));
            pt_cli_wrap_line(stdout, p, (size_t)((nl ? nl : e) - p), o->width);
            if (!nl) break;
            fputc('\n', stdout);
        }
        fclose(o->f);
        free(o->buf);
        o->buf = NULL;
        o->len = 0;
        if (!(o->f = open_memstream(&o->buf, &o->len))) { o->f = stdout; o->width = 0; }
    }
    return fflush(stdout) != 0 || ferror(stdout) ? -1 : 0;
}

int pt_cli_out_close(pt_cli_out *o)
{
    int rc = pt_cli_out_flush(o);

    if (o->width) {
        fclose(o->f);
        free(o->buf);
    }
    o->f = stdout;
    o->width = 0;
    return rc;
}
