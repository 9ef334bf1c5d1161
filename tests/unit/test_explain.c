/*
** tests/unit/test_explain.c -- journeys and the formulas with their numbers put in
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "io/explain.h"
#include "io/explain_course.h"
#include "stages/rv_nearclip.h"
#include "io/numfmt.h"

/* The triangle of docs/examples/triangle.scene: 20 x 10, translate 0 0 -2. */
static const char tri[] = "framebuffer 20 10\nmodel t\ntranslate 0 0 -2\n";

static char b[PT_EXPLAINLEN];

/* The journey pt_run() hands over for a scene of head and the one vertex v_m
** (no segment uses it: pt_run_journey() runs it all the same). */
static void journey_at(pt_journey *j, const char *head, pt_vec3 v_m)
{
    char text[512], err[PT_ERRLEN];
    pt_scene s;

    memset(j, 0, sizeof *j);
    snprintf(text, sizeof text, "%sv %.17g %.17g %.17g\n", head, v_m.x, v_m.y, v_m.z);
    if (pt_scene_parse(&s, "test", text, strlen(text), err, sizeof err) != 0) {
        PT_CHECK(err, 0);
        return;
    }
    PT_CHECK("ex-0.1 pt_run_journey", pt_run_journey(j, &s, &s.models[0], 1, 0) == 0 &&
             j->norder == PT_CLASSIC_NORDER && j->pipe == &pt_pipe_classic);
    pt_scene_free(&s);
}

static const char *stage_text(const pt_journey *j, pt_stage st)
{
    pt_explain_stage(b, sizeof b, j, st, " | ");
    return b;
}

static const char *next_text(const pt_journey *j, pt_stage st)
{
    pt_explain_next(b, sizeof b, j, st);
    return b;
}

static void test_triangle(void)
{
    pt_journey j;

    journey_at(&j, tri, (pt_vec3){-1, -1, 0});
    PT_CHECK("ex-1.1 model", !strcmp(stage_text(&j, PT_STAGE_MODEL), "x_m = -1 | y_m = -1 | z_m = 0"));
    PT_CHECK("ex-1.2 camera: negative addend in parentheses",
             !strcmp(stage_text(&j, PT_STAGE_CAMERA),
                     "x_c = x_m + x_t = -1 + 0 = -1 | y_c = y_m + y_t = -1 + 0 = -1 | "
                     "z_c = z_m + z_t = 0 + (-2) = -2"));
    PT_CHECK("ex-1.3 image: -z_c spelled -(-2)",
             !strcmp(stage_text(&j, PT_STAGE_IMAGE),
                     "x_ip = x_c / -z_c = -1 / -(-2) = -0.5 | y_ip = y_c / -z_c = -1 / -(-2) = -0.5 | "
                     "z_ip = -1 (the image plane)"));
    PT_CHECK("ex-1.4 pixel: shortest round-trip numbers",
             !strcmp(stage_text(&j, PT_STAGE_PIXEL),
                     "x_pp = 0.5 + w/2.001 * (x_ip + 1) = 0.5 + 20/2.001 * (-0.5 + 1) = 5.497501249375313 | "
                     "y_pp = 0.5 + h/2.001 * (y_ip + 1) = 0.5 + 10/2.001 * (-0.5 + 1) = 2.9987506246876565"));
    PT_CHECK("ex-1.5 viewport",
             !strcmp(stage_text(&j, PT_STAGE_VIEWPORT),
                     "x_vp = round(x_pp) - 1 = round(5.497501249375313) - 1 = 5 - 1 = 4 | "
                     "y_vp = h - round(y_pp) = 10 - round(2.9987506246876565) = 10 - 3 = 7"));
    PT_CHECK("ex-1.6 framebuffer",
             !strcmp(stage_text(&j, PT_STAGE_FRAMEBUFFER),
                     "x_fb = x_ul + x_vp = 0 + 4 = 4 | y_fb = y_ul + y_vp = 0 + 7 = 7"));
    PT_CHECK("ex-1.7 index", !strcmp(stage_text(&j, PT_STAGE_INDEX),
                                     "idx = y_fb * W + x_fb = 7 * 20 + 4 = 144"));
    pt_explain_values(b, sizeof b, &j, PT_STAGE_PIXEL);
    PT_CHECK("ex-1.8 values", !strcmp(b, "(x_pp, y_pp) = (5.497501249375313, 2.9987506246876565)"));
    pt_explain_values(b, sizeof b, &j, PT_STAGE_INDEX);
    PT_CHECK("ex-1.9 index value", !strcmp(b, "idx = 144"));
    pt_explain_tuple(b, sizeof b, &j, PT_STAGE_CAMERA);
    PT_CHECK("ex-1.9.1 the numbers alone, as why's journeys show them", !strcmp(b, "(-1, -1, -2)"));
    pt_explain_tuple(b, sizeof b, &j, PT_STAGE_INDEX);
    PT_CHECK("ex-1.9.2 ... an index", !strcmp(b, "144"));
    PT_CHECK("ex-1.10 next after viewport: inside",
             !strncmp(next_text(&j, PT_STAGE_VIEWPORT), "inside the viewport", 19));
    PT_CHECK("ex-1.11 next after camera: in front",
             !strncmp(next_text(&j, PT_STAGE_CAMERA), "in front of the camera (z_c < 0)", 32));
}

