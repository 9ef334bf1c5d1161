/*
** tests/unit/test_stages.c -- each stage's formula on hand-computed values
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <string.h>
#include "testhelp.h"
#include "stages/s1_model2camera.h"
#include "stages/s2_camera2image.h"
#include "stages/s3_image2pixel.h"
#include "stages/s4_pixel2viewport.h"
#include "stages/s5_viewport2fb.h"
#include "stages/s6_fb2index.h"
#include "stages/m7_screen2viewport.h"

/* A sink that keeps the last record. */
static pt_vrec last;
static int nrec;
static void keep(void *ud, const pt_vrec *r) { (void)ud; last = *r; nrec++; }
static const pt_sink sink = {keep, NULL};

static void test_s1(void)
{
    pt_vec3 c = pt_model2camera((pt_vec3){-1, -1, 0}, (pt_vec3){0, 0, -2}, &sink);
    PT_CHECK("s1-1.1 (-1,-1,0) + (0,0,-2) = (-1,-1,-2)", c.x == -1 && c.y == -1 && c.z == -2);
    PT_CHECK("s1-1.2 record is the camera stage", last.stage == PT_STAGE_CAMERA && last.z == -2);
    c = pt_model2camera((pt_vec3){-0.0, 0.25, 1e300}, (pt_vec3){0, 0, 0}, NULL);
    PT_CHECK("s1-1.3 -0.0 + 0.0 = +0.0, as the formula gives", c.x == 0 && !signbit(c.x));
    PT_CHECK("s1-1.4 no rounding of exact sums", c.y == 0.25 && c.z == 1e300);
    c = pt_model2camera((pt_vec3){0.1, 0, 0}, (pt_vec3){0.2, 0, 0}, NULL);
    PT_CHECK("s1-1.5 0.1 + 0.2 is the double sum 0.30000000000000004", c.x == 0.30000000000000004);
}

static void test_s2(void)
{
    pt_vec3 ip = pt_camera2image((pt_vec3){-1, -1, -2}, 2, 1, &sink);
    PT_CHECK("s2-1.1 perspective (-1,-1,-2) -> (-0.5,-0.5,-1)",
             ip.x == -0.5 && ip.y == -0.5 && ip.z == -1);
    PT_CHECK("s2-1.2 in front: not behind", !(last.flags & PT_REC_BEHIND));
    ip = pt_camera2image((pt_vec3){1, 2, 4}, 0, 1, &sink);
    PT_CHECK("s2-1.3 behind the camera is mirrored: (1,2,4) -> (-0.25,-0.5)",
             ip.x == -0.25 && ip.y == -0.5);
    PT_CHECK("s2-1.4 behind flag set for z_c > 0", last.flags & PT_REC_BEHIND);
    ip = pt_camera2image((pt_vec3){0.3, -0.7, 5}, 0, 0, &sink);
    PT_CHECK("s2-2.1 orthographic keeps x, y and sets z = 0",
             ip.x == 0.3 && ip.y == -0.7 && ip.z == 0 && !(last.flags & PT_REC_BEHIND));
    ip = pt_camera2image((pt_vec3){1, -1, 0}, 0, 1, NULL);
    PT_CHECK("s2-3.1 z_c = 0 gives infinities, as the formula does: 1 / -0.0 = -inf",
             isinf(ip.x) && ip.x < 0 && isinf(ip.y) && ip.y > 0);
    ip = pt_camera2image((pt_vec3){0, 1, -3}, 0, 1, NULL);
    PT_CHECK("s2-3.2 x_ip = 0 / 3 = +0",
             ip.x == 0 && !signbit(ip.x));
}

