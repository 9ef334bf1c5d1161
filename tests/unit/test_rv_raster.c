/*
** tests/unit/test_rv_raster.c -- renderers 7 and 9's rasterizer against the course's Java
** See LICENSE for copyright and license.
**
** Each case of tests/data/course-raster/cases (made by extract.py there from
** the course's harness: its clipped models, its image, its log) is drawn
** primitive by primitive into a framebuffer cleared as the harness clears
** it; the image must equal the course's byte for byte and the lines
** rv_log_raster writes must equal the log's rasterizer lines; drawn again
** with nobody listening (the quiet steps, gamma's bytes by table) the image
** must be the same, and drawn for a listener that reads bytes alone
** (bytes_only: the traces' pixel records) the image, the pixel lines and
** their bytes must be those a listener of floats hears, the bytes the
** formula's.  Random primitives beyond the cases (far ends, NaN, viewports
** sticking out) are drawn the three ways too (rv-5).  Usage:
** test_rv_raster [DIR] (default tests/data/course-raster).
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "testhelp.h"
#include "stages/rv_raster.h"
#include "core/raster.h"
#include "io/rv_log_raster.h"
#include "io/trace.h"

#define MAXN 4096                /* vertices, colours, primitives a position */

typedef struct tcase {
    pt_rv_raster_par par;
    unsigned char fbg[3];        /* the framebuffer's background */
    int debug;                   /* the log has Rasterize.debug's lines */
} tcase;

/* All of f from where it stands, NUL-terminated (NULL on error). */
static char *slurp_stream(FILE *f, size_t *len)
{
    size_t n = 0, cap = 4096, r;
    char *buf = malloc(cap), *nb;

    while (buf && (r = fread(buf + n, 1, cap - n - 1, f)) > 0) {
        n += r;
        if (cap - n - 1 == 0) {
            nb = realloc(buf, cap *= 2);
            if (!nb) { free(buf); return NULL; }
            buf = nb;
        }
    }
    if (buf) { buf[n] = '\0'; *len = n; }
    return buf;
}

static char *slurp(const char *path, size_t *len)
{
    FILE *f = fopen(path, "rb");
    char *buf;

    if (!f) return NULL;
    buf = slurp_stream(f, len);
    fclose(f);
    return buf;
}

/* The first line where a and b differ, printed; 1 when they are equal. */
static int same_text(const char *name, const char *a, size_t na, const char *b, size_t nb)
{
    size_t i = 0, line = 1, start = 0;

    while (i < na && i < nb && a[i] == b[i]) {
        if (a[i] == '\n') { line++; start = i + 1; }
        i++;
    }
    if (i == na && i == nb) return 1;
    printf("%s: log line %zu differs\n  got : %.200s\n  want: %.200s\n", name, line,
           a + start, b + start);
    return 0;
}

/* A listener that counts: the writes its pixel lines announce, the bad ones;
** with keep, it keeps the pixel lines too (px, n of them). */
typedef struct tally {
    uint64_t said, bad, ret;     /* ret: what pt_rv_raster_prim() returned, summed */
    int keep, bytes_only;        /* keep the lines; the listener reads bytes alone */
    pt_rv_pixel *px;
    size_t n, cap;
    int failed;                  /* out of memory keeping them */
} tally;

static void count_pixel(void *ud, const pt_rv_pixel *px)
{
    tally *t = ud;
    if (t->keep && t->n == t->cap) {
        size_t cap = t->cap ? 2 * t->cap : 256;
        pt_rv_pixel *n = realloc(t->px, cap * sizeof *n);
        if (!n) t->failed = 1;
        else { t->px = n; t->cap = cap; }
    }
    if (t->keep && t->n < t->cap) t->px[t->n++] = *px;
    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:   t->said += 1; break;
    case PT_RV_PX_AA:    t->said += 2; break;
    case PT_RV_PX_POINT: t->said += !px->clipped; break;
    }
}

static void count_bad(void *ud, int x, int y, int W, int H)
{
    (void)x; (void)y; (void)W; (void)H;
    ((tally *)ud)->bad++;
}

/* The log's block, writing to the case's log file (set where it is opened). */
static pt_trace *log_block;

static void set_ls(pt_rv_raster_ls *ls, FILE *lg, tally *t, int debug)
{
    memset(ls, 0, sizeof *ls);
    if (lg) { pt_rv_log_raster_ls(ls, log_block, debug); return; }
    ls->pixel = count_pixel;
    ls->bad = count_bad;
    ls->ud = t;
    ls->clipped_points = 1;
    ls->bytes_only = t && t->bytes_only;
}

