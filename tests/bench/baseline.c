/*
** tests/bench/baseline.c -- the plain-C yardstick of `make bench`: the same formulas, no trace
** See LICENSE for copyright and license.
**
** Usage: baseline SCENE [OUT.ppm].  What a programmer would write in an
** afternoon: fgets and strtod for the scene (framebuffer, viewport, camera
** perspective|orthographic [L R B T], model, translate, color, v, l, f;
** nothing checked), the classic camera's formulas in a loop, floor(x + 0.5)
** for rounding, the DDA of src/core/raster.c without its fast-forward, and a
** uint32 framebuffer.  A scene that says `renderer 7` or `renderer 9` (with
** view, antialias, gamma, matrix translate, matrix rotate x|y|z) goes
** through the course's renderer instead: "Renderers 7 and 9" below.  It
** prints "parse S render S pixels N": the least of 5 parses, the least of 15
** renders (the first touches the framebuffer's pages for the first time: the
** least is a warm one, as tests/bench/bench.c's are), and the pixels of one
** render; with OUT it writes the image too (binary PPM), so that the whole
** process can be timed.  tests/bench/bench.c compares pipetrace with it.
*/
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

typedef double mat[4][4];        /* [row][column] */

typedef struct model {
    double tx, ty, tz;           /* translate */
    uint32_t color;              /* 0xRRGGBB */
    mat m;                       /* renderer 9: the position's matrix */
    float rgb[3];                /* renderers 7, 9: the colour, byte / 255f */
    double *v;                   /* x y z per vertex */
    size_t nv, capv;
    uint32_t *seg;               /* a b per segment, 0-based */
    size_t nseg, capseg;
} model;

typedef struct vtx { double x, y, z; float c[3]; } vtx;   /* renderers 7, 9: a vertex, its colour */

static model *models;
static size_t nmodels, capmodels;
static int W = 800, H = 600, vx, vy, vw = -1, vh = -1, perspective = 1;
static uint32_t *fb;
static double *pp;               /* pixel-plane points of the current model */
static int renderer = 4, aa, gamma_on = 1;      /* renderers 7 and 9: */
static double cl = -1, cr = 1, cb = -1, ct = 1, near = -0.1, view[3];
static mat normalize;            /* renderer 9: the camera's normalize matrix */
static unsigned char *fb8;       /* W x H x 3 */
static double *cam;              /* camera coordinates of the current model */
static uint64_t pixels;

static double now(void)                 /* CPU time, as tests/bench/bench.c measures */
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static void *grow(void *p, size_t *cap, size_t size)
{
    *cap = *cap ? 2 * *cap : 1024;
    p = realloc(p, *cap * size);
    if (!p) { fprintf(stderr, "baseline: out of memory\n"); exit(1); }
    return p;
}

/* Matrix times (x, y, z, w): each row's four products summed left to right. */
static void times(mat a, const double v[4], double out[4])
{
    int i;
    for (i = 0; i < 4; i++)
        out[i] = a[i][0] * v[0] + a[i][1] * v[1] + a[i][2] * v[2] + a[i][3] * v[3];
}

/* a * b, column by column (Matrix.times(Matrix)); into a. */
static void times_mat(mat a, mat b)
{
    mat c;
    double col[4], out[4];
    int i, j;
    for (j = 0; j < 4; j++) {
        for (i = 0; i < 4; i++) col[i] = b[i][j];
        times(a, col, out);
        for (i = 0; i < 4; i++) c[i][j] = out[i];
    }
    memcpy(a, c, sizeof c);
}

static void translation(mat t, double x, double y, double z)
{
    memset(t, 0, sizeof(mat));
    t[0][0] = t[1][1] = t[2][2] = t[3][3] = 1.0;
    t[0][3] = x; t[1][3] = y; t[2][3] = z;
}

