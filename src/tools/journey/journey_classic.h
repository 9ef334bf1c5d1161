/*
** src/tools/journey/journey_classic.h -- the classic camera's panels: model .. pixel array
** See LICENSE for copyright and license.
*/
#ifndef PT_JOURNEY_CLASSIC_H
#define PT_JOURNEY_CLASSIC_H

#include <stddef.h>
#include <stdint.h>
#include "tools/journey/jmodel.h"

/* Who draws each classic stage's panel (background, foreground, note),
** indexed by stage; NULL rows for the stages it does not have.  The matrix
** camera's rows for model, viewport, framebuffer and index point here. */
extern const pt_jstage_row pt_jclassic_rows[PT_NSTAGES_ALL];

/* Take used vertex k + 1's journey j into jm->span: its part in the model,
** camera, image, pixel, viewport and framebuffer panels.  Can't fail. */
void pt_jclassic_absorb(pt_jmodel *jm, const pt_journey *j, size_t k);

/* Fit the views of the model, camera, image, pixel, viewport and framebuffer
** panels to jm's used vertices (axes, the view pyramid's depth), from
** jm->span.  Returns 0, or -1 when out of memory. */
int pt_jclassic_layout(pt_jmodel *jm);

/* Segment s's ends as every stage sees them: its two vertices' journeys.
** Returns 1.  This function can't fail. */
int pt_jclassic_ends(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb);

/* The pixel-plane point the rasterizer draws from: j's (x_pp, y_pp).
** Returns 0.  This function can't fail. */
int pt_jclassic_pixelplane(const pt_jmodel *jm, const pt_journey *j, pt_vec2 *pp);

/* The index a pixel (x, y) of a W-wide framebuffer would have without the
** index stage's bounds test, for a pixel off the frame (|x|, |y| < 2^40).  On
** the frame it is pt_fb2index()'s (tests/unit/test_journey.c checks).  Can't fail. */
int64_t pt_jclassic_would_index(int64_t x, int64_t y, int64_t W);

#endif
