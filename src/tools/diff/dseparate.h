/*
** src/tools/diff/dseparate.h -- pipetrace diff: a scene that tells apart the mistakes diff could not
** See LICENSE for copyright and license.
**
** When several known mistakes each explain every vertex and pixel, diff says
** "ambiguous", lists them and prints a small scene made for the purpose, on
** which each of them gives a trace of its own (and none the right one's): the
** student renders it with their build, diffs it, and one mistake is named.
**
** The scene is searched for, not written by hand.  A fixed family of
** candidate pieces -- renderer 4: vertices on ties of the pixel plane, on both
** sides of zero, one pixel off each edge of the framebuffer, translated,
** behind the camera; segments along which the DDA's running y reaches
** 0.49999999999999994, that start left of the viewport, that run along a row;
** renderers 7 and 9, for the stage whose mistakes are listed: the world's
** positions of a rotation and a translation, the camera's segments off the
** lines through the eye where a skew and a size mistake agree, the near
** clip's segments across the near plane and its mirror image, the clip's
** segments across one edge -- is run through the right stages and through
** each known mistake, with the
** catalogue's own functions (those diff tests a hypothesis with), and the
** fewest pieces are kept, greedily, that tell every listed mistake from every
** other mistake of the catalogue and from the right stages.
*/
#ifndef PT_DSEPARATE_H
#define PT_DSEPARATE_H

#include <stddef.h>
#include "tools/catalogue79.h"
#include "tools/diff/dsearch.h"

/* What renderer 4's search starts from: EXPECTED's header. */
typedef struct pt_sep_r4 {
    int have;                    /* 1: the sizes below are EXPECTED's */
    int w, h, x_ul, y_ul;        /* the viewport */
    int W, H;                    /* the framebuffer */
    int perspective;             /* 1: perspective, 0: orthographic */
    int pixels_only;             /* 1: the rasterizer's mistakes (every vertex
                                 ** agreed): told apart by the pixels alone */
} pt_sep_r4;

/* The scene for renderer 4 that tells the n mistakes names[] (the
** catalogue's names: pt_mistakes, or with pixels_only pt_raster_mistakes)
** apart, into *out.  This function can't fail. */
void pt_sep_classic(const pt_sep_r4 *sp, const char *const *names, size_t n, pt_sep *out);

/* The same for renderers 7 and 9 (pt_mistakes79, all of one stage), with
** EXPECTED's camera: a scene for the world's, the camera's, the near clip's
** and the clip's mistakes; for the pixels' (which never both fit a pixel
** strictly between 0 and 1) a sentence saying why there is none.  This
** function can't fail. */
void pt_sep_course(const pt_c79cam *cam, const char *const *names, size_t n, pt_sep *out);

/* Print s to standard output between two marker lines (or its sentence), and
** when path is not NULL write the scene there: then returns 0, or -1 after a
** message on standard error. */
int pt_sep_emit(const pt_sep *s, const char *path);

#endif
