/*
** src/io/trace_kraft.h -- write the course renderer's own debug log (--format kraft)
** See LICENSE for copyright and license.
**
** The teaching renderer the seeds come from (renderer 4) prints, with its
** scene's debug flag on, a log of every model: its translation, the whole
** vertex list after each of its stages ("0. Model", "1. Camera", "2.
** Projected", "3. Pixel-plane"; vIndex 0-based), the segments and colours,
** and "4. Rasterize" per segment; with its rasterizer's debug flag on too,
** the slopes, the rounded endpoints and one line per pixel ("Clip: " for a
** pixel outside the viewport).  This module writes that log byte for byte
** for a scene of the classic camera, so a student can compare their own
** renderer's log with it (and pipetrace diff reads either: tread_kraft.c).
** Every position is named after its model; every model has one colour per
** vertex, its `color`; the scene's name is empty.  Numbers are spelled as
** Java spells them (io/jnum.h).  The numbers are pt_run()'s: each vertex's
** journey (pt_run_journeys), and each step's pixel from the viewport stage.
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

/* Write the log of scene s to f; pixels: 1 adds the rasterizer's lines
** (--format kraft-pixels).  Returns 0; or -1 with a message in err ("FILE:
** error: ...": the scene uses the matrix camera, which the course's renderer
** does not have; or pixels and a segment that the course's renderer would step
** more than PT_KRAFT_MAX_STEPS times or beyond its int range; or out of
** memory), having written nothing or part of the log (the caller's output
** file is then dropped).  Write errors show in ferror(f). */
int pt_kraft_write(FILE *f, const pt_scene *s, int pixels, char *err, size_t errlen);

#endif