static void test_s3(void)
{
    pt_vec2 pp = pt_image2pixel((pt_vec3){-0.5, -0.5, -1}, 20, 10, &sink);
    PT_CHECK("s3-1.1 x_pp = 0.5 + 20/2.001 * 0.5 = 5.497501249375313", pp.x == 5.497501249375313);
    PT_CHECK("s3-1.2 y_pp = 0.5 + 10/2.001 * 0.5 = 2.9987506246876565", pp.y == 2.9987506246876565);
    pp = pt_image2pixel((pt_vec3){-1, -1, -1}, 640, 480, NULL);
    PT_CHECK("s3-1.3 corner (-1,-1) -> (0.5,0.5)", pp.x == 0.5 && pp.y == 0.5);
    pp = pt_image2pixel((pt_vec3){1, 1, -1}, 640, 480, NULL);
    PT_CHECK("s3-1.4 corner (1,1) stays below w+0.5 and rounds to w",
             pp.x < 640.5 && pt_java_round(pp.x) == 640 && pt_java_round(pp.y) == 480);
    PT_CHECK("s3-1.5 record is the pixel stage", last.stage == PT_STAGE_PIXEL);
}

static void test_round(void)
{
    PT_CHECK("s4-1.1 round(0.49999999999999994) = 0 (floor(x+0.5) gives 1)",
             pt_java_round(0.49999999999999994) == 0);
    PT_CHECK("s4-1.2 round(0.5) = 1", pt_java_round(0.5) == 1);
    PT_CHECK("s4-1.3 round(-0.5) = 0 (ties up; C round() gives -1)",
             pt_java_round(-0.5) == 0 && !signbit(pt_java_round(-0.5) + 0.0));
    PT_CHECK("s4-1.4 round(-2.5) = -2", pt_java_round(-2.5) == -2);
    PT_CHECK("s4-1.5 round(2.5) = 3", pt_java_round(2.5) == 3);
    PT_CHECK("s4-1.6 round(-0.49999999999999994) = 0", pt_java_round(-0.49999999999999994) == 0);
    PT_CHECK("s4-1.7 round(-0.5000000000000001) = -1", pt_java_round(-0.5000000000000001) == -1);
    PT_CHECK("s4-1.8 round(4503599627370495.5) = 4503599627370496",
             pt_java_round(4503599627370495.5) == 4503599627370496.0);
    PT_CHECK("s4-1.9 round(-4503599627370495.5) = -4503599627370495",
             pt_java_round(-4503599627370495.5) == -4503599627370495.0);
    PT_CHECK("s4-1.10 round(2^53 + 2) stays", pt_java_round(9007199254740994.0) == 9007199254740994.0);
    PT_CHECK("s4-1.11 round(NaN) = 0 as in Java", pt_java_round((double)NAN) == 0);
    PT_CHECK("s4-1.12 round(142.50000000000003) = 143", pt_java_round(142.50000000000003) == 143);
    PT_CHECK("s4-1.13 round(114.49999999999997) = 114", pt_java_round(114.49999999999997) == 114);
}

static void test_s4(void)
{
    int64_t r;
    pt_pix vp = pt_pixel2viewport((pt_vec2){5.497501249375313, 2.9987506246876565}, 20, 10, &sink);
    PT_CHECK("s4-2.1 (5.4975, 2.9988) in 20x10 -> (4, 7)", vp.ok && vp.x == 4 && vp.y == 7);
    PT_CHECK("s4-2.2 inside", (last.flags & PT_REC_INSIDE) && last.ix == 4 && last.iy == 7);
    vp = pt_pixel2viewport((pt_vec2){0.5, 10.5}, 20, 10, &sink);
    PT_CHECK("s4-2.3 (0.5, 10.5): round up to (1, 11) -> (0, -1), outside",
             vp.x == 0 && vp.y == -1 && !(last.flags & PT_REC_INSIDE));
    vp = pt_pixel2viewport((pt_vec2){(double)INFINITY, 3}, 20, 10, &sink);
    PT_CHECK("s4-2.4 infinite x_pp has no pixel", !vp.ok && (last.flags & PT_REC_NULL));
    vp = pt_pixel2viewport((pt_vec2){3, 1e300}, 20, 10, &sink);
    PT_CHECK("s4-2.5 1e300 has no pixel (no overflow)", !vp.ok);
    PT_CHECK("s4-2.6 2^62 - 512 rounds, 2^62 does not",
             pt_pix_round(4611686018427387392.0, &r) && r == 4611686018427387392LL &&
             !pt_pix_round(PT_PIX_LIMIT, &r) && !pt_pix_round(-PT_PIX_LIMIT, &r));
}

