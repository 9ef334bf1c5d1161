/*
** src/core/scene_course.c -- the scene directives of the course's renderers 4, 7 and 9
** See LICENSE for copyright and license.
**
** The directives a scene needs to say what a client of the course's Java
** renderer says (docs/scene-format.md, "The course's renderers"): which
** renderer, the Scene's name, the camera's view volume and near plane,
** renderer 9's view vector and position matrices, the switches, colour lists,
** segments with colour indices, points, hidden positions and models.  Each
** handler checks its own line; what depends on the renderer, which a scene
** may name last, is checked once the file is read (pt_sc_finish_course).
** Whatever the course's renderer would throw on (a colour index past the
** model's colours, a float colour outside 0..1) is an error here.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/scene.h"
#include "core/scene_int.h"

#define MAX_RADIUS 4096         /* a point's |radius|: (2r+1)^2 pixels at most */
#define MAX_CINDEX 0x7fffffffu  /* colour indices: Java ints */
#define JAVA_PI    3.141592653589793    /* Math.PI */

/* Record where the directive dir of src is, for the checks at the end. */
static void mark(pt_sc_at *at, const source *src, const token *dir)
{
    if (at->line != 0) return;
    at->line = src->lineno;
    at->col = (size_t)(dir->p - src->line) + 1;
}

/* A once-per-scene directive. */
static int once_at(parser *ps, const source *src, const token *dir, pt_sc_at *at)
{
    char q[QUOTE_BUF];

    if (at->line != 0)
        return pt_sc_fail(ps, src, dir->p, "duplicate '%s' (first at line %zu)",
                          pt_sc_shown(dir->p, dir->n, q), at->line);
    mark(at, src, dir);
    return 0;
}

/* A copy of the token t as a C string, or NULL when out of memory. */
static char *copy_token(const token *t)
{
    char *c = malloc(t->n + 1);

    if (c == NULL) return NULL;
    memcpy(c, t->p, t->n);
    c[t->n] = '\0';
    return c;
}

void pt_sc_start_course(pt_scene *s)
{
    s->renderer = 4;
    s->nearclip = 1;
    s->gamma = 1;
    s->cam_l = -1.0; s->cam_r = 1.0;
    s->cam_b = -1.0; s->cam_t = 1.0;
}

/* renderer 4|7|9 */
int pt_sc_renderer(parser *ps, source *src, const token *dir, cursor *args)
{
    char q[QUOTE_BUF];
    token a;

    if (once_at(ps, src, dir, &ps->course.renderer) < 0
        || pt_sc_take_args(ps, src, dir, args, &a, 1, 1, "number", NULL) < 0)
        return -1;
    if (pt_sc_tok_is(&a, "4")) ps->s->renderer = 4;
    else if (pt_sc_tok_is(&a, "7")) ps->s->renderer = 7;
    else if (pt_sc_tok_is(&a, "9")) ps->s->renderer = 9;
    else return pt_sc_fail(ps, src, a.p, "unknown renderer '%s' (expected 4, 7 or 9)",
                           pt_sc_shown(a.p, a.n, q));
    return 0;
}

/* scene NAME: one word, checked like every byte of a line (UTF-8, no controls)
** and like a model name for format characters (it reaches terminals). */
int pt_sc_scene_name(parser *ps, source *src, const token *dir, cursor *args)
{
    token a;

    if (once_at(ps, src, dir, &ps->course.scene) < 0
        || pt_sc_take_args(ps, src, dir, args, &a, 1, 1, "name", NULL) < 0
        || pt_sc_name_chars(ps, src, &a, "scene") < 0)
        return -1;
    if ((ps->s->scene_name = copy_token(&a)) == NULL)
        return pt_sc_fail(ps, src, dir->p, "out of memory");
    return 0;
}

/* viewport-background R G B */
int pt_sc_vp_background(parser *ps, source *src, const token *dir, cursor *args)
{
    if (once_at(ps, src, dir, &ps->course.vpbg) < 0)
        return -1;
    return pt_sc_rgb(ps, src, dir, args, "color component", ps->s->vp_background);
}

