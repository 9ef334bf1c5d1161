/*
** tests/unit/test_shapes.c -- `shape NAME ARGS` against the course's own models
** See LICENSE for copyright and license.
**
** Run from the repository root.  Ids:
**   shapes-1  every case in tests/data/shapes/ (made by make.sh there with the
**             course's jar): the same vertices, bit for bit or within one ulp
**             where sin/cos differ, the same segments, or the same refusal
**   shapes-2  shape mixes with v and l lines: indices count every vertex
**   shapes-3  bad arguments: FILE:LINE:COL messages pointing at the culprit
**   shapes-4  the table: names, defaults and arities are consistent
** A summary line says how many coordinates matched exactly and how many were
** one ulp away (libm's sin/cos against Java's Math.sin/cos).
*/
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "testhelp.h"
#include "core/scene.h"
#include "core/shapes.h"

#define DIR "tests/data/shapes/"

static char err[PT_ERRLEN];
static long exact, one_ulp;

/* How many doubles lie between a and b (0: the same bits). */
static uint64_t ulps(double a, double b)
{
    int64_t ia, ib;

    memcpy(&ia, &a, sizeof ia);
    memcpy(&ib, &b, sizeof ib);
    if (ia < 0) ia = INT64_MIN - ia;          /* order the bit patterns */
    if (ib < 0) ib = INT64_MIN - ib;
    return ia > ib ? (uint64_t)ia - (uint64_t)ib : (uint64_t)ib - (uint64_t)ia;
}

/* One coordinate: exact or one ulp off; counts which. */
static int same(double got, double want)
{
    uint64_t d = ulps(got, want);

    if (d == 0) exact++;
    else if (d == 1) one_ulp++;
    return d <= 1;
}

/* Parse "model m\n" + body as t.scene. */
static int parse(pt_scene *s, const char *body)
{
    char text[4096];

    snprintf(text, sizeof text, "model m\n%s", body);
    err[0] = '\0';
    return pt_scene_parse(s, "t.scene", text, strlen(text), err, sizeof err);
}

/* ----------------------------------------------------------- shapes-1 */

/* Compare `shape ARGS` with the file name (format: tests/data/shapes/make.sh). */
static void against_java(const char *name)
{
    char path[300], line[512], args[256], body[300], id[800];
    size_t nv = 0, ns = 0, badv = 0, bads = 0;
    int refused = 0, r;
    pt_scene s;
    FILE *f;

    snprintf(path, sizeof path, DIR "%s", name);
    f = fopen(path, "r");
    PT_CHECK(path, f != NULL);
    if (f == NULL)
        return;
    if (fgets(line, sizeof line, f) == NULL || strncmp(line, "# shape ", 8) != 0) {
        PT_CHECK("shapes-1.0 the file starts with '# shape'", 0);
        fclose(f);
        return;
    }
    line[strcspn(line, "\n")] = '\0';
    snprintf(args, sizeof args, "%.200s", line + 8);
    snprintf(body, sizeof body, "shape %s\n", args);
    r = parse(&s, body);
    while (fgets(line, sizeof line, f) != NULL) {
        double x, y, z;
        unsigned a, b;

        line[strcspn(line, "\n")] = '\0';
        if (strncmp(line, "error ", 6) == 0) {
            refused = 1;
            snprintf(id, sizeof id, "shapes-1.2 %s refused: %.100s (got: %.200s)", args,
                     line + 6, r == 0 ? "accepted" : err);
            PT_CHECK(id, r < 0 && strstr(err, line + 6) != NULL
                     && strncmp(err, "t.scene:2:", 10) == 0);
        } else if (sscanf(line, "v %lf %lf %lf", &x, &y, &z) == 3) {
            if (r == 0 && nv < s.models[0].nv) {
                const pt_vec3 *v = &s.models[0].v[nv];
                int ok = same(v->x, x) & same(v->y, y) & same(v->z, z);

                if (!ok && badv++ == 0)
                    printf("    %s: vertex %zu is %.17g %.17g %.17g, Java %.17g %.17g %.17g\n",
                           args, nv, v->x, v->y, v->z, x, y, z);
            }
            nv++;
        } else if (sscanf(line, "l %u %u", &a, &b) == 2) {
            if (r == 0 && ns < s.models[0].nseg
                && (s.models[0].seg[ns].a != a || s.models[0].seg[ns].b != b) && bads++ == 0)
                printf("    %s: segment %zu is %u %u, Java %u %u\n", args, ns,
                       (unsigned)s.models[0].seg[ns].a, (unsigned)s.models[0].seg[ns].b, a, b);
            ns++;
        }
    }
    fclose(f);
    if (!refused) {
        snprintf(id, sizeof id, "shapes-1.1 shape %s: %zu vertices, %zu segments as in Java%s%.200s",
                 args, nv, ns, r == 0 ? "" : ": ", r == 0 ? "" : err);
        PT_CHECK(id, r == 0 && s.models[0].nv == nv && s.models[0].nseg == ns
                 && badv == 0 && bads == 0);
    }
    pt_scene_free(&s);
}