static void test_outside(void)
{
    /* docs/examples/clip.scene, vertex 1: orthographic, 8 x 4 at (2, 2) in 12 x 8 */
    static const char clip[] = "framebuffer 12 8\nviewport 2 2 8 4\ncamera orthographic\n"
                               "model m\n";
    pt_journey j;

    journey_at(&j, clip, (pt_vec3){-2, 0, 0});
    PT_CHECK("ex-2.1 orthographic image",
             !strcmp(stage_text(&j, PT_STAGE_IMAGE),
                     "x_ip = x_c = -2 | y_ip = y_c = 0 | z_ip = 0 (orthographic)"));
    PT_CHECK("ex-2.2 framebuffer: negative x_vp in parentheses",
             !strncmp(stage_text(&j, PT_STAGE_FRAMEBUFFER), "x_fb = x_ul + x_vp = 2 + (-4) = -2", 34));
    PT_CHECK("ex-2.3 index outside the framebuffer",
             !strcmp(stage_text(&j, PT_STAGE_INDEX), "idx = y_fb * W + x_fb: none, (x_fb, y_fb) = "
                     "(-2, 4) lies outside the 12 x 8 framebuffer"));
    PT_CHECK("ex-2.4 next after viewport: clipped",
             !strncmp(next_text(&j, PT_STAGE_VIEWPORT), "outside the viewport: its pixel is clipped", 42));
    PT_CHECK("ex-2.5 next after index: no index",
             !strncmp(next_text(&j, PT_STAGE_INDEX), "outside the framebuffer: no index", 33));
    PT_CHECK("ex-2.6 next after image: outside the view rectangle",
             strstr(next_text(&j, PT_STAGE_IMAGE), "outside the view rectangle") != NULL);
    pt_explain_values(b, sizeof b, &j, PT_STAGE_INDEX);
    PT_CHECK("ex-2.7 index value none", !strcmp(b, "idx = none"));
}

static void test_odd(void)
{
    pt_journey j;
    size_t n;

    journey_at(&j, tri, (pt_vec3){1, 2, 4});          /* z_c = 2 > 0 */
    PT_CHECK("ex-3.1 behind: flagged and explained",
             !strncmp(next_text(&j, PT_STAGE_IMAGE), "behind the camera (z_c > 0): projected mirrored", 47));
    journey_at(&j, tri, (pt_vec3){1, 1, 2});          /* z_c = 0 */
    PT_CHECK("ex-3.2 z_c = 0: division by zero", strstr(next_text(&j, PT_STAGE_CAMERA), "divides by zero") != NULL);
    PT_CHECK("ex-3.3 ... so no integer pixel",
             strstr(stage_text(&j, PT_STAGE_VIEWPORT), ") - 1: none, it is not finite") != NULL);
    PT_CHECK("ex-3.4 ... and no framebuffer pixel",
             strstr(stage_text(&j, PT_STAGE_FRAMEBUFFER), "x_fb = x_ul + x_vp: none") != NULL);
    journey_at(&j, tri, (pt_vec3){1e300, 0, 0});       /* x_pp ~ 1e301 */
    PT_CHECK("ex-3.5 beyond 2^62", strstr(stage_text(&j, PT_STAGE_VIEWPORT), "beyond 2^62") != NULL);
    /* 2024 audit: this named x_pp, which has a value; x_vp is the one without */
    PT_CHECK("ex-3.6 ... y still computed but unused, and x_vp named as the one without",
             strstr(b, " = 10 - 5 = 5, but the viewport pixel has no value: x_vp has none "
                       "(x_pp is beyond 2^62)") != NULL);
    journey_at(&j, tri, (pt_vec3){0, 1e300, 0});       /* y_pp ~ 1e300 */
    PT_CHECK("ex-3.7 ... and the other way round: y_vp named",
             strstr(stage_text(&j, PT_STAGE_VIEWPORT), " = 10 - 1 = 9, but the viewport pixel "
                    "has no value: y_vp has none (y_pp is beyond 2^62)") != NULL);
    journey_at(&j, tri, (pt_vec3){1e308, 0, 0});       /* x_pp overflows */
    PT_CHECK("ex-3.8 ... x_pp not finite: said so",
             strstr(stage_text(&j, PT_STAGE_VIEWPORT), "but the viewport pixel has no value: "
                    "x_vp has none (x_pp is not finite)") != NULL);

    journey_at(&j, tri, (pt_vec3){-1, -1, 0});
    n = pt_explain_stage(b, 10, &j, PT_STAGE_PIXEL, "; ");
    PT_CHECK("ex-4.1 cut short: full length returned, NUL-terminated",
             n > 100 && strlen(b) == 9 && !strncmp(b, "x_pp = 0.", 9));
    PT_CHECK("ex-4.2 a stage past the last one: empty",
             pt_explain_stage(b, sizeof b, &j, PT_NSTAGES_ALL, "; ") == 0 && b[0] == '\0');
    PT_CHECK("ex-4.3 coordinate names", !strcmp(pt_coord_name(PT_STAGE_IMAGE, 2), "z_ip") &&
             pt_coord_count(PT_STAGE_INDEX) == 1 && !strcmp(pt_coord_name(PT_STAGE_INDEX, 1), ""));
}