/* Matrix.rotate(theta, x, y, z) about the axis x, y or z: Rodrigues'
** formula term by term as the course writes it. */
static void rotation(mat m, double theta, char axis)
{
    double x = axis == 'x', y = axis == 'y', z = axis == 'z';
    double norm = sqrt(x*x + y*y + z*z), ux = x/norm, uy = y/norm, uz = z/norm;
    double c = cos((3.141592653589793/180.0)*theta), s = sin((3.141592653589793/180.0)*theta);

    translation(m, 0, 0, 0);
    m[0][0] = ux*ux*(1-c)+c;      m[0][1] = ux*uy*(1-c)-(uz*s); m[0][2] = ux*uz*(1-c)+(uy*s);
    m[1][0] = uy*ux*(1-c)+(uz*s); m[1][1] = uy*uy*(1-c)+c;      m[1][2] = uy*uz*(1-c)-(ux*s);
    m[2][0] = uz*ux*(1-c)-(uy*s); m[2][1] = uz*uy*(1-c)+(ux*s); m[2][2] = uz*uz*(1-c)+c;
}

static void add_seg(model *m, long a, long b)
{
    if (m->nseg == m->capseg) m->seg = grow(m->seg, &m->capseg, 2 * sizeof *m->seg);
    m->seg[2 * m->nseg] = (uint32_t)a;
    m->seg[2 * m->nseg + 1] = (uint32_t)b;
    m->nseg++;
}

/* l I J ... or f I J K ...: indices from 1, or negative from the end. */
static void polyline(model *m, char *p, int closed)
{
    long first = -1, prev = -1, k;
    char *e;

    for (;;) {
        k = strtol(p, &e, 10);
        if (e == p) break;
        p = e;
        k = k > 0 ? k - 1 : (long)m->nv + k;
        if (first < 0) first = k; else add_seg(m, prev, k);
        prev = k;
    }
    if (closed && first >= 0) add_seg(m, prev, first);
}

/* Forget the scene read so far. */
static void clear(void)
{
    size_t k;

    for (k = 0; k < nmodels; k++) { free(models[k].v); free(models[k].seg); }
    nmodels = 0;
    W = 800; H = 600; vx = vy = 0; vw = vh = -1; perspective = 1;
    renderer = 4; aa = 0; gamma_on = 1;
    cl = -1; cr = 1; cb = -1; ct = 1; near = -0.1; view[0] = view[1] = view[2] = 0;
}