/* near N: camera.changeNear(N), so n = -N (any sign, as the course allows). */
int pt_sc_near(parser *ps, source *src, const token *dir, cursor *args)
{
    token a;

    if (once_at(ps, src, dir, &ps->course.near) < 0
        || pt_sc_take_args(ps, src, dir, args, &a, 1, 1, "number", NULL) < 0)
        return -1;
    return pt_sc_number(ps, src, &a, "near distance", &ps->course.near_value);
}

/* view X Y Z: camera.translate(X, Y, Z) (renderer 9). */
int pt_sc_view(parser *ps, source *src, const token *dir, cursor *args)
{
    token a[3];
    double v[3];

    if (once_at(ps, src, dir, &ps->course.view) < 0
        || pt_sc_take_args(ps, src, dir, args, a, 3, 3, "numbers", NULL) < 0
        || pt_sc_numbers(ps, src, a, 3, "view coordinate", v) < 0)
        return -1;
    ps->s->view = (pt_vec3){ v[0], v[1], v[2] };
    return 0;
}

/* nearclip|antialias|gamma on|off */
int pt_sc_switch(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_sc_at *at = &ps->course.nearclip;
    int *field = &ps->s->nearclip;
    char q[QUOTE_BUF], r[QUOTE_BUF];
    token a;

    if (pt_sc_tok_is(dir, "antialias")) { at = &ps->course.antialias; field = &ps->s->antialias; }
    if (pt_sc_tok_is(dir, "gamma")) { at = &ps->course.gamma; field = &ps->s->gamma; }
    if (once_at(ps, src, dir, at) < 0
        || pt_sc_take_args(ps, src, dir, args, &a, 1, 1, "word", NULL) < 0)
        return -1;
    if (pt_sc_tok_is(&a, "on")) *field = 1;
    else if (pt_sc_tok_is(&a, "off")) *field = 0;
    else return pt_sc_fail(ps, src, a.p, "expected on or off after '%s', found '%s'",
                           pt_sc_shown(dir->p, dir->n, q), pt_sc_shown(a.p, a.n, r));
    return 0;
}

/* pipeline2 */
int pt_sc_pipeline2(parser *ps, source *src, const token *dir, cursor *args)
{
    if (once_at(ps, src, dir, &ps->course.pipeline2) < 0
        || pt_sc_take_args(ps, src, dir, args, NULL, 0, 0, "words", NULL) < 0)
        return -1;
    ps->s->pipeline2 = 1;
    return 0;
}

/* ===== the camera's view volume ===== */

/* camera perspective L R B T [FOCAL] | orthographic L R B T
** | perspective-fov FOVY ASPECT | orthographic-fov FOVY ASPECT: the Camera's
** fields as its factory methods store them (scene/Camera.java). */
int pt_sc_camera_volume(parser *ps, source *src, const token *a, size_t n)
{
    pt_scene *s = ps->s;
    int fov = a[0].n > 4 && memcmp(a[0].p + a[0].n - 4, "-fov", 4) == 0;
    size_t want = fov ? 3 : 5;
    double v[5], top, right;
    char q[QUOTE_BUF];

    if (!(n == want || (!fov && s->perspective && n == 6)))
        return pt_sc_fail(ps, src, a[0].p, "expected %s after 'camera %s', found %zu",
                          fov ? "FOVY ASPECT" : s->perspective ? "L R B T [FOCAL]" : "L R B T",
                          pt_sc_shown(a[0].p, a[0].n, q), n - 1);
    if (pt_sc_numbers(ps, src, a + 1, n - 1, "camera number", v) < 0)
        return -1;
    mark(&ps->course.cam_params, src, &a[0]);
    if (fov) {                          /* top = tan((PI/180.0)*fovy/2.0) */
        top = tan(((JAVA_PI / 180.0) * v[0]) / 2.0);
        right = top * v[1];
        s->cam_l = -right; s->cam_r = right;
        s->cam_b = -top;   s->cam_t = top;
    } else if (n == 6) {                /* l/f, r/f, b/f, t/f */
        s->cam_l = v[0] / v[4]; s->cam_r = v[1] / v[4];
        s->cam_b = v[2] / v[4]; s->cam_t = v[3] / v[4];
    } else {
        s->cam_l = v[0]; s->cam_r = v[1];
        s->cam_b = v[2]; s->cam_t = v[3];
    }
    if (!isfinite(s->cam_l) || !isfinite(s->cam_r) || !isfinite(s->cam_b)
        || !isfinite(s->cam_t))
        return pt_sc_fail(ps, src, a[0].p, "the camera's view rectangle is not finite");
    return 0;
}