/* ===== the journey handed over is the records ===== */

/* One record as the listener got it, with the point it belongs to. */
typedef struct logged {
    pt_vrec r;
    uint64_t point;              /* which point (counted from 1, vertex or clip) */
} logged;

/* What a run told the listener. */
typedef struct runlog {
    logged *recs;                /* every record, in order */
    size_t n, cap;
    uint64_t point;              /* points begun so far */
    int want_journey;            /* 1: the listener asks for journeys */
    pt_journey j;                /* the current point's journey, */
    uint64_t j_point;            /*   for this point (0: none yet) */
    int clip;                    /* 1: the current point was made by clipping */
    int j_clip;                  /* ... and the journey's point */
    uint64_t journeys;           /* journeys handed over */
    uint64_t bad;                /* records not matching their point's journey */
    uint64_t short_j;            /* journeys whose order holds stages with no
                                 ** record, or whose records did not all come */
    int lost;                    /* out of memory */
} runlog;

static void log_begin(void *ud, const pt_model *m, uint64_t v)
{
    runlog *g = ud;
    (void)m; (void)v;
    g->point++;
    g->clip = 0;
}

static void log_clip(void *ud, const pt_model *m, uint64_t seg, uint64_t from, uint64_t to,
                     double t, pt_vec4 q)
{
    runlog *g = ud;
    (void)m; (void)seg; (void)from; (void)to; (void)t; (void)q;
    g->point++;
    g->clip = 1;
}

/* The journey's stages all came as records (all stages traced; a point made
** by clipping starts at the clip stage and reports from ndc on): the last
** point's check, made when the next journey comes and at the end. */
static void check_done(runlog *g)
{
    int c = 0;
    size_t k;

    if (!g->j_point) return;
    for (k = g->n; k > 0 && g->recs[k - 1].point == g->j_point; k--) c++;
    if (c + (g->j_clip ? 5 : 0) != g->j.norder) g->short_j++;
}

static void log_journey(void *ud, const pt_model *m, uint64_t v, const pt_journey *j)
{
    runlog *g = ud;
    int i;
    (void)m;

    check_done(g);                          /* the previous point: complete? */
    g->journeys++;
    g->j = *j;
    g->j_point = g->point;
    g->j_clip = g->clip;
    if ((v == 0) != g->clip) g->short_j++;
    for (i = g->clip ? 3 : 0; i < j->norder; i++)  /* every stage of its order filed */
        if (j->rec[j->order[i]].stage != j->order[i]) g->short_j++;
}

static void log_rec(void *ud, const pt_vrec *r)
{
    runlog *g = ud;

    if (g->n == g->cap) {
        size_t cap = g->cap ? 2 * g->cap : 256;
        logged *nr = realloc(g->recs, cap * sizeof *nr);
        if (!nr) { g->lost = 1; return; }
        g->recs = nr;
        g->cap = cap;
    }
    g->recs[g->n].r = *r;
    g->recs[g->n].point = g->point;
    g->n++;
    if (g->want_journey && (g->j_point != g->point || !pt_journey_matches(&g->j, r))) g->bad++;
}

/* 1 when a and b are the same record, bit for bit. */
static int same(const pt_vrec *r1, const pt_vrec *r2)
{
    pt_journey j;

    memset(&j, 0, sizeof j);
    if ((int)r1->stage >= PT_NSTAGES_ALL) return 0;
    j.rec[r1->stage] = *r1;
    return pt_journey_matches(&j, r2);
}

/* Run scene s with options o (raster traced), the listener asking for
** journeys or not, into *g. */
static int run_logged(const pt_scene *s, const pt_options *o, int journeys, runlog *g)
{
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    int rc;

    memset(g, 0, sizeof *g);
    memset(&l, 0, sizeof l);
    g->want_journey = journeys;
    l.vertex_begin = log_begin;
    l.clipvertex_begin = log_clip;
    l.sink.vertex = log_rec;
    l.sink.ud = g;
    if (journeys) l.journey = log_journey;
    l.ud = g;
    if (pt_plan_make(&p, s, o) != 0) return -1;
    rc = pt_run(s, &p, o, &l, NULL, &sum);
    pt_plan_free(&p);
    return rc != 0 || g->lost ? -1 : 0;
}

