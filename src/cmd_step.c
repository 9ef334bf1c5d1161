/*
** src/cmd_step.c -- pipetrace step: one vertex, one stage at a time
** See LICENSE for copyright and license.
**
**   pipetrace step [SCENE] --vertex N [--model NAME] [--all | --interactive]
**
** For each of the seven stages: its name, the spaces it maps from and to, what
** it does, its formula, the formula with this vertex's numbers and the result,
** and what the result means for the next stage (src/explain.h writes all of it).
** When standard input and output are terminals the stages come one at a time:
** Enter shows the next, b the one before, q quits; lines are read from standard
** input, no raw terminal mode.  Otherwise (or with --all) every stage is
** printed at once, the same bytes every run.  --interactive forces the loop
** (the tests drive it through a pipe; input lines are then echoed).
*/
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "builtin.h"
#include "commands.h"
#include "explain.h"
#include "scene.h"

#define EXIT_USAGE 1
#define EXIT_INPUT 2

static const char usage[] =
"usage: pipetrace step [SCENE] [--vertex N] [--model NAME] [--all | --interactive]\n"
"Follow vertex N (1-based, default 1) of model NAME (default: the first model\n"
"that has a vertex N) from model coordinates to its pixel-array index, one\n"
"stage at a time: the formula, the formula with the vertex's numbers, the\n"
"result, and what the next stage will do with it.  SCENE defaults to the\n"
"built-in scene.\n"
"\n"
"  --all            print every stage at once (the default unless standard\n"
"                   input and output are both terminals)\n"
"  --interactive    one stage at a time even when not on a terminal\n"
"                   (Enter: next stage, b: back, q: quit)\n";

static int usage_error(const char *msg, const char *arg)
{
    fprintf(stderr, "pipetrace step: %s%s\nTry 'pipetrace step --help'.\n", msg, arg);
    return EXIT_USAGE;
}

/* Print stage st of journey j: name, spaces, what, formula, numbers, next. */
static void show_stage(const pt_journey *j, pt_stage st)
{
    const pt_stage_info *in = &pt_stage_infos[st];
    char b[PT_EXPLAINLEN];

    printf("stage %d of %d: %s (%s -> %s)\n", (int)st + 1, PT_NSTAGES, in->name,
           in->from, in->to);
    printf("  what     %s\n", in->what);
    printf("  formula  %s\n", in->formula);
    pt_explain_stage(b, sizeof b, j, st, "\n           ");
    printf("  here     %s\n", b);
    pt_explain_next(b, sizeof b, j, st);
    printf("  next     %s\n", b);
}

/* Read one line of standard input into b (newline dropped; the rest of a too
** long line is skipped).  echo: print it, so that a transcript driven through
** a pipe reads like a terminal session.  Returns 0, or -1 at end of input. */
static int read_line(char *b, size_t n, int echo)
{
    size_t len;

    if (!fgets(b, (int)n, stdin)) return -1;
    len = strlen(b);
    if (len && b[len - 1] == '\n') b[--len] = '\0';
    else { int ch; while ((ch = getchar()) != EOF && ch != '\n') {} }
    if (len && b[len - 1] == '\r') b[--len] = '\0';
    if (echo) printf("%s\n", b);
    return 0;
}

/* Enter, b, q: walk the stages until q, end of input, or Enter after the last. */
static void interact(const pt_journey *j)
{
    int st = 0, show = 1, echo = !isatty(STDIN_FILENO);
    char line[256];

    for (;;) {
        if (show) show_stage(j, (pt_stage)st);
        show = 1;
        printf("[Enter] %s, b back, q quit: ", st + 1 < PT_NSTAGES ? "next stage" : "done");
        fflush(stdout);
        if (read_line(line, sizeof line, echo) != 0) { putchar('\n'); break; }
        if (!strcmp(line, "q") || !strcmp(line, "quit")) break;
        if (!strcmp(line, "b") || !strcmp(line, "back")) {
            if (st > 0) st--;
        } else if (line[0] == '\0') {
            if (st + 1 == PT_NSTAGES) break;
            st++;
        } else {
            printf("(Enter: next stage, b: back, q: quit)\n");
            show = 0;
            continue;
        }
        putchar('\n');
    }
}