static void java_cases(void)
{
    char name[256];
    int cases[64] = { 0 }, i, thin = 0;
    FILE *idx = fopen(DIR "index", "r");

    PT_CHECK("shapes-1.0 " DIR "index is there", idx != NULL);
    if (idx == NULL)
        return;
    while (fgets(name, sizeof name, idx) != NULL) {
        name[strcspn(name, "\n")] = '\0';
        against_java(name);
        for (i = 0; i < pt_nshapes; i++)     /* NAME.expect or NAME_ARGS.expect */
            if (strncmp(name, pt_shapes[i].name, strlen(pt_shapes[i].name)) == 0
                && strchr("_.", name[strlen(pt_shapes[i].name)]) != NULL)
                cases[i]++;
    }
    fclose(idx);
    for (i = 0; i < pt_nshapes; i++)
        if (cases[i] < (pt_shapes[i].nparam > 0 ? 3 : 1)) {
            printf("    %s: %d cases\n", pt_shapes[i].name, cases[i]);
            thin++;
        }
    PT_CHECK("shapes-1.0 every shape has a case, those with parameters three or more",
             thin == 0);
}

/* ----------------------------------------------------------- shapes-2 */

static void mixes(void)
{
    pt_scene s;
    int r = parse(&s, "v 5 5 5\nv 6 6 6\nshape square 2\nl 1 3\nl -1 2\nshape axes3d\n");
    const pt_model *m = &s.models[0];

    PT_CHECK("shapes-2.1 v, shape, l and shape in one model parse", r == 0);
    if (r != 0) {
        printf("    %s\n", err);
        return;
    }
    PT_CHECK("shapes-2.2 2 + 4 + 6 vertices, 4 + 2 + 3 segments", m->nv == 12 && m->nseg == 9);
    PT_CHECK("shapes-2.3 the square's vertices follow the v lines",
             m->v[2].x == -2 && m->v[2].y == -2 && m->v[5].x == 2 && m->v[5].y == -2);
    PT_CHECK("shapes-2.4 the square's segments are offset by 2",
             m->seg[0].a == 2 && m->seg[0].b == 3 && m->seg[3].a == 5 && m->seg[3].b == 2);
    PT_CHECK("shapes-2.5 l 1 3 after the shape: vertex 3 is the square's first",
             m->seg[4].a == 0 && m->seg[4].b == 2);
    PT_CHECK("shapes-2.6 l -1 2: -1 is the square's last vertex",
             m->seg[5].a == 5 && m->seg[5].b == 1);
    PT_CHECK("shapes-2.7 the second shape's segments are offset by 6",
             m->seg[6].a == 6 && m->seg[6].b == 7 && m->seg[8].a == 10 && m->seg[8].b == 11);
    pt_scene_free(&s);
    r = parse(&s, "shape cube   # a comment\n");
    PT_CHECK("shapes-2.8 a comment after the arguments", r == 0 && s.models[0].nv == 8);
    pt_scene_free(&s);
}

/* ----------------------------------------------------------- shapes-3 */

static void bad(const char *id, const char *body, const char *where, const char *word)
{
    pt_scene s;
    int r = parse(&s, body);
    int ok = r < 0 && strncmp(err, where, strlen(where)) == 0 && strstr(err, word) != NULL;

    PT_CHECK(id, ok);
    if (!ok)
        printf("    got %d: %s\n    want: %s ... %s\n", r, err, where, word);
    pt_scene_free(&s);
}

