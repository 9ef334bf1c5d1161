/*
** tests/student/s6_vpw.c -- s6, one mistake: the viewport's width for W
** See LICENSE for copyright and license.
**
** A copy of stages/s6_fb2index.c with one mistake, marked MISTAKE below, for
** tests/diff.sh and docs/teaching.md.  idx = y_fb * w + x_fb with the
** viewport's width.  This stage is not given w (in the teaching renderer
** both widths are in scope), so the copy writes in the 24 of
** tests/data/diff/offset.scene, the scene tests/diff.sh renders with it.
** Build: make STAGE_index=tests/student/s6_vpw.c
*/
#include <assert.h>
#include "s6_fb2index.h"

int64_t pt_fb2index(pt_pix fb, int W, int H, const pt_sink *sink)
{
    int64_t idx = -1;
    pt_vrec r = {0};

    assert(W > 0 && H > 0);
    if (fb.ok && fb.x >= 0 && fb.x < W && fb.y >= 0 && fb.y < H)
        idx = fb.y * (int64_t)24 + fb.x;    /* MISTAKE: idx = y_fb * w + x_fb, w = 24 */
    r.stage = PT_STAGE_INDEX;
    if (idx < 0) r.flags |= PT_REC_NULL;
    if (idx < 0 && fb.ok) r.warn |= PT_WARN_OUTSIDE;
    r.i = idx;
    pt_emit(sink, &r);
    return idx;
}