/* Whether the bytes of a pixel line's colour k are the formula's: byte(c)
** of its colour c, or byte(gamma(c)) when enc (c is before gamma). */
static int formula_bytes(const pt_rv_pixel *px, int k, int enc)
{
    const pt_rgb *c = &px->c[k];
    float r = enc ? pt_gamma(c->r) : c->r, g = enc ? pt_gamma(c->g) : c->g,
          b = enc ? pt_gamma(c->b) : c->b;

    return px->b[k][0] == pt_color_byte(r) && px->b[k][1] == pt_color_byte(g) &&
           px->b[k][2] == pt_color_byte(b);
}

/* The same float's bits (NaN included). */
static int same_float(float a, float b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* The pixel lines of a listener that reads floats (f) and of one that reads
** bytes alone (b), of the same draw: the same pixels; f's bytes are its
** floats' (byte(c)), b's colours are f's before gamma (gamma(b's) = f's,
** to the bit) and its bytes the formula's, byte(gamma(c)).  The number of
** lines that differ. */
static size_t bytes_only_diff(const tally *f, const tally *b, int gamma)
{
    size_t i, bad = 0;
    int k;

    if (f->n != b->n) return f->n + b->n + 1;
    for (i = 0; i < f->n; i++) {
        const pt_rv_pixel *p = &f->px[i], *q = &b->px[i];
        int two = p->kind == PT_RV_PX_AA ? 2 : 1, ok = p->kind == q->kind &&
                 p->x_vp == q->x_vp && p->y_vp == q->y_vp && p->lo == q->lo && p->hi == q->hi;
        for (k = 0; k < two && ok; k++) {
            int enc = gamma && p->kind != PT_RV_PX_END;
            ok = formula_bytes(p, k, 0) && formula_bytes(q, k, enc) &&
                 memcmp(p->b[k], q->b[k], 3) == 0 &&
                 same_float(p->c[k].r, enc ? pt_gamma(q->c[k].r) : q->c[k].r) &&
                 same_float(p->c[k].g, enc ? pt_gamma(q->c[k].g) : q->c[k].g) &&
                 same_float(p->c[k].b, enc ? pt_gamma(q->c[k].b) : q->c[k].b);
        }
        bad += !ok;
    }
    return bad;
}

static pt_rv_gamma_lut lut;      /* for the draws nobody listens to */

