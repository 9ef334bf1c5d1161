/*
** stages/pt_mat4.c -- 4x4 matrices on homogeneous row vectors, and the camera's
** See LICENSE for copyright and license.
*/
#include <float.h>
#include <math.h>
#include <string.h>
#include "pt_mat4.h"

static const double PI = 3.14159265358979323846;

pt_mat4 pt_mat4_identity(void)
{
    pt_mat4 r;
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++) r.m[i][j] = i == j ? 1.0 : 0.0;
    return r;
}

pt_mat4 pt_mat4_mul(const pt_mat4 *a, const pt_mat4 *b)
{
    pt_mat4 r;
    int i, j;

    for (i = 0; i < 4; i++)
        for (j = 0; j < 4; j++)             /* (a*b)_ij = sum_k a_ik b_kj */
            r.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j]
                      + a->m[i][2] * b->m[2][j] + a->m[i][3] * b->m[3][j];
    return r;
}

pt_vec4 pt_vec4_mul(pt_vec4 v, const pt_mat4 *m)
{
    pt_vec4 r;

    r.x = v.x * m->m[0][0] + v.y * m->m[1][0] + v.z * m->m[2][0] + v.w * m->m[3][0];
    r.y = v.x * m->m[0][1] + v.y * m->m[1][1] + v.z * m->m[2][1] + v.w * m->m[3][1];
    r.z = v.x * m->m[0][2] + v.y * m->m[1][2] + v.z * m->m[2][2] + v.w * m->m[3][2];
    r.w = v.x * m->m[0][3] + v.y * m->m[1][3] + v.z * m->m[2][3] + v.w * m->m[3][3];
    return r;
}

double pt_mat4_col_scale(const double s[4], const pt_mat4 *m, int c)
{
    double big = 0;
    int i;

    for (i = 0; i < 4; i++)
        big = fmax(big, fabs(s[i] * m->m[i][c]));       /* fmax ignores a NaN */
    return big;
}

int pt_vec4_mul_bits_lost(pt_vec4 v, const pt_mat4 *m, pt_vec4 r)
{
    const double s[4] = {fabs(v.x), fabs(v.y), fabs(v.z), fabs(v.w)};
    const double c[4] = {r.x, r.y, r.z, r.w};
    int k, lost = 0, l;

    for (k = 0; k < 4; k++) {
        l = pt_bits_lost(pt_mat4_col_scale(s, m, k), c[k]);
        if (l > lost) lost = l;
    }
    return lost;
}

pt_mat4 pt_mat4_translate(double x, double y, double z)
{
    pt_mat4 r = pt_mat4_identity();

    r.m[3][0] = x; r.m[3][1] = y; r.m[3][2] = z;
    return r;
}

pt_mat4 pt_mat4_scale(double x, double y, double z)
{
    pt_mat4 r = pt_mat4_identity();

    r.m[0][0] = x; r.m[1][1] = y; r.m[2][2] = z;
    return r;
}

/* deg reduced to [0, 360): at a multiple of 90 degrees sets *s and *c
** exactly (sin(pi/180 * 90) would give 1 but cos 6.1e-17 instead of 0) and
** returns 0; otherwise sets *rad, the radians to give sin and cos, and
** returns 1. */
static int deg_arg(double deg, double *rad, double *s, double *c)
{
    double a = fmod(deg, 360.0);            /* exact */

    if (a < 0) a += 360.0;
    if (a == 0)        { *s = 0;  *c = 1;  return 0; }
    if (a == 90)       { *s = 1;  *c = 0;  return 0; }
    if (a == 180)      { *s = 0;  *c = -1; return 0; }
    if (a == 270)      { *s = -1; *c = 0;  return 0; }
    *rad = a * (PI / 180);
    return 1;
}

/* sin and cos of an angle in degrees. */
static void sincos_deg(double deg, double *s, double *c)
{
    double rad;

    if (deg_arg(deg, &rad, s, c)) { *s = sin(rad); *c = cos(rad); }
}

int pt_perspective_sincos_arg(double fov_deg, double *rad, double *s, double *c)
{
    return deg_arg(fov_deg / 2, rad, s, c);     /* the half angle */
}

double pt_aspect_auto(int w, int h)
{
    return (double)w / h;
}

pt_vec3 pt_lookat_dir(pt_vec3 eye, pt_vec3 target)
{
    pt_vec3 d;

    d.x = target.x - eye.x;
    d.y = target.y - eye.y;
    d.z = target.z - eye.z;
    return d;
}

pt_mat4 pt_mat4_rotate(int axis, double degrees)
{
    pt_mat4 r = pt_mat4_identity();
    int i = (axis + 1) % 3, j = (axis + 2) % 3;  /* the plane turned: i to j */
    double s, c;

    sincos_deg(degrees, &s, &c);
    r.m[i][i] = c;  r.m[i][j] = s;          /* row vectors: e_i -> c e_i + s e_j */
    r.m[j][i] = -s; r.m[j][j] = c;
    return r;
}

const char *pt_cam_error_text(pt_cam_error e)
{
    switch (e) {
    case PT_CAM_OK:          return "no error";
    case PT_CAM_DIR_ZERO:    return "direction has length 0";
    case PT_CAM_UP_ZERO:     return "up has length 0";
    case PT_CAM_UP_PARALLEL: return "up is parallel to direction";
    case PT_CAM_FOV:         return "field of view must lie strictly between 0 and 180 degrees";
    case PT_CAM_ASPECT:      return "aspect ratio must be > 0";
    case PT_CAM_NEAR:        return "near must be > 0";
    case PT_CAM_FAR:         return "near must be < far";
    case PT_CAM_EYE_RANGE:   return "position too far from the origin: the view matrix overflows";
    case PT_CAM_FOV_RANGE:   return "field of view too close to 0 or 180 degrees: cot(fov/2) is not a finite, nonzero double";
    case PT_CAM_ASPECT_RANGE: return "aspect ratio too extreme: cot(fov/2)/aspect is not a finite, nonzero double";
    case PT_CAM_DEPTH_RANGE: return "near and far too extreme: f/(f-n) or f*n/(n-f) is not a finite, nonzero double";
    }
    return "unknown camera error";
}