int pt_cmd_step(int argc, char **argv)
{
    const char *path = NULL, *model = NULL;
    unsigned long long v = 1;
    int k, all = 0, inter = 0, rc;
    const pt_model *m = NULL;
    pt_stage_params par;
    pt_journey j;
    pt_scene s;
    char err[PT_ERRLEN];
    size_t mi;

    for (k = 1; k < argc; k++) {
        const char *a = argv[k];

        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(usage, stdout); return 0; }
        if (!strcmp(a, "--all")) all = 1;
        else if (!strcmp(a, "--interactive")) inter = 1;
        else if (!strcmp(a, "--vertex") || !strcmp(a, "--model")) {
            if (k + 1 >= argc) return usage_error("option needs a value: ", a);
            if (!strcmp(a, "--model")) model = argv[++k];
            else {
                char *end;
                const char *val = argv[++k];
                errno = 0;
                v = strtoull(val, &end, 10);
                if (val[0] < '0' || val[0] > '9' || *end || errno || v < 1 || v > 4294967295ULL)
                    return usage_error("--vertex takes a vertex number >= 1, not ", val);
            }
        } else if (a[0] == '-' && a[1] != '\0') return usage_error("unknown option ", a);
        else if (path) return usage_error("more than one scene given: ", a);
        else path = a;
    }
    if (all && inter) return usage_error("--all and --interactive exclude each other", "");

    rc = path ? pt_scene_load(&s, path, err, sizeof err)
              : pt_scene_parse(&s, "<builtin>", pt_builtin_scene,
                               strlen(pt_builtin_scene), err, sizeof err);
    if (rc != 0) { fprintf(stderr, "%s\n", err); return EXIT_INPUT; }
    rc = pt_journey_agrees(&s);
    if (rc != 1) {
        fprintf(stderr, "pipetrace step: %s: %s\n", s.path, rc < 0 ? "out of memory"
                : "this scene's camera takes other stages than model -> camera -> image "
                  "-> pixel -> viewport -> framebuffer -> index, the only ones step knows");
        pt_scene_free(&s);
        return EXIT_INPUT;
    }
    for (mi = 0; mi < s.nmodels && !m; mi++) {
        const pt_model *c = &s.models[mi];
        if (model ? !strcmp(model, c->name) : c->nv >= v) m = c;
    }
    if (!m || m->nv < v) {
        if (model && !m) fprintf(stderr, "pipetrace step: %s has no model '%s'\n", s.path, model);
        else fprintf(stderr, "pipetrace step: %s: no model%s%s has a vertex %llu\n", s.path,
                     model ? " " : "", model ? model : "", v);
        pt_scene_free(&s);
        return EXIT_INPUT;
    }

    pt_stage_params_of(&par, &s, m);
    pt_journey_compute(&j, &par, m->v[v - 1]);
    printf("pipetrace step: vertex %llu of model %s in %s\n", v, m->name, s.path);
    printf("camera %s; viewport %d x %d at (x_ul, y_ul) = (%d, %d); framebuffer %d x %d\n\n",
           s.perspective ? "perspective" : "orthographic", s.vp_w, s.vp_h, s.vp_x, s.vp_y,
           s.fb_w, s.fb_h);
    if (!pt_vertex_used(m, v))
        printf("note: no segment uses vertex %llu, so the renderer does not transform it;\n"
               "      here is the journey it would take.\n\n", v);
    if (inter || (!all && isatty(STDIN_FILENO) && isatty(STDOUT_FILENO)))
        interact(&j);
    else
        for (k = 0; k < PT_NSTAGES; k++) {
            if (k) putchar('\n');
            show_stage(&j, (pt_stage)k);
        }
    pt_scene_free(&s);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("pipetrace step: cannot write to standard output\n", stderr);
        return EXIT_INPUT;
    }
    return 0;
}