/* Draw the positions of the .raster file f into rgb, logging to lg, or
** counting in *t when lg is NULL, or with nobody listening (and the gamma
** table) when both are NULL. */
static int draw_case(FILE *f, tcase *tc, unsigned char *rgb, FILE *lg, tally *t, int *nbad)
{
    static pt_vec4 v[MAXN];
    static pt_rgb c[MAXN];
    static pt_rv_prim p[MAXN];
    pt_rv_model m;
    pt_rv_raster_ls ls;
    char line[512], word[32];
    size_t k;
    int pending = 0;

    set_ls(&ls, lg, t, tc->debug);
    tc->par.lut = lg || (t && !t->bytes_only) ? NULL : &lut;
    memset(&m, 0, sizeof m);
    m.v = v; m.c = c; m.p = p;
    for (;;) {
        int eof = !fgets(line, sizeof line, f);
        if (eof || strncmp(line, "position", 8) == 0) {
            if (pending)
                for (k = 0; k < m.np; k++) {
                    uint64_t n = pt_rv_raster_prim(&m, &p[k], &tc->par, rgb,
                                                   lg || t ? &ls : NULL);
                    if (t) t->ret += n;
                }
            if (eof) return 0;
            m.nv = m.nc = m.np = 0;
            pending = 1;
            continue;
        }
        if (sscanf(line, "%31s", word) != 1 || word[0] == '#') continue;
        if (strcmp(word, "v") == 0 && m.nv < MAXN) {
            pt_vec4 *q = &v[m.nv++];
            if (sscanf(line, "v %lf %lf %lf", &q->x, &q->y, &q->z) != 3) return -1;
            q->w = 1.0;
        } else if (strcmp(word, "c") == 0 && m.nc < MAXN) {
            unsigned hex;
            pt_rgb *q = &c[m.nc++];
            if (sscanf(line, "c %f %f %f %x", &q->r, &q->g, &q->b, &hex) != 4) return -1;
            if ((unsigned)(pt_color_byte(q->r) << 16 | pt_color_byte(q->g) << 8 |
                           pt_color_byte(q->b)) != hex) (*nbad)++;
        } else if (strcmp(word, "l") == 0 && m.np < MAXN) {
            pt_rv_prim *q = &p[m.np++];
            memset(q, 0, sizeof *q);
            q->kind = PT_RV_LINE;
            if (sscanf(line, "l %u %u %u %u", &q->v[0], &q->v[1], &q->c[0], &q->c[1]) != 4)
                return -1;
        } else if (strcmp(word, "p") == 0 && m.np < MAXN) {
            pt_rv_prim *q = &p[m.np++];
            memset(q, 0, sizeof *q);
            q->kind = PT_RV_POINT;
            if (sscanf(line, "p %u %u %d", &q->v[0], &q->c[0], &q->radius) != 3) return -1;
        } else if (strcmp(word, "fb") == 0) {
            pt_rv_raster_par *r = &tc->par;
            if (sscanf(line, "fb %d %d %hhu %hhu %hhu", &r->W, &r->H, &tc->fbg[0], &tc->fbg[1],
                       &tc->fbg[2]) != 5) return -1;
        } else if (strcmp(word, "vp") == 0) {
            pt_rv_raster_par *r = &tc->par;
            size_t i, n = (size_t)r->W * (size_t)r->H;
            if (sscanf(line, "vp %d %d %d %d %hhu %hhu %hhu", &r->x_ul, &r->y_ul, &r->w, &r->h,
                       &r->bg[0], &r->bg[1], &r->bg[2]) != 7) return -1;
            for (i = 0; i < n; i++) memcpy(rgb + 3 * i, tc->fbg, 3);   /* new FrameBuffer */
            pt_rv_clear_vp(r, rgb, lg ? &ls : NULL);                    /* fb.vp.clearVP() */
        } else if (strcmp(word, "aa") == 0) {
            if (sscanf(line, "aa %d", &tc->par.antialias) != 1) return -1;
        } else if (strcmp(word, "gamma") == 0) {
            if (sscanf(line, "gamma %d", &tc->par.gamma) != 1) return -1;
        } else if (strcmp(word, "debug") == 0) {
            if (sscanf(line, "debug %d", &tc->debug) != 1) return -1;
            set_ls(&ls, lg, t, tc->debug);
        } else {
            return -1;
        }
    }
}

