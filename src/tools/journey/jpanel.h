/*
** src/tools/journey/jpanel.h -- what every pipeline's panels share: points, segments, wireframe
** See LICENSE for copyright and license.
**
** A panel draws the journeys of one model's vertices (pt_jmodel, jmodel.h):
** where a point of a stage sits in its panel (pt_jlooks[] says how the stage
** is shown), the ends of a segment as a stage sees them (the pipeline's
** hook: after the matrix camera's cvv, where clipping cut it), the faint
** wireframe, the vertex's segments and marker, and the pixels the rasterizer
** lit for them (the run's pixel records, not a line walked again).
*/
#ifndef PT_JPANEL_H
#define PT_JPANEL_H

#include <stddef.h>
#include <stdint.h>
#include "tools/journey/jmodel.h"

/* The point of stage st in its panel's data coordinates: projected for the
** 3-D panels, the pixel's centre for the pixel grids.  Returns 1, or 0 when
** the stage has no such point (no pixel, not reached, not a point) or it is
** not finite; *x, *y are then still set where a direction is known (infinite
** values).  This function can't fail. */
int pt_jstage_xy(const pt_journey *j, pt_stage st, double *x, double *y);

/* The journeys of segment s's two ends as stage st sees them (jm->rows->ends).
** Returns 0 when the stage sees no segment.  This function can't fail. */
int pt_jseg_ends(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb);

/* The faint wireframe of the model in stage st's view (the first
** PT_JOURNEY_MAXSEG segments).  This function can't fail. */
void pt_jwireframe(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st);

/* The segments that use vertex k + 1, in view v, width units wide, a dot at
** each other end.  This function can't fail. */
void pt_jsegments(pt_sbuf *sb, const pt_jmodel *jm, const pt_jview *v, pt_stage st, size_t k,
                  double width);

/* The foreground of a point in a space or a plane: vertex k + 1's segments
** and its marker in stage st's view.  This function can't fail. */
void pt_jfg_point(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st);

/* A 3-D panel's dashed path from the origin along x, then y, then z to j's
** point of stage st.  This function can't fail. */
void pt_jfg_path(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, pt_stage st);

/* The journey of vertex k + 1, one of those jm keeps (jm->keep: the vertices
** shown, the other ends of their segments, the ends of the segments the
** wireframe draws, vertex 1).  This function can't fail. */
const pt_journey *pt_jmodel_journey(const pt_jmodel *jm, size_t k);

/* 1 when the panels draw segment s (0-based): the wireframe's (the first
** PT_JOURNEY_MAXSEG), or one of a vertex shown.  This function can't fail. */
int pt_jseg_drawn(const pt_jmodel *jm, size_t s);

/* Start an empty span (every box empty, every largest value none).  Can't fail. */
void pt_jspan_start(pt_jspan *sp);

/* Grow box b to take in box a, coordinate by coordinate (an empty a leaves
** b as it is).  This function can't fail. */
void pt_jspan_merge(double b[4], const double a[4]);

/* The pixels pt_run() drew of every segment that uses vertex k + 1, from its
** pixel records (jm->pix, kept by pt_jmodel_init's run for the vertices it
** was told are shown: k + 1 must be one), in segment and step order into
** px(ud, x_vp, y_vp).  This function can't fail. */
void pt_jraster_segs(const pt_jmodel *jm, size_t k, void (*px)(void *, int64_t, int64_t),
                     void *ud);

#endif
