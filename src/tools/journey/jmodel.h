/*
** src/tools/journey/jmodel.h -- a model's panels laid out, and a pipeline's panel rows (types)
** See LICENSE for copyright and license.
**
** The types the journey's files share, and nothing else (no .c): the
** geometry of one model's panels (pt_jmodel), laid out by journey.c with its
** pipeline's hooks, and those hooks (pt_jrows), one row per pipeline and in
** it one row per stage (pt_jstage_row), which say who draws a stage's panel.
** The rows themselves are in jrows.c.
*/
#ifndef PT_JMODEL_H
#define PT_JMODEL_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"
#include "io/sbuf.h"
#include "tools/journey/jdraw.h"
#include "tools/journey/jplace.h"

#define PT_JOURNEY_PW      400   /* a panel's width, SVG units */
#define PT_JOURNEY_PH      340   /* a panel's height */
#define PT_JOURNEY_REACH   4.0   /* drawn range: at most this many times the
                                 ** stage's rectangle in each direction */
#define PT_JOURNEY_MAXSEG  5000  /* faint wireframe: the first this many segments */
#define PT_JOURNEY_MAXV    2000  /* the HTML page: at most this many vertices */
#define PT_JOURNEY_MAXPIX  8000000  /* pixels the segments of the vertices shown
                                     ** draw, kept (16 bytes each): past it,
                                     ** journey stops, -2 */
#define PT_JOURNEY_FRAMEMAX 16777216  /* framebuffer panel: the whole frame drawn
                                      ** up to this many pixels (W x H) */
