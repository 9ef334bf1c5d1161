/*
** src/tools/cmd_step.c -- pipetrace step: one vertex, one stage at a time
** See LICENSE for copyright and license.
**
**   pipetrace step [SCENE] --vertex N [--model NAME] [--all | --interactive]
**
** For each of the seven stages: its name, the spaces it maps from and to, what
** it does, its formula, the formula with this vertex's numbers and the result,
** and what the result means for the next stage (src/io/explain.h writes all of it).
** When standard input and output are terminals the stages come one at a time:
** Enter shows the next, b the one before, q quits; lines are read from standard
** input, no raw terminal mode.  Otherwise (or with --all) every stage is
** printed at once, the same bytes every run.  --interactive forces the loop
** (the tests drive it through a pipe; input lines are then echoed).
*/
#define _POSIX_C_SOURCE 200809L
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "io/explain.h"
#include "io/explain_course.h"
#include "io/numfmt.h"
#include "core/pipetrace.h"


/* Where step writes: standard output, wrapped to the terminal's width
** (src/tools/cli.h).  File-static because every printing function here writes
** to it and one command runs per process. */
static pt_cli_out term = {NULL, 0, NULL, 0};

static const char usage[] =
"usage: pipetrace step [SCENE] [--vertex N] [--model NAME] [--all | --interactive]\n"
"                      [--compare-cameras] [--raw-lookat]\n"
"Follow vertex N (1-based, default 1) of model NAME (default: the first model\n"
"that has a vertex N) from model coordinates to its pixel-array index, one\n"
"stage at a time: the formula, the formula with the vertex's numbers, the\n"
"result, and what the next stage will do with it.  SCENE defaults to the\n"
"built-in scene.  A scene of the course's renderer 7 or 9 is followed through\n"
"its stages (view volume, near clip, clip, pixel); N past the model's vertices\n"
"is a vertex a clip stage made, numbered as the trace numbers it.\n"
"\n"
"  --all            print every stage at once (the default unless standard\n"
"                   input and output are both terminals)\n"
"  --interactive    one stage at a time even when not on a terminal\n"
"                   (Enter: next stage, b: back, q: quit)\n"
"  --compare-cameras  the vertex through the classic and the matrix camera,\n"
"                   side by side (docs/cameras.md)\n"
"  --raw-lookat     matrix camera: keep the given up vector as it is\n"
"Docs: docs/step-why-quiz.md, docs/cameras.md\n";

/* Print a paragraph that is broken into lines for 80 columns; when the output
** is wrapped to the terminal's width, the breaks inside it are dropped first
** (a line break and the spaces after it become one space), so the wrapping
** reflows it. */
static void para(const char *fmt, ...) PT_PRINTF_LIKE(1, 2);
static void para(const char *fmt, ...)
{
    char b[1024], *p, *q;
    va_list ap;

    va_start(ap, fmt);
    vsnprintf(b, sizeof b, fmt, ap);
    va_end(ap);
    if (term.width) {
        for (p = q = b; *p; p++) {
            if (*p == '\n' && p[1]) {
                while (p[1] == ' ') p++;
                *q++ = ' ';
            } else *q++ = *p;
        }
        *q = '\0';
    }
    fputs(b, term.f);
}

/* Print stage st of journey j: name, spaces, what, formula, numbers, next. */
static void show_stage(const pt_journey *j, int i)
{
    pt_stage st = j->order[i];
    const pt_stage_info *in = pt_journey_info(j, st);
    char b[PT_EXPLAINLEN];

    fprintf(term.f, "stage %d of %d: %s (%s -> %s)\n", i + 1, j->norder, in->name,
           in->from, in->to);
    fprintf(term.f, "  what     %s\n", in->what);
    fprintf(term.f, "  formula  %s\n", in->formula);
    pt_explain_stage(b, sizeof b, j, st, "\n           ");
    fprintf(term.f, "  here     %s\n", b);
    pt_explain_next(b, sizeof b, j, st);
    fprintf(term.f, "  next     %s\n", b);
}

/* Show stage i of a journey (renderer 4's or a course renderer's). */
typedef void (*show_fn)(const void *j, int i);

static void show_r4(const void *j, int i)
{
    show_stage(j, i);
}

