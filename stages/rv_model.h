/*
** stages/rv_model.h -- the model the view-volume renderers (7 and 9) pass between stages
** See LICENSE for copyright and license.
**
** The course's renderers 7 and 9 work on whole models, as its Java does: each
** stage takes a model and gives the next one.  A model is three lists, as
** scene/Model.java keeps them:
**   v[]  vertices (x, y, z, w); renderer 7 has no w (kept 1.0);
**   c[]  colours, java.awt.Color's float components (an int colour b is
**        b / 255f; a colour made from floats keeps its floats);
**   p[]  primitives in list order: a line segment (two vertex indices, two
**        colour indices) or a point (one of each, and a radius).
** The transform stages give new vertices one for one; the clip stages append
** the vertices and colours they make (so a new vertex is number nv + k) and
** give a new primitive list.  Indices here are 0-based; the log and the trace
** print them as the course does (0-based in its log, 1-based in pipetrace's
** trace: the scene's numbering).
** Every index a primitive holds must be in range (the scene parser checks
** them); the stages do not check again.
*/
#ifndef PT_RV_MODEL_H
#define PT_RV_MODEL_H

#include <stddef.h>
#include <stdint.h>
#include "pt_stage.h"
#include "pt_mat4.h"

typedef enum pt_rv_kind {
    PT_RV_LINE,                  /* LineSegment(v0, v1, c0, c1) */
    PT_RV_POINT                  /* Point(v0, c0), radius */
} pt_rv_kind;

typedef struct pt_rv_prim {
    pt_rv_kind kind;
    uint32_t v[2];               /* vertex indices (a point: v[0]) */
    uint32_t c[2];               /* colour indices (a point: c[0]) */
    int radius;                  /* a point's radius (Point.radius) */
} pt_rv_prim;

typedef struct pt_rv_model {
    pt_vec4 *v;   size_t nv, cap_v;
    pt_rgb *c;    size_t nc, cap_c;
    pt_rv_prim *p; size_t np, cap_p;
} pt_rv_model;

/* The Camera as renderers 7 and 9 keep it (scene/Camera.java): the view
** rectangle l .. r, b .. t (already divided by the focal length), n the z of
** the near plane (-near), and renderer 9's view vector (camera.translate). */
typedef struct pt_rv_camera {
    int perspective;             /* 1: projPerspective, 0: projOrtho */
    double l, r, b, t, n;
    pt_vec3 view;                /* renderer 9 only; 0 0 0 */
} pt_rv_camera;

/* One cut a clip stage makes (the course's debug lines print it). */
typedef enum pt_rv_edge {
    PT_RV_NEAR,                  /* the near plane z = n (NearClip) */
    PT_RV_XPOS, PT_RV_XNEG,      /* the view rectangle's x = +1, x = -1, */
    PT_RV_YPOS, PT_RV_YNEG       /*   y = +1, y = -1 (Clip) */
} pt_rv_edge;

typedef struct pt_rv_cut {
    pt_rv_edge edge;
    int off;                     /* the end cut off: 0 (v0) or 1 (v1) */
    double plane;                /* n, or +-1 */
    double t;                    /* the course's t (its formula in the stage) */
    pt_vec4 p[3];                /* near: v0, v1, the new point;
                                 ** rectangle: inside, outside, the new point */
    pt_rgb c[3];                 /* their colours, in the same order */
    uint32_t v_new, c_new;       /* the indices the new vertex and colour got */
} pt_rv_cut;

/* Who hears a clip stage, primitive by primitive (any callback may be NULL). */
typedef struct pt_rv_clip_ls {
    void (*begin)(void *ud, const pt_rv_model *m, const pt_rv_prim *p);
    void (*trivial)(void *ud, int accept);          /* "Trivial accept." / "delete." */
    void (*cut)(void *ud, const pt_rv_cut *c);
    void (*end)(void *ud, const pt_rv_model *m, const pt_rv_prim *p, int accepted);
                                 /* p: the primitive kept, or the original
                                 ** when it was rejected */
    void *ud;
} pt_rv_clip_ls;

/* Make room in m's lists for nv more vertices, nc more colours and np more
** primitives, so that as many appends (or stores past the counts) need no
** allocation: 0, or -1 when out of memory (the counts unchanged). */
int pt_rv_reserve(pt_rv_model *m, size_t nv, size_t nc, size_t np);

/* Append to m's lists: 0, or -1 when out of memory (m unchanged). */
int pt_rv_add_vertex(pt_rv_model *m, pt_vec4 v);
int pt_rv_add_color(pt_rv_model *m, pt_rgb c);
int pt_rv_add_prim(pt_rv_model *m, const pt_rv_prim *p);

/* Finish a cut that a clip stage filled in but for its new colour and
** indices: c[2] = (1 - t_)*c[1] + t_*c[0] in float, t_ = (float)t (both
** clippers' formula: c[1] is the end t runs from); append p[2] and c[2] to
** m, set v_new and c_new, and tell ls->cut.  0; -1 when out of memory, -2
** when java.awt.Color would refuse c[2] (the course's render throws); m is
** unchanged then. */
int pt_rv_cut_finish(pt_rv_model *m, pt_rv_cut *cut, const pt_rv_clip_ls *ls);

/* 1 when java.awt.Color's float constructor takes c: each component in
** 0 .. 1 or NaN (it throws otherwise).  This function can't fail. */
int pt_rv_color_ok(pt_rgb c);

/* Empty m's lists, keeping their room for the next model.  This function
** can't fail. */
void pt_rv_model_empty(pt_rv_model *m);

/* Free what m owns and leave it empty.  This function can't fail. */
void pt_rv_model_free(pt_rv_model *m);

#endif