static void parse(FILE *f)
{
    char line[4096], *p, *e;
    model *m = NULL;

    while (fgets(line, sizeof line, f)) {
        if (line[0] == 'v' && line[1] == ' ') {
            if (m->nv == m->capv) m->v = grow(m->v, &m->capv, 3 * sizeof *m->v);
            p = line + 2;
            m->v[3 * m->nv] = strtod(p, &e);
            m->v[3 * m->nv + 1] = strtod(e, &e);
            m->v[3 * m->nv + 2] = strtod(e, &e);
            m->nv++;
        } else if ((line[0] == 'f' || line[0] == 'l') && line[1] == ' ') {
            polyline(m, line + 2, line[0] == 'f');
        } else if (strncmp(line, "model ", 6) == 0) {
            if (nmodels == capmodels) models = grow(models, &capmodels, sizeof *models);
            m = &models[nmodels++];
            memset(m, 0, sizeof *m);
            m->color = 0xffffff;
            translation(m->m, 0, 0, 0);                 /* Matrix.identity() */
            m->rgb[0] = m->rgb[1] = m->rgb[2] = 1.0f;   /* Pipeline.DEFAULT_COLOR */
        } else if (strncmp(line, "matrix translate ", 17) == 0) {
            mat t;
            double x = strtod(line + 17, &e), y = strtod(e, &e), z = strtod(e, &e);
            translation(t, x, y, z);
            times_mat(m->m, t);                         /* the matrix times OP */
        } else if (strncmp(line, "matrix rotate ", 14) == 0) {
            mat r;
            rotation(r, strtod(line + 16, &e), line[14]);
            times_mat(m->m, r);
        } else if (strncmp(line, "translate ", 10) == 0) {
            m->tx = strtod(line + 10, &e);
            m->ty = strtod(e, &e);
            m->tz = strtod(e, &e);
            if (renderer == 9) translation(m->m, m->tx, m->ty, m->tz);
        } else if (strncmp(line, "color ", 6) == 0) {
            long r = strtol(line + 6, &e, 10), g = strtol(e, &e, 10), b = strtol(e, &e, 10);
            m->color = (uint32_t)(r << 16 | g << 8 | b);
            m->rgb[0] = (float)r / 255.0f;              /* new Color(int, ...) */
            m->rgb[1] = (float)g / 255.0f;
            m->rgb[2] = (float)b / 255.0f;
        } else if (strncmp(line, "framebuffer ", 12) == 0) {
            W = (int)strtol(line + 12, &e, 10);
            H = (int)strtol(e, &e, 10);
        } else if (strncmp(line, "viewport ", 9) == 0) {
            vx = (int)strtol(line + 9, &e, 10);
            vy = (int)strtol(e, &e, 10);
            vw = (int)strtol(e, &e, 10);
            vh = (int)strtol(e, &e, 10);
        } else if (strncmp(line, "camera ", 7) == 0) {
            perspective = strncmp(line + 7, "perspective", 11) == 0;
            near = perspective ? -0.1 : 1.0;
            p = line + 7 + strcspn(line + 7, " \n");
            cl = strtod(p, &e);
            if (e != p) { cr = strtod(e, &e); cb = strtod(e, &e); ct = strtod(e, &e); }
            else cl = -1;
        } else if (strncmp(line, "renderer ", 9) == 0) {
            renderer = atoi(line + 9);
        } else if (strncmp(line, "view ", 5) == 0) {
            view[0] = strtod(line + 5, &e);
            view[1] = strtod(e, &e);
            view[2] = strtod(e, &e);
        } else if (strncmp(line, "antialias ", 10) == 0) {
            aa = strncmp(line + 10, "on", 2) == 0;
        } else if (strncmp(line, "gamma ", 6) == 0) {
            gamma_on = strncmp(line + 6, "on", 2) == 0;
        }
    }
    if (vw < 0) { vx = vy = 0; vw = W; vh = H; }
    {                          /* (Perspective|Orthographic)NormalizeMatrix: m2 * m1 */
        mat m1, m2;
        translation(m1, 0, 0, 0);
        translation(m2, 0, 0, 0);
        if (perspective) { m1[0][2] = (cr + cl) / 2; m1[1][2] = (ct + cb) / 2; }
        else { m1[0][3] = -(cr + cl) / 2; m1[1][3] = -(ct + cb) / 2; }
        m2[0][0] = 2 / (cr - cl);
        m2[1][1] = 2 / (ct - cb);
        times_mat(m2, m1);
        memcpy(normalize, m2, sizeof normalize);
    }
}

/* The DDA: x from x0 to x1, y += m; transposed when |slope| > 1. */
static uint64_t segment(double x0, double y0, double x1, double y1, uint32_t color)
{
    uint64_t n = 0;
    int tr;
    double m, y, t;
    long s, s1;

    x0 = floor(x0 + 0.5); y0 = floor(y0 + 0.5);
    x1 = floor(x1 + 0.5); y1 = floor(y1 + 0.5);
    tr = fabs(y1 - y0) > fabs(x1 - x0);
    if (tr) { t = x0; x0 = y0; y0 = t; t = x1; x1 = y1; y1 = t; }
    if (x1 < x0) { t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t; }
    m = x1 == x0 ? 0 : (y1 - y0) / (x1 - x0);
    y = y0;
    for (s = (long)x0, s1 = (long)x1; s <= s1; s++, y += m) {
        long px = tr ? (long)floor(y + 0.5) : s, py = tr ? s : (long)floor(y + 0.5);
        long x_vp = px - 1, y_vp = vh - py;             /* the viewport stage */
        if (x_vp < 0 || x_vp >= vw || y_vp < 0 || y_vp >= vh) continue;
        fb[(long)(vy + y_vp) * W + (vx + x_vp)] = color;  /* framebuffer, index */
        n++;
    }
    return n;
}