/* Enter, a stage number, b, q: walk the n stages of j until q, end of input,
** or Enter after the last. */
static void interact(const void *j, int n, show_fn show_at)
{
    int st = 0, show = 1, echo = !isatty(STDIN_FILENO);
    char line[256];
    uint64_t to;

    for (;;) {
        if (show) show_at(j, st);
        show = 1;
        fprintf(term.f, "[Enter] %s, 1-%d go to a stage, b back, q quit: ",
                st + 1 < n ? "next stage" : "done", n);
        pt_cli_out_flush(&term);
        if (pt_cli_read_line(line, sizeof line, echo) != 0) {
            fprintf(term.f, "\n(end of input: step ends)\n");
            break;
        }
        if (!strcmp(line, "q") || !strcmp(line, "Q") || !strcmp(line, "quit")) break;
        if (!strcmp(line, "b") || !strcmp(line, "B") || !strcmp(line, "back")) {
            if (st == 0) {
                fprintf(term.f, "(this is the first stage: there is none before it)\n");
                show = 0;
                continue;
            }
            st--;
        } else if (line[0] == '\0') {
            if (st + 1 == n) break;
            st++;
        } else if (pt_cli_count(line, 1, (uint64_t)n, &to) == 0) {
            st = (int)to - 1;
        } else {
            fprintf(term.f, "(Enter: next stage, 1-%d: that stage, b: back, q: quit)\n", n);
            show = 0;
            continue;
        }
        fputc('\n', term.f);
    }
}

/* ===== --compare-cameras ===== */

/* Which stages of each camera answer the same question, row by row. */
static const struct cmp_row {
    const char *what;
    int classic[2], matrix[3];               /* -1: none */
} cmp_rows[] = {
    { "the vertex",      {PT_STAGE_MODEL, -1}, {PT_STAGE_MODEL, -1, -1} },
    { "seen from the camera", {PT_STAGE_CAMERA, -1}, {PT_STAGE_WORLD, PT_STAGE_VIEW, -1} },
    { "projected",       {PT_STAGE_IMAGE, -1}, {PT_STAGE_CLIP, PT_STAGE_CVV, PT_STAGE_NDC} },
    { "on the viewport", {PT_STAGE_PIXEL, PT_STAGE_VIEWPORT}, {PT_STAGE_SCREEN, PT_STAGE_VIEWPORT, -1} },
    { "in the framebuffer", {PT_STAGE_FRAMEBUFFER, -1}, {PT_STAGE_FRAMEBUFFER, -1, -1} },
    { "in the pixel array", {PT_STAGE_INDEX, -1}, {PT_STAGE_INDEX, -1, -1} },
};

/* 1 when stage st is part of journey j. */
static int in_journey(const pt_journey *j, pt_stage st)
{
    int i;
    for (i = 0; i < j->norder; i++)
        if (j->order[i] == st) return 1;
    return 0;
}

/* One side of a row: "stage  values" per stage, each on its own line. */
static int side_lines(const pt_journey *j, const int *sts, int n, char out[][PT_EXPLAINLEN + 16])
{
    int i, k = 0;

    for (i = 0; i < n && sts[i] >= 0; i++) {
        char b[PT_EXPLAINLEN];
        if (!in_journey(j, (pt_stage)sts[i])) continue;
        pt_explain_values(b, sizeof b, j, (pt_stage)sts[i]);
        snprintf(out[k++], PT_EXPLAINLEN + 16, "%-9s %s", pt_stage_infos[sts[i]].name, b);
    }
    return k;
}

