/*
** stages/pt_stage.h -- what every stage shares: vectors, stage ids, the trace record
** See LICENSE for copyright and license.
**
** A stage is a pure function from one coordinate space to the next.  It reports what
** it computed through a pt_sink: one pt_vrec per vertex, handed over as numbers (the
** stage never formats text and never knows where the record goes).  A NULL sink means
** "compute, do not report"; the value computed is the same either way.
**
** The stages, in pipeline order, with the suffix each space uses in code and trace:
**
**   model       (x_m,  y_m,  z_m)    the model's own coordinates, as in the scene
**   camera      (x_c,  y_c,  z_c)    s1: add the model's translation
**   image       (x_ip, y_ip, z_ip)   s2: project onto the image plane z = -1 (or 0)
**   pixel       (x_pp, y_pp)         s3: logical pixel plane [0.5, w+0.5) x [0.5, h+0.5)
**   viewport    (x_vp, y_vp)         s4: nearest logical pixel, y flipped, 0-based
**   framebuffer (x_fb, y_fb)         s5: offset by the viewport's upper-left corner
**   index       (idx)                s6: row-major position in the pixel array
*/
#ifndef PT_STAGE_H
#define PT_STAGE_H

#include <stdint.h>

typedef struct pt_vec3 { double x, y, z; } pt_vec3;
typedef struct pt_vec2 { double x, y; } pt_vec2;

/* A pixel position.  ok == 0 means "no value": the coordinate was not finite or too
** large for rounding to an integer to mean anything (see s4_pixel2viewport.h). */
typedef struct pt_pix { int64_t x, y; int ok; } pt_pix;

typedef enum pt_stage {
    PT_STAGE_MODEL,
    PT_STAGE_CAMERA,
    PT_STAGE_IMAGE,
    PT_STAGE_PIXEL,
    PT_STAGE_VIEWPORT,
    PT_STAGE_FRAMEBUFFER,
    PT_STAGE_INDEX,
    PT_NSTAGES
} pt_stage;

/* Flags of a pt_vrec. */
#define PT_REC_BEHIND  0x01u   /* image: z_c > 0 under a perspective camera */
#define PT_REC_INSIDE  0x02u   /* viewport: 0 <= x_vp < w and 0 <= y_vp < h */
#define PT_REC_NULL    0x04u   /* viewport, framebuffer, index: no value */

/* One vertex at one stage.  Which fields hold values depends on the stage:
** model, camera, image use x y z; pixel uses x y; viewport and framebuffer use
** ix iy; index uses i.  PT_REC_NULL marks an integer result that does not exist
** (a pixel outside the framebuffer has no index). */
typedef struct pt_vrec {
    pt_stage stage;            /* which stage produced it */
    unsigned flags;            /* PT_REC_* */
    double x, y, z;            /* real-valued stages */
    int64_t ix, iy;            /* viewport, framebuffer */
    int64_t i;                 /* index */
} pt_vrec;

/* Where stages send their records.  The driver sets which model and vertex the
** records belong to; stages see only this interface. */
typedef struct pt_sink {
    void (*vertex)(void *ud, const pt_vrec *r);   /* called once per record */
    void *ud;                                     /* passed back unchanged */
} pt_sink;

/* Report r to sink (nothing when sink is NULL).  This function can't fail. */
static inline void pt_emit(const pt_sink *sink, const pt_vrec *r)
{
    if (sink) sink->vertex(sink->ud, r);
}

/* Fixed facts about a stage, for headers, step-through and docs. */
typedef struct pt_stage_info {
    const char *name;          /* trace name: "camera" */
    const char *from;          /* space it reads: "model" */
    const char *to;            /* space it writes: "camera" */
    const char *formula;       /* the formula as the trace and docs print it */
} pt_stage_info;

/* The table of the seven stages, indexed by pt_stage. */
extern const pt_stage_info pt_stage_infos[PT_NSTAGES];

/* The pt_stage whose name is s, or -1. This function can't fail. */
int pt_stage_by_name(const char *s);

#endif