/* For each scene, with every stage traced: a run asking for journeys gets the
** same records as one that does not, each record is its point's journey's
** (handed over before it), and every stage of a journey came as a record. */
static void test_handed_over(void)
{
    static const char *const scenes[] = {
        "docs/examples/triangle.scene", "docs/examples/clip.scene",
        "docs/examples/behind.scene", "docs/examples/two-models.scene",
        "docs/examples/cube.scene", "docs/examples/ortho.scene",
        "docs/examples/lookat-cube.scene", "docs/examples/lookat-near.scene",
        "docs/examples/lookat-world.scene",
    };
    size_t k, i;
    uint64_t clipped = 0;

    for (k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        pt_scene s;
        pt_options o;
        runlog plain, with;
        char err[PT_ERRLEN], d[256];
        int ok = pt_scene_load(&s, scenes[k], err, sizeof err) == 0, same_recs;

        PT_CHECK(scenes[k], ok);
        if (!ok) continue;
        pt_options_default(&o);
        o.all_stages = 1;
        ok = run_logged(&s, &o, 0, &plain) == 0 && run_logged(&s, &o, 1, &with) == 0;
        if (ok) check_done(&with);
        same_recs = ok && plain.n == with.n && plain.n > 0;
        for (i = 0; same_recs && i < plain.n; i++)
            same_recs = same(&plain.recs[i].r, &with.recs[i].r) &&
                        plain.recs[i].point == with.recs[i].point;
        snprintf(d, sizeof d, "ex-6.1 %s: the same records with journeys asked for", scenes[k]);
        PT_CHECK(d, same_recs);
        snprintf(d, sizeof d, "ex-6.2 %s: one journey a point, before its records, "
                 "each record its journey's", scenes[k]);
        PT_CHECK(d, ok && with.journeys == with.point && with.bad == 0);
        snprintf(d, sizeof d, "ex-6.3 %s: every stage of a journey came as a record", scenes[k]);
        PT_CHECK(d, ok && with.short_j == 0);
        for (i = 0; ok && i < with.n; i++) clipped += with.recs[i].r.stage == PT_STAGE_NDC &&
                                                      i > 0 && with.recs[i - 1].point != with.recs[i].point;
        free(plain.recs);
        free(with.recs);
        pt_scene_free(&s);
    }
    PT_CHECK("ex-6.4 some points made by clipping were checked", clipped > 0);
}

/* A stage the trace leaves out is in the journey all the same. */
static void test_left_out(void)
{
    pt_scene s;
    pt_options o;
    runlog g;
    char err[PT_ERRLEN];
    size_t i;
    int fb_recs = 0, ok = pt_scene_load(&s, "docs/examples/triangle.scene", err, sizeof err) == 0;

    PT_CHECK("ex-7.0 triangle loads", ok);
    if (!ok) return;
    pt_options_default(&o);                 /* framebuffer: identity, left out */
    ok = run_logged(&s, &o, 1, &g) == 0;
    for (i = 0; ok && i < g.n; i++) fb_recs += g.recs[i].r.stage == PT_STAGE_FRAMEBUFFER;
    PT_CHECK("ex-7.1 no framebuffer record reaches the listener", ok && g.n > 0 && fb_recs == 0);
    PT_CHECK("ex-7.2 ... but the journey holds it, with the index's inputs",
             ok && g.j.rec[PT_STAGE_FRAMEBUFFER].stage == PT_STAGE_FRAMEBUFFER &&
             g.j.rec[PT_STAGE_FRAMEBUFFER].ix == g.j.rec[PT_STAGE_VIEWPORT].ix &&
             g.j.rec[PT_STAGE_INDEX].i == g.j.rec[PT_STAGE_FRAMEBUFFER].iy * 20 +
                                          g.j.rec[PT_STAGE_FRAMEBUFFER].ix);
    PT_CHECK("ex-7.3 ... and the records that came are its", ok && g.bad == 0);
    free(g.recs);
    pt_scene_free(&s);
}