/* One case: its image and its log. */
static void run_case(const char *dir, const char *name)
{
    char path[1024], head[320];
    size_t nppm = 0, nlog = 0, ngot = 0;
    char *ppm, *want, *got;
    unsigned char *rgb = NULL, *again = NULL, *quiet = NULL, *fl = NULL, *by = NULL;
    tally t1, t2, tf, tb;
    tcase tc;
    FILE *f, *lg;
    int W = 0, H = 0, hl = 0, nbad = 0, ok;

    memset(&tc, 0, sizeof tc);
    snprintf(path, sizeof path, "%s/%s.ppm", dir, name);
    ppm = slurp(path, &nppm);
    snprintf(path, sizeof path, "%s/%s.rlog", dir, name);
    want = slurp(path, &nlog);
    snprintf(path, sizeof path, "%s/%s.raster", dir, name);
    f = fopen(path, "r");
    lg = tmpfile();
    if (lg && (log_block = malloc(sizeof *log_block)) != NULL)
        pt_trace_init(log_block, lg, PT_FORMAT_KRAFT, 0);
    PT_CHECK(name, ppm && want && f && lg && log_block);
    if (!ppm || !want || !f || !lg || !log_block) goto done;
    PT_CHECK("ppm header", sscanf(ppm, "P6 %d %d 255%n", &W, &H, &hl) == 2 && hl > 0);
    if (W <= 0 || H <= 0 || (size_t)hl + 1 + (size_t)W * H * 3 != nppm) {
        PT_CHECK("ppm size", 0);
        goto done;
    }
    memset(&t1, 0, sizeof t1);
    memset(&t2, 0, sizeof t2);
    memset(&tf, 0, sizeof tf);
    memset(&tb, 0, sizeof tb);
    tf.keep = tb.keep = tb.bytes_only = 1;
    rgb = calloc((size_t)W * H, 3);
    again = calloc((size_t)W * H, 3);
    quiet = calloc((size_t)W * H, 3);
    fl = calloc((size_t)W * H, 3);
    by = calloc((size_t)W * H, 3);
    ok = rgb && again && quiet && fl && by && draw_case(f, &tc, rgb, lg, &t1, &nbad) == 0;
    rewind(f);
    ok = ok && draw_case(f, &tc, again, NULL, &t2, &nbad) == 0;
    rewind(f);
    ok = ok && draw_case(f, &tc, quiet, NULL, NULL, &nbad) == 0;
    rewind(f);
    ok = ok && draw_case(f, &tc, fl, NULL, &tf, &nbad) == 0;
    rewind(f);
    ok = ok && draw_case(f, &tc, by, NULL, &tb, &nbad) == 0 && !tf.failed && !tb.failed;
    snprintf(head, sizeof head, "%s: parsed", name);
    PT_CHECK(head, ok && tc.par.W == W && tc.par.H == H);
    if (!ok) goto done;
    snprintf(head, sizeof head, "%s: colour bytes", name);
    PT_CHECK(head, nbad == 0);
    snprintf(head, sizeof head, "%s: image", name);
    PT_CHECK(head, memcmp(rgb, ppm + hl + 1, (size_t)W * H * 3) == 0);
    snprintf(head, sizeof head, "%s: the same image, listened to or not", name);
    PT_CHECK(head, memcmp(rgb, again, (size_t)W * H * 3) == 0 && t1.ret == t2.ret);
    snprintf(head, sizeof head, "%s: the same image with nobody listening", name);
    PT_CHECK(head, memcmp(rgb, quiet, (size_t)W * H * 3) == 0);
    snprintf(head, sizeof head, "%s: the same image heard in bytes alone", name);
    PT_CHECK(head, memcmp(rgb, fl, (size_t)W * H * 3) == 0 &&
                   memcmp(rgb, by, (size_t)W * H * 3) == 0 && tf.ret == tb.ret);
    snprintf(head, sizeof head, "%s: bytes alone: the formula's bytes", name);
    PT_CHECK(head, tb.n > 0 && bytes_only_diff(&tf, &tb, tc.par.gamma) == 0);
    snprintf(head, sizeof head, "%s: pixels written = pixels logged - bad ones", name);
    PT_CHECK(head, t2.ret == t2.said - t2.bad && t2.said > 0);
    PT_CHECK("log written", pt_trace_finish(log_block) == 0);
    rewind(lg);
    got = slurp_stream(lg, &ngot);
    snprintf(head, sizeof head, "%s: log", name);
    PT_CHECK(head, got && same_text(name, got, ngot, want, nlog));
    free(got);
done:
    if (f) fclose(f);
    if (lg) fclose(lg);
    free(log_block);
    log_block = NULL;
    free(rgb);
    free(again);
    free(quiet);
    free(fl);
    free(by);
    free(tf.px);
    free(tb.px);
    free(ppm);
    free(want);
}

/* Primitives no course case has: coordinates far outside the view, NaN. */
static void extremes(void)
{
    pt_vec4 v[3] = {{1e12, 1e12, 0.0, 1.0}, {(double)NAN, (double)NAN, 0.0, 1.0}, {-1.0, -1.0, 0.0, 1.0}};
    pt_rgb c[1] = {{1.0f, 0.5f, 0.25f}};
    pt_rv_prim pt = {PT_RV_POINT, {0, 0}, {0, 0}, 0};
    pt_rv_prim nan_seg = {PT_RV_LINE, {1, 1}, {0, 0}, 0};
    pt_rv_prim corner = {PT_RV_POINT, {2, 0}, {0, 0}, 1};
    pt_rv_model m;
    pt_rv_raster_par par;
    pt_rv_raster_ls ls;
    unsigned char rgb[4 * 3 * 3];
    tally t;

    memset(&m, 0, sizeof m);
    m.v = v; m.nv = 3; m.c = c; m.nc = 1;
    memset(&par, 0, sizeof par);
    par.w = par.W = 4;
    par.h = par.H = 3;
    par.gamma = 0;
    memset(rgb, 0, sizeof rgb);
    memset(&t, 0, sizeof t);
    set_ls(&ls, NULL, &t, 0);
    /* Java's loop of a radius-0 point at (int) 2^31 - 1 never ends (++ wraps) */
    PT_CHECK("rv-2.1 a point at 1e12 (Java: an endless loop): clipped, nothing written",
             pt_rv_raster_prim(&m, &pt, &par, rgb, &ls) == 0 && t.said == 0 && t.bad == 0);
    /* NaN rounds to 0: pixel (-1, h), index h*W - 1, the row above's last pixel */
    PT_CHECK("rv-2.2 a NaN segment is one pixel at (-1, h): the framebuffer's last byte",
             pt_rv_raster_prim(&m, &nan_seg, &par, rgb, &ls) == 1 &&
             rgb[sizeof rgb - 3] == 255 && rgb[sizeof rgb - 2] == 128 && rgb[sizeof rgb - 1] == 64);
    memset(rgb, 0, sizeof rgb);
    /* (-1, -1) maps to pixel-plane (0.5, 0.5), rounded (1, 1): viewport (0, h-1) */
    PT_CHECK("rv-2.3 a radius-1 point at the lower-left corner: 4 of its 9 pixels",
             pt_rv_raster_prim(&m, &corner, &par, rgb, &ls) == 4 &&
             rgb[(2 * 4 + 0) * 3] == 255 && rgb[(1 * 4 + 1) * 3] == 255 && rgb[(2 * 4 + 2) * 3] == 0);
}