/* Each case: the lines after "model m", where the message must begin and a
** word it must contain. */
static const struct bad_case {
    const char *id, *body, *where, *word;
} bad_cases[] = {
    { "shapes-3.1 no name",
      "shape\n", "t.scene:2:1: error: ", "expected a shape name" },
    { "shapes-3.2 unknown name",
      "shape blob 1\n", "t.scene:2:7: error: ", "unknown shape 'blob'" },
    { "shapes-3.3 names are lower case",
      "shape Sphere\n", "t.scene:2:7: ", "unknown shape" },
    { "shapes-3.4 an arity Java has no overload for",
      "shape sphere 1 2\n", "t.scene:2:1: error: ", "shape sphere takes 0, 1 or 3 arguments (r n k), found 2" },
    { "shapes-3.5 too many arguments point at the first extra",
      "shape circle 1 5 7 8\n", "t.scene:2:18: error: ", "takes 0, 1 or 2 arguments (r n), found 4" },
    { "shapes-3.6 arguments to a shape without parameters",
      "shape cube 1\n", "t.scene:2:12: error: ", "shape cube takes no arguments, found 1" },
    { "shapes-3.7 an int that is not one",
      "shape sphere 1 15.0 8\n", "t.scene:2:16: error: ", "n '15.0' is not an integer" },
    { "shapes-3.8 a real that is not one",
      "shape box 1 0x10 1\n", "t.scene:2:13: error: ", "ys '0x10' is not a decimal number" },
    { "shapes-3.9 inf is refused",
      "shape square inf\n", "t.scene:2:14: ", "is not a decimal" },
    { "shapes-3.10 1e999 is not finite",
      "shape square 1e999\n", "t.scene:2:14: ", "is not finite" },
    { "shapes-3.11 an int beyond Java's range",
      "shape circle 1 2147483648\n", "t.scene:2:16: ", "out of range" },
    { "shapes-3.12 Java's refusal, at its argument",
      "shape torus 1 0.5 2 3\n", "t.scene:2:19: error: ", "shape torus: n must be greater than 2, found 2" },
    { "shapes-3.13 Java checks n before k",
      "shape disk 1 0 0\n", "t.scene:2:14: ", "n must be greater than 0" },
    { "shapes-3.14 squaregrid checks r last",
      "shape squaregrid -1 0 -1\n", "t.scene:2:23: ", "k must be greater than or equal to 0" },
    { "shapes-3.15 too many vertices for one shape",
      "shape sphere 1 100000 100000\n", "t.scene:2:1: ", "would make 10000000002 vertices" },
    { "shapes-3.16 coordinates that overflow",
      "shape torus 1e308 1e308 3 3\n", "t.scene:2:1: ", "is not finite" },
    { "shapes-3.17 a cone of height 0 divides 0 by 0",
      "shape cone 1 0 2 4\n", "t.scene:2:1: ", "shape cone: vertex 1 is not finite" },
    { "shapes-3.19 the line's second error is not reached",
      "shape circle 1 2 x\n", "t.scene:2:18: ", "found 3" },
};

static void refusals(void)
{
    pt_scene s;
    size_t i;

    for (i = 0; i < sizeof bad_cases / sizeof bad_cases[0]; i++)
        bad(bad_cases[i].id, bad_cases[i].body, bad_cases[i].where, bad_cases[i].word);
    err[0] = '\0';
    PT_CHECK("shapes-3.18 shape needs a model",
             pt_scene_parse(&s, "t.scene", "shape cube\n", 11, err, sizeof err) < 0
             && strstr(err, "t.scene:1:1: error: 'shape' before any 'model'") != NULL);
    pt_scene_free(&s);
}

/* ----------------------------------------------------------- shapes-4 */

static void table(void)
{
    int i, k, ok = 1;

    for (i = 0; i < pt_nshapes; i++) {
        const pt_shape_info *in = &pt_shapes[i];

        ok &= pt_shape_find(in->name, strlen(in->name)) == in;
        ok &= (in->arities & 1u) && (in->arities >> (in->nparam + 1)) == 0;
        ok &= (int)strlen(in->kind) == in->nparam;
        for (k = 0; k < in->nparam; k++)
            ok &= in->param[k] != NULL && in->dflt[k] != NULL;
    }
    PT_CHECK("shapes-4.1 each shape is found by name, takes 0 arguments, and has a "
             "default for every parameter", ok);
    PT_CHECK("shapes-4.2 the 18 shapes of the course's list", pt_nshapes == 18);
    PT_CHECK("shapes-4.3 an unknown name is NULL", pt_shape_find("sphere2", 7) == NULL
             && pt_shape_find("spher", 5) == NULL);
}

int main(void)
{
    java_cases();
    mixes();
    refusals();
    table();
    printf("coordinates: %ld exactly as in Java, %ld one ulp away\n", exact, one_ulp);
    return pt_test_report();
}
