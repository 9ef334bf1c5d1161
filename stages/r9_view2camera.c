/*
** stages/r9_view2camera.c -- renderer 9, stage 3: view -> camera (the normalize matrix)
** See LICENSE for copyright and license.
*/
#include "r9_view2camera.h"

static pt_vec4 col4(double x, double y, double z, double w)
{
    pt_vec4 v;

    v.x = x; v.y = y; v.z = z; v.w = w;
    return v;
}

pt_jmat pt_r9_normalize_matrix(const pt_rv_camera *cam)
{
    double l = cam->l, r = cam->r, b = cam->b, t = cam->t;
    pt_jmat m1, m2;

    m1.col[0] = col4(1.0, 0.0, 0.0, 0.0);
    m1.col[1] = col4(0.0, 1.0, 0.0, 0.0);
    if (cam->perspective) {             /* PerspectiveNormalizeMatrix: skew */
        m1.col[2] = col4((r+l)/2, (t+b)/2, 1.0, 0.0);
        m1.col[3] = col4(0.0, 0.0, 0.0, 1.0);
    } else {                            /* OrthographicNormalizeMatrix: translate */
        m1.col[2] = col4(0.0, 0.0, 1.0, 0.0);
        m1.col[3] = col4(-(r+l)/2, -(t+b)/2, 0.0, 1.0);
    }
    m2.col[0] = col4(2/(r-l), 0.0, 0.0, 0.0);
    m2.col[1] = col4(0.0, 2/(t-b), 0.0, 0.0);
    m2.col[2] = col4(0.0, 0.0, 1.0, 0.0);
    m2.col[3] = col4(0.0, 0.0, 0.0, 1.0);
    return pt_jmat_times(&m2, &m1);     /* m2.times(m1): skew first, then scale */
}

pt_vec4 pt_r9_view2camera(pt_vec4 v, const pt_jmat *norm)
{
    return pt_jmat_times_vec(norm, v);      /* v_c = N v_v */
}

void pt_r9_view2camera_all(pt_vec4 *v, size_t n, const pt_jmat *norm)
{
    pt_jmat_times_vecs(norm, v, n);         /* v_c = N v_v, each */
}