/* The matrix camera's journey: its stages, its formulas, where it stops. */
static void test_matrix(void)
{
    pt_scene s;
    pt_journey j;
    char err[PT_ERRLEN];
    int ok = pt_scene_load(&s, "docs/examples/lookat-near.scene", err, sizeof err) == 0;

    PT_CHECK("ex-5.0 lookat-near loads", ok);
    if (!ok) return;
    PT_CHECK("ex-5.1 vertex 1 (inside) goes through all 10 stages",
             pt_run_journey(&j, &s, &s.models[0], 1, 0) == 0 && j.pipe == &pt_pipe_matrix && j.norder == 10);
    pt_explain_stage(b, sizeof b, &j, PT_STAGE_NDC, "; ");
    PT_CHECK("ex-5.2 ndc: the divide with its numbers",
             !strcmp(b, "x_n = x_k / w_k = 0.375 / 4 = 0.09375; y_n = y_k / w_k = 0.25 / 4 = 0.0625; "
                        "z_n = z_k / w_k = 3.0303030303030303 / 4 = 0.7575757575757576"));
    pt_explain_stage(b, sizeof b, &j, PT_STAGE_SCREEN, "; ");
    PT_CHECK("ex-5.3 screen: (x_n + 1) * w * 0.5",
             !strncmp(b, "x_s = (x_n + 1) * w * 0.5 = (0.09375 + 1) * 40 * 0.5 = 21.875; "
                         "y_s = (1 - y_n) * h * 0.5 = (1 - 0.0625) * 30 * 0.5 = 14.0625", 120));
    pt_explain_stage(b, sizeof b, &j, PT_STAGE_VIEWPORT, "; ");
    PT_CHECK("ex-5.4 viewport floors under the matrix camera",
             !strcmp(b, "x_vp = floor(x_s) = floor(21.875) = 21; y_vp = floor(y_s) = floor(14.0625) = 14"));
    PT_CHECK("ex-5.5 the matrix viewport formula", !strcmp(pt_journey_info(&j, PT_STAGE_VIEWPORT)->formula,
             "x_vp = floor(x_s), y_vp = floor(y_s)"));
    PT_CHECK("ex-5.6 vertex 2 (behind the eye) stops at the cvv",
             pt_run_journey(&j, &s, &s.models[0], 2, 0) == 0 && j.norder == 5 &&
             j.order[4] == PT_STAGE_CVV);
    pt_explain_stage(b, sizeof b, &j, PT_STAGE_CVV, "; ");
    PT_CHECK("ex-5.7 cvv names the planes", !strcmp(b, "code = 61: outside near, left, right, bottom, top (w_k = -4)"));
    pt_explain_stage(b, sizeof b, &j, PT_STAGE_CLIP, "; ");
    PT_CHECK("ex-5.8 clip: a row vector times Projection, term by term",
             !strncmp(b, "x_k = column 0 of Projection: 0.5*0.75 + 0.25*0 + (-4)*0 + 1*0 = 0.375", 70));
    pt_scene_free(&s);
}

/* What the Java renderer's (int)Math.round holds, for step's notes. */
static void test_java(void)
{
    /* (int)Math.round(x) as Java 17 prints it: the long saturates, the cast keeps 32 bits */
    PT_CHECK("explain-9.1 Java's (int)Math.round: 1e300 -> -1, +inf -> -1",
             pt_explain_java_int_round(1e300) == -1 && pt_explain_java_int_round((double)INFINITY) == -1);
    PT_CHECK("explain-9.2 ... -1e300 -> 0, -inf -> 0, NaN -> 0",
             pt_explain_java_int_round(-1e300) == 0 && pt_explain_java_int_round(-(double)INFINITY) == 0
             && pt_explain_java_int_round((double)NAN) == 0);
    PT_CHECK("explain-9.3 ... 3e9 -> 3e9 - 2^32 = -1294967296, 2^31 -> -2^31",
             pt_explain_java_int_round(3e9) == -1294967296 && pt_explain_java_int_round(2147483648.0) == INT32_MIN);
    PT_CHECK("explain-9.4 ... 2^63 - 1024 -> -1024, -2^63 -> 0, in range as Math.round",
             pt_explain_java_int_round(9223372036854774784.0) == -1024
             && pt_explain_java_int_round(-9223372036854775808.0) == 0
             && pt_explain_java_int_round(-2.5) == -2 && pt_explain_java_int_round(0.49999999999999994) == 0);
}

/* explain writes each classic formula out again with the numbers put in; its
** symbolic part ("x_pp = 0.5 + w/2.001 * (x_ip + 1)", before the numbers) must
** be the formula of the stage table (stages/pt_stage.c), value by value, in
** perspective and orthographic scenes. */
static void test_formulas_are_the_table(void)
{
    static const char *const heads[2] = {
        "framebuffer 20 10\nviewport 1 2 16 7\nmodel m\ntranslate 0.25 -0.5 -2\n",
        "framebuffer 20 10\ncamera orthographic\nmodel m\ntranslate 0.25 -0.5 -2\n",
    };
    int h, i, st, k, bad = 0, n = 0;

    for (h = 0; h < 2; h++) {
        pt_journey j;
        journey_at(&j, heads[h], (pt_vec3){0.5, 0.25, -1});
        for (i = 1; i < PT_CLASSIC_NORDER; i++) {
            char *part = b, *sep;
            st = pt_classic_order[i];
            pt_explain_stage(b, sizeof b, &j, (pt_stage)st, "|");
            for (k = 0; k < pt_stage_nvalues((pt_stage)st); k++) {
                char sym[PT_EXPLAINLEN], *eq, *paren;
                sep = strchr(part, '|');
                if (sep) *sep = '\0';
                /* the symbols end where the first number does: at the second
                ** " = ", or a parenthesis after a constant ("z_ip = -1 (...)") */
                snprintf(sym, sizeof sym, "%s", part);
                eq = strstr(sym, " = ");
                if (eq && (eq = strstr(eq + 3, " = ")) != NULL) *eq = '\0';
                else if ((paren = strstr(sym, " (")) != NULL) *paren = '\0';
                if (!strstr(pt_stage_infos[st].formula, sym)) {
                    bad++;
                    printf("  %s: '%s' is not in the table's '%s'\n",
                           pt_stage_infos[st].name, sym, pt_stage_infos[st].formula);
                }
                n++;
                if (!sep) break;
                part = sep + 1;
            }
        }
    }
    PT_CHECK("ex-9.1 explain's formulas are the stage table's, value by value", bad == 0 && n >= 20);
}