static void test_s5_s6(void)
{
    pt_pix vp = {58, 73, 1}, fb;
    int64_t idx;

    fb = pt_viewport2fb(vp, 40, 30, &sink);
    PT_CHECK("s5-1.1 (58,73) + (40,30) = (98,103)", fb.ok && fb.x == 98 && fb.y == 103);
    idx = pt_fb2index(fb, 300, 200, &sink);
    PT_CHECK("s6-1.1 103*300 + 98 = 30998", idx == 30998 && last.i == 30998);
    fb = pt_viewport2fb((pt_pix){-6, 18, 1}, 5, 5, NULL);
    idx = pt_fb2index(fb, 50, 40, &sink);
    PT_CHECK("s6-1.2 (-1, 23) is outside: no index", idx == -1 && (last.flags & PT_REC_NULL));
    idx = pt_fb2index((pt_pix){50, 0, 1}, 50, 40, NULL);
    PT_CHECK("s6-1.3 x = W is outside (would alias the next row)", idx == -1);
    idx = pt_fb2index((pt_pix){16383, 16383, 1}, 16384, 16384, NULL);
    PT_CHECK("s6-1.4 last pixel of 16384x16384 is 268435455", idx == 268435455);
    fb = pt_viewport2fb((pt_pix){0, 0, 0}, 5, 5, &sink);
    PT_CHECK("s5-1.2 no viewport pixel, no framebuffer pixel", !fb.ok && (last.flags & PT_REC_NULL));
}

static void test_warnings(void)
{
    pt_vec3 c;

    c = pt_model2camera((pt_vec3){1000000000.1, 0, 0}, (pt_vec3){-1000000000, 0, -2}, &sink);
    PT_CHECK("warn-1.1 1e9 + 0.1 - 1e9: cancellation flagged",
             (last.warn & PT_WARN_CANCEL) && last.digits_lost >= 9 && last.digits_lost <= 10);
    PT_CHECK("warn-1.2 ... and the value is what the doubles give", c.x == 0.10000002384185791);
    pt_model2camera((pt_vec3){1.5, -1, 0}, (pt_vec3){-1, 1, -5}, &sink);
    PT_CHECK("warn-1.3 exact cancellation to 0 and mild loss raise nothing", last.warn == 0);
    pt_model2camera((pt_vec3){1e308, 0, 0}, (pt_vec3){1e308, 0, 0}, &sink);
    PT_CHECK("warn-1.4 overflow to inf: nonfinite", last.warn & PT_WARN_NONFINITE);
    pt_camera2image((pt_vec3){1, 1, -1e-12}, 5, 1, &sink);
    PT_CHECK("warn-2.1 z_c = 5 - 5.000000000001: ill-conditioned projection",
             (last.warn & PT_WARN_ILLCOND) && last.digits_lost == 12);
    pt_camera2image((pt_vec3){1, 1, -1e-12}, 1e-12, 1, &sink);
    PT_CHECK("warn-2.2 the same z_c given exactly: no warning", last.warn == 0);
    pt_camera2image((pt_vec3){1, 1, 0}, 0, 1, &sink);
    PT_CHECK("warn-2.3 z_c = 0: nonfinite", last.warn == PT_WARN_NONFINITE);
    pt_camera2image((pt_vec3){1, 1, -4.9e-324}, 4.9e-324, 1, &sink);
    PT_CHECK("warn-2.4 divide by the smallest subnormal: nonfinite", last.warn & PT_WARN_NONFINITE);
    pt_image2pixel((pt_vec3){1.7e308, 0, -1}, 800, 600, &sink);
    PT_CHECK("warn-3.1 pixel plane overflow: nonfinite", last.warn & PT_WARN_NONFINITE);
    pt_pixel2viewport((pt_vec2){1e300, 1}, 8, 8, &sink);
    PT_CHECK("warn-4.1 x_pp = 1e300: out_of_range", last.warn == PT_WARN_RANGE);
    pt_fb2index((pt_pix){-1, 0, 1}, 8, 8, &sink);
    PT_CHECK("warn-6.1 x_fb = -1: outside_pixel_array", last.warn == PT_WARN_OUTSIDE);
    PT_CHECK("warn-7.1 digits from bits: 26 bits = 7 digits, 53 bits = 15 digits",
             pt_bits_to_digits(26) == 7 && pt_bits_to_digits(53) == 15);
    {   /* pt_bits_lost reads exponents off the bits: as ilogb gives them, for
        ** every kind of double (subnormals, zeros, infinities, NaN) */
        static const double edge[] = {0.0, -0.0, 5e-324, -5e-324, 2.2250738585072009e-308,
                                      2.2250738585072014e-308, 1e-300, 0.5, 1, 1.5, 2,
                                      1e300, 1.7976931348623157e308, INFINITY, -INFINITY, NAN};
        uint64_t r = 88172645463325252u;
        int i, j, ok = 1, n = (int)(sizeof edge / sizeof edge[0]);
        for (i = 0; i < 200000 + n * n; i++) {
            double a, b;
            int want;
            if (i < n * n) { a = edge[i / n]; b = edge[i % n]; }
            else {
                uint64_t u[2];
                for (j = 0; j < 2; j++) {   /* xorshift64; exponents 0 .. 2047 alike */
                    r ^= r << 13; r ^= r >> 7; r ^= r << 17;
                    u[j] = r;
                }
                memcpy(&a, &u[0], sizeof a);
                memcpy(&b, &u[1], sizeof b);
            }
            want = b == 0 || !isfinite(b) || !isfinite(a) || fabs(b) >= fabs(a) ? 0
                 : ilogb(a) - ilogb(b) > 53 ? 53 : ilogb(a) - ilogb(b);
            ok &= pt_bits_lost(a, b) == want;
        }
        PT_CHECK("warn-7.2 bits lost: ilogb(scale) - ilogb(x), at most 53, for edge "
                 "and random doubles", ok);
    }
}