/* The vertex through both cameras.  A classic scene gets the matrix camera
** that sees exactly what the classic one sees; a matrix scene gets the classic
** camera with each model's translation (its world lines and look-at have no
** classic counterpart). */
static int compare_cameras(const pt_scene *s, const pt_model *m, uint64_t v, int raw)
{
    pt_journey jc, jm;
    pt_scene cs = *s, ms = *s;
    pt_model *models = NULL;
    size_t r, mi = (size_t)(m - s->models);
    int rc = 0, stacked;
    int matrix = pt_scene_pipeline(s) == &pt_pipe_matrix;  /* these two, exactly */

    if (matrix) {                           /* the classic camera, perspective */
        cs.pipe = PT_PIPE_CLASSIC;
        cs.perspective = 1;
    }
    if (pt_run_journey(&jc, &cs, &cs.models[mi], v, raw) != 0) return PT_EXIT_INPUT;
    if (!matrix) {                          /* the equivalent matrix camera */
        models = malloc(s->nmodels * sizeof *models);
        if (!models) return PT_EXIT_INPUT;
        memcpy(models, s->models, s->nmodels * sizeof *models);
        for (r = 0; r < s->nmodels; r++) {  /* World = T(translate) * S(1, 1, -1) */
            pt_mat4 t = pt_mat4_translate(models[r].translate.x, models[r].translate.y,
                                          models[r].translate.z);
            pt_mat4 flip = pt_mat4_scale(1, 1, -1);
            models[r].world = pt_mat4_mul(&t, &flip);
            models[r].translate.x = models[r].translate.y = models[r].translate.z = 0;
        }
        ms.models = models;
        ms.pipe = PT_PIPE_MATRIX;
        ms.eye = (pt_vec3){0, 0, 0};
        ms.dir = (pt_vec3){0, 0, 1};
        ms.up = (pt_vec3){0, 1, 0};
        ms.fov = 90;
        ms.aspect = 1;
        ms.znear = 0.01;
        ms.zfar = 1e9;
    }
    if (pt_run_journey(&jm, &ms, &ms.models[mi], v, raw) != 0) { free(models); return PT_EXIT_INPUT; }

    fprintf(term.f, "pipetrace step --compare-cameras: vertex %llu of model %s in %s\n",
           (unsigned long long)v, m->name, s->path);
    if (!matrix) {
        fprintf(term.f, "classic camera: %s, at the origin, looking down -z (right-handed)\n",
               s->perspective ? "perspective" : "orthographic");
        para("matrix camera:  the same view as look-at matrices: eye (0, 0, 0), direction\n"
               "                (0, 0, 1), up (0, 1, 0), fov 90, aspect 1, near 0.01, far 1e9;\n"
               "                World = T(translate) * S(1, 1, -1) turns the right-handed\n"
               "                camera space into the left-handed view space\n");
        if (!s->perspective)
            para("note: the matrix camera is a perspective camera; the classic one here is\n"
                   "      orthographic, so their image points differ\n");
    } else {
        fprintf(term.f, "matrix camera:  this scene's look-at camera\n");
        para("classic camera: perspective at the origin looking down -z, with each model's\n"
               "                translation (world lines and the look-at have no classic form)\n");
    }
    /* side by side; on a terminal narrower than that, one camera under the other */
    stacked = term.width && term.width < 20 + 1 + 52 + 3 + 60;
    if (!stacked) fprintf(term.f, "\n%-20s %-52s | %s\n", "", "classic camera", "matrix camera");
    for (r = 0; r < sizeof cmp_rows / sizeof cmp_rows[0]; r++) {
        char left[2][PT_EXPLAINLEN + 16], right[3][PT_EXPLAINLEN + 16];
        int nl = side_lines(&jc, cmp_rows[r].classic, 2, left);
        int nr = side_lines(&jm, cmp_rows[r].matrix, 3, right), i;

        if (stacked) {
            fprintf(term.f, "\n%s\n", cmp_rows[r].what);
            for (i = 0; i < nl; i++) fprintf(term.f, "  classic  %s\n", left[i]);
            for (i = 0; i < nr; i++) fprintf(term.f, "  matrix   %s\n", right[i]);
            continue;
        }
        for (i = 0; i < nl || i < nr; i++)
            fprintf(term.f, "%-20s %-52s | %s\n", i ? "" : cmp_rows[r].what, i < nl ? left[i] : "",
                   i < nr ? right[i] : "");
    }
    if (in_journey(&jm, PT_STAGE_NDC) && s->perspective) {
        const pt_vrec *ip = &jc.rec[PT_STAGE_IMAGE], *n = &jm.rec[PT_STAGE_NDC];
        int same = memcmp(&ip->x, &n->x, sizeof ip->x) == 0 && memcmp(&ip->y, &n->y, sizeof ip->y) == 0;
        fprintf(term.f, "\n(x_ip, y_ip) and (x_n, y_n) are %s\n", same
               ? "equal, bit for bit: both cameras put the vertex at the same point of the view rectangle"
               : "different: the two cameras do not look at the same view");
    } else if (!in_journey(&jm, PT_STAGE_NDC)) {
        fprintf(term.f, "\nthe matrix camera stops at the cvv: the vertex is outside its view volume\n");
    }
    if (in_journey(&jm, PT_STAGE_VIEWPORT) && !(jc.rec[PT_STAGE_VIEWPORT].flags & PT_REC_NULL)) {
        const pt_vrec *a = &jc.rec[PT_STAGE_VIEWPORT], *b = &jm.rec[PT_STAGE_VIEWPORT];
        const char *x_pp = pt_stage_infos[PT_STAGE_PIXEL].formula;  /* "x_pp = ..., y_pp" */
        if (a->ix != b->ix || a->iy != b->iy)
            para("the pixels differ: the classic camera rounds %.*s\n"
                   "to the nearest logical pixel; the matrix camera floors x_s = (x_n + 1) * w/2\n",
                   (int)strcspn(x_pp, ","), x_pp);
        else
            fprintf(term.f, "both cameras pick the same pixel\n");
    }
    free(models);
    return rc;
}

