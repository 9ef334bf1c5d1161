/*
** src/tools/journey/jplace.c -- where a panel's labels go (see jplace.h)
** See LICENSE for copyright and license.
*/
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "tools/journey/jplace.h"

/* DejaVu Sans: advance widths of ' ' .. '~' in thousandths of an em, rounded
** up; the oblique faces have the regular and bold ones' widths (within a
** thousandth for bold oblique, which is no wider). */
static const unsigned short sans_regular[95] = {
     318,  401,  460,  838,  637,  951,  780,  275,  391,  391,  500,  838,  318,  361,  318,  337,
     637,  637,  637,  637,  637,  637,  637,  637,  637,  637,  337,  337,  838,  838,  838,  531,
    1000,  685,  687,  699,  771,  632,  576,  775,  752,  295,  295,  656,  558,  863,  749,  788,
     604,  788,  695,  635,  611,  732,  685,  989,  686,  611,  686,  391,  337,  391,  838,  500,
     500,  613,  635,  550,  635,  616,  353,  635,  634,  278,  278,  580,  278,  975,  634,  612,
     635,  635,  412,  521,  393,  634,  592,  818,  592,  592,  525,  637,  337,  637,  838
};
static const unsigned short sans_bold[95] = {
     349,  457,  521,  838,  696, 1002,  873,  307,  458,  458,  523,  838,  380,  416,  380,  366,
     696,  696,  696,  696,  696,  696,  696,  696,  696,  696,  400,  400,  838,  838,  838,  581,
    1000,  774,  763,  734,  831,  684,  684,  821,  837,  373,  373,  775,  638,  996,  837,  851,
     733,  851,  771,  721,  683,  813,  774, 1104,  771,  725,  726,  458,  366,  458,  838,  500,
     500,  675,  716,  593,  716,  679,  436,  716,  712,  343,  343,  666,  343, 1042,  712,  688,
     716,  716,  494,  596,  479,  712,  652,  924,  646,  652,  583,  712,  366,  712,  838
};
#define MONO_WIDTH  603          /* DejaVu Sans Mono: 1233 / 2048 em, rounded up */
#define OTHER_WIDTH 1000         /* a character past ASCII: an em (arrows are 0.838) */
#define ASCENT      0.928        /* DejaVu Sans: 1901 / 2048 em above the baseline */
#define DESCENT     0.236        /* 483 / 2048 em below */
#define GAP         1.0          /* kept between a label and anything else */

int pt_jtext_face(const char *extra)
{
    return strstr(extra, "monospace") ? PT_JFACE_MONO
         : strstr(extra, "bold") ? PT_JFACE_BOLD : PT_JFACE_REGULAR;
}

double pt_jtext_width(const char *t, double size, int face)
{
    const unsigned short *w = face == PT_JFACE_BOLD ? sans_bold : sans_regular;
    unsigned long sum = 0;

    for (; *t; t++) {
        unsigned char c = (unsigned char)*t;
        if ((c & 0xc0u) == 0x80u) continue;             /* inside a character */
        if (face == PT_JFACE_MONO) sum += MONO_WIDTH;
        else if (c >= 32 && c < 127) sum += w[c - 32];
        else sum += OTHER_WIDTH;
    }
    return size * (double)sum / 1000.0;
}

/* The box of a text w wide at size with its baseline at (x, y). */
static void box_of(double b[4], double x, double y, double w, double size, const char *anchor)
{
    if (strcmp(anchor, "middle") == 0) x -= w / 2;
    else if (strcmp(anchor, "end") == 0) x -= w;
    b[0] = x; b[1] = y - ASCENT * size; b[2] = x + w; b[3] = y + DESCENT * size;
}

void pt_jtext_box(double b[4], double x, double y, double size, const char *anchor,
                  int face, const char *t, double maxw)
{
    double w = pt_jtext_width(t, size, face);

    if (maxw > 0 && w > maxw) w = maxw;                 /* squeezed (textLength) */
    box_of(b, x, y, w, size, anchor);
}

void pt_jplace_init(pt_jplace *p, const double a[4])
{
    memset(p, 0, sizeof *p);
    memcpy(p->area, a, sizeof p->area);
}

void pt_jplace_free(pt_jplace *p)
{
    free(p->box); free(p->seg); free(p->lab);
    p->box = NULL; p->seg = NULL; p->lab = NULL;
    p->nbox = p->capbox = p->nseg = p->capseg = p->nlab = p->caplab = 0;
}