/* The gamma table against the formula: at each range's ends and step (and
** the floats beside them), and on many floats from 0 to beyond 1, negative,
** NaN. */
static void gamma_table(void)
{
    unsigned long long state = 88172645463325252ULL;
    int k, bad = 0, steps = 0;
    long i;

    PT_CHECK("rv-3.1 the gamma table comes out monotone", lut.ok);
    for (k = 0; k < PT_RV_LUT_N; k++) {
        uint32_t a = 0x35800000u + ((uint32_t)k << 16), at[6], j;
        at[0] = a; at[1] = a + 0xffffu; at[2] = lut.step[k] - 1; at[3] = lut.step[k];
        at[4] = lut.step[k] + 1; at[5] = a - 1;
        steps += lut.step[k] <= a + 0xffffu;
        for (j = 0; j < 6; j++) {
            float c;
            memcpy(&c, &at[j], sizeof c);
            bad += pt_rv_gamma_byte(&lut, c) != pt_color_byte(pt_gamma(c));
        }
    }
    PT_CHECK("rv-3.2 byte(gamma(c)) by table at every range's ends and step", bad == 0);
    PT_CHECK("rv-3.3 the table steps once to each byte from 1 to 255", steps == 255);
    for (i = 0, bad = 0; i < 400000; i++) {
        uint32_t b;
        float c;
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        b = (uint32_t)(state >> 33);                /* 0 .. 2^31: every positive float, NaN */
        if (i % 4 == 0) b = (uint32_t)(state >> 40) + 0x3f000000u;   /* 0.5 .. 2 */
        if (i % 7 == 0) b |= 0x80000000u;           /* negative */
        memcpy(&c, &b, sizeof c);
        bad += pt_rv_gamma_byte(&lut, c) != pt_color_byte(pt_gamma(c));
    }
    PT_CHECK("rv-3.4 byte(gamma(c)) by table on 400,000 floats", bad == 0);
    PT_CHECK("rv-3.5 0, 1, infinity, NaN, -0.25",
             pt_rv_gamma_byte(&lut, 0.0f) == 0 && pt_rv_gamma_byte(&lut, 1.0f) == 255 &&
             pt_rv_gamma_byte(&lut, (float)INFINITY) == 255 &&
             pt_rv_gamma_byte(&lut, nanf("")) == 0 && pt_rv_gamma_byte(&lut, -0.25f) == 0 &&
             pt_rv_gamma_byte(NULL, 0.5f) == pt_color_byte(pt_gamma(0.5f)));
}

