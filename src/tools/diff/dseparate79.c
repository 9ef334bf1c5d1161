/*
** src/tools/diff/dseparate79.c -- pipetrace diff: separating scenes for renderers 7 and 9
** See LICENSE for copyright and license.
**
** The stage whose mistakes are listed says the candidates: the world's
** positions of a rotation and a translation (renderer 9), the camera's
** segments off the lines through the eye where a skew and a size mistake
** agree, the near clip's segments across the near plane and its mirror
** image, the clip's segments across one edge.  Each goes through the right
** stage and through every mistake of that stage with the catalogue's own
** function; the search and the text are dseparate.c's (dsearch.h).
*/
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/tread79.h"
#include "tools/diff/diff.h"
#include "tools/diff/dseparate.h"

/* ===== renderers 7 and 9: the world, the camera, the near clip, the clip ===== */

/* A segment of the candidates, in view coordinates, with its two colours. */
typedef struct piece79 {
    double v[2][3];
    int rgb[2][3];
} piece79;

/* v (view coordinates) in camera coordinates, by cam's renderer's stage. */
static pt_vec4 camera79(const pt_c79cam *cam, const double v[3])
{
    pt_rv_camera k = pt_c79cam_stages(cam);
    pt_vec4 p = {v[0], v[1], v[2], 1.0};

    if (cam->renderer == 9) {
        pt_jmat m = pt_r9_normalize_matrix(&k);
        return pt_r9_view2camera(p, &m);
    }
    return pt_r7_view2camera(p, &k);
}

/* The camera stage's (x, y, z, w) of pc's vertices, mk's (or the right
** stage's when NULL): the catalogue's own function, given the view values
** and the right ones, as diff tests the hypothesis. */
static void sig_camera(const pt_c79cam *cam, const piece79 *pc, const pt_mistake79 *mk, pt_sep_sig *s)
{
    int e, k;

    for (e = 0; e < 2; e++) {
        pt_vec4 r = camera79(cam, pc->v[e]);
        double prev[4] = {pc->v[e][0], pc->v[e][1], pc->v[e][2], 1.0};
        double right[4] = {r.x, r.y, r.z, r.w}, o[4];
        if (mk) mk->vertex(cam, prev, right, o);
        else memcpy(o, right, sizeof o);
        for (k = 0; k < 4; k++) pt_sep_real(s, o[k], 0);
    }
}

/* What clip stage st (mk's, or the right one when NULL) leaves of pc: the
** near clip takes the camera's vertices, the clip the image plane's. */
static void sig79(const pt_c79cam *cam, int st, const piece79 *pc, const pt_mistake79 *mk, pt_sep_sig *s)
{
    pt_rv_model m;
    pt_rv_prim p;
    size_t k;
    int rc, e;

    memset(s, 0, sizeof *s);
    if (st == PT_T79_CAMERA) {
        sig_camera(cam, pc, mk, s);
        return;
    }
    memset(&m, 0, sizeof m);
    memset(&p, 0, sizeof p);
    rc = 0;
    for (e = 0; e < 2; e++) {
        pt_vec4 v = camera79(cam, pc->v[e]);
        pt_rgb c;
        c.r = (float)pc->rgb[e][0] / 255.0f;
        c.g = (float)pc->rgb[e][1] / 255.0f;
        c.b = (float)pc->rgb[e][2] / 255.0f;
        if (st == PT_T79_CLIP) v = pt_rv_project(v, cam->persp);
        rc |= pt_rv_add_vertex(&m, v) | pt_rv_add_color(&m, c);
    }
    p.kind = PT_RV_LINE;
    p.v[1] = p.c[1] = 1;
    rc |= pt_rv_add_prim(&m, &p);
    if (rc == 0)
        rc = mk ? mk->clip(cam, &m) : st == PT_T79_CLIP ? pt_rv_clip(&m, NULL) < 0 ? -1 : 0
                                                        : pt_rv_nearclip(&m, cam->n, NULL);
    pt_sep_real(s, rc, 1);
    pt_sep_real(s, (double)m.nv, 1);
    pt_sep_real(s, (double)m.np, 1);
    for (k = 0; rc == 0 && k < m.nv; k++) {
        pt_sep_real(s, m.v[k].x, 0); pt_sep_real(s, m.v[k].y, 0); pt_sep_real(s, m.v[k].z, 0);
    }
    for (k = 0; rc == 0 && k < m.nc; k++) {     /* the log prints Color bytes */
        const float f[3] = {m.c[k].r, m.c[k].g, m.c[k].b};
        for (e = 0; e < 3; e++) {
            double x = (double)f[e] * 255;      /* 6 decimals: +-0.00013 of a byte */
            s->fragile |= fabs(x - floor(x) - 0.5) < 0.01;
            pt_sep_real(s, pt_color_byte(f[e]), 1);
        }
    }
    for (k = 0; rc == 0 && k < m.np; k++) {
        pt_sep_real(s, m.p[k].v[0], 1); pt_sep_real(s, m.p[k].v[1], 1);
        pt_sep_real(s, m.p[k].c[0], 1); pt_sep_real(s, m.p[k].c[1], 1);
    }
    pt_rv_model_free(&m);
}