void pt_jplace_clear(pt_jplace *p) { p->nbox = p->nseg = p->nlab = 0; }

pt_jplace_mark pt_jplace_save(const pt_jplace *p)
{
    pt_jplace_mark m;

    m.nbox = p->nbox; m.nseg = p->nseg; m.nlab = p->nlab;
    return m;
}

void pt_jplace_back(pt_jplace *p, pt_jplace_mark m)
{
    if (m.nbox < p->nbox) p->nbox = m.nbox;
    if (m.nseg < p->nseg) p->nseg = m.nseg;
    if (m.nlab < p->nlab) p->nlab = m.nlab;
}

/* Room for one more of *n items of size sz in *a (capacity *cap). */
static int room(pt_jplace *p, void **a, size_t *n, size_t *cap, size_t sz)
{
    void *g;
    size_t c;

    if (*n < *cap) return 1;
    c = *cap ? 2 * *cap : 32;
    g = realloc(*a, c * sz);
    if (!g) { p->failed = 1; return 0; }
    *a = g; *cap = c;
    return 1;
}

static void put4(double q[4], double a, double b, double c, double d)
{
    q[0] = a; q[1] = b; q[2] = c; q[3] = d;
}

void pt_jplace_box(pt_jplace *p, double x0, double y0, double x1, double y1, double cost)
{
    void *a = p->box;

    if (!(x0 <= x1 && y0 <= y1)) return;                /* NaN or empty */
    if (!room(p, &a, &p->nbox, &p->capbox, sizeof *p->box)) return;
    p->box = a;
    put4(p->box[p->nbox], x0, y0, x1, y1);
    p->box[p->nbox++][4] = cost;
}

void pt_jplace_seg(pt_jplace *p, double ax, double ay, double bx, double by)
{
    void *a = p->seg;

    if (!(isfinite(ax) && isfinite(ay) && isfinite(bx) && isfinite(by))) return;
    if (!room(p, &a, &p->nseg, &p->capseg, sizeof *p->seg)) return;
    p->seg = a;
    put4(p->seg[p->nseg++], ax, ay, bx, by);
}

void pt_jplace_label(pt_jplace *p, const pt_jlabel *l)
{
    void *a = p->lab;

    pt_jlabel *n;

    if (!room(p, &a, &p->nlab, &p->caplab, sizeof *p->lab)) return;
    p->lab = a;
    n = &p->lab[p->nlab++];
    *n = *l;
    n->w = pt_jtext_width(n->text, n->size, pt_jtext_face(n->extra));
    if (n->maxw > 0 && n->w > n->maxw) n->w = n->maxw;
    box_of(n->want, n->x, n->y, n->w, n->size, n->anchor);
}

static int overlaps(const double a[4], const double *b)   /* b: 4 numbers or more */
{
    return a[0] < b[2] && b[0] < a[2] && a[1] < b[3] && b[1] < a[3];
}

/* Does segment s pass through box b?  (Liang-Barsky against b's four sides) */
static int crosses(const double s[4], const double b[4])
{
    double t0 = 0, t1 = 1, dx = s[2] - s[0], dy = s[3] - s[1];
    double q[4][2];
    int k;

    q[0][0] = -dx; q[0][1] = s[0] - b[0];
    q[1][0] = dx;  q[1][1] = b[2] - s[0];
    q[2][0] = -dy; q[2][1] = s[1] - b[1];
    q[3][0] = dy;  q[3][1] = b[3] - s[1];
    for (k = 0; k < 4; k++) {
        double a = q[k][0], c = q[k][1], t;
        if (a == 0) { if (c < 0) return 0; continue; }
        t = c / a;
        if (a < 0) { if (t > t1) return 0; if (t > t0) t0 = t; }
        else { if (t < t0) return 0; if (t < t1) t1 = t; }
    }
    return t0 < t1;
}

static void label_box(double b[4], const pt_jlabel *l, double x, double y)
{
    b[0] = l->want[0] + (x - l->x); b[2] = l->want[2] + (x - l->x);
    b[1] = l->want[1] + (y - l->y); b[3] = l->want[3] + (y - l->y);
}