/* Renderers 7 and 9's index rule (pt_rv_fb_index, Java ints) and the core's
** (pt_raster_fb_pixel with wrap, which renderer 4's rasterizer and the tools
** ask) are two spellings of FrameBuffer.setPixelFB: within the scene's limits
** (corner -16384..16384, sizes 1..16384) they name the same element, or both
** none, for every viewport pixel; here the corners and edges of 2000
** viewports of random size and place, and random pixels inside them. */
static void index_rules(void)
{
    uint64_t r = 88172645463325252ULL;
    int k, bad = 0, tried = 0;

    for (k = 0; k < 2000; k++) {
        pt_rv_raster_par par;
        int j;
        memset(&par, 0, sizeof par);
#define RND(lo, hi) (r ^= r << 13, r ^= r >> 7, r ^= r << 17, (int)((lo) + (int64_t)(r % (uint64_t)((hi) - (lo) + 1))))
        par.W = k % 3 ? RND(1, 64) : RND(1, 16384);
        par.H = k % 3 ? RND(1, 64) : RND(1, 16384);
        par.w = k % 2 ? RND(1, 2 * par.W) : RND(1, 16384);
        par.h = k % 2 ? RND(1, 2 * par.H) : RND(1, 16384);
        par.x_ul = k % 5 ? RND(-par.w, par.W) : RND(-16384, 16384);
        par.y_ul = k % 5 ? RND(-par.h, par.H) : RND(-16384, 16384);
        for (j = 0; j < 24; j++) {
            int x = j < 4 ? (j & 1) * (par.w - 1) : RND(0, par.w - 1);
            int y = j < 4 ? (j >> 1) * (par.h - 1) : RND(0, par.h - 1);
            int xf, yf, i7 = pt_rv_fb_index(&par, x, y, &xf, &yf);
            pt_fb_pixel px;
            int64_t i4 = pt_raster_fb_pixel(x, y, par.x_ul, par.y_ul, par.W, par.H, 1, &px);
            tried++;
            if (i4 != i7 || px.x_fb != xf || px.y_fb != yf) {
                if (!bad++)
                    fprintf(stderr, "  viewport %d %d %d %d in %d x %d, pixel (%d, %d): "
                            "rv %d, core %lld\n", par.x_ul, par.y_ul, par.w, par.h, par.W,
                            par.H, x, y, i7, (long long)i4);
            }
        }
#undef RND
    }
    PT_CHECK("rv-4.1 pt_rv_fb_index and pt_raster_fb_pixel name the same element (48,000 pixels)",
             bad == 0 && tried == 48000);
}

/* ===== the quiet steps against the told ones ===== */

static void no_pixel(void *ud, const pt_rv_pixel *px)
{
    (void)ud; (void)px;
}

/* A listener of bytes's pixels as the traces' pixel records say them:
** where, the bytes, the coverage; folded into a hash, in order. */
static void out_hash(uint64_t *h, int x, int y, const unsigned char b[3], float cov)
{
    uint32_t cb;

    memcpy(&cb, &cov, sizeof cb);
    *h = *h * 1000003u + (uint64_t)(uint32_t)x * 65599u + (uint32_t)y;
    *h = *h * 1000003u + ((uint64_t)b[0] << 16 | (uint64_t)b[1] << 8 | b[2]) + ((uint64_t)cb << 24);
}

static void hash_pixel(void *ud, const pt_rv_pixel *px)   /* as trace_course_rec.c's on_pixel */
{
    uint64_t *h = ud;
    double y = px->transposed ? px->x_pp : px->y_pp;
    float f = (float)(y - (double)(int64_t)y);

    switch (px->kind) {
    case PT_RV_PX_STEP:
    case PT_RV_PX_END: out_hash(h, px->x_vp, px->y_vp, px->b[0], 1.0f); break;
    case PT_RV_PX_POINT: if (!px->clipped) out_hash(h, px->x_vp, px->y_vp, px->b[0], 1.0f); break;
    case PT_RV_PX_AA:
        if (px->transposed) {
            out_hash(h, px->lo, px->y_vp, px->b[0], 1.0f - f);
            out_hash(h, px->hi, px->y_vp, px->b[1], f);
        } else {
            out_hash(h, px->x_vp, px->lo, px->b[0], 1.0f - f);
            out_hash(h, px->x_vp, px->hi, px->b[1], f);
        }
        break;
    }
}

static void hash_run(void *ud, const pt_rv_raster_par *par, const pt_rv_px_out *px, size_t n)
{
    size_t k;

    (void)par;
    for (k = 0; k < n; k++) out_hash(ud, px[k].x_vp, px[k].y_vp, px[k].b, px[k].coverage);
}

static void bad_count(void *ud, int x, int y, int W, int H)    /* where, in order */
{
    uint64_t *h = ud;

    (void)W; (void)H;
    *h = *h * 1000003u + (uint64_t)(uint32_t)x * 65599u + (uint32_t)y + 1u;
}

static uint64_t rnd(uint64_t *st)                /* xorshift64 */
{
    *st ^= *st << 13; *st ^= *st >> 7; *st ^= *st << 17;
    return *st;
}

/* The image-plane x whose pixel-plane x (0.5 + w/2.001 (x + 1)) is near p. */
static double from_pp(double p, int w)
{
    return (p - 0.5) * 2.001 / w - 1.0;
}

