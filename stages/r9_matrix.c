/*
** stages/r9_matrix.c -- renderer 9's Matrix: its builders and products, in Java's order
** See LICENSE for copyright and license.
*/
#include <math.h>
#include "r9_matrix.h"

#define JAVA_PI 3.141592653589793       /* Math.PI, 0x1.921fb54442d18p+1 */

static pt_vec4 col4(double x, double y, double z, double w)
{
    pt_vec4 v;

    v.x = x; v.y = y; v.z = z; v.w = w;
    return v;
}

static pt_jmat from_cols(pt_vec4 c1, pt_vec4 c2, pt_vec4 c3, pt_vec4 c4)
{
    pt_jmat m;

    m.col[0] = c1; m.col[1] = c2; m.col[2] = c3; m.col[3] = c4;
    return m;
}

/* Matrix.scale(x, y, z); Matrix.identity() is scale(1, 1, 1). */
static pt_jmat jscale(double x, double y, double z)
{
    return from_cols(col4(x, 0.0, 0.0, 0.0), col4(0.0, y, 0.0, 0.0),
                     col4(0.0, 0.0, z, 0.0), col4(0.0, 0.0, 0.0, 1.0));
}

/* Matrix.rotate(theta, x, y, z): Rodrigues' formula, term by term as Java
** writes it (norm from x*x + y*y + z*z, then c and s of (PI/180.0)*theta). */
static pt_jmat jrotate(double theta, double x, double y, double z)
{
    double norm = sqrt(x*x + y*y + z*z);
    double ux = x/norm, uy = y/norm, uz = z/norm;
    double c = cos((JAVA_PI/180.0)*theta);
    double s = sin((JAVA_PI/180.0)*theta);

    return from_cols(
        col4(ux*ux*(1-c)+c,      uy*ux*(1-c)+(uz*s), uz*ux*(1-c)-(uy*s), 0.0),
        col4(ux*uy*(1-c)-(uz*s), uy*uy*(1-c)+c,      uz*uy*(1-c)+(ux*s), 0.0),
        col4(ux*uz*(1-c)+(uy*s), uy*uz*(1-c)-(ux*s), uz*uz*(1-c)+c,      0.0),
        col4(0.0,                0.0,                0.0,                1.0));
}

/* The matrix an operation builds. */
static pt_jmat build(const pt_matop *op)
{
    const double *a = op->a;

    switch (op->kind) {
    case PT_MATOP_IDENTITY:  return jscale(1.0, 1.0, 1.0);
    case PT_MATOP_TRANSLATE:
        return from_cols(col4(1.0, 0.0, 0.0, 0.0), col4(0.0, 1.0, 0.0, 0.0),
                         col4(0.0, 0.0, 1.0, 0.0), col4(a[0], a[1], a[2], 1.0));
    case PT_MATOP_SCALE:     return jscale(a[0], a[1], a[2]);
    case PT_MATOP_ROTATE:    return jrotate(a[0], a[1], a[2], a[3]);
    case PT_MATOP_ROWS:      /* buildFromRows: row i's k-th entry goes to column k */
        return from_cols(col4(a[0], a[4], a[8],  a[12]), col4(a[1], a[5], a[9],  a[13]),
                         col4(a[2], a[6], a[10], a[14]), col4(a[3], a[7], a[11], a[15]));
    }
    return jscale(1.0, 1.0, 1.0);
}

/* The product, inline here for pt_jmat_times_vecs' loop. */
static inline pt_vec4 times_vec(const pt_jmat *a, pt_vec4 v)
{
    const pt_vec4 *c = a->col;

    return col4((c[0].x * v.x) + (c[1].x * v.y) + (c[2].x * v.z) + (c[3].x * v.w),
                (c[0].y * v.x) + (c[1].y * v.y) + (c[2].y * v.z) + (c[3].y * v.w),
                (c[0].z * v.x) + (c[1].z * v.y) + (c[2].z * v.z) + (c[3].z * v.w),
                (c[0].w * v.x) + (c[1].w * v.y) + (c[2].w * v.z) + (c[3].w * v.w));
}

pt_vec4 pt_jmat_times_vec(const pt_jmat *a, pt_vec4 v)
{
    return times_vec(a, v);
}

pt_jmat pt_jmat_times(const pt_jmat *a, const pt_jmat *b)
{
    return from_cols(pt_jmat_times_vec(a, b->col[0]), pt_jmat_times_vec(a, b->col[1]),
                     pt_jmat_times_vec(a, b->col[2]), pt_jmat_times_vec(a, b->col[3]));
}

pt_jmat pt_r9_position_matrix(const pt_matop *ops, size_t n)
{
    pt_jmat m = jscale(1.0, 1.0, 1.0), op;
    size_t i;

    for (i = 0; i < n; i++) {
        op = build(&ops[i]);
        switch (ops[i].mul) {
        case PT_MATMUL_POST: m = pt_jmat_times(&m, &op); break;
        case PT_MATMUL_PRE:  m = pt_jmat_times(&op, &m); break;
        case PT_MATMUL_SET:  m = op; break;
        }
    }
    return m;
}

void pt_jmat_times_vecs(const pt_jmat *a, pt_vec4 *v, size_t n)
{
    size_t k;

    for (k = 0; k < n; k++) v[k] = times_vec(a, v[k]);
}