/* The near clip's candidates: segments across the near plane and its mirror
** image, between them, beyond them. */
static size_t pieces_near(const pt_c79cam *cam, piece79 *pc)
{
    static const int col[6][3] = {{255, 0, 0}, {0, 0, 255}, {0, 255, 0}, {255, 255, 0},
                                  {200, 100, 50}, {90, 30, 220}};
    static const double xy[5][4] = {{-0.3, -0.2, 0.4, 0.3}, {0.2, -0.3, -0.1, 0.25},
                                    {0.1, 0.1, -0.2, 0.15}, {-0.25, 0.3, 0.3, -0.2},
                                    {0.35, -0.1, -0.3, 0.2}};
    double lo = fmin(cam->n, -cam->n), hi = fmax(cam->n, -cam->n), a = hi - lo;
    double far, mid, beyond;
    size_t c;
    int i;

    if (!(a > 0) || !isfinite(a)) a = 0.2;
    far = lo - 10 * a; mid = (lo + hi) / 2; beyond = hi + 2 * a;
    {
        const double z[5][2] = {{far, beyond}, {far, mid}, {beyond, beyond + 2 * a},
                                {mid, far}, {far, beyond + a}};
        for (c = 0; c < 5; c++)
            for (i = 0; i < 2; i++) {
                pc[c].v[i][0] = xy[c][2 * i];
                pc[c].v[i][1] = xy[c][2 * i + 1];
                pc[c].v[i][2] = z[c][i];
                memcpy(pc[c].rgb[i], col[(2 * c + i) % 6], sizeof pc[c].rgb[i]);
            }
    }
    return 5;
}

/* The camera's candidates: segments in front of the camera whose ends lie
** off the lines where a skew mistake and a size mistake agree: through the
** eye, x_v = k z_v (r+l)/2 and y_v = k z_v (t+b)/2 with k = 1 (the skew
** forgotten, the width), -3 (its sign, the half-width twice), -2 (forgotten,
** twice), 3 (its sign, the width); orthographic, parallel to the z axis,
** x_v = k (r+l)/2 with k = -1, 3, 2, -3. */
static size_t pieces_camera(piece79 *pc)
{
    static const double v[3][6] = {{-0.3, -0.2, -2.1, 0.4, 0.3, -2.6},
                                   {0.35, -0.15, -3.2, -0.25, 0.45, -1.7},
                                   {0.6, 0.1, -2.4, 0.05, -0.55, -3.5}};
    static const int col[2][3] = {{255, 0, 0}, {0, 0, 255}};
    size_t c;
    int i;

    for (c = 0; c < 3; c++)
        for (i = 0; i < 2; i++) {
            memcpy(pc[c].v[i], v[c] + 3 * i, sizeof pc[c].v[i]);
            memcpy(pc[c].rgb[i], col[i], sizeof pc[c].rgb[i]);
        }
    return 3;
}

