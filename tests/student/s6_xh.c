/*
** tests/student/s6_xh.c -- s6, one mistake: x * H + y for y * W + x
** See LICENSE for copyright and license.
**
** A copy of stages/s6_fb2index.c with one mistake, marked MISTAKE below, for
** tests/diff.sh and docs/teaching.md.  idx = x_fb * H + y_fb numbers
** the pixels column by column, but the array is row-major.
** Build: make STAGE_index=tests/student/s6_xh.c
*/
#include <assert.h>
#include "s6_fb2index.h"

int64_t pt_fb2index(pt_pix fb, int W, int H, const pt_sink *sink)
{
    int64_t idx = -1;
    pt_vrec r = {0};

    assert(W > 0 && H > 0);
    if (fb.ok && fb.x >= 0 && fb.x < W && fb.y >= 0 && fb.y < H)
        idx = fb.x * (int64_t)H + fb.y;     /* MISTAKE: idx = x_fb * H + y_fb */
    r.stage = PT_STAGE_INDEX;
    if (idx < 0) r.flags |= PT_REC_NULL;
    if (idx < 0 && fb.ok) r.warn |= PT_WARN_OUTSIDE;
    r.i = idx;
    pt_emit(sink, &r);
    return idx;
}
