/*
** src/io/tread79.h -- read the traces and logs of the course's renderers 7 and 9 back into memory
** See LICENSE for copyright and license.
**
** What `pipetrace diff` compares for a renderer 7 or 9 scene, from any of:
**   pipetrace's trace of it   JSON Lines (exact doubles), text (6 decimals),
**                             CSV (exact doubles, no pixels): trace_course_rec.c;
**   the course's log          as its jar prints it on System.err, or as
**                             `pipetrace --format kraft` writes it (5 decimals;
**                             colours as java.awt.Color bytes; pixels with 4).
** Each vertex at each stage becomes one pt_t79v, keyed by (position, 1-based
** vertex number, stage); the vertices the clip stages make keep the numbers
** the course gives them (old count + k).  The log lists every vertex after a
** clip stage; only the ones that stage made are kept for it, as the trace
** has them.  Each pixel the rasterizer reports becomes one pt_t79px in
** framebuffer coordinates.  Lines of no kind read here are counted (unread).
** Nothing here prints; an error comes back as "FILE:LINE:COL: error: ...".
*/
#ifndef PT_TREAD79_H
#define PT_TREAD79_H

#include <stddef.h>
#include <stdint.h>
#include "io/tread.h"

/* The stages of renderers 7 and 9, in pipeline order (world: renderer 9). */
typedef enum pt_t79_stage {
    PT_T79_MODEL, PT_T79_WORLD, PT_T79_VIEW, PT_T79_CAMERA, PT_T79_NEARCLIP,
    PT_T79_IMAGE, PT_T79_CLIP
} pt_t79_stage;
#define PT_T79_NSTAGES 7

/* The stage's name as the trace spells it.  This function can't fail. */
const char *pt_t79_stage_name(int st);

/* What a file of a renderer 7 or 9 scene is. */
typedef enum pt_t79_kind {
    PT_T79_JSONL, PT_T79_TEXT, PT_T79_CSV, PT_T79_LOG
} pt_t79_kind;

/* One vertex at one stage. */
typedef struct pt_t79v {
    uint32_t pos;                /* position name id */
    uint32_t v;                  /* 1-based vertex number */
    uint32_t line;               /* line of the file */
    unsigned char st;            /* pt_t79_stage */
    unsigned char has_rgb;       /* 1: rgb holds its colour */
    unsigned char has_w;         /* 1: x[3] is its w */
    double x[4];                 /* x, y, z, w */
    double rgb[3];               /* the colour's components, 0 .. 1 (a log: byte/255) */
} pt_t79v;

/* One pixel the rasterizer wrote. */
typedef struct pt_t79px {
    int64_t x, y;                /* framebuffer pixel */
    double rgb[3];               /* its colour, 0 .. 1 */
    double cov;                  /* its coverage (a trace's), or -1 */
    uint32_t line;               /* line of the file */
    uint32_t pair;               /* 1-based index of the anti-aliasing partner, 0: none */
    uint32_t pos, prim;          /* its position's name id, its primitive (a trace's; log: 0) */
    unsigned char seg_end;       /* 1: a segment's last pixel, which the course
                                 ** writes after the loop, without gamma */
} pt_t79px;

/* A primitive a log lists as a clip stage's input (0-based, as the log). */
typedef struct pt_t79prim {
    uint32_t pos;                /* position name id */
    unsigned char st;            /* PT_T79_CAMERA: entering the near clip;
                                 ** PT_T79_NEARCLIP: entering the clip */
    unsigned char point;         /* 1: a Point (v[0], c[0], radius) */
    uint32_t v[2], c[2];         /* vertex and colour indices */
    int radius;
    size_t seq;                  /* its place among the file's primitives */
} pt_t79prim;

/* A trace or log read back. */
typedef struct pt_t79 {
    pt_t79_kind kind;
    int renderer;                /* 7 or 9 */
    double vtol;                 /* half a unit in the last digit of its coordinates */
    double ctol;                 /* the same for vertex colours (0: exact floats) */
    int cbytes;                  /* 1: vertex colours are java.awt.Color bytes */
    double ptol;                 /* the same for pixel colours */
    int have_cam;                /* 1: the camera below is known */
    int persp;                   /* 1: perspective */
    double l, r, b, t, n;        /* the view rectangle and the near plane's z */
    int aa, gamma;               /* the switches: 1 on, 0 off, -1 not said */
    int raster;                  /* 1: the rasterizer's pixels are in it */
    pt_t79v *vx; size_t nvx, cap_vx;    /* vertices, file order; owned */
    pt_t79px *px; size_t npx, cap_px;   /* pixels, file order; owned */
    pt_t79prim *pr; size_t npr, cap_pr; /* a log's primitive lists; owned */
    uint64_t unread;             /* lines of no kind read here */
    uint64_t unread_line;        /*   the first of them (0: none) */
} pt_t79;

/* The renderer (7 or 9) whose scene buf[0..len) is a trace or log of, or 0
** (its first 1 KiB tell; a CSV trace, whether it has a world stage).  This
** function can't fail. */
int pt_t79_renderer(const char *buf, size_t len);

/* Parse buf[0..len) (buf[len] == '\0'), named path in messages, into *t;
** names go into nm.  Returns 0, or -1 with "FILE:LINE:COL: error: ..." in err.
** Free *t with pt_t79_free() either way. */
int pt_t79_parse(pt_t79 *t, const char *path, const char *buf, size_t len, pt_names *nm,
                 char *err, size_t errlen);

/* Free what *t owns.  This function can't fail. */
void pt_t79_free(pt_t79 *t);

#endif