/* The view coordinates at z_v = -2 that the image plane's (x, y) comes
** from, by the camera's formula turned around: a first guess only, the
** signatures run the stages themselves. */
static void view_at(const pt_c79cam *cam, double x, double y, double v[3])
{
    double d = cam->persp ? 2 : 1;              /* x_c = x_p * -z_v (orthographic: x_p) */

    v[0] = x * d * (cam->r - cam->l) / 2 + d * (cam->r + cam->l) / 2;
    v[1] = y * d * (cam->t - cam->b) / 2 + d * (cam->t + cam->b) / 2;
    v[2] = -2;
}

/* The clip's candidates, each from an inside end to an outside one beyond
** one edge, given on the image plane (view_at()).  Two colours five bytes apart,
** cut a quarter of the way in from the outside end: the new colour
** interpolated (1.25 bytes in: a byte), in bytes (truncated: the next one)
** and not at all (the inside end's) are three bytes, and a t outside 0 .. 1
** (a mistake's) still makes a colour java.awt.Color takes; or one colour,
** which shows where each cut lands. */
static size_t pieces_clip(const pt_c79cam *cam, piece79 *pc)
{
    static const double img[6][4] = {
        {0.4, 0.15, 1.2, -0.1}, {-0.1, -0.4, 0.15, -1.2}, {0.3, 0.4, 1.6, 0.7},
        {-0.5, -0.2, -1.3, -0.6}, {0.1, 0.6, 0.4, 1.5}, {0.6, 0.7, 1.3, 1.4}};
    static const int col[6][2][3] = {
        {{125, 115, 105}, {130, 120, 110}}, {{60, 200, 90}, {65, 205, 95}},
        {{255, 0, 0}, {255, 0, 0}}, {{0, 255, 0}, {0, 255, 0}}, {{0, 0, 255}, {0, 0, 255}},
        {{255, 255, 0}, {255, 255, 0}}};
    size_t c;
    int i;

    for (c = 0; c < 6; c++)
        for (i = 0; i < 2; i++) {
            view_at(cam, img[c][2 * i], img[c][2 * i + 1], pc[c].v[i]);
            memcpy(pc[c].rgb[i], col[c][i], sizeof pc[c].rgb[i]);
        }
    return 6;
}

/* A position of the world stage's candidates: two matrix lines, a rotation
** and a translation, that do not commute, on a cube of side 1.  Composed
** backwards, rotate-then-translate is the order mistake's way 1 and
** translate-then-rotate its way 0 (catalogue79.c: [A | A^-1 t], [A | A t]). */
typedef struct pos79 {
    int rot_first;               /* 1: rotate, then translate */
    char axis;                   /* x, y or z */
    double deg, t[3];
} pos79;

static const pos79 world_pieces[3] = {
    {1, 'y', 30.0, {1.5, 0.0, -6.0}}, {0, 'z', 25.0, {-1.0, 0.5, -5.0}},
    {1, 'x', 40.0, {0.5, -1.0, -5.0}}};

/* The cube's corner k (0..7) in model coordinates. */
static void corner(int k, double v[4])
{
    v[0] = k & 4 ? 0.5 : -0.5;
    v[1] = k & 2 ? 0.5 : -0.5;
    v[2] = k & 1 ? 0.5 : -0.5;
    v[3] = 1.0;
}

/* The world stage's (x, y, z, w) of the cube at position pp: the right
** stage (mk NULL) with the matrix its lines build, or position mistake mk
** from the model's and the right world vertices, as diff tests it (the way
** the lines go, where the mistake has more than one). */
static void sig_world(const pos79 *pp, const pt_mistake79 *mk, pt_sep_sig *s)
{
    pt_matop op[2];
    pt_jmat m;
    double prev[8][4], right[8][4], out[8][4];
    int k, i, r = pp->rot_first ? 0 : 1;

    memset(op, 0, sizeof op);
    op[r].mul = op[1 - r].mul = PT_MATMUL_POST;
    op[r].kind = PT_MATOP_ROTATE;
    op[r].a[0] = pp->deg;
    op[r].a[1 + (pp->axis - 'x')] = 1.0;        /* rotate x|y|z DEG, as a scene gives it */
    op[1 - r].kind = PT_MATOP_TRANSLATE;
    memcpy(op[1 - r].a, pp->t, sizeof pp->t);
    m = pt_r9_position_matrix(op, 2);
    for (k = 0; k < 8; k++) {
        pt_vec4 v, o;
        corner(k, prev[k]);
        v.x = prev[k][0]; v.y = prev[k][1]; v.z = prev[k][2]; v.w = prev[k][3];
        o = pt_r9_model2world(v, &m);
        right[k][0] = o.x; right[k][1] = o.y; right[k][2] = o.z; right[k][3] = o.w;
    }
    if (!mk) memcpy(out, right, sizeof out);
    else if (mk->position(8, (const double (*)[4])prev, (const double (*)[4])right,
                          pp->rot_first, out) != 0 &&
             mk->position(8, (const double (*)[4])prev, (const double (*)[4])right, 0, out) != 0) {
        pt_sep_real(s, -1, 1);                     /* the mistake finds no matrix */
        return;
    }
    pt_sep_real(s, 0, 1);
    for (k = 0; k < 8; k++)
        for (i = 0; i < 4; i++) pt_sep_real(s, out[k][i], 0);
}