/* ===== renderers 7 and 9 ===== */

/* Stage i of a course renderer's journey: name, spaces, what, formula, numbers. */
static void show_course(const void *jv, int i)
{
    const pt_cx_journey *j = jv;
    const pt_cx_row *in = pt_cx_row_of(j->steps[i]);
    static char b[16384];

    const char *from = in->from;

    if (j->steps[i] == PT_CXS_VIEW) from = j->renderer == 9 ? "world" : "model";
    fprintf(term.f, "stage %d of %d: %s (%s -> %s)\n", i + 1, j->nsteps, in->name, from, in->to);
    fprintf(term.f, "  what     %s\n", in->what);
    fprintf(term.f, "  formula  %s\n", pt_cx_formula(j->renderer, j->steps[i]));
    pt_cx_stage(b, sizeof b, j, j->steps[i], "\n           ");
    fprintf(term.f, "  here     %s\n", b);
}

/* step on a scene of the course's renderer 7 or 9: the vertex is found in
** one render (pt_cx_run); a vertex past the model's own is one a clip made. */
static int course_step(const pt_scene *s, const char *model, uint64_t v, int all, int inter)
{
    static pt_cx_journey j;
    size_t mi = 0, k;
    int rc = 1;
    char cam[PT_CAMERA_TITLE];

    if (model) {
        const pt_model *m = pt_cli_model(s, "step", model);
        if (!m) return PT_EXIT_INPUT;
        mi = (size_t)(m - s->models);
        rc = pt_cx_run(&j, s, mi, v);
    } else if ((rc = pt_cx_find(s, v, &mi)) == 0) {
        rc = pt_cx_run(&j, s, mi, v);
    }
    if (rc < 0) {
        fprintf(stderr, "pipetrace step: %s: out of memory\n", s->path);
        return PT_EXIT_INPUT;
    }
    if (rc == 1) {
        if (model)
            fprintf(stderr, "pipetrace step: --vertex %llu: the position of model %s of %s has "
                    "no vertex %llu (it has %zu after the clips%s)\n", (unsigned long long)v,
                    model, s->path, (unsigned long long)v, j.nv_last,
                    s->models[mi].hidden_model || s->models[mi].hidden_position
                    ? "; it is hidden" : "");
        else
            fprintf(stderr, "pipetrace step: --vertex %llu: no position of %s has a vertex "
                    "%llu, not even after the clips\n", (unsigned long long)v, s->path,
                    (unsigned long long)v);
        return PT_EXIT_INPUT;
    }
    pt_cli_out_open(&term);
    fprintf(term.f, "pipetrace step: vertex %llu of model %s (position %s) in %s, renderer %d%s\n",
            (unsigned long long)v, s->models[mi].name,
            s->models[mi].position ? s->models[mi].position : s->models[mi].name, s->path,
            s->renderer, s->renderer == 9 && s->pipeline2 ? " (pipeline2)" : "");
    fprintf(term.f, "camera %s; viewport %d x %d at (x_ul, y_ul) = (%d, %d); framebuffer %d x %d;"
            " nearclip %s, antialias %s, gamma %s\n",
            pt_scene_camera_title(s, cam, sizeof cam), s->vp_w, s->vp_h, s->vp_x, s->vp_y,
            s->fb_w, s->fb_h, s->nearclip ? "on" : "off", s->antialias ? "on" : "off",
            s->gamma ? "on" : "off");
    if (v > j.nv)
        fprintf(term.f, "vertex %llu is not the scene's: the model has %zu, a clip stage made "
                "this one\n", (unsigned long long)v, j.nv);
    fputc('\n', term.f);
    if (inter || (!all && isatty(STDIN_FILENO) && isatty(STDOUT_FILENO)))
        interact(&j, j.nsteps, show_course);
    else
        for (k = 0; k < (size_t)j.nsteps; k++) {
            if (k) fputc('\n', term.f);
            show_course(&j, (int)k);
        }
    if (pt_cli_out_close(&term) != 0) {
        fputs("pipetrace step: cannot write to standard output\n", stderr);
        return PT_EXIT_INPUT;
    }
    return 0;
}