/* A student's stage (make STAGE_x=FILE.c) reports other numbers than the
** formula: the text states the reference's result, true arithmetic with the
** numbers put in, and says what the stage gave after it.  Before 2024's
** reference build, --explain printed "y_vp = ... = 10 - 3 = 7" under a
** record saying y_vp = 2 (tests/teach/student.sh s4_noflip), and step ended the
** pixel stage's equation with the student's x_pp = 5.5. */
static void test_student_records(void)
{
    pt_journey j, ref;
    unsigned differ = 0;
    int i;

    journey_at(&j, tri, (pt_vec3){-1, -1, 0});
    j.rec[PT_STAGE_VIEWPORT].iy = 2;        /* y_vp = round(y_pp) - 1: no flip */
    PT_CHECK("ex-7.1 viewport: the formula's result, then the stage's",
             !strcmp(stage_text(&j, PT_STAGE_VIEWPORT),
                     "x_vp = round(x_pp) - 1 = round(5.497501249375313) - 1 = 5 - 1 = 4 | "
                     "y_vp = h - round(y_pp) = 10 - round(2.9987506246876565) = 10 - 3 = 7 | "
                     "your stage gave y_vp = 2"));
    j.rec[PT_STAGE_FRAMEBUFFER].iy = 2;     /* handed on: framebuffer's input */
    PT_CHECK("ex-7.2 the next stage computes from the numbers it was handed",
             !strcmp(stage_text(&j, PT_STAGE_FRAMEBUFFER),
                     "x_fb = x_ul + x_vp = 0 + 4 = 4 | y_fb = y_ul + y_vp = 0 + 2 = 2"));
    journey_at(&j, tri, (pt_vec3){-1, -1, 0});
    j.rec[PT_STAGE_PIXEL].x = 5.5;          /* 2 for 2.001 */
    PT_CHECK("ex-7.3 pixel: the same, for a real value",
             !strcmp(stage_text(&j, PT_STAGE_PIXEL),
                     "x_pp = 0.5 + w/2.001 * (x_ip + 1) = 0.5 + 20/2.001 * (-0.5 + 1) = 5.497501249375313"
                     " | your stage gave x_pp = 5.5 | "
                     "y_pp = 0.5 + h/2.001 * (y_ip + 1) = 0.5 + 10/2.001 * (-0.5 + 1) = 2.9987506246876565"));
    j.rec[PT_STAGE_INDEX].flags = PT_REC_NULL;
    j.rec[PT_STAGE_INDEX].i = -1;
    PT_CHECK("ex-7.4 index: a value where the stage gave none",
             !strcmp(stage_text(&j, PT_STAGE_INDEX),
                     "idx = y_fb * W + x_fb = 7 * 20 + 4 = 144 | your stage gave idx = none"));
    pt_explain_reference(&ref, &j);
    PT_CHECK("ex-7.5 pt_explain_reference: the reference's values from the stage on",
             ref.rec[PT_STAGE_PIXEL].x == 5.497501249375313 && ref.rec[PT_STAGE_INDEX].i == 144 &&
             !(ref.rec[PT_STAGE_INDEX].flags & PT_REC_NULL) && ref.rec[PT_STAGE_VIEWPORT].ix == 4);
    journey_at(&j, tri, (pt_vec3){-1, -1, 0});
    pt_explain_reference(&ref, &j);
    for (i = 0; i < j.norder; i++) differ |= pt_ref_differ(j.order[i], &ref.rec[j.order[i]],
                                                           &j.rec[j.order[i]]);
    PT_CHECK("ex-7.6 ... and the run's, value for value, when no stage is a student's", differ == 0);
}