/* Position pp as a model of the scene: its matrix lines and the cube. */
static void write_position(const pos79 *pp, size_t k, pt_sep *out)
{
    static const int col[8][3] = {{255, 0, 0}, {255, 128, 0}, {255, 255, 0}, {0, 255, 0},
                                  {0, 255, 255}, {0, 0, 255}, {128, 0, 255}, {255, 255, 255}};
    char b[3][PT_NUMLEN];
    double v[4];
    int i, bit;

    pt_sep_put(out, "model p%zu\n", k);
    for (i = 0; i < 2; i++) {
        if ((i == 0) == (pp->rot_first != 0))
            pt_sep_put(out, "matrix rotate %c %s\n", pp->axis, pt_diff_num(pp->deg, b[0]));
        else
            pt_sep_put(out, "matrix translate %s %s %s\n", pt_diff_num(pp->t[0], b[0]),
                pt_diff_num(pp->t[1], b[1]), pt_diff_num(pp->t[2], b[2]));
    }
    for (i = 0; i < 8; i++) {
        corner(i, v);
        pt_sep_put(out, "v %s %s %s\n", pt_diff_num(v[0], b[0]), pt_diff_num(v[1], b[1]),
            pt_diff_num(v[2], b[2]));
    }
    for (i = 0; i < 8; i++) pt_sep_put(out, "vcolor %d %d %d\n", col[i][0], col[i][1], col[i][2]);
    for (bit = 1; bit < 8; bit <<= 1)           /* the 12 edges: corners one bit apart */
        for (i = 0; i < 8; i++)
            if (!(i & bit)) pt_sep_put(out, "segment %d %d\n", i + 1, (i | bit) + 1);
}

/* The stage of the catalogue's mistake name for cam's renderer, or -1. */
static int stage_of(const pt_c79cam *cam, const char *name)
{
    size_t k;

    for (k = 0; k < PT_NMISTAKES79; k++)
        if (!strcmp(pt_mistakes79[k].name, name) &&
            (!pt_mistakes79[k].renderer || pt_mistakes79[k].renderer == cam->renderer))
            return pt_mistakes79[k].stage;
    return -1;
}

/* Why there is no scene for stage st's mistakes (a sentence's end), or NULL
** when the search makes one. */
static const char *no_search(int st)
{
    switch ((pt_t79_stage)st) {
    case PT_T79_WORLD:
    case PT_T79_CAMERA:
    case PT_T79_NEARCLIP:
    case PT_T79_CLIP:
        return NULL;
    case PT_T79_MODEL:
    case PT_T79_VIEW:
    case PT_T79_IMAGE:
        return "the stage has at most one known mistake, which no other can be taken for";
    }
    return "no two of the pixels' mistakes give the same colour to a pixel strictly "
           "between 0 and 1 (gamma twice makes it lighter, no gamma darker, and the swapped "
           "weights give a pair each other's colours, which gamma would have to map to one "
           "another and back), so they both fit only where ACTUAL's pixels differ from "
           "EXPECTED's by little more than the digits printed; any segment of two colours "
           "between 0 and 255, with anti-aliasing and gamma on, tells them apart";
}