int pt_cmd_step(int argc, char **argv)
{
    const char *path = NULL, *model = NULL;
    uint64_t v = 1;
    int k, all = 0, inter = 0, raw = 0, compare = 0, rc;
    const pt_model *m = NULL;
    pt_journey j;
    pt_scene s;
    char note[512], cam[PT_CAMERA_TITLE];
    pt_cli_args ca = {"step", usage, 1, NULL, NULL, 1};

    for (k = 1; k < argc; k++) {
        const char *a = argv[k];
        int u;

        if (!strcmp(a, "--all")) all = 1;
        else if (!strcmp(a, "--interactive")) inter = 1;
        else if (!strcmp(a, "--raw-lookat")) raw = 1;
        else if (!strcmp(a, "--compare-cameras")) compare = 1;
        else if ((u = pt_cli_arg(&ca, argc, argv, &k)) >= 0) return u;  /* SCENE, --vertex, ... */
    }
    path = ca.path;
    model = ca.model;
    v = ca.vertex;
    if (all && inter) return pt_cli_usage("step", "--all and --interactive exclude each other");

    if (pt_cli_load(&s, path) != 0) return PT_EXIT_INPUT;
    if (s.renderer == 7 || s.renderer == 9) {
        if (compare || raw) {
            int r = s.renderer;
            pt_scene_free(&s);
            return pt_cli_usage("step", "renderer %d has no classic and matrix camera: no "
                                "--compare-cameras, --raw-lookat", r);
        }
        rc = course_step(&s, model, v, all, inter);
        pt_scene_free(&s);
        return rc;
    }
    m = pt_cli_vertex_model(&s, "step", model, v);
    if (!m) {
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }

    pt_cli_out_open(&term);
    if (compare) {
        rc = compare_cameras(&s, m, v, raw);
        pt_scene_free(&s);
        if (pt_cli_out_close(&term) != 0) {
            fputs("pipetrace step: cannot write to standard output\n", stderr);
            return PT_EXIT_INPUT;
        }
        return rc;
    }
    if (pt_run_journey(&j, &s, m, v, raw) != 0) {
        fputs("pipetrace step: out of memory\n", stderr);
        pt_cli_out_close(&term);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    fprintf(term.f, "pipetrace step: vertex %llu of model %s in %s\n", (unsigned long long)v, m->name, s.path);
    if (pt_cli_student_note(note, sizeof note)) fprintf(term.f, "%s\n", note);
    fprintf(term.f, "camera %s; viewport %d x %d at (x_ul, y_ul) = (%d, %d); framebuffer %d x %d\n\n",
           pt_scene_camera_title(&s, cam, sizeof cam), s.vp_w, s.vp_h, s.vp_x, s.vp_y, s.fb_w, s.fb_h);
    if (!pt_vertex_used(m, v))
        para("note: no segment uses vertex %llu, so the renderer does not transform it;\n"
               "      here is the journey it would take.\n\n", (unsigned long long)v);
    if (inter || (!all && isatty(STDIN_FILENO) && isatty(STDOUT_FILENO)))
        interact(&j, j.norder, show_r4);
    else
        for (k = 0; k < j.norder; k++) {
            if (k) fputc('\n', term.f);
            show_stage(&j, k);
        }
    if (j.norder < j.pipe->norder)
        fprintf(term.f, "\n(the journey ends at the cvv: the vertex is outside the view volume)\n");
    pt_scene_free(&s);
    if (pt_cli_out_close(&term) != 0) {
        fputs("pipetrace step: cannot write to standard output\n", stderr);
        return PT_EXIT_INPUT;
    }
    return 0;
}