static uint64_t render(void)
{
    uint64_t n = 0;
    size_t k, j;

    for (k = 0; k < nmodels; k++) {
        model *m = &models[k];
        pp = realloc(pp, (m->nv ? m->nv : 1) * 2 * sizeof *pp);
        for (j = 0; j < m->nv; j++) {
            double xc = m->v[3 * j] + m->tx, yc = m->v[3 * j + 1] + m->ty;
            double zc = m->v[3 * j + 2] + m->tz;
            double xip = perspective ? xc / -zc : xc, yip = perspective ? yc / -zc : yc;
            pp[2 * j] = 0.5 + vw / 2.001 * (xip + 1);
            pp[2 * j + 1] = 0.5 + vh / 2.001 * (yip + 1);
        }
        for (j = 0; j < m->nseg; j++) {
            uint32_t a = m->seg[2 * j], b = m->seg[2 * j + 1];
            n += segment(pp[2 * a], pp[2 * a + 1], pp[2 * b], pp[2 * b + 1], m->color);
        }
    }
    return n;
}

/* ===== Renderers 7 and 9 =====
** The course's formulas written out in one loop a segment (renderer 9: the
** position's matrix, the view vector, the normalize matrix, each a 4 x 4
** product summed left to right; renderer 7: the translation and its
** normalizing formulas), the near plane, the projection, the view
** rectangle's recursive clip, the pixel plane with 2.001, Math.round, the
** DDA with its colours in float, anti-aliasing and gamma, and a byte
** framebuffer; the viewport is the framebuffer.  The course applies each
** stage to the whole model before the next; every stage is a function of
** one vertex or one segment and keeps the segments' order, so taking each
** segment through all of them draws the same pixels in the same order. */

/* Java's Math.round, exactly: floor(x + 0.5) without the sum's rounding. */
static double jround(double x)
{
    double r = floor(x);
    return x != x ? 0 : x - r >= 0.5 ? r + 1 : r;
}

static float gam(float c)                           /* (float)Math.pow(c, 1/2.2) */
{
    return gamma_on ? (float)pow((double)c, 0.45454545454545453) : c;
}

/* setPixelVP: the viewport is the framebuffer; an index outside it is dropped. */
static void put(int x, int y, const float c[3])
{
    int64_t idx = (int64_t)y * W + x, k;
    unsigned char *o = fb8 + 3 * idx;

    if (idx < 0 || idx >= (int64_t)W * H) return;
    for (k = 0; k < 3; k++) {                       /* new Color(float r, g, b) */
        double b = (double)(c[k] * 255.0f) + 0.5;
        o[k] = b < 1.0 ? 0 : b >= 255.0 ? 255 : (unsigned char)b;
    }
    pixels++;
}

/* Rasterize_AntiAlias_Line: a clipped segment from a to b (image plane). */
static void raster(const vtx *a, const vtx *b)
{
    double x0 = jround(0.5 + W / 2.001 * (a->x + 1)), y0 = jround(0.5 + H / 2.001 * (a->y + 1));
    double x1 = jround(0.5 + W / 2.001 * (b->x + 1)), y1 = jround(0.5 + H / 2.001 * (b->y + 1));
    double m, y, t, mc[3];
    const float *c0 = a->c, *c1 = b->c, *cs;
    float c[3], lo[3], hi[3], bg = 0.0f;
    int x, k, tr;

    if (x0 == x1 && y0 == y1) { put((int)x0 - 1, H - (int)y0, c0); return; }
    tr = fabs(y1 - y0) > fabs(x1 - x0);
    if (tr) { t = x0; x0 = y0; y0 = t; t = x1; x1 = y1; y1 = t; }
    if (x1 < x0) { t = x0; x0 = x1; x1 = t; t = y0; y0 = y1; y1 = t; cs = c0; c0 = c1; c1 = cs; }
    m = (y1 - y0) / (x1 - x0);
    for (k = 0; k < 3; k++) mc[k] = (double)(c1[k] - c0[k]) / (x1 - x0);
    for (x = (int)x0, y = y0; x < (int)x1; x++, y += m) {
        for (k = 0; k < 3; k++) c[k] = (float)fabs((double)c0[k] + mc[k] * (x - x0));
        if (aa) {
            int yl = (int)y, yh = yl + 1;
            float f;
            if ((!tr && y == H) || (tr && y == W)) yh = yl;     /* the edge rule */
            f = (float)(y - yl);
            for (k = 0; k < 3; k++) {
                lo[k] = gam((1 - f) * c[k] + f * bg);
                hi[k] = gam(f * c[k] + (1 - f) * bg);
            }
            if (!tr) { put(x - 1, H - yl, lo); put(x - 1, H - yh, hi); }
            else { put(yl - 1, H - x, lo); put(yh - 1, H - x, hi); }
        } else {
            int ry = (int)jround(y);
            for (k = 0; k < 3; k++) c[k] = gam(c[k]);
            if (!tr) put(x - 1, H - ry, c); else put(ry - 1, H - x, c);
        }
    }
    if (!tr) put((int)x1 - 1, H - (int)y1, c1); else put((int)y1 - 1, H - (int)x1, c1);
}