#define PT_JOURNEY_RED_RGB {214, 39, 40}    /* the vertex's red, "#d62728" in the
                                            ** panels (jdraw.h's PT_JC_VTX) */

struct pt_jrows;

/* What the layouts need of the used vertices, gathered as the run hands
** their journeys over (pt_jrows.absorb), so that no journey is kept but those
** drawn.  A box is {x_min, y_min, x_max, y_max} of the points that widen a
** panel, by that panel's rules; +inf, +inf, -inf, -inf when none did. */
typedef struct pt_jspan {
    double b[PT_NSTAGES_ALL][4]; /* classic rules: model and camera (finite, not
                                 ** huge), image .. framebuffer (within
                                 ** PT_JOURNEY_REACH of the stage's rectangle) */
    double big, deep;            /* the largest |x_m|, |y_m|, |z_m| and -z_c, not
                                 ** huge (0: none) */
    double wbig;                 /* matrix: the largest |x_w|, |y_w|, |z_w| (0: none) */
    double depth;                /* matrix: the largest 1.1 z_v (-inf: none) */
    double world[4];             /* matrix: the world panel's points */
    double clip[3][4];           /* matrix: (w_k, x_k), (w_k, y_k), (w_k, z_k) */
} pt_jspan;

/* A pixel the rasterizer drew, in viewport coordinates. */
typedef struct pt_jpix {
    int64_t x_vp, y_vp;
} pt_jpix;

/* The panels' geometry for one model: shared by all its vertices. */
typedef struct pt_jmodel {
    const pt_scene *s;           /* the scene, not owned */
    const pt_model *m;           /* the model drawn, not owned */
    const struct pt_jrows *rows; /* its pipeline's panels (jrows.h) */
    pt_stage_params par;         /* the numbers of the formulas */
    unsigned char *used;         /* used[k]: a segment uses vertex k + 1; owned */
    unsigned char *show;         /* show[k]: vertex k + 1's foreground is drawn; owned */
    size_t *keep;                /* the vertices (0-based, ascending) whose whole
                                 ** journeys are kept, the only ones drawn: those
                                 ** shown, the other ends of their segments, the
                                 ** ends of the first PT_JOURNEY_MAXSEG segments
                                 ** (the wireframe), vertex 1; owned */
    pt_journey *kept;            /* kept[i]: vertex keep[i] + 1's, from pt_run(); owned */
    size_t nkeep;
    pt_jspan span;               /* every used vertex's part in the layout */
    unsigned char *code;         /* matrix: code[k], vertex k + 1's outcode (a
                                 ** used vertex's; zeros for the classic camera);
                                 ** owned */
    pt_jpix *pix;                /* the pixels drawn of the segments of the
                                 ** vertices shown (the others': none), from the
                                 ** same pt_run()'s pixel records, in record
                                 ** order; owned */
    size_t *pixat;               /* segment s's: pix[pixat[s] .. pixat[s + 1]);
                                 ** nseg + 1 of them; owned */
    pt_jview view[PT_NSTAGES_ALL];  /* each panel's main view (index: unused) */
    pt_jview clip_y, clip_z;     /* matrix: the (w_k, y_k) and (w_k, z_k) plots */
    pt_journey *cut;             /* matrix: the points clipping made on the
                                 ** segments drawn (pt_jseg_drawn()), owned */
    size_t ncut, *cutix;         /* cutix[2s], [2s + 1]: segment s's end a, b:
                                 ** 0 the vertex, i + 1 cut[i], CULLED: none,
                                 ** UNKEPT: a point of a segment not drawn; owned */
    double axis_m, axis_c;       /* axis lengths of the two 3-D panels */
    double depth;                /* camera panel: depth of the view pyramid */
    pt_jplace *place;            /* place[st]: stage st's lines, boxes and labels
                                 ** (jplace.h), recorded by its background; owned */
    const pt_fb *frame;          /* the scene rendered, every model: the
                                 ** framebuffer panel's pixels; NULL when
                                 ** W x H > PT_JOURNEY_FRAMEMAX */
    pt_fb own_frame;             /* frame, when this jm rendered it; owned */
    int owns_frame;
} pt_jmodel;

#define PT_JOURNEY_CULLED ((size_t)-1)   /* cutix: the segment is wholly outside */
#define PT_JOURNEY_UNKEPT ((size_t)-2)   /* cutix: cut, on a segment not drawn */

/* Who draws stage st's panel: its background (frame, title and formula are
** the driver's; this draws what is inside the box), its foreground for vertex
** k + 1 whose journey is j (reached st), and the note under it (n bytes into
** t; used: some segment uses the vertex). */
typedef struct pt_jstage_row {
    void (*bg)(pt_sbuf *sb, const pt_jmodel *jm, pt_stage st);
    void (*fg)(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k, pt_stage st);
    void (*note)(char *t, size_t n, const pt_jmodel *jm, const pt_journey *j, pt_stage st,
                 int used);
} pt_jstage_row;

/* A pipeline's panels.  stage[st] is NULL for a stage not in its order.  The
** three `stopped` hooks draw a stage that a point did not reach (it stopped
** before, pt_journey_stopped()); NULL for a pipeline whose points go through
** every stage (its stops_at is its last stage). */
typedef struct pt_jrows {
    void (*absorb)(pt_jmodel *jm, const pt_journey *j, size_t k);
                                 /* take used vertex k + 1's journey j into
                                 ** jm->span (and what else the layout needs of
                                 ** it), as the run hands it over */
    int (*layout)(pt_jmodel *jm);
                                 /* fit the views of its panels (jm->view, and
                                 ** what else they keep); returns 0, or -1 when
                                 ** out of memory */
    int (*ends)(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb);
                                 /* the journeys of segment s's ends as stage st
                                 ** sees them; returns 0 when it sees none */
    int (*pixelplane)(const pt_jmodel *jm, const pt_journey *j, pt_vec2 *pp);
                                 /* the point of the pixel plane the rasterizer
                                 ** draws j's end from (to the pipeline's
                                 ** to_viewport); returns 0, or -1 when none */
    void (*stopped_fg)(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k,
                       pt_stage st);
    size_t (*stopped_coords)(char *t, size_t n, pt_stage st);
                                 /* the coordinates label ("(x_n, y_n, z_n): not
                                 ** reached"); returns its length */
    void (*stopped_note)(char *t, size_t n, const pt_journey *j, pt_stage st);
    const pt_jstage_row *stage[PT_NSTAGES_ALL];
} pt_jrows;

#endif