/* An end's pixel coordinate: mostly in the viewport, else (with far) near
** 2^30 or 2^31 or beyond (where the quiet loop hands over to the general
** one), or NaN; the other end of a far one stays within 40 pixels of it
** (near), and the other end of any other is not far: a segment takes as
** many steps as it is long. */
static double pick(uint64_t *st, int size, double near, int far_ok)
{
    static const double far[] = {1073741800.0, 1073741830.0, 2147483600.0, 2147483660.0,
                                 -1073741830.0, -2147483660.0, 4611686018427387904.0};
    if (near == near && fabs(near) > 4.0 * size) return near + (double)(rnd(st) % 81) - 40.0;
    switch (rnd(st) % 16) {
    case 0: if (far_ok) return far[rnd(st) % (sizeof far / sizeof far[0])];
            return 0.0;
    case 1: return (double)NAN;
    case 2: return -3.0 - (double)(rnd(st) % 20);
    default: return (double)(rnd(st) % (uint64_t)(size * 4 + 1)) / 4.0 - 2.0;
    }
}

/* rv-5: random segments and points (flat, grey and changing colours, AA and
** gamma on and off, viewports inside the framebuffer and sticking out of
** it, ends far outside and NaN) drawn three ways: for nobody (the quiet
** loops, gamma by table), for a listener of bytes and for a listener of
** floats.  The three framebuffers, counts of pixels written and "bad"
** reports must agree. */
static void quiet_vs_told(void)
{
    enum { W = 40, H = 30, N = 6000 };
    static unsigned char fb[3][W * H * 3];
    uint64_t st = 0x9e3779b97f4a7c15u, bad[3], n[3];
    pt_vec4 v[2];
    pt_rgb c[2];
    pt_rv_model m;
    pt_rv_prim p;
    pt_rv_raster_par par;
    pt_rv_raster_ls ls[3], lh[2];
    uint64_t h[2], h0, n0, bad0;
    int k, j, i, same = 1, counts = 1, far = 0, runs = 1, none = 1;

    memset(&m, 0, sizeof m);
    m.v = v; m.nv = 2; m.c = c; m.nc = 2;
    for (k = 0; k < N; k++) {
        memset(&par, 0, sizeof par);
        par.W = W; par.H = H;
        par.w = 10 + (int)(rnd(&st) % 31);
        par.h = 10 + (int)(rnd(&st) % 21);
        par.x_ul = rnd(&st) % 3 ? 0 : (int)(rnd(&st) % 21) - 10;
        par.y_ul = rnd(&st) % 3 ? 0 : (int)(rnd(&st) % 21) - 10;
        par.bg[0] = par.bg[1] = par.bg[2] = (unsigned char)(rnd(&st) % 2 ? 0 : 200);
        if (rnd(&st) % 4 == 0) par.bg[1] = 17;
        par.antialias = (int)(rnd(&st) % 2);
        par.gamma = (int)(rnd(&st) % 2);
        par.lut = &lut;
        for (j = 0; j < 2; j++) {
            double x = pick(&st, par.w, (double)NAN, 1);
            double y = pick(&st, par.h, (double)NAN, 1);
            if (j == 1) {                            /* near the first end when it is far */
                double x0 = (v[0].x + 1.0) * par.w / 2.001 + 0.5;
                double y0 = (v[0].y + 1.0) * par.h / 2.001 + 0.5;
                int far0 = !(fabs(x0) <= 4.0 * par.w && fabs(y0) <= 4.0 * par.h);
                x = pick(&st, par.w, x0, 0);
                y = pick(&st, par.h, y0, 0);
                if (far0 && !(fabs(x0) > 4.0 * par.w)) x = x0;   /* NaN x or y: */
                if (far0 && !(fabs(y0) > 4.0 * par.h)) y = y0;   /*   keep it short */
            }
            far |= fabs(x) > 1e9 || fabs(y) > 1e9;
            v[j].x = from_pp(x, par.w);
            v[j].y = from_pp(y, par.h);
            v[j].z = 0.0; v[j].w = 1.0;
        }
        c[0].r = (float)(rnd(&st) % 256) / 255.0f;
        c[0].g = c[0].b = rnd(&st) % 2 ? c[0].r : (float)(rnd(&st) % 256) / 255.0f;
        c[1] = c[0];
        if (rnd(&st) % 3 == 0) c[1].g = (float)(rnd(&st) % 256) / 255.0f;
        memset(&p, 0, sizeof p);
        p.kind = rnd(&st) % 8 ? PT_RV_LINE : PT_RV_POINT;
        p.v[1] = p.c[1] = 1;
        p.radius = (int)(rnd(&st) % 3);
        for (i = 0; i < 3; i++) {
            memset(&ls[i], 0, sizeof ls[i]);
            ls[i].bad = bad_count;
            ls[i].ud = &bad[i];
            if (i > 0) ls[i].pixel = no_pixel;
            ls[i].bytes_only = i == 1;
            bad[i] = 0;
            memset(fb[i], 77, sizeof fb[i]);
            n[i] = pt_rv_raster_prim(&m, &p, &par, fb[i], &ls[i]);
        }
        if (memcmp(fb[0], fb[1], sizeof fb[0]) || memcmp(fb[0], fb[2], sizeof fb[0])) same = 0;
        if (n[0] != n[1] || n[0] != n[2] || bad[0] != bad[1] || bad[0] != bad[2]) counts = 0;
        for (i = 0; i < 2; i++) {                  /* pixel lines, and runs (no bad) */
            memset(&lh[i], 0, sizeof lh[i]);
            lh[i].pixel = hash_pixel;
            lh[i].pixels = i ? hash_run : NULL;
            lh[i].bytes_only = 1;
            lh[i].ud = &h[i];
            h[i] = 0;
            memset(fb[i], 77, sizeof fb[i]);
            n[i] = pt_rv_raster_prim(&m, &p, &par, fb[i], &lh[i]);
        }
        if (h[0] != h[1] || n[0] != n[1] || memcmp(fb[0], fb[1], sizeof fb[0])) runs = 0;
        for (i = 0; i < 3; i++) {                  /* no pixels: all else the same */
            bad0 = bad[i];
            bad[i] = 0;
            if (pt_rv_raster_prim(&m, &p, &par, NULL, &ls[i]) != n[0] || bad[i] != bad0) none = 0;
        }
        for (i = 0; i < 2; i++) {
            h0 = h[i];
            h[i] = 0;
            if (pt_rv_raster_prim(&m, &p, &par, NULL, &lh[i]) != n[i] || h[i] != h0) none = 0;
        }
        bad[1] = 0;
        n0 = pt_rv_clear_vp(&par, fb[0], &ls[1]);
        bad0 = bad[1];
        bad[1] = 0;
        if (pt_rv_clear_vp(&par, NULL, &ls[1]) != n0 || bad[1] != bad0) none = 0;
    }
    PT_CHECK("rv-5.1 6,000 random primitives: the quiet loops write the framebuffer a listener "
             "of bytes and one of floats see written", same);
    PT_CHECK("rv-5.2 ... and the same pixel counts and bad reports, in order", counts);
    PT_CHECK("rv-5.3 ... some with ends beyond 2^30", far);
    PT_CHECK("rv-5.4 ... and a listener of runs (pixels) hears the pixels, bytes and coverages "
             "a listener of pixel lines hears, in order", runs);
    PT_CHECK("rv-5.5 ... and with no pixels to write (rgb NULL) each of those listeners hears "
             "the same, and the counts are the same (the viewport's clearing too)", none);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : "tests/data/course-raster";
    char path[1024], name[256];
    FILE *list;
    int n = 0;

    pt_rv_gamma_lut_init(&lut);
    gamma_table();
    snprintf(path, sizeof path, "%s/cases", dir);
    list = fopen(path, "r");
    PT_CHECK("the list of cases", list != NULL);
    while (list && fscanf(list, "%255s", name) == 1) {
        run_case(dir, name);
        n++;
    }
    if (list) fclose(list);
    extremes();
    index_rules();
    quiet_vs_told();
    /* java.awt.Color(float): the float product, then + 0.5 in double (NOTES 9.4) */
    PT_CHECK("rv-1.1 Color byte of 0.50392157f is 129 (widened first: 128)",
             pt_color_byte(0.50392157f) == 129 &&
             (int)((double)0.50392157f * 255.0 + 0.5) == 128);
    PT_CHECK("rv-1.2 Color byte of NaN is 0, of 1 is 255, of 0 is 0",
             pt_color_byte(nanf("")) == 0 && pt_color_byte(1.0f) == 255 &&
             pt_color_byte(0.0f) == 0);
    PT_CHECK("at least 16 cases", n >= 16);
    return pt_test_report();
}
