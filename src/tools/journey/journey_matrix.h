/*
** src/tools/journey/journey_matrix.h -- the matrix camera's panels: world .. screen
** See LICENSE for copyright and license.
*/
#ifndef PT_JOURNEY_MATRIX_H
#define PT_JOURNEY_MATRIX_H

#include <stddef.h>
#include "tools/journey/jmodel.h"

/* Who draws each of the matrix camera's own stages' panels (world, view,
** clip, cvv, ndc, screen), indexed by stage; NULL rows elsewhere (its model,
** viewport, framebuffer and index are the classic panels). */
extern const pt_jstage_row pt_jmatrix_rows[PT_NSTAGES_ALL];

/* Take used vertex k + 1's journey j into jm->span (the classic panels'
** part too) and its outcode into jm->code.  Can't fail. */
void pt_jmatrix_absorb(pt_jmodel *jm, const pt_journey *j, size_t k);

/* Lay out the classic panels it shares, run the scene once more for the
** points clipping made on jm's model, and lay out its own panels.  Returns 0,
** or -1 when out of memory. */
int pt_jmatrix_layout(pt_jmodel *jm);

/* Segment s's ends as stage st sees them: its vertices' journeys up to the
** cvv, after it the points clipping made.  Returns 0 when the stage sees none
** of it (wholly outside).  This function can't fail. */
int pt_jmatrix_ends(const pt_jmodel *jm, size_t s, pt_stage st, pt_journey *ja, pt_journey *jb);

/* The rasterizer's pixel-plane point of a journey's viewport pixel (m7's
** pt_viewport2pixelplane()).  Returns 0, or -1 when it has no pixel. */
int pt_jmatrix_pixelplane(const pt_jmodel *jm, const pt_journey *j, pt_vec2 *pp);

/* A stage vertex k + 1 did not reach (it stopped at the cvv): its segments
** from the cuts, and a note in the box; the coordinates label ("(x_n, y_n,
** z_n): not reached", returns its length, cut short when >= n); the note
** under the panel.  These functions can't fail. */
void pt_jmatrix_stopped_fg(pt_sbuf *sb, const pt_jmodel *jm, const pt_journey *j, size_t k,
                           pt_stage st);
size_t pt_jmatrix_unreached(char *t, size_t n, pt_stage st);
void pt_jmatrix_stopped_note(char *t, size_t n, const pt_journey *j, pt_stage st);

#endif