/* ===== positions and matrices ===== */

/* `model NAME POSITION`: the position's name. */
int pt_sc_position(parser *ps, source *src, const token *t)
{
    char q[QUOTE_BUF];
    size_t i;

    for (i = 0; i < t->n; i++)          /* it goes where model names go */
        if (t->p[i] == '"' || t->p[i] == '\\' || t->p[i] == ',')
            return pt_sc_fail(ps, src, t->p + i, "position name '%s' may not contain '%c'",
                              pt_sc_shown(t->p, t->n, q), t->p[i]);
    if ((pt_sc_model(ps)->position = copy_token(t)) == NULL)
        return pt_sc_fail(ps, src, t->p, "out of memory");
    return 0;
}

/* Append op to the current model's matrix operations. */
static int add_op(parser *ps, const source *src, const char *at, const pt_matop *op)
{
    pt_model *m = pt_sc_model(ps);

    if (pt_sc_room(ps, src, at, (void **)&m->ops, m->nops, &m->cap_ops, sizeof *m->ops,
                   1u << 20, "matrix lines") != 0)
        return -1;
    m->ops[m->nops++] = *op;
    return 0;
}

int pt_sc_translate_op(parser *ps, source *src, const token *dir, pt_vec3 t)
{
    pt_matop op;

    memset(&op, 0, sizeof op);
    op.mul = PT_MATMUL_SET;
    op.kind = PT_MATOP_TRANSLATE;
    op.a[0] = t.x; op.a[1] = t.y; op.a[2] = t.z;
    return add_op(ps, src, dir->p, &op);
}