/* Cost of box b (grown by GAP); the labels not yet placed (done[i] == 0, or
** all when done is NULL) count with the box they want, l itself aside. */
static double cost_of(const pt_jplace *p, const double b[4], const unsigned char *done,
                      const pt_jlabel *l, int lines)
{
    double g[4], c = 0;
    size_t i;

    put4(g, b[0] - GAP, b[1] - GAP, b[2] + GAP, b[3] + GAP);
    if (!(b[0] >= p->area[0] && b[1] >= p->area[1] && b[2] <= p->area[2] && b[3] <= p->area[3]))
        c += 1e6;
    for (i = 0; i < p->nbox; i++)
        if (overlaps(g, p->box[i])) c += p->box[i][4];
    for (i = 0; lines && i < p->nseg; i++)
        if (crosses(p->seg[i], g)) c += 100;
    for (i = 0; i < p->nlab; i++) {
        if ((done && done[i]) || &p->lab[i] == l) continue;
        if (overlaps(g, p->lab[i].want)) c += 1000;
    }
    return c;
}

double pt_jplace_cost(const pt_jplace *p, const double b[4], int lines)
{
    return cost_of(p, b, NULL, NULL, lines);
}

/* Candidate moves: rings of radius R[r] in sixteen directions (unit vectors
** written out, so that every machine gets the same places), up and down
** first: a label slides along its line of text before it leaves it. */
static const double R[] = { 3, 6, 10, 15, 21, 28, 36, 46, 58, 72, 88, 106 };
static const double DIR[16][2] = {
    {0, -1}, {0, 1}, {1, 0}, {-1, 0}, {0.7071, -0.7071}, {-0.7071, -0.7071},
    {0.7071, 0.7071}, {-0.7071, 0.7071}, {0.9239, -0.3827}, {-0.9239, -0.3827},
    {0.9239, 0.3827}, {-0.9239, 0.3827}, {0.3827, -0.9239}, {-0.3827, -0.9239},
    {0.3827, 0.9239}, {-0.3827, 0.9239}
};

/* Place label l: at the nearest place that costs nothing, the rings first;
** when there is none, where the cost and the move together are least. */
static void place_one(pt_jplace *p, const pt_jlabel *l, const unsigned char *done,
                      double *px, double *py)
{
    double b[4], best, bx = l->x, by = l->y, x, y, free_d = (double)INFINITY;
    size_t r;
    int d;

    label_box(b, l, l->x, l->y);
    best = cost_of(p, b, done, l, 1);
    if (best == 0) { *px = l->x; *py = l->y; return; }
    for (r = 0; r < sizeof R / sizeof R[0]; r++)
        for (d = 0; d < 16; d++) {
            double c;
            x = l->x + R[r] * DIR[d][0]; y = l->y + R[r] * DIR[d][1];
            label_box(b, l, x, y);
            c = cost_of(p, b, done, l, 1);
            if (c == 0) { *px = x; *py = y; return; }
            if (c + R[r] < best) { best = c + R[r]; bx = x; by = y; }
        }
    /* nothing free nearby: anywhere in the area, on a grid of 8 units */
    for (y = p->area[1] + 8; y <= p->area[3]; y += 8)
        for (x = p->area[0]; x <= p->area[2]; x += 8) {
            double dx = x - l->x, dy = y - l->y, dist = sqrt(dx * dx + dy * dy), c;
            label_box(b, l, x, y);
            c = cost_of(p, b, done, l, 1);
            if (c == 0 && dist < free_d) { free_d = dist; bx = x; by = y; }
            else if (free_d == (double)INFINITY && c + dist < best) { best = c + dist; bx = x; by = y; }
        }
    *px = bx; *py = by;
}

void pt_jplace_run(pt_jplace *p, void (*put)(void *ud, const pt_jlabel *l, double x, double y),
                   void *ud)
{
    size_t n = p->nlab, i, k;
    unsigned char *done = calloc(n ? n : 1, 1);
    int prio;

    /* most important first (smallest prio), equal ones in the order asked */
    for (prio = -1; ; ) {
        int next = -1;
        for (i = 0; i < n; i++)
            if (p->lab[i].prio > prio && (next < 0 || p->lab[i].prio < next)) next = p->lab[i].prio;
        if (next < 0) break;
        prio = next;
        for (k = 0; k < n; k++) {
            const pt_jlabel *l = &p->lab[k];
            double x, y, b[4];
            if (l->prio != prio) continue;
            place_one(p, l, done, &x, &y);
            if (done) done[k] = 1;
            put(ud, l, x, y);
            label_box(b, l, x, y);
            pt_jplace_box(p, b[0], b[1], b[2], b[3], PT_JPLACE_TAKEN);
        }
    }
    if (!done) p->failed = 1;
    free(done);
}