/* The comment of stage st's scene, after its first sentence. */
static void course_comment(const pt_c79cam *cam, int st, pt_sep *out, const char *names)
{
    char b[2][PT_NUMLEN];
    double sx = cam->r + cam->l, sy = cam->t + cam->b;

    if (st == PT_T79_NEARCLIP) {
        pt_sep_comment(out, "A scene that tells these mistakes apart: %s. Made by pipetrace diff for "
                "the purpose: on it each gives a log of its own, and none gives the right "
                "one's. The camera's rectangle and near plane are EXPECTED's; it sits at the "
                "origin (no view vector, no matrix), so the segments are given where the near "
                "clip sees them. The framebuffer's size, antialias off and gamma on are the "
                "course's usual ones: the near clip does not depend on them. Render it with "
                "both renderers, debug on, and diff the logs.", names);
        return;
    }
    pt_sep_comment(out, "A scene that tells these mistakes apart: %s. Made by pipetrace diff for the "
            "purpose: on it each gives a log of its own, and none gives the right one's. It "
            "keeps EXPECTED's camera, at the origin (no view vector)%s.", names,
            st == PT_T79_WORLD ? "" : "; no matrix either, so the segments are given in view "
            "coordinates");
    if (st == PT_T79_WORLD)
        pt_sep_comment(out, "Its position's two matrix lines, a rotation and a translation of a few "
                "units, do not commute: composed backwards they put the cube elsewhere, and "
                "the transposed product turns it the other way and puts t.v_m + 1, far from "
                "1, into w.");
    else if (st == PT_T79_CAMERA && (sx != 0 || sy != 0))
        pt_sep_comment(out, "The rectangle is asymmetric (r + l = %s, t + b = %s), so the skew moves "
                "each vertex; the ends lie off the lines %s on which a skew mistake and a size "
                "mistake give the same camera coordinates (x_v = k %s(r+l)/2, y_v = k %s(t+b)/2 "
                "for k = %s).", pt_diff_num(sx, b[0]), pt_diff_num(sy, b[1]),
                cam->persp ? "through the eye" : "parallel to the z axis",
                cam->persp ? "z_v " : "", cam->persp ? "z_v " : "",
                cam->persp ? "1, -3, -2, 3" : "-1, 3, 2, -3");
    else if (st == PT_T79_CAMERA)
        pt_sep_comment(out, "The rectangle is symmetric (r + l = t + b = 0), so no skew mistake "
                "changes anything; the ends lie off the camera's axis, where the size mistakes "
                "move them.");
    else
        pt_sep_comment(out, "Each segment runs from inside the rectangle to beyond one edge. Where it "
                "has two colours, they are five bytes apart and the edge cuts it a quarter of "
                "the way in from the outside end, so that the new colour interpolated, in "
                "bytes (truncated) and not at all (the inside end's) are three different "
                "bytes, and a t outside 0 .. 1 still makes a colour java.awt.Color takes; "
                "where it has one, it shows where the cut lands.");
    pt_sep_comment(out, "The framebuffer's size, antialias off and gamma on are the course's usual "
            "ones: the %s does not depend on them. Render it with both renderers, debug on, "
            "and diff the logs.", st == PT_T79_WORLD ? "world stage"
                                  : st == PT_T79_CAMERA ? "camera stage" : "clip");
}

