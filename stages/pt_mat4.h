/*
** stages/pt_mat4.h -- 4x4 matrices on homogeneous row vectors, and the camera's
** See LICENSE for copyright and license.
**
** The matrix camera follows the convention of Direct3D-style renderers: points
** are ROW vectors and a matrix multiplies from the right, v' = v * M, so in a
** product A * B the transformation A happens first.  m[r][c] is row r, column
** c; a translation sits in the last row.
**
**   v * M = (x y z w) | m00 m01 m02 m03 |    x' = x*m00 + y*m10 + z*m20 + w*m30
**                     | m10 m11 m12 m13 |    y' = x*m01 + y*m11 + z*m21 + w*m31
**                     | m20 m21 m22 m23 |    ...
**                     | m30 m31 m32 m33 |    (summed left to right, no fma)
**
** The camera looks along +direction; the view space is left-handed: x right
** (horizontal = up x direction), y up, z forward.  docs/cameras.md compares
** this with the classic camera.
*/
#ifndef PT_MAT4_H
#define PT_MAT4_H

#include "pt_stage.h"

typedef struct pt_vec4 { double x, y, z, w; } pt_vec4;
typedef struct pt_mat4 { double m[4][4]; } pt_mat4;   /* m[row][col] */

/* The identity.  This function can't fail. */
pt_mat4 pt_mat4_identity(void);

/* a * b: first a, then b.  This function can't fail. */
pt_mat4 pt_mat4_mul(const pt_mat4 *a, const pt_mat4 *b);

/* e, the binary exponent of (x, y, z)'s largest component (0 when they are
** all 0 or one is not finite): scaling the vector by 2^-e, ldexp(x, -e), is
** exact and keeps its direction, and its squared length can then neither
** overflow nor underflow (a direction of 1e200 or 1e-200).  (2^-e itself may
** not be a double: e runs from -1073 to 1024.)  This function can't fail. */
int pt_vec3_exp(double x, double y, double z);

/* The largest term |s_i * m_ic| (i = 0..3) of column c: when s_i is the
** magnitude component i of v was computed from, this is the magnitude
** component c of v * m is computed from -- its rounding error is a few units
** in the last place of it, whatever cancellation leaves of the sum.  With s = |v|
** it is the sum's own largest term.  This function can't fail. */
double pt_mat4_col_scale(const double s[4], const pt_mat4 *m, int c);

/* Bits of r = v * m lost to cancellation, the most over its four components:
** pt_bits_lost(largest term |v_i * m_ic|, r_c).  This function can't fail. */
int pt_vec4_mul_bits_lost(pt_vec4 v, const pt_mat4 *m, pt_vec4 r);

/* v * m, each component summed in row order.  This function can't fail. */
pt_vec4 pt_vec4_mul(pt_vec4 v, const pt_mat4 *m);

/* Translation, scale, and rotation by `degrees` about axis 0 (x), 1 (y) or 2
** (z), counterclockwise looking from the positive axis toward the origin in a
** right-handed frame (y to z for x, z to x for y, x to y for z).  Multiples of
** 90 degrees give exact 0 and +-1 entries.  These functions can't fail. */
pt_mat4 pt_mat4_translate(double x, double y, double z);
pt_mat4 pt_mat4_scale(double x, double y, double z);
pt_mat4 pt_mat4_rotate(int axis, double degrees);

/* Why a look-at or a perspective camera cannot be built. */
typedef enum pt_cam_error {
    PT_CAM_OK = 0,
    PT_CAM_DIR_ZERO,             /* direction has length 0 */
    PT_CAM_UP_ZERO,              /* up has length 0 */
    PT_CAM_UP_PARALLEL,          /* up is parallel to direction */
    PT_CAM_FOV,                  /* field of view not in (0, 180) degrees */
    PT_CAM_ASPECT,               /* aspect ratio <= 0 */
    PT_CAM_NEAR,                 /* near <= 0 */
    PT_CAM_FAR,                  /* near >= far */
    PT_CAM_EYE_RANGE,            /* -eye.h, -eye.u or -eye.d overflows */
    PT_CAM_FOV_RANGE,            /* cot(fov/2) is 0 or overflows */
    PT_CAM_ASPECT_RANGE,         /* cot(fov/2)/aspect is 0 or overflows */
    PT_CAM_DEPTH_RANGE           /* f/(f-n) or f*n/(n-f) is 0 or overflows */
} pt_cam_error;

/* The message for e ("up is parallel to direction").  This function can't fail. */
const char *pt_cam_error_text(pt_cam_error e);

/* The view matrix of a camera at eye looking along dir with up vector up:
**   d = dir/|dir|, u = up/|up|, h = (u x d)/|u x d|
**   raw != 0: the seed's matrix, with u as given (normalised only);
**   raw == 0: u is re-derived as d x h, so h, u, d are orthonormal.
**   columns h, u, d; last row (-eye.h, -eye.u, -eye.d, 1).
** *skewed is set to 1 when the given up was not perpendicular to dir (|u.d| >
** 1e-12).  A vector whose squared length overflows or underflows (1e200,
** 1e-200) is first scaled by a power of two, which is exact.  Returns
** PT_CAM_OK, or the reason (then *view is untouched): never a matrix with an
** infinite entry. */
pt_cam_error pt_lookat(pt_mat4 *view, pt_vec3 eye, pt_vec3 dir, pt_vec3 up,
                       int raw, int *skewed);

/* The perspective matrix from the vertical field of view in degrees, the
** aspect ratio w/h, and the near and far distances:
**   m00 = cot(fov/2)/aspect, m11 = cot(fov/2), m22 = f/(f-n), m23 = 1,
**   m32 = f*n/(n-f), all else 0.
** It maps z = n to z'/w' = 0 and z = f to 1, with w' = z.  Returns PT_CAM_OK or
** the reason (then *proj is untouched): also when one of the four entries is
** 0 or not finite (fov 1e-320, aspect 1e300), which would be no camera. */
pt_cam_error pt_perspective(pt_mat4 *proj, double fov_deg, double aspect,
                            double n, double f);

/* The reduction of pt_perspective()'s half angle fov_deg/2: 0 with *s and
** *c set exactly at a multiple of 90 degrees; else 1 with *rad, the very
** argument pt_perspective() gives sin and cos.  (The journey page's sliders
** hand the module libm's sin and cos of each such argument.)  This function
** can't fail. */
int pt_perspective_sincos_arg(double fov_deg, double *rad, double *s, double *c);

/* The aspect ratio `auto` means: the viewport's w / h.  This function can't
** fail. */
double pt_aspect_auto(int w, int h);

/* The direction of `camera lookat-target`: target - eye.  This function
** can't fail. */
pt_vec3 pt_lookat_dir(pt_vec3 eye, pt_vec3 target);

/* Report v as a record of stage st with x y z w set, flagged nonfinite, and
** cancellation when lost (bits, pt_vec4_mul_bits_lost()) is more than
** PT_BITS_LOST_WARN; the shared tail of the matrix stages.  This function
** can't fail. */
void pt_emit_vec4(const pt_sink *sink, pt_stage st, pt_vec4 v, int lost);

#endif
