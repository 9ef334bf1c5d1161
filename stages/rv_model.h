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
*/
#ifndef PT_RV_MODEL_H
#define PT_RV_MODEL_H

#include <stddef.h>
#include <stdint.h>
#include "stages/pt_stage.h"
#include "stages/pt_mat4.h"

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

#endif