static double dot(pt_vec3 a, pt_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

static pt_vec3 cross(pt_vec3 a, pt_vec3 b)
{
    pt_vec3 r;
    r.x = a.y * b.z - a.z * b.y;
    r.y = a.z * b.x - a.x * b.z;
    r.z = a.x * b.y - a.y * b.x;
    return r;
}

int pt_vec3_exp(double x, double y, double z)
{
    double big = fmax(fabs(x), fmax(fabs(y), fabs(z)));
    int e;

    if (!isfinite(big) || big == 0) return 0;
    (void)frexp(big, &e);                   /* big = f 2^e, 0.5 <= f < 1 */
    return e;
}

/* v / |v|, or 0 when v is 0 or not finite.  When v.v overflows or falls
** below DBL_MIN (losing digits), v is first scaled by 2^-pt_vec3_exp(v). */
static int normalize(pt_vec3 *v)
{
    double len = sqrt(dot(*v, *v));         /* sqrt is correctly rounded */
    double big = fmax(fabs(v->x), fmax(fabs(v->y), fabs(v->z)));
    int e;

    if (!isfinite(big) || big == 0) return 0;
    if (!isfinite(len) || len * len < DBL_MIN) {
        e = pt_vec3_exp(v->x, v->y, v->z);
        v->x = ldexp(v->x, -e); v->y = ldexp(v->y, -e); v->z = ldexp(v->z, -e);
        len = sqrt(dot(*v, *v));            /* now 2^-2 <= v.v < 3 */
    }
    v->x = v->x / len; v->y = v->y / len; v->z = v->z / len;
    return 1;
}

pt_cam_error pt_lookat(pt_mat4 *view, pt_vec3 eye, pt_vec3 dir, pt_vec3 up,
                       int raw, int *skewed)
{
    pt_vec3 d = dir, u = up, h;
    pt_mat4 r = pt_mat4_identity();

    if (!normalize(&d)) return PT_CAM_DIR_ZERO;
    if (!normalize(&u)) return PT_CAM_UP_ZERO;
    h = cross(u, d);                        /* horizontal = up x direction */
    if (!normalize(&h) || sqrt(dot(cross(u, d), cross(u, d))) < 1e-12)
        return PT_CAM_UP_PARALLEL;
    *skewed = fabs(dot(u, d)) > 1e-12;
    if (!raw) u = cross(d, h);              /* re-derived: exactly perpendicular */
    r.m[0][0] = h.x; r.m[1][0] = h.y; r.m[2][0] = h.z;
    r.m[0][1] = u.x; r.m[1][1] = u.y; r.m[2][1] = u.z;
    r.m[0][2] = d.x; r.m[1][2] = d.y; r.m[2][2] = d.z;
    r.m[3][0] = -dot(eye, h);               /* move the eye to the origin */
    r.m[3][1] = -dot(eye, u);
    r.m[3][2] = -dot(eye, d);
    if (!isfinite(r.m[3][0]) || !isfinite(r.m[3][1]) || !isfinite(r.m[3][2]))
        return PT_CAM_EYE_RANGE;
    *view = r;
    return PT_CAM_OK;
}

static int finite_nonzero(double x) { return isfinite(x) && x != 0; }

pt_cam_error pt_perspective(pt_mat4 *proj, double fov_deg, double aspect,
                            double n, double f)
{
    pt_mat4 r;
    double s, c, cot, rad;

    if (!(fov_deg > 0 && fov_deg < 180)) return PT_CAM_FOV;
    if (!(aspect > 0) || !isfinite(aspect)) return PT_CAM_ASPECT;
    if (!(n > 0)) return PT_CAM_NEAR;
    if (!(n < f) || !isfinite(f)) return PT_CAM_FAR;
    if (pt_perspective_sincos_arg(fov_deg, &rad, &s, &c)) { s = sin(rad); c = cos(rad); }
    cot = fov_deg == 90 ? 1.0 : c / s;      /* cot(fov/2); exact at 90 degrees */
    memset(&r, 0, sizeof r);
    r.m[0][0] = cot / aspect;               /* x' = x * cot(fov/2) / aspect */
    r.m[1][1] = cot;                        /* y' = y * cot(fov/2) */
    r.m[2][2] = f / (f - n);                /* z' = z * f/(f-n) ... */
    r.m[3][2] = f * n / (n - f);            /*      - f*n/(f-n) */
    r.m[2][3] = 1.0;                        /* w' = z */
    if (!finite_nonzero(r.m[1][1])) return PT_CAM_FOV_RANGE;
    if (!finite_nonzero(r.m[0][0])) return PT_CAM_ASPECT_RANGE;
    if (!finite_nonzero(r.m[2][2]) || !finite_nonzero(r.m[3][2])) return PT_CAM_DEPTH_RANGE;
    *proj = r;
    return PT_CAM_OK;
}

void pt_emit_vec4(const pt_sink *sink, pt_stage st, pt_vec4 v, int lost)
{
    pt_vrec r = {0};
    double a[4];

    r.stage = st;
    r.x = a[0] = v.x; r.y = a[1] = v.y; r.z = a[2] = v.z; r.w = a[3] = v.w;
    r.warn = pt_warn_nonfinite(a, 4);
    pt_warn_lost(&r, PT_WARN_CANCEL, lost);
    pt_emit(sink, &r);
}