/* The viewport's text writes round(x_pp) and the formula's "- 1" and "h -"
** again; the result is the reference stage's.  Tied here: on ties, near
** ties and the 2^62 limit, "round(X) - 1 = R - 1 = V" has R = pt_pix_round(X)
** and V = R - 1 = ptref_pixel2viewport's x_vp, likewise y. */
static void test_viewport_text_is_the_stage(void)
{
    static const double xs[] = {-2.5, -1.5, -0.5, 0.49999999999999994, 0.5, 2.5, 3.5, -79.46,
                                1e6 + 0.5, -1e6 - 0.5};
    pt_journey j;
    size_t i;
    int bad = 0;

    journey_at(&j, tri, (pt_vec3){-1, -1, 0});
    for (i = 0; i < sizeof xs / sizeof xs[0]; i++) {
        pt_vec2 pp = {xs[i], -xs[i]};
        pt_pix vp = ptref_pixel2viewport(pp, j.par.w, j.par.h, NULL);
        int64_t rx, ry;
        char want[PT_EXPLAINLEN], nx[PT_NUMLEN], ny[PT_NUMLEN];

        j.rec[PT_STAGE_PIXEL].x = pp.x;
        j.rec[PT_STAGE_PIXEL].y = pp.y;
        j.rec[PT_STAGE_VIEWPORT].ix = vp.x;     /* as the run would have it */
        j.rec[PT_STAGE_VIEWPORT].iy = vp.y;
        pt_pix_round(pp.x, &rx);
        pt_pix_round(pp.y, &ry);
        pt_fmt_shortest(nx, pp.x);
        pt_fmt_shortest(ny, pp.y);
        snprintf(want, sizeof want, "x_vp = round(x_pp) - 1 = round(%s) - 1 = %lld - 1 = %lld | "
                 "y_vp = h - round(y_pp) = 10 - round(%s) = 10 - %s%lld%s = %lld", nx,
                 (long long)rx, (long long)(rx - 1), ny, ry < 0 ? "(" : "", (long long)ry,
                 ry < 0 ? ")" : "", (long long)(10 - ry));
        if (vp.x != rx - 1 || vp.y != 10 - ry || strcmp(stage_text(&j, PT_STAGE_VIEWPORT), want)) {
            bad++;
            printf("  x_pp = %s: %s\n  want %s\n", nx, b, want);
        }
    }
    PT_CHECK("ex-7.7 the viewport's text: true arithmetic, ending in the stage's values", bad == 0);
}

/* Every stage of every pipeline has its rows in explain.c: its formula
** (the pipeline's own viewport), what comes next, and after the first stage
** what the second does.  A new stage or pipeline fails here until it has them. */
static void test_every_stage_has_rows(void)
{
    int p, i, missing = 0;
    char d[96];

    for (p = 0; p < PT_NPIPES; p++)
        for (i = 0; i < pt_pipelines[p]->norder; i++) {
            pt_stage st = pt_pipelines[p]->order[i];
            if (pt_explain_has_rows(pt_pipelines[p], st)) continue;
            snprintf(d, sizeof d, "ex-9.1 %s: explain has the %s stage's rows",
                     pt_pipelines[p]->name, pt_stage_infos[st].name);
            PT_CHECK(d, 0);
            missing++;
        }
    PT_CHECK("ex-9.2 every stage of every pipeline has explain's rows", missing == 0);
    /* the kind and flags columns agree with the counts, and both viewport
    ** rows hold the same values */
    for (p = 0; p < PT_NPIPES; p++)
        for (i = 0; i < pt_pipelines[p]->norder; i++) {
            const pt_stage_info *in = pt_pipeline_info(pt_pipelines[p], pt_pipelines[p]->order[i]);
            int ok = in->kind == PT_VAL_REAL ? in->nreal > 0 && in->flags == (in->flags & PT_REC_BEHIND)
                   : in->kind == PT_VAL_PIXEL ? in->nint == 2 && (in->flags & PT_REC_HAS_Y)
                   : in->kind == PT_VAL_INDEX ? in->nint == 1 && in->flags == PT_REC_NULL
                   : in->nint == 1 && in->flags == 0;
            snprintf(d, sizeof d, "ex-9.3 %s %s: kind and flags fit its values",
                     pt_pipelines[p]->name, in->name);
            PT_CHECK(d, ok);
        }
}

/* Renderers 7 and 9: every stage course.c drives, and the pixel stages
** after them, have explain_course.c's rows. */
static void test_course_rows(void)
{
    int r, i, missing = 0;
    char d[96];

    for (r = 7; r <= 9; r += 2)
        for (i = 0; i < PT_NCST + 3; i++) {
            pt_cx_step st = i < PT_NCST ? pt_cx_step_of((pt_course_stage)i)
                          : i == PT_NCST ? PT_CXS_PIXEL : i == PT_NCST + 1 ? PT_CXS_VIEWPORT
                          : PT_CXS_RASTER;
            if (r == 7 && i == PT_CST_WORLD) continue;
            if (pt_cx_has_rows(r, st)) continue;
            snprintf(d, sizeof d, "ex-9.4 renderer %d: explain has the %s stage's rows", r,
                     pt_cx_row_of(st)->name);
            PT_CHECK(d, 0);
            missing++;
        }
    PT_CHECK("ex-9.5 every stage of renderers 7 and 9 has explain's rows", missing == 0);
    PT_CHECK("ex-9.6 renderer 7 has no world stage", !pt_cx_has_rows(7, PT_CXS_WORLD));
}

/* Parse a course scene. */
static int course_scene(pt_scene *s, const char *text)
{
    char err[PT_ERRLEN];

    if (pt_scene_parse(s, "test", text, strlen(text), err, sizeof err) == 0) return 0;
    PT_CHECK(err, 0);
    return -1;
}