/* matrix OP | matrix-pre OP | matrix-set OP, where OP = identity
** | translate X Y Z | scale S | scale X Y Z | rotate x|y|z DEG
** | rotate DEG X Y Z | rows A00 A01 .. A33 (16 numbers, row by row). */
int pt_sc_matrix(parser *ps, source *src, const token *dir, cursor *args)
{
    char q[QUOTE_BUF];
    token a[18];
    size_t n = 0;
    pt_matop op;
    token t;

    memset(&op, 0, sizeof op);
    op.mul = pt_sc_tok_is(dir, "matrix-pre") ? PT_MATMUL_PRE
           : pt_sc_tok_is(dir, "matrix-set") ? PT_MATMUL_SET : PT_MATMUL_POST;
    while (pt_sc_next_token(args, &t)) {
        if (n == 18)
            return pt_sc_fail(ps, src, t.p, "too many words after '%s'",
                              pt_sc_shown(dir->p, dir->n, q));
        a[n++] = t;
    }
    if (n == 0)
        return pt_sc_fail(ps, src, dir->p, "expected an operation after '%s' (identity, "
                          "translate, scale, rotate or rows)", pt_sc_shown(dir->p, dir->n, q));
    mark(&ps->course.matrix, src, dir);
    if (pt_sc_tok_is(&a[0], "identity") && n == 1) {
        op.kind = PT_MATOP_IDENTITY;
    } else if (pt_sc_tok_is(&a[0], "translate") && n == 4) {
        op.kind = PT_MATOP_TRANSLATE;
        if (pt_sc_numbers(ps, src, a + 1, 3, "translation", op.a) < 0) return -1;
    } else if (pt_sc_tok_is(&a[0], "scale") && (n == 2 || n == 4)) {
        op.kind = PT_MATOP_SCALE;
        if (pt_sc_numbers(ps, src, a + 1, n - 1, "scale factor", op.a) < 0) return -1;
        if (n == 2) op.a[1] = op.a[2] = op.a[0];
    } else if (pt_sc_tok_is(&a[0], "rotate") && n == 3) {
        const char *axes = "xyz", *at = a[1].n == 1 ? strchr(axes, a[1].p[0]) : NULL;
        if (at == NULL || *at == '\0')
            return pt_sc_fail(ps, src, a[1].p, "unknown axis '%s' (expected x, y or z)",
                              pt_sc_shown(a[1].p, a[1].n, q));
        op.kind = PT_MATOP_ROTATE;
        if (pt_sc_number(ps, src, &a[2], "angle", &op.a[0]) < 0) return -1;
        op.a[1 + (at - axes)] = 1.0;    /* rotateX(t) = rotate(t, 1, 0, 0) */
    } else if (pt_sc_tok_is(&a[0], "rotate") && n == 5) {
        op.kind = PT_MATOP_ROTATE;
        if (pt_sc_numbers(ps, src, a + 1, 4, "rotation number", op.a) < 0) return -1;
    } else if (pt_sc_tok_is(&a[0], "rows") && n == 17) {
        op.kind = PT_MATOP_ROWS;
        if (pt_sc_numbers(ps, src, a + 1, 16, "matrix entry", op.a) < 0) return -1;
    } else {
        return pt_sc_fail(ps, src, a[0].p, "expected identity, translate X Y Z, scale S, "
                          "scale X Y Z, rotate x|y|z DEG, rotate DEG X Y Z or rows and 16 "
                          "numbers after '%s'", pt_sc_shown(dir->p, dir->n, q));
    }
    return add_op(ps, src, dir->p, &op);
}

/* ===== colours, segments, points, visibility ===== */

/* vcolor R G B (integers 0..255: Color(int, int, int), whose components are
** c / 255f) | vcolor-float R G B (Float.parseFloat, 0..1: Color(float,
** float, float), which keeps the floats). */
int pt_sc_vcolor(parser *ps, source *src, const token *dir, cursor *args)
{
    int is_float = pt_sc_tok_is(dir, "vcolor-float");
    pt_model *m = pt_sc_model(ps);
    float f[3];
    token a[3];
    int i, c;

    if (ps->color_line != 0)
        return pt_sc_fail(ps, src, dir->p, "a model has 'color' or 'vcolor' lines, not both "
                          "('color' at line %zu)", ps->color_line);
    if (pt_sc_take_args(ps, src, dir, args, a, 3, 3, "numbers", NULL) < 0)
        return -1;
    for (i = 0; i < 3; i++) {
        if (!is_float) {
            if (pt_sc_int(ps, src, &a[i], "color component", 0, 255, &c) < 0) return -1;
            f[i] = (float)c / 255.0f;
        } else {
            double d;
            char buf[64];
            if (pt_sc_number(ps, src, &a[i], "color component", &d) < 0) return -1;
            if (a[i].n >= sizeof buf)   /* round the decimal to float once, as */
                f[i] = (float)d;        /* Float.parseFloat does (a long one: */
            else {                      /* its double is within 1e-17 anyway) */
                memcpy(buf, a[i].p, a[i].n);
                buf[a[i].n] = '\0';
                f[i] = strtof(buf, NULL);
            }
            if (!(f[i] >= 0.0f && f[i] <= 1.0f))
                return pt_sc_fail(ps, src, a[i].p, "color component %.*s is outside 0..1 "
                                  "(the course's Color would throw)", (int)a[i].n, a[i].p);
        }
    }
    if (pt_sc_room(ps, src, dir->p, (void **)&m->colors, m->ncolors, &m->cap_colors,
                   sizeof *m->colors, MAX_CINDEX, "colors") != 0)
        return -1;
    m->colors[m->ncolors++] = (pt_rgb){ f[0], f[1], f[2] };
    m->colors_given = 1;
    if (ps->course.vcolor_line == 0)
        ps->course.vcolor_line = src->lineno;
    return 0;
}

