/*
** src/io/trace_kraft.h -- write the course renderer's own debug log (--format kraft)
** See LICENSE for copyright and license.
**
** The course's renderer 4 prints, with its scene's or a position's debug
** flag on, a log of every position and model: its translation, the whole
** vertex list after each of its stages ("0. Model", "1. Camera", "2.
** Projected", "3. Pixel-plane"; vIndex 0-based), the primitives (segments
** and points in file order) and the colour list, and "4. Rasterize" per
** primitive; with its rasterizer's debug flag on too, the slopes, the
** rounded endpoints and one line per pixel, or per anti-aliased pair of
** pixels ("Clip: " for one outside the viewport), and each point's pixels.
** Its warnings (CheckModel, the default colours) come whatever the flags.
** This module writes that log byte for byte for a scene of the classic
** camera, so a student can compare their own renderer's log with it (and
** pipetrace diff reads either: tread_kraft.c).  Numbers are spelled as Java
** spells them (io/jnum.h).  The numbers are pt_run()'s: each vertex's
** journey (pt_run_journeys), each step's pixel from the viewport stage and
** its colour from the rasterizer (core/raster.h), which draws the image.
*/
#ifndef PT_TRACE_KRAFT_H
#define PT_TRACE_KRAFT_H

#include <stdio.h>
#include "core/pipetrace.h"

/* The course's debug switches (--kraft-debug LIST): which of its flags the
** course's program sets.  --format kraft is PT_KDBG_SCENE, kraft-pixels
** PT_KDBG_SCENE | PT_KDBG_RASTERIZE. */
#define PT_KDBG_SCENE      0x01u   /* scene.debug */
#define PT_KDBG_POSITION   0x02u   /* every Position.debug */
#define PT_KDBG_RASTERIZE  0x04u   /* Rasterize.debug */
#define PT_KDBG_CLIP       0x08u   /* Clip.debug (both clippers' lines) */
#define PT_KDBG_NEARCLIP   0x10u   /* NearClip.debug (read by no renderer) */
#define PT_KDBG_ALL        0x1Fu

/* Most steps of one segment the pixel log writes: a line each. */
#define PT_KRAFT_MAX_STEPS (1L << 24)

/* Write the log of scene s to f as the course's program prints it with the
** debug switches dbg (PT_KDBG_*: scene or position show the log, rasterize
** adds the rasterizer's lines, clip and nearclip change nothing in renderer
** 4).  Returns 0; or -1 with a message in err ("FILE: error: ...": the scene
** uses the matrix camera, which the course's renderer does not have; or
** the rasterizer's lines and a segment that the course's renderer would
** step more than PT_KRAFT_MAX_STEPS times or beyond its int range, or a
** point as large or beyond it; or out of memory), having written nothing or
** part of the log (the caller's output file is then dropped).  Write errors
** show in ferror(f). */
int pt_kraft_write(FILE *f, const pt_scene *s, unsigned dbg, char *err, size_t errlen);

/* The course's renderer can log the pixels of every segment and point of s:
** ends and centres in its int range, at most PT_KRAFT_MAX_STEPS lines each
** (trace_kraft_check.c).  Returns 0, or -1 with a message in err. */
int pt_kraft_check(const pt_scene *s, char *err, size_t errlen);

/* The rule of every renderer's pixel log for a point of radius radius of
** model `model`: at most PT_KRAFT_MAX_STEPS pixels ((2 radius + 1)^2; none
** for radius < 0).  Returns 0, or -1 with a message in err ("FILE: error:
** model 'NAME': a point of radius R has N pixels, more than ...").  This
** function can't fail otherwise (trace_kraft_check.c). */
int pt_kraft_point_check(const pt_scene *s, const char *model, int radius, char *err,
                         size_t errlen);

/* The switches of LIST (--kraft-debug: scene, position, rasterize, clip,
** nearclip, all, none, comma-separated) into *dbg.  Returns 0, or -1 when an
** item is none of them (then *dbg is unchanged).  This function can't fail
** otherwise (trace_kraft_check.c). */
int pt_kraft_debug_parse(const char *list, unsigned *dbg);

#endif
