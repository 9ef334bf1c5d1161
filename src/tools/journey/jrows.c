/*
** src/tools/journey/jrows.c -- who draws each pipeline's panels: a row per pipeline and stage
** See LICENSE for copyright and license.
**
** The driver (journey.c) asks these rows and never which pipeline it draws:
** a pipeline's layout, how a stage sees a segment's ends, where the
** rasterizer starts, what a stage a point did not reach shows, and per stage
** its background, foreground and note.  Stages two pipelines share point to
** the same row (the matrix camera's model, viewport, framebuffer and index
** are the classic panels).
*/
#include "tools/journey/jrows.h"
#include "tools/journey/journey_classic.h"
#include "tools/journey/journey_matrix.h"

#define CLASSIC(st) [st] = &pt_jclassic_rows[st]
#define MATRIX(st)  [st] = &pt_jmatrix_rows[st]

const pt_jrows pt_jpipes[PT_NPIPES] = {
    [PT_PIPE_CLASSIC] = {
        pt_jclassic_absorb, pt_jclassic_layout, pt_jclassic_ends, pt_jclassic_pixelplane,
        NULL, NULL, NULL,                    /* every point reaches the index */
        {
            CLASSIC(PT_STAGE_MODEL), CLASSIC(PT_STAGE_CAMERA), CLASSIC(PT_STAGE_IMAGE),
            CLASSIC(PT_STAGE_PIXEL), CLASSIC(PT_STAGE_VIEWPORT),
            CLASSIC(PT_STAGE_FRAMEBUFFER), CLASSIC(PT_STAGE_INDEX),
        },
    },
    [PT_PIPE_MATRIX] = {
        pt_jmatrix_absorb, pt_jmatrix_layout, pt_jmatrix_ends, pt_jmatrix_pixelplane,
        pt_jmatrix_stopped_fg, pt_jmatrix_unreached, pt_jmatrix_stopped_note,
        {
            CLASSIC(PT_STAGE_MODEL), MATRIX(PT_STAGE_WORLD), MATRIX(PT_STAGE_VIEW),
            MATRIX(PT_STAGE_CLIP), MATRIX(PT_STAGE_CVV), MATRIX(PT_STAGE_NDC),
            MATRIX(PT_STAGE_SCREEN), CLASSIC(PT_STAGE_VIEWPORT),
            CLASSIC(PT_STAGE_FRAMEBUFFER), CLASSIC(PT_STAGE_INDEX),
        },
    },
};