/* A 1-based colour index into *out (0-based); remembered for the model's
** end, where its colour list is known. */
static int colour_index(parser *ps, const source *src, const token *t, uint32_t *out)
{
    int c;

    if (pt_sc_int(ps, src, t, "color index", 1, (int)MAX_CINDEX, &c) < 0)
        return -1;
    *out = (uint32_t)(c - 1);
    if ((uint32_t)c > ps->course.cindex_max) {
        ps->course.cindex_max = (uint32_t)c;
        ps->course.cindex.line = src->lineno;
        ps->course.cindex.col = (size_t)(t->p - src->line) + 1;
    }
    return 0;
}

/* segment I J [CI CJ] */
int pt_sc_segment(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_model *m = pt_sc_model(ps);
    pt_segment sg;
    token a[4];
    size_t n;

    if (pt_sc_take_args(ps, src, dir, args, a, 2, 4, "indices", &n) < 0)
        return -1;
    if (n == 3)
        return pt_sc_fail(ps, src, a[2].p, "expected 2 vertex indices and 0 or 2 color "
                          "indices after 'segment', found 3 indices");
    if (pt_sc_index(ps, src, &a[0], &sg.a) < 0 || pt_sc_index(ps, src, &a[1], &sg.b) < 0)
        return -1;
    sg.ca = sg.a;
    sg.cb = sg.b;
    if (n == 4 && (colour_index(ps, src, &a[2], &sg.ca) < 0
                   || colour_index(ps, src, &a[3], &sg.cb) < 0))
        return -1;
    if (pt_sc_room(ps, src, dir->p, (void **)&m->seg, m->nseg, &m->cap_seg, sizeof *m->seg,
                   MAX_SEGS, "segments") != 0)
        return -1;
    m->seg[m->nseg++] = sg;
    return 0;
}

/* point I [C [RADIUS]] */
int pt_sc_point(parser *ps, source *src, const token *dir, cursor *args)
{
    pt_model *m = pt_sc_model(ps);
    pt_point pt;
    token a[3];
    size_t n;

    if (pt_sc_take_args(ps, src, dir, args, a, 1, 3, "numbers", &n) < 0
        || pt_sc_index(ps, src, &a[0], &pt.v) < 0)
        return -1;
    pt.c = pt.v;
    pt.radius = 0;
    if ((n >= 2 && colour_index(ps, src, &a[1], &pt.c) < 0)
        || (n == 3 && pt_sc_int(ps, src, &a[2], "radius", -MAX_RADIUS, MAX_RADIUS,
                                &pt.radius) < 0))
        return -1;
    pt.after = m->nseg;
    mark(&ps->course.point, src, dir);
    if (pt_sc_room(ps, src, dir->p, (void **)&m->pts, m->npts, &m->cap_pts, sizeof *m->pts,
                   MAX_SEGS, "points") != 0)
        return -1;
    m->pts[m->npts++] = pt;
    return 0;
}

/* hidden-position | hidden-model */
int pt_sc_hidden(parser *ps, source *src, const token *dir, cursor *args)
{
    int pos = pt_sc_tok_is(dir, "hidden-position");

    if (pt_sc_once(ps, src, dir, pos ? &ps->course.hidepos_line
                                     : &ps->course.hidemodel_line) < 0
        || pt_sc_take_args(ps, src, dir, args, NULL, 0, 0, "words", NULL) < 0)
        return -1;
    if (pos) pt_sc_model(ps)->hidden_position = 1;
    else pt_sc_model(ps)->hidden_model = 1;
    return 0;
}

/* ===== checks at the end of a model and of the file ===== */

