/*
** stages/r9_matrix.h -- renderer 9's Matrix: a position's 4x4 matrix, built as its Java builds it
** See LICENSE for copyright and license.
**
** A scene gives a position's matrix as a list of operations (the `matrix`,
** `matrix-pre`, `matrix-set` and renderer 9's `translate` lines):
**   POST  M = M.times(OP)     PRE  M = OP.times(M)     SET  M = OP
** starting from Matrix.identity().  OP is one of Matrix's builders, as
** Matrix.java builds them (a Matrix is four column vectors):
**   identity = scale(1, 1, 1);  translate: column 4 = (x, y, z, 1);
**   scale: diag(x, y, z, 1);  buildFromRows: row i's entries become the
**   columns' i-th components (a transpose);
**   rotate(theta, x, y, z): norm = sqrt(x*x + y*y + z*z), u = (x, y, z)/norm,
**   c = cos((PI/180.0)*theta), s = sin(...), column 1 =
**   (ux*ux*(1-c)+c, uy*ux*(1-c)+(uz*s), uz*ux*(1-c)-(uy*s), 0), column 2 =
**   (ux*uy*(1-c)-(uz*s), uy*uy*(1-c)+c, uz*uy*(1-c)+(ux*s), 0), column 3 =
**   (ux*uz*(1-c)+(uy*s), uy*uz*(1-c)-(ux*s), uz*uz*(1-c)+c, 0) (Rodrigues:
**   R = c I + (1-c) u u^T + s [u]x); rotateX(theta) is rotate(theta, 1, 0, 0),
**   so its M00 = 1*1*(1-c)+c, not always 1.0.  Java's Math.sin/cos differ
**   from libm's in the last bit for about 0.2% of angles.
** A.times(v): x = (A00*v.x) + (A01*v.y) + (A02*v.z) + (A03*v.w), each row
** left to right, all four products; A.times(B) = A times each column of B.
*/
#ifndef PT_R9_MATRIX_H
#define PT_R9_MATRIX_H

#include <stddef.h>
#include "pt_mat4.h"

typedef enum pt_matmul {
    PT_MATMUL_POST,              /* matrix OP */
    PT_MATMUL_PRE,               /* matrix-pre OP */
    PT_MATMUL_SET                /* matrix-set OP, and renderer 9's translate */
} pt_matmul;

typedef enum pt_matop_kind {
    PT_MATOP_IDENTITY,           /* Matrix.identity() */
    PT_MATOP_TRANSLATE,          /* Matrix.translate(a0, a1, a2) */
    PT_MATOP_SCALE,              /* Matrix.scale(a0, a1, a2) (`scale S`: S S S) */
    PT_MATOP_ROTATE,             /* Matrix.rotate(a0 degrees, a1, a2, a3);
                                 ** `rotate x DEG` is rotate(DEG, 1, 0, 0) */
    PT_MATOP_ROWS                /* Matrix.buildFromRows(a0 .. a15, row by row) */
} pt_matop_kind;

typedef struct pt_matop {
    pt_matmul mul;
    pt_matop_kind kind;
    double a[16];
} pt_matop;

/* A Matrix as renderer 9 keeps it: four column vectors. */
typedef struct pt_jmat { pt_vec4 col[4]; } pt_jmat;

/* The position's matrix: identity, then ops[0 .. n-1] in order (ops may be
** NULL when n is 0).  This function can't fail. */
pt_jmat pt_r9_position_matrix(const pt_matop *ops, size_t n);

/* A.times(B) and A.times(v), summed as Matrix.java sums them.  These
** functions can't fail. */
pt_jmat pt_jmat_times(const pt_jmat *a, const pt_jmat *b);
pt_vec4 pt_jmat_times_vec(const pt_jmat *a, pt_vec4 v);
/* v[k] = a v[k] (pt_jmat_times_vec) for each of n vectors, in place.  This
** function can't fail. */
void pt_jmat_times_vecs(const pt_jmat *a, pt_vec4 *v, size_t n);

#endif