void pt_sep_course(const pt_c79cam *cam, const char *const *names, size_t n, pt_sep *out)
{
    pt_sep_search *q = malloc(sizeof *q);
    const pt_mistake79 *hy[PT_SEP_MAXH];
    piece79 pc[PT_SEP_MAXC];
    size_t k, j, c, i;
    int st = n ? stage_of(cam, names[0]) : -1;
    char b[3][PT_NUMLEN], nb[1024];
    const char *why;

    memset(out, 0, sizeof *out);
    if (!q) { pt_sep_none(out, "%s%s", "out of memory", "."); return; }
    for (k = 0; k < n; k++)
        if (stage_of(cam, names[k]) != st) {   /* never: diff lists one stage's */
            pt_sep_none(out, "%s is not of the stage %s is.", names[k], names[0]);
            free(q);
            return;
        }
    why = st < 0 ? "no mistake of the catalogue is listed" : no_search(st);
    if (why) {
        pt_sep_none(out, "%s%s", why, ".");
        free(q);
        return;
    }
    memset(q, 0, sizeof *q);
    hy[0] = NULL;
    q->nh = 1;
    for (k = 0; k < PT_NMISTAKES79 && q->nh < PT_SEP_MAXH; k++) {
        const pt_mistake79 *m = &pt_mistakes79[k];
        if (m->stage != st || !(st == PT_T79_WORLD ? m->position != NULL
                                : st == PT_T79_CAMERA ? m->vertex != NULL : m->clip != NULL)) continue;
        if (m->renderer && m->renderer != cam->renderer) continue;
        hy[q->nh++] = m;
    }
    for (k = 0; k < n; k++)
        for (j = 1; j < q->nh; j++)
            if (!strcmp(hy[j]->name, names[k])) q->listed[j] = 1;
    q->nc = st == PT_T79_NEARCLIP ? pieces_near(cam, pc)
          : st == PT_T79_CAMERA ? pieces_camera(pc)
          : st == PT_T79_WORLD ? sizeof world_pieces / sizeof world_pieces[0] : pieces_clip(cam, pc);
    for (c = 0; c < q->nc; c++) {
        int usable = 1;
        for (i = 0; i < q->nh; i++) {
            if (st == PT_T79_WORLD) sig_world(&world_pieces[c], hy[i], &q->s[c][i]);
            else sig79(cam, st, &pc[c], hy[i], &q->s[c][i]);
            usable &= q->s[c][i].val[0] == 0;   /* the stage ran (a colour Java takes) */
            usable &= !q->s[c][i].fragile;      /* its bytes read back */
        }
        if (st == PT_T79_CLIP && !usable)       /* a student's renderer would throw, or
                                                ** a trace leave a byte in doubt: unused */
            for (i = 0; i < q->nh; i++) memset(&q->s[c][i], 0, sizeof q->s[c][i]);
    }
    if (pt_sep_cover(q) != 0) {
        pt_sep_none(out, "no scene of the candidates pipetrace diff tries tells %s from %s.",
             q->bad[0] ? hy[q->bad[0]]->name : "the right stage", hy[q->bad[1]]->name);
        free(q);
        return;
    }
    out->ok = 1;
    course_comment(cam, st, out, pt_sep_names(nb, sizeof nb, names, n));
    pt_sep_put(out, "renderer %d\nscene separate\nframebuffer 60 50\n", cam->renderer);
    pt_sep_put(out, "camera %s %s %s %s", cam->persp ? "perspective" : "orthographic",
        pt_diff_num(cam->l, b[0]), pt_diff_num(cam->r, b[1]), pt_diff_num(cam->b, b[2]));
    pt_sep_put(out, " %s\n", pt_diff_num(cam->t, b[0]));
    if (cam->persp && cam->n != -0.1) pt_sep_put(out, "near %s\n", pt_diff_num(-cam->n, b[0]));
    pt_sep_put(out, "nearclip on\nantialias off\ngamma on\n");
    if (st == PT_T79_WORLD) {
        for (c = 0; c < q->nc; c++)
            if (q->keep[c]) write_position(&world_pieces[c], c + 1, out);
        free(q);
        return;
    }
    pt_sep_put(out, "model separate\n");
    for (c = 0; c < q->nc; c++)
        for (i = 0; q->keep[c] && i < 2; i++)
            pt_sep_put(out, "v %s %s %s\n", pt_diff_num(pc[c].v[i][0], b[0]), pt_diff_num(pc[c].v[i][1], b[1]),
                pt_diff_num(pc[c].v[i][2], b[2]));
    for (c = 0; c < q->nc; c++)
        for (i = 0; q->keep[c] && i < 2; i++)
            pt_sep_put(out, "vcolor %d %d %d\n", pc[c].rgb[i][0], pc[c].rgb[i][1], pc[c].rgb[i][2]);
    for (c = 0, k = 0; c < q->nc; c++)
        if (q->keep[c]) { pt_sep_put(out, "segment %zu %zu\n", k + 1, k + 2); k += 2; }
    free(q);
}
