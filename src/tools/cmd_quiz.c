/*
** src/tools/cmd_quiz.c -- pipetrace quiz: compute a vertex's journey yourself
** See LICENSE for copyright and license.
**
**   pipetrace quiz [SCENE] [--vertex N | --seed S] [--model NAME]
**
** Asks for each stage's values in pipeline order, one line of standard input
** per stage ("camera: x_c y_c z_c = ? "), and checks each answer against the
** pipeline's own numbers (src/io/explain.h).  Real numbers are right within 1e-6
** absolute or 1e-6 relative; pixel coordinates and the index must be exact;
** "none" answers a value that does not exist.  A wrong answer gets the formula
** with the numbers put in, and the quiz goes on from the right value, so one
** slip costs one stage.  End of input ends the quiz with the score so far.
** Without --vertex a used vertex is picked at random: --seed S makes the pick
** repeatable (xorshift64*, below); without it the seed is the time.
*/
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "io/explain.h"
#include "core/pipetrace.h"

#define TOL        1e-6          /* absolute and relative tolerance for doubles */

static const char usage[] =
"usage: pipetrace quiz [SCENE] [--vertex N | --seed S] [--model NAME]\n"
"Ask for vertex N's values at every stage, from model coordinates to the\n"
"pixel-array index, one line of standard input per stage, and check them.\n"
"Real numbers are right within 1e-6 absolute or 1e-6 relative; pixel\n"
"coordinates and the index must be exact; write 'none' for a value that does\n"
"not exist.  Without --vertex a used vertex is picked at random (--seed S:\n"
"repeatably).  SCENE defaults to the built-in scene.\n";

/* xorshift64* (Vigna, 2016): small, and the same numbers on every platform. */
static uint64_t xorshift(uint64_t *st)
{
    uint64_t x = *st;

    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    *st = x;
    return x * 0x2545F4914F6CDD1DULL;
}

/* Split an answer into numbers (spaces, tabs or commas between them); "none"
** sets none[k].  Returns how many, or -1 when a token is not a number or there
** are more than max. */
static int parse_answer(const char *line, double *v, int *none, int max)
{
    int n = 0;

    for (;;) {
        char tok[64], *end;
        size_t len = 0;

        while (*line == ' ' || *line == '\t' || *line == ',') line++;
        if (!*line) return n;
        while (line[len] && line[len] != ' ' && line[len] != '\t' && line[len] != ',') len++;
        if (n == max || len >= sizeof tok) return -1;
        memcpy(tok, line, len);
        tok[len] = '\0';
        line += len;
        none[n] = !strcmp(tok, "none");
        v[n] = 0;
        if (!none[n]) {
            v[n] = strtod(tok, &end);
            if (end == tok || *end) return -1;
        }
        n++;
    }
}

/* a is b, within the tolerance (non-finite: the same value). */
static int close_enough(double a, double b)
{
    if (isnan(b)) return isnan(a);
    if (!isfinite(b)) return a == b;
    return fabs(a - b) <= TOL || fabs(a - b) <= TOL * fabs(b);
}

/* 1 when the n answers are stage st's values in j. */
/* 1 for the stages whose values are integers: they must be exact. */
static int int_stage(pt_stage st)
{
    return st == PT_STAGE_VIEWPORT || st == PT_STAGE_FRAMEBUFFER ||
           st == PT_STAGE_INDEX || st == PT_STAGE_CVV;
}

static int check(const pt_journey *j, pt_stage st, const double *v, const int *none, int n)
{
    const pt_vrec *r = &j->rec[st];
    int k, want = pt_coord_count(st);

    if (int_stage(st) && (r->flags & PT_REC_NULL)) {
        for (k = 0; k < n; k++)
            if (!none[k]) return 0;
        return n >= 1 && n <= want;
    }
    if (n != want) return 0;
    for (k = 0; k < n; k++) {
        double e = st == PT_STAGE_INDEX ? (double)r->i
                 : st == PT_STAGE_CVV ? (double)r->code
                 : int_stage(st) ? (double)(k ? r->iy : r->ix)
                 : k == 0 ? r->x : k == 1 ? r->y : k == 2 ? r->z : r->w;
        if (none[k]) return 0;
        if (int_stage(st) ? v[k] != e : !close_enough(v[k], e)) return 0;
    }
    return 1;
}

/* Ask the seven questions; returns the number right, *asked how many were. */
static int ask(const pt_journey *j, int *asked)
{
    int i, k, right = 0, echo = !isatty(STDIN_FILENO);
    char line[1024], b[PT_EXPLAINLEN];

    *asked = 0;
    for (i = 0; i < j->norder; i++) {
        pt_stage st = j->order[i];
        double v[4];
        int none[4], n, ok, want;

        printf("\n%s:", pt_stage_infos[st].name);
        for (k = 0; k < pt_coord_count((pt_stage)st); k++)
            printf(" %s", pt_coord_name((pt_stage)st, k));
        printf(" = ? ");
        fflush(stdout);
        if (pt_cli_read_line(line, sizeof line, echo) != 0) { putchar('\n'); return right; }
        ++*asked;
        n = parse_answer(line, v, none, 4);
        ok = n >= 0 && check(j, (pt_stage)st, v, none, n);
        pt_explain_values(b, sizeof b, j, (pt_stage)st);
        if (ok) {
            right++;
            printf("  correct: %s\n", b);
            continue;
        }
        want = pt_coord_count((pt_stage)st);
        if (n < 0)                          /* only an integer stage may have none */
            printf("  wrong: expected %d number%s%s\n", want, want > 1 ? "s" : "",
                   int_stage(st) && st != PT_STAGE_CVV ? ", or none" : "");
        else if (n != want && !(j->rec[st].flags & PT_REC_NULL))
            printf("  wrong: expected %d number%s, found %d\n", want, want > 1 ? "s" : "", n);
        else printf("  wrong\n");
        printf("  %s\n", st == PT_STAGE_MODEL ? "the scene gives:" : pt_journey_info(j, st)->formula);
        pt_explain_stage(b, sizeof b, j, (pt_stage)st, "\n    ");
        printf("    %s\n", b);
        pt_explain_values(b, sizeof b, j, (pt_stage)st);
        printf("  go on with %s\n", b);
    }
    return right;
}