/* Clip_Line: trivially accepted, deleted, or cut at one edge and tried again. */
static void clip(vtx a, vtx b)
{
    vtx *o, *in, n;
    double t, e;
    float tf;
    int k, onx;

    if (!(fabs(a.x) > 1 || fabs(a.y) > 1 || fabs(b.x) > 1 || fabs(b.y) > 1)) {
        raster(&a, &b);
        return;
    }
    if ((a.x > 1 && b.x > 1) || (a.x < -1 && b.x < -1) || (a.y > 1 && b.y > 1)
        || (a.y < -1 && b.y < -1)) return;
    onx = a.x > 1 || b.x > 1 || a.x < -1 || b.x < -1;
    if (onx) { e = a.x > 1 || b.x > 1 ? 1 : -1; o = a.x * e > 1 ? &a : &b; }
    else { e = a.y > 1 || b.y > 1 ? 1 : -1; o = a.y * e > 1 ? &a : &b; }
    in = o == &a ? &b : &a;
    if (onx) {
        t = (e - o->x) / (in->x - o->x);
        n.x = e;
        n.y = (1 - t) * o->y + t * in->y;
    } else {
        t = (e - o->y) / (in->y - o->y);
        n.x = (1 - t) * o->x + t * in->x;
        n.y = e;
    }
    n.z = 0;
    tf = (float)t;
    for (k = 0; k < 3; k++) n.c[k] = (1 - tf) * o->c[k] + tf * in->c[k];
    *o = n;
    clip(a, b);
}

/* Projection of a camera-space vertex. */
static vtx project(double x, double y, double z, const float *c)
{
    vtx p;
    p.x = perspective ? x / -z : x;
    p.y = perspective ? y / -z : y;
    p.z = perspective ? -1 : 0;
    memcpy(p.c, c, sizeof p.c);
    return p;
}

/* NearClip_Line, then the projection and Clip_Line of what is left. */
static void course_segment(const model *m, uint32_t ia, uint32_t ib)
{
    const double *v0 = cam + 3 * ia, *v1 = cam + 3 * ib;
    double t;
    float tf, c[3];
    int k;

    if (v0[2] <= near && v1[2] <= near) {
        clip(project(v0[0], v0[1], v0[2], m->rgb), project(v1[0], v1[1], v1[2], m->rgb));
        return;
    }
    if (v0[2] > near && v1[2] > near) return;
    t = (near - v1[2]) / (v0[2] - v1[2]);           /* from v1 towards v0 */
    tf = (float)t;
    for (k = 0; k < 3; k++) c[k] = (1 - tf) * m->rgb[k] + tf * m->rgb[k];
    {
        vtx n = project((1 - t) * v1[0] + t * v0[0], (1 - t) * v1[1] + t * v0[1], near, c);
        if (v0[2] > near) clip(n, project(v1[0], v1[1], v1[2], m->rgb));
        else clip(project(v0[0], v0[1], v0[2], m->rgb), n);
    }
}