int pt_sc_end_model(parser *ps, const char *name)
{
    const pt_model *m = pt_sc_model(ps);
    size_t ncolors = m->ncolors > 0 ? m->ncolors : m->nv;
    size_t i;

    if (ps->course.cindex_max > ncolors)
        return pt_sc_fail_at(ps->err, ps->errlen, name, ps->course.cindex.line,
                             ps->course.cindex.col, "color index %lu is past the %zu colors "
                             "of model '%s' (the course's renderer would throw)",
                             (unsigned long)ps->course.cindex_max, ncolors, m->name);
    /* `l`, `f`, `segment I J` and `point I` take their colour indices from
    ** their vertices: with a colour list, those must be in it too. */
    for (i = 0; m->ncolors > 0 && i < m->nseg + m->npts; i++) {
        uint32_t c = i < m->nseg ? (m->seg[i].ca > m->seg[i].cb ? m->seg[i].ca : m->seg[i].cb)
                                 : m->pts[i - m->nseg].c;
        if (c >= ncolors)
            return pt_sc_fail_at(ps->err, ps->errlen, name, ps->model_line[ps->s->nmodels - 1],
                                 1, "model '%s': %s %zu takes color %lu from its vertex, but "
                                 "the model has %zu colors (the course's renderer would "
                                 "throw)", m->name, i < m->nseg ? "segment" : "point",
                                 i < m->nseg ? i + 1 : i - m->nseg + 1,
                                 (unsigned long)c + 1, ncolors);
    }
    return 0;
}

/* A directive seen at `at` that renderer s->renderer has no use for. */
static int not_here(parser *ps, const char *name, const pt_sc_at *at, const char *what,
                    const char *which)
{
    if (at->line == 0) return 0;
    return pt_sc_fail_at(ps->err, ps->errlen, name, at->line, at->col,
                         "%s needs %s; this scene is %s", what, which,
                         ps->s->pipe == PT_PIPE_MATRIX ? "the matrix camera's"
                         : ps->s->renderer == 4 ? "renderer 4's (the default; say 'renderer 7' "
                         "or 'renderer 9')" : "renderer 7's");
}

int pt_sc_finish_course(parser *ps, const char *name)
{
    pt_scene *s = ps->s;
    const pt_sc_course *c = &ps->course;

    if (c->vpbg.line == 0)
        memcpy(s->vp_background, s->background, 3);
    s->cam_n = c->near.line != 0 ? -c->near_value : s->perspective ? -0.1 : 1.0;
    if (s->renderer != 4 && s->pipe == PT_PIPE_MATRIX)
        return pt_sc_fail_at(ps->err, ps->errlen, name, ps->cam_line, ps->cam_col,
                             "'camera lookat' is the matrix camera, not renderer %d's "
                             "(leave out the renderer line, or give renderer %d a camera "
                             "perspective or orthographic)", s->renderer, s->renderer);
    if (s->renderer == 4 && (not_here(ps, name, &c->cam_params, "a camera with a view "
                                      "volume", "renderer 7 or 9") < 0
                             || not_here(ps, name, &c->near, "'near'", "renderer 7 or 9") < 0
                             || not_here(ps, name, &c->nearclip, "'nearclip'",
                                         "renderer 7 or 9") < 0))
        return -1;
    if (s->renderer != 9 && (not_here(ps, name, &c->view, "'view'", "renderer 9") < 0
                             || not_here(ps, name, &c->matrix, "a 'matrix' line",
                                         "renderer 9") < 0
                             || not_here(ps, name, &c->pipeline2, "'pipeline2'",
                                         "renderer 9") < 0))
        return -1;
    if (s->pipe == PT_PIPE_MATRIX      /* the matrix camera draws one colour a model */
        && not_here(ps, name, &c->point, "'point'", "a course renderer") < 0)
        return -1;
    return 0;
}

void pt_sc_free_model(pt_model *m)
{
    free(m->position);
    free(m->colors);
    free(m->pts);
    free(m->ops);
}