/* The k-th (0-based) used vertex of the models passing the filter. */
static int pick(const pt_scene *s, const char *model, uint64_t k,
                const pt_model **m, unsigned long long *v)
{
    size_t mi, j;

    for (mi = 0; mi < s->nmodels; mi++) {
        const pt_model *c = &s->models[mi];
        if (model && strcmp(model, c->name)) continue;
        for (j = 0; j < c->nv; j++)
            if (pt_vertex_used(c, j + 1) && k-- == 0) { *m = c; *v = j + 1; return 0; }
    }
    return -1;
}

int pt_cmd_quiz(int argc, char **argv)
{
    const char *path = NULL, *model = NULL;
    unsigned long long v = 0, seed = 0;
    int k, seeded = 0, picked = 0, right, asked;
    const pt_model *m = NULL;
    pt_journey j;
    pt_scene s;
    uint64_t n;
    size_t mi;
    pt_cli_args ca = {"quiz", usage, 1, NULL, NULL, 0};

    for (k = 1; k < argc; k++) {
        const char *a = argv[k];

        const char *val;
        int u;

        if (!strcmp(a, "--seed")) {
            if ((u = pt_cli_value("quiz", argc, argv, &k, &val)) >= 0) return u;
            if (pt_cli_count(val, 0, UINT64_MAX, &n))
                return pt_cli_usage("quiz", "--seed takes a whole number >= 0, not %s", val);
            seed = n;
            seeded = 1;
        } else if ((u = pt_cli_arg(&ca, argc, argv, &k)) >= 0) return u;  /* SCENE, --vertex, ... */
    }
    path = ca.path;
    model = ca.model;
    v = ca.vertex;
    if (v && seeded) return pt_cli_usage("quiz", "--vertex and --seed exclude each other");

    if (pt_cli_load(&s, path) != 0) return PT_EXIT_INPUT;
    if (v) m = pt_cli_vertex_model(&s, "quiz", model, v);
    if ((v && !m) || (!v && model && !pt_cli_model(&s, "quiz", model))) {
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    if (!v) {
        uint64_t total = 0, st;
        size_t q;

        if (!seeded) seed = (unsigned long long)time(NULL);
        for (mi = 0; mi < s.nmodels; mi++)
            if (!model || !strcmp(model, s.models[mi].name))
                for (q = 0; q < s.models[mi].nv; q++)
                    total += (uint64_t)pt_vertex_used(&s.models[mi], q + 1);
        if (total == 0) {
            fprintf(stderr, "pipetrace quiz: %s: no segment uses any vertex%s%s\n", s.path,
                    model ? " of " : "", model ? model : "");
            pt_scene_free(&s);
            return PT_EXIT_INPUT;
        }
        st = seed ^ 0x9E3779B97F4A7C15ULL;
        if (st == 0) st = 1;
        xorshift(&st);
        pick(&s, model, xorshift(&st) % total, &m, &v);
        picked = 1;
    }

    if (pt_run_journey(&j, &s, m, v, 0) != 0) {
        fputs("pipetrace quiz: out of memory\n", stderr);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    printf("pipetrace quiz: vertex %llu of model %s in %s", v, m->name, s.path);
    if (picked) printf(" (picked with --seed %llu)", seed);
    putchar('\n');
    printf("camera %s; viewport %d x %d at (x_ul, y_ul) = (%d, %d); framebuffer %d x %d\n",
           s.matrix ? "lookat (matrix camera)" : s.perspective ? "perspective" : "orthographic",
           s.vp_w, s.vp_h, s.vp_x, s.vp_y,
           s.fb_w, s.fb_h);
    {
        char t[PT_EXPLAINLEN];
        pt_explain_next(t, sizeof t, &j, PT_STAGE_MODEL);
        printf("model %s: %s\n", m->name, t);
    }
    if (!pt_vertex_used(m, v))
        printf("note: no segment uses this vertex, so the renderer does not transform it\n");
    printf("Answer each stage with its values on one line, separated by spaces or commas.\n"
           "Real numbers are right within 1e-6 absolute or 1e-6 relative; pixel\n"
           "coordinates and the index must be exact; write none for a value that does\n"
           "not exist.\n");
    right = ask(&j, &asked);
    if (asked == j.norder) printf("\nscore: %d/%d\n", right, j.norder);
    else printf("\nscore: %d/%d (input ended after %d of %d stages)\n", right, asked,
                asked, j.norder);
    pt_scene_free(&s);
    fflush(stdout);
    return 0;
}