static uint64_t render79(void)
{
    size_t k, j;

    memset(fb8, 0, (size_t)W * H * 3);              /* clearVP: black */
    pixels = 0;
    for (k = 0; k < nmodels; k++) {
        model *m = &models[k];
        cam = realloc(cam, (m->nv ? m->nv : 1) * 3 * sizeof *cam);
        for (j = 0; j < m->nv; j++) {
            const double *p = m->v + 3 * j;
            double *o = cam + 3 * j;
            if (renderer == 9) {
                double v[4] = {p[0], p[1], p[2], 1.0}, w[4];
                times(m->m, v, w);                              /* world */
                v[0] = -view[0] + w[0];                         /* view: w = 1 */
                v[1] = -view[1] + w[1];
                v[2] = -view[2] + w[2];
                v[3] = 1.0;
                times(normalize, v, w);                            /* camera */
                o[0] = w[0]; o[1] = w[1]; o[2] = w[2];
            } else {
                double x = m->tx + p[0], y = m->ty + p[1], z = m->tz + p[2];
                if (perspective) {
                    x = x + z * (cr + cl) / 2.0;
                    y = y + z * (ct + cb) / 2.0;
                } else {
                    x = x - (cr + cl) / 2.0;
                    y = y - (ct + cb) / 2.0;
                }
                o[0] = 2.0 * x / (cr - cl);
                o[1] = 2.0 * y / (ct - cb);
                o[2] = z;
            }
        }
        for (j = 0; j < m->nseg; j++) course_segment(m, m->seg[2 * j], m->seg[2 * j + 1]);
    }
    return pixels;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

int main(int argc, char **argv)
{
    double t0, tparse[5], t[15];
    uint64_t n = 0;
    FILE *f;
    int k, runs = argc > 2 ? 1 : 5;     /* with OUT: once, as a user would */
    int renders = argc > 2 ? 1 : 15;    /* as many as tests/bench/bench.c's RENDERS */

    for (k = 0; k < runs; k++) {
        if (argc < 2 || !(f = fopen(argv[1], "r"))) {
            fprintf(stderr, "usage: baseline SCENE [OUT.ppm]\n");
            return 1;
        }
        clear();
        t0 = now();
        parse(f);
        tparse[k] = now() - t0;
        fclose(f);
    }
    fb = calloc((size_t)W * H, sizeof *fb);
    fb8 = malloc((size_t)W * H * 3);
    for (k = 0; k < renders; k++) {
        t0 = now();
        n = renderer == 4 ? render() : render79();
        t[k] = now() - t0;
    }
    if (argc > 2) {              /* the image: RGB bytes */
        unsigned char *rgb = renderer == 4 ? malloc((size_t)W * H * 3) : fb8;
        size_t i;
        f = fopen(argv[2], "wb");
        for (i = 0; renderer == 4 && i < (size_t)W * H; i++) {
            rgb[3 * i] = (unsigned char)(fb[i] >> 16);
            rgb[3 * i + 1] = (unsigned char)(fb[i] >> 8);
            rgb[3 * i + 2] = (unsigned char)fb[i];
        }
        if (!f || fprintf(f, "P6\n%d %d\n255\n", W, H) < 0
            || fwrite(rgb, 3, (size_t)W * H, f) != (size_t)W * H || fclose(f) != 0) {
            fprintf(stderr, "baseline: cannot write %s\n", argv[2]);
            return 1;
        }
        if (rgb != fb8) free(rgb);
        printf("parse %.6f render %.6f pixels %llu\n", tparse[0], t[0], (unsigned long long)n);
        return 0;
    }
    qsort(t, (size_t)renders, sizeof *t, by_value);
    qsort(tparse, 5, sizeof *tparse, by_value);
    printf("parse %.6f render %.6f pixels %llu\n", tparse[0], t[0], (unsigned long long)n);
    return 0;
}