/* A renderer 7 segment from in front of the near plane to behind it and past
** the view rectangle's right edge: the journey's numbers are the stages'. */
static void test_course_journey(void)
{
    static const char text[] =
        "renderer 7\nframebuffer 40 30\ncamera perspective\nantialias off\ngamma off\n"
        "model m\ntranslate 0.25 0 -1\nv 0 0 -2\nv 3 0.5 2\nsegment 1 2\n";
    pt_scene s;
    pt_cx_journey j;
    pt_rv_model m;
    pt_vec4 c;
    pt_rv_camera cam;
    int rc;

    if (course_scene(&s, text) != 0) return;
    rc = pt_cx_run(&j, &s, 0, 1);
    PT_CHECK("ex-10.1 pt_cx_run: vertex 1, nine stages", rc == 0 && j.nsteps == 9 &&
             j.steps[0] == PT_CXS_MODEL && j.steps[8] == PT_CXS_RASTER);
    cam = j.cam.cam;
    PT_CHECK("ex-10.2 view: the stage's x_t + x_m",
             !strcmp((pt_cx_stage(b, sizeof b, &j, PT_CXS_VIEW, " | "), b),
                     "x_v = x_t + x_m = 0.25 + 0 = 0.25 | y_v = y_t + y_m = 0 + 0 = 0 | "
                     "z_v = z_t + z_m = -1 + (-2) = -3"));
    c = pt_r7_view2camera(j.at[PT_CST_VIEW], &cam);
    PT_CHECK("ex-10.3 camera: the run's record is the stage's",
             memcmp(&c, &j.at[PT_CST_CAMERA], sizeof c) == 0);
    {   /* the shift shown, then the scaling, is the stage */
        pt_vec4 mid = pt_r7_view2camera_shift(j.at[PT_CST_VIEW], &cam);
        double x = (2.0 * mid.x)/(cam.r - cam.l);
        PT_CHECK("ex-10.4 camera: shift then scale is pt_r7_view2camera", x == c.x);
    }
    pt_cx_stage(b, sizeof b, &j, PT_CXS_NEARCLIP, " | ");
    PT_CHECK("ex-10.5 nearclip of the kept end: the test and the cut that replaces the other",
             strstr(b, "z_c = -3 <= n = -0.1: on the visible side") == b);
    rc = pt_cx_run(&j, &s, 0, 3);
    PT_CHECK("ex-10.6 vertex 3 is the near clip's", rc == 0 && j.born == PT_CST_NEARCLIP &&
             j.nsteps == 6 && j.steps[0] == PT_CXS_NEARCLIP && j.cut_prim == 1);
    memset(&m, 0, sizeof m);
    {   /* the same cut, by the stage alone */
        pt_vec4 a = j.cut.p[0], e = j.cut.p[1];
        pt_rgb w = {1, 1, 1};
        pt_rv_prim p = {PT_RV_LINE, {0, 1}, {0, 1}, 0};
        rc = pt_rv_add_vertex(&m, a) | pt_rv_add_vertex(&m, e) | pt_rv_add_color(&m, w) |
             pt_rv_add_color(&m, w) | pt_rv_add_prim(&m, &p) | pt_rv_nearclip(&m, cam.n, NULL);
        PT_CHECK("ex-10.7 the journey's new vertex is the near clip stage's",
                 rc == 0 && m.nv == 3 && memcmp(&m.v[2], &j.at[PT_CST_NEARCLIP], sizeof m.v[2]) == 0);
        pt_rv_model_free(&m);
    }
    pt_cx_stage(b, sizeof b, &j, PT_CXS_NEARCLIP, " | ");
    PT_CHECK("ex-10.8 the cut's text: t and the new point", strstr(b, "made by the near clip of "
             "segment 1: z0 = -3, z1 = 1, n = -0.1: v1 lies beyond the near plane | t = (n - z1)/"
             "(z0 - z1) = (-0.1 - 1)/(-3 - 1) = ") == b);
    rc = pt_cx_run(&j, &s, 0, 4);
    PT_CHECK("ex-10.9 vertex 4 is the clip's, at x = +1", rc == 0 && j.born == PT_CST_CLIP &&
             j.cut.edge == PT_RV_XPOS && j.at[PT_CST_CLIP].x == 1 && j.nsteps == 4);
    pt_cx_stage(b, sizeof b, &j, PT_CXS_RASTER, " | ");
    PT_CHECK("ex-10.10 its pixel: the segment's end, raw colour, gamma off",
             strstr(b, "its last pixel, coverage 1") != NULL || strstr(b, "its first step") != NULL);
    PT_CHECK("ex-10.11 no vertex 5", pt_cx_run(&j, &s, 0, 5) == 1);
    pt_scene_free(&s);
}

int main(void)
{
    test_course_rows();
    test_course_journey();
    test_every_stage_has_rows();
    test_triangle();
    test_outside();
    test_odd();
    test_handed_over();
    test_left_out();
    test_matrix();
    test_java();
    test_formulas_are_the_table();
    test_student_records();
    test_viewport_text_is_the_stage();
    return pt_test_report();
}