static void test_table(void)
{
    PT_CHECK("stage-1.1 names map to ids", pt_stage_by_name("viewport") == PT_STAGE_VIEWPORT &&
             pt_stage_by_name("index") == PT_STAGE_INDEX && pt_stage_by_name("nope") == -1);
    PT_CHECK("stage-1.2 every stage has a formula",
             strlen(pt_stage_infos[PT_STAGE_PIXEL].formula) > 10);
    nrec = 0;
    pt_model2camera((pt_vec3){1, 2, 3}, (pt_vec3){0, 0, 0}, NULL);
    PT_CHECK("stage-1.3 a NULL sink reports nothing", nrec == 0);
}

/* The matrix camera's rasterizer maps its steps back with a copy of s4's
** formula (m7_screen2viewport.h says why): the two must agree on every point,
** ties, the limit and values without a pixel included. */
static void test_plane2viewport(void)
{
    static const double xs[] = {
        0.5, 1.0, 1.5, 2.4999999999999996, 2.5, -0.5, -2.5, -0.49999999999999994,
        0.49999999999999994, 19.5, 20.5, 1e15 + 0.5, -1e15, 4611686018427387904.0,
        4611686018427386880.0, -4611686018427387904.0, 1e300, (double)INFINITY,
        (double)NAN, 0.0, -0.0, 7.25,
    };
    int n = (int)(sizeof xs / sizeof xs[0]), i, j, h, agree = 1;

    for (h = 1; h <= 30; h += 29)
        for (i = 0; i < n; i++)
            for (j = 0; j < n; j++) {
                pt_vec2 p = {xs[i], xs[j]};
                pt_pix a = pt_pixel2viewport(p, 20, h, NULL);
                pt_pix b = pt_pixelplane2viewport(p, 20, h, NULL);
                if (a.ok != b.ok || (a.ok && (a.x != b.x || a.y != b.y))) agree = 0;
            }
    PT_CHECK("m7-2.1 pt_pixelplane2viewport() is s4's formula on every point", agree);
}

/* The table is the one place each stage's values are described. */
static void test_values(void)
{
    int st, ok = 1;

    for (st = 0; st < PT_NSTAGES_ALL; st++) {
        const pt_stage_info *in = &pt_stage_infos[st];
        int k;
        if ((in->nreal > 0) == (in->nint > 0) || pt_stage_nvalues(st) > 4) ok = 0;
        for (k = 0; k < 4; k++)
            if ((k < pt_stage_nvalues(st)) != (in->coord[k] != NULL && in->key[k] != NULL))
                ok = 0;
    }
    PT_CHECK("stage-2.1 every stage has reals or integers, each named and keyed", ok);
    PT_CHECK("stage-2.2 pixel: x_pp, y_pp as x, y",
             !strcmp(pt_stage_infos[PT_STAGE_PIXEL].coord[1], "y_pp") &&
             !strcmp(pt_stage_infos[PT_STAGE_PIXEL].key[1], "y"));
    for (st = 0; st < PT_NSTAGES_ALL; st++) {
        int k, seen = 0;
        for (k = 0; k < PT_NSTAGES_ALL; k++) seen += (int)pt_trace_order[k] == st;
        if (seen != 1) ok = 0;
    }
    PT_CHECK("stage-2.3 the trace order lists every stage once", ok);
    PT_CHECK("stage-2.4 both cameras start at model and end at index",
             pt_classic_order[0] == PT_STAGE_MODEL && pt_matrix_order[0] == PT_STAGE_MODEL &&
             pt_classic_order[pt_classic_norder - 1] == PT_STAGE_INDEX &&
             pt_matrix_order[pt_matrix_norder - 1] == PT_STAGE_INDEX);
}

/* pt_pix_round() (integers, for the rasterizer) against pt_java_round(). */
static void test_pix_round(void)
{
    static const double edge[] = {
        0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994, -0.49999999999999994,
        0.5000000000000001, -0.5000000000000001, 4503599627370495.5, -4503599627370495.5,
        4503599627370496.0, 9007199254740991.0, 9007199254740993.0, -9007199254740993.0,
        4611686018427386880.0, -4611686018427386880.0, 4611686018427387904.0,
        -4611686018427387904.0, 1e300, -1e300, 0.0, -0.0, 1e-310, -1e-310,
        (double)INFINITY, -(double)INFINITY, (double)NAN,
    };
    uint64_t st = 88172645463325252u;
    int k, agree = 1, agree_in = 1;

    for (k = 0; k < 200000 + (int)(sizeof edge / sizeof edge[0]); k++) {
        double x, r;
        int64_t got;
        int ok;
        if (k < (int)(sizeof edge / sizeof edge[0])) x = edge[k];
        else {                              /* xorshift: halves, and any bits */
            st ^= st << 13; st ^= st >> 7; st ^= st << 17;
            x = k % 2 ? (double)(int64_t)(st % 2000001) / 2 - 500000.0
                      : ldexp((double)(st >> 11), (int)(st % 120) - 60) * (st & 1 ? -1 : 1);
        }
        r = pt_java_round(x);
        ok = pt_pix_round(x, &got);
        if (ok != (isfinite(x) && fabs(r) < PT_PIX_LIMIT) || (ok && (double)got != r))
            agree = 0;
        if (isfinite(x) && fabs(x) < PT_PIX_LIMIT && (double)pt_pix_round_in(x) != r)
            agree_in = 0;
    }
    PT_CHECK("s4-2.1 pt_pix_round() is Java's rounding on 200000 values, ties and limits included",
             agree);
    PT_CHECK("s4-2.7 pt_pix_round_in() is Java's rounding on the same values within the limit",
             agree_in);
}

int main(void)
{
    test_s1();
    test_s2();
    test_s3();
    test_round();
    test_s4();
    test_s5_s6();
    test_warnings();
    test_table();
    test_plane2viewport();
    test_pix_round();
    test_values();
    return pt_test_report();
}
