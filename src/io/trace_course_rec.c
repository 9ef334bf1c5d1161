/*
** src/io/trace_course_rec.c -- pipetrace's trace of a renderer 7 or 9 scene (text, jsonl, csv)
** See LICENSE for copyright and license.
**
** One walker listens to the driver (core/course.h) and fills a record per
** event: a vertex at a stage (the clip stages: only the vertices they make,
** with the primitive and t they came from), a primitive drawn.  Three small
** formatters spell a record: JSON Lines, text, CSV.  docs/trace-format.md
** lists the fields.  They write as renderer 4's writers do (io/trace_int.h):
** into the trace's 256 KiB block, a record's numbers in place, JSON's and
** CSV's doubles through the block's kept spellings.  A pixel record, the
** most of them, is written straight from the rasterizer's pixel line: the
** opening its primitive's records share, made once a primitive and copied,
** then its numbers (on_pixels).
*/
#include <assert.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "io/trace_course.h"
#include "io/trace.h"
#include "io/trace_int.h"
#include "io/tlanes.h"
#include "io/explain_course.h"
#include "io/numfmt.h"
#include "io/sbuf.h"

/* The records' seldom paths stay out of line (NOINLINE); what every pixel
** and vertex record does is written inline in the loops that make them
** (ALWAYS_INLINE). */
#if defined(__GNUC__)
#define NOINLINE __attribute__((noinline))
#define ALWAYS_INLINE __attribute__((always_inline))
#else
#define NOINLINE
#define ALWAYS_INLINE
#endif

static const char *const stage_names[PT_NCST] = {
    "model", "world", "view", "camera", "nearclip", "image", "clip"};

typedef enum rkind { R_VERTEX, R_PRIM, R_WARN } rkind;

/* One record. */
typedef struct rec {
    rkind kind;
    const char *model, *position;
    pt_course_stage st;          /* vertex: its stage */
    uint64_t v;                  /* vertex: 1-based; prim: its number in the list */
    pt_vec4 p;                   /* vertex: x y z (w with renderer 9) */
    int has_color;
    pt_rgb color;                /* vertex: the colour of its number; a clip
                                 ** stage's vertex: the colour it made */
    const char *from;            /* a clip stage's new vertex: the stage, */
    uint64_t from_prim;          /*   the segment's number in its list (1-based), */
    double t;                    /*   t, */
    const char *edge;            /*   the edge: "z=n", "x=+1", ... */
    const pt_rv_prim *prim;      /* prim: the primitive (0-based indices) */
    uint64_t pixels;             /* prim: pixels written */
    const char *warning;         /* warn: what the course warns of */
    const char *explain;         /* vertex, --explain: its formula with its numbers */
} rec;

#define KEPT_BITS 8              /* log2 of the slots of each table of kept() */

/* A pixel record's end after its y: JSON's rgb and coverage (at most 60
** bytes), text's (at most 80) */
#define PIXEL_TAIL 96
#define PIXEL_TAIL_JSON 64       /* JSON's, copied (at most 60 bytes) */
#define VSPELL_N 8192            /* the vertex numbers whose spellings are kept */
#define TAIL_BITS 9              /* log2 of the pixel records' ends kept */

typedef struct walker {
    pt_course_lane ln;           /* its lane (first: pt_course_lane_ls) */
    pt_trace *t;                 /* the output block and its numbers (trace_int.h) */
    const pt_scene *s;
    int fmt, precision, w4;
    int failed;                  /* out of memory: nothing more is written */
    pt_sbuf sb;                  /* the header, --explain's JSON string */
    uint64_t prim_no;            /* the primitive a clip stage is on */
    uint64_t raster_no;          /* the primitive the rasterizer is on */
    const char *clip_stage;
    /* the clip stages' new vertices: where each came from, by number */
    struct origin { uint32_t v, c; uint64_t prim; double t; pt_rv_edge edge; pt_rv_cut cut; } *org;
    size_t norg, cap_org;
    uint64_t nvrec, nprims, npixels;   /* the summary's (lane 0's: on lane 1,
                                 ** which skips the others' primitives,
                                 ** npixels counts its own pieces' only) */
    const pt_course_pos *pos;    /* the position the rasterizer draws */
    pt_sbuf names;               /* how a record names its position, made once
                                 ** for the names below (every record of a
                                 ** position has it): JSON ,"model":M,"position":P;
                                 ** text M made safe for a terminal; CSV M,P, */
    const char *names_model, *names_position;
    int pix_made;                /* how the pixel records of the primitive being
                                 ** drawn begin (JSON up to "x":, text up to
                                 ** "x_fb = "; pixel_head) is made (0: at its
                                 ** first pixel); */
    size_t pix_len;              /*   its length, */
    char pix_fixed[96];          /*   the opening when it fits, for a copy of
                                 ** a fixed size, */
    pt_sbuf pix;                 /*   else the opening */
    struct vspell {              /* JSON: each vertex number's last spellings */
        uint64_t bits[4];        /*   of x, y, z, w (vnum_at), by the number */
        unsigned char len[4];    /*   (0: none yet) */
        char s[4][PT_SHORTLEN];
    } *vspell;                   /*   mod VSPELL_N (JSON only) */
    struct pt_trace_frag skey[PT_NCST];  /* each stage's name in a vertex record
                                 ** with what comes around it, made once
                                 ** (skeys_make): JSON ',"stage":"NAME","x":',
                                 ** text ' NAME (left-aligned in 12) x =', CSV
                                 ** ',NAME,'; copied as one 32-byte slot */
    uint64_t names_gen;          /* counts the names made (names_make) */
    struct opened {              /* a record's head and names (opening), */
        uint64_t gen;            /*   for these names (0: none yet) */
        size_t len;
        char s[96];
    } opened[4];                 /*   one for each OPEN_ */
    struct vcolor {              /* JSON's spelling of the last vertex colour */
        pt_rgb c;                /*   (color_json_at) */
        size_t len;              /*   (0: none yet) */
        char s[3 * (PT_NUMLEN + 2) + 16];
    } vcolor;
    struct tail {                /* pixel records' ends after their y (tail_of), */
        uint64_t key;            /*   by the bits of the coverage and the bytes
                                 **   (tail_key; 0: an empty slot) */
        size_t len;
        char s[PIXEL_TAIL];
    } tails[1 << TAIL_BITS], *tail_last;   /* (tail_last: never NULL) */
    int explain;                 /* --explain: each vertex record's formula */
    pt_course_cam cam;           /*   the camera, */
    struct prev { pt_vec4 *v; size_t n; } *prev;  /* each position's vertices
                                 ** after the stage reported last */
    char xbuf[8192];             /*   and the text of one record */
    struct kept {                /* text: fixed-point spellings (kept()) */
        uint64_t bits;
        unsigned char len;       /* 0: an empty slot */
        char s[39];
    } kept[3][1 << KEPT_BITS];
    char spill[400];             /* a spelling too long to keep ("%.6f" of
                                 ** any double: 317 bytes at most) */
} walker;

/* The most a record writes after its names and before --explain's text:
** eight numbers of 64 bytes (PT_NUMLEN + 2 at most; a colour's or
** coverage's "%.6f" of a float, 47), integers of 20 digits, the stage's
** and the edge's names, the keys. */
#define REC_REST (8 * 64 + 8 * 24 + 256)

/* ===== numbers ===== */

/* A CSV cell's double: pt_fmt_shortest's spelling ("-0" for -0.0, "nan",
** "inf"), kept for the next time in the trace's slots. */
static char *num_csv_at(pt_trace *t, char *o, double x)
{
    return short_at(t, o, x);
}

/* The text trace's fixed-point spellings kept, by the bits' hash as the
** trace keeps its shortest ones (trace_int.h: num_slot): a table for the
** coordinates (w->precision digits), one for the colours (6), one for the
** pixels' coverage (4).  A scene's colours and many of its coordinates come
** again and again (white, a model's z, coverage 1). */
enum { KEPT_XYZ, KEPT_RGB, KEPT_COVERAGE };
enum { OPEN_WARN, OPEN_PRIM, OPEN_VERTEX, OPEN_NAMES };   /* opening()'s slots */

/* x with prec digits after the point, from table which when kept there: the
** spelling, its length in *n.  The coordinates as pt_fmt_fixed spells them;
** a colour and a coverage "%.*f" (pt_fmt_fixed where it spells as printf
** does, a finite x below 1e15; else printf: "-nan", a float's 39 digits). */
static const char *kept(walker *w, int which, double x, int prec, size_t *n)
{
    struct kept *e;
    uint64_t bits;
    char b[sizeof w->spill];
    size_t len;

    memcpy(&bits, &x, sizeof bits);
    e = &w->kept[which][(bits * UINT64_C(0x9e3779b97f4a7c15)) >> (64 - KEPT_BITS)];
    if (e->bits == bits && e->len) { *n = e->len; return e->s; }
    if (which == KEPT_XYZ || (isfinite(x) && fabs(x) < 1e15)) len = pt_fmt_fixed(b, x, prec);
    else len = (size_t)snprintf(b, sizeof b, "%.*f", prec, x);
    if (len > sizeof e->s) {                 /* too long to keep */
        memcpy(w->spill, b, len);
        *n = len;
        return w->spill;
    }
    e->bits = bits;
    e->len = (unsigned char)len;
    memcpy(e->s, b, len);
    *n = len;
    return e->s;
}

/* Text: a coordinate right-aligned in 13 columns ("%13s" of pt_fmt_fixed). */
static char *num_text_at(walker *w, char *o, double x)
{
    size_t n;
    const char *s = kept(w, KEPT_XYZ, x, w->precision, &n);

    if (n < 13) { memset(o, ' ', 13 - n); o += 13 - n; }
    memcpy(o, s, n);
    return o + n;
}

/* "%.*f" of x, a colour (which KEPT_RGB, prec 6) or a coverage. */
static char *fixed_at(walker *w, char *o, double x, int which, int prec)
{
    size_t n;
    const char *s = kept(w, which, x, prec, &n);

    memcpy(o, s, n);
    return o + n;
}

static const char *edge_name(pt_rv_edge e)
{
    switch (e) {
    case PT_RV_NEAR: return "z=n";
    case PT_RV_XPOS: return "x=+1";
    case PT_RV_XNEG: return "x=-1";
    case PT_RV_YPOS: return "y=+1";
    case PT_RV_YNEG: return "y=-1";
    }
    return "";
}

/* ===== the three formatters ===== */

/* Make w->skey for format w->fmt, from stage_names. */
static void skeys_make(walker *w)
{
    int st, n;

    for (st = 0; st < PT_NCST; st++) {
        struct pt_trace_frag *k = &w->skey[st];
        if (w->fmt == PT_FORMAT_JSONL)
            n = snprintf(k->s, sizeof k->s, ",\"stage\":\"%s\",\"x\":", stage_names[st]);
        else if (w->fmt == PT_FORMAT_CSV)
            n = snprintf(k->s, sizeof k->s, ",%s,", stage_names[st]);
        else
            n = snprintf(k->s, sizeof k->s, " %-12s x =", stage_names[st]);
        k->len = (unsigned char)n;              /* stage_names are short: it fits */
    }
}

/* Slot k's text at o: one copy of the whole slot (two 16-byte moves; the
** bytes past its length are written over next); returns the end. */
static inline char *slot_at(char *o, const struct pt_trace_frag *k)
{
    memcpy(o, k, sizeof *k);
    return o + k->len;
}

/* Stage st's key at o (w->skey); returns the end. */
static inline char *skey_at(const walker *w, char *o, pt_course_stage st)
{
    return slot_at(o, &w->skey[st]);
}

/* Make w->names say r's model and position as format fmt writes them. */
static void names_make(walker *w, const rec *r)
{
    pt_sbuf *nb = &w->names;

    nb->len = 0;
    if (w->fmt == PT_FORMAT_JSONL) {
        pt_sbuf_add(nb, ",\"model\":");
        pt_sbuf_add_json(nb, r->model);
        pt_sbuf_add(nb, ",\"position\":");
        pt_sbuf_add_json(nb, r->position);
    } else if (w->fmt == PT_FORMAT_CSV) {
        pt_sbuf_add_csv(nb, r->model);
        pt_sbuf_add(nb, ",");
        pt_sbuf_add_csv(nb, r->position);
        pt_sbuf_add(nb, ",");
    } else {
        pt_sbuf_add_term(nb, r->model, strlen(r->model));
    }
    w->names_model = r->model;
    w->names_position = r->position;
    w->names_gen++;
}

/* Make w->names say r's model and position, unless it does (inlined where
** a record is written: most records name the one before's).  0 when out of
** memory (then the record is not written). */
static inline int names(walker *w, const rec *r)
{
    if (!w->names.s || r->model != w->names_model || r->position != w->names_position)
        names_make(w, r);
    if (w->names.failed) w->failed = 1;
    return !w->names.failed;
}

/* opening() when slot e is not made for the names: made when the head
** and the names fit it, else written the long way. */
static NOINLINE char *opening_make(walker *w, struct opened *e, const char *head, size_t n)
{
    pt_trace *t = w->t;

    if (n + w->names.len > sizeof e->s) {
        put(t, head, n);
        put(t, w->names.s, w->names.len);
        return room(t, REC_REST);
    }
    memcpy(e->s, head, n);
    memcpy(e->s + n, w->names.s, w->names.len);
    e->len = n + w->names.len;
    e->gen = w->names_gen;
    return NULL;
}

/* The record's head (the slot k of w->opened keeps it: one a call site)
** and names, then room for the rest of it: where that goes.  The two are
** kept together while the names stay the same, and copied as one block of a
** fixed size. */
static inline char *opening(walker *w, int k, const char *head, size_t n)
{
    struct opened *e = &w->opened[k];
    pt_trace *t = w->t;
    char *o;

    if (e->gen != w->names_gen && (o = opening_make(w, e, head, n)) != NULL) return o;
    o = room(t, sizeof e->s + REC_REST);
    memcpy(o, e->s, sizeof e->s);
    t->len += e->len;
    return o + e->len;
}

/* The record ends at o. */
static void done(walker *w, char *o)
{
    w->t->len = (size_t)(o - w->t->buf);
}

#define LIT(s) s, sizeof s - 1           /* a literal and its length, for put() */

/* A literal in a 32-byte slot with its length, copied whole (slot_at) */
#define KEY(s) {s, sizeof s - 1}

/* A primitive drawn, its numbers after keys[]: a point's v, c, radius
** (keys 0 .. 3), a line's v v c c (keys 4 .. 8); 1-based indices. */
static char *prim_at(const pt_trace *t, char *o, const pt_rv_prim *p,
                     const struct pt_trace_frag keys[9])
{
    if (p->kind == PT_RV_POINT) {
        o = u64_at(t, slot_at(o, &keys[0]), (uint64_t)p->v[0] + 1);
        o = u64_at(t, slot_at(o, &keys[1]), (uint64_t)p->c[0] + 1);
        return slot_at(int_at(t, slot_at(o, &keys[2]), p->radius, 0), &keys[3]);
    }
    o = u64_at(t, slot_at(o, &keys[4]), (uint64_t)p->v[0] + 1);
    o = u64_at(t, slot_at(o, &keys[5]), (uint64_t)p->v[1] + 1);
    o = u64_at(t, slot_at(o, &keys[6]), (uint64_t)p->c[0] + 1);
    o = u64_at(t, slot_at(o, &keys[7]), (uint64_t)p->c[1] + 1);
    return slot_at(o, &keys[8]);
}

/* Coordinate c (0 .. 3: x y z w) of a vertex as JSON spells it
** (json_num_at), at o, e its number's slot in w->vspell; returns the end.
** The course's stages go over a whole model one stage after another, and a
** vertex keeps many of its numbers from one stage to the next (the view's x
** and y are the model's after a translation; renderer 9's camera and view
** often the world's): the last spelling of each vertex number's
** coordinates is kept, by the number's bits, and copied when they come
** again; the trace's own slots (json_num_at) see 8,000 other numbers in
** between. */
static inline char *vnum_at(walker *w, char *o, struct vspell *e, int c, double x)
{
    uint64_t bits;
    char *end;
    size_t n;

    memcpy(&bits, &x, sizeof bits);
    if (e->len[c] && e->bits[c] == bits) {
        memcpy(o, e->s[c], PT_SHORTLEN);
        return o + e->len[c];
    }
    end = json_num_at(w->t, o, x);
    n = (size_t)(end - o);
    if (n <= PT_SHORTLEN) {                      /* a fixed size: what follows n is */
        e->bits[c] = bits;                       /*   never copied beyond the record */
        e->len[c] = (unsigned char)n;
        memcpy(e->s[c], o, PT_SHORTLEN);
    }
    return end;
}

/* ,"color":[R,G,B] of a vertex record, at o; returns the end.  The last
** colour's spelling is kept: a model's vertices mostly share one. */
static char *color_json_at(walker *w, char *o, pt_rgb c)
{
    struct vcolor *e = &w->vcolor;
    pt_trace *t = w->t;
    char *s;

    if (e->len && memcmp(&c, &e->c, sizeof c) == 0) {
        memcpy(o, e->s, sizeof e->s);
        return o + e->len;
    }
    s = json_num_at(t, str_at(e->s, ",\"color\":["), (double)c.r);
    s = json_num_at(t, str_at(s, ","), (double)c.g);
    s = json_num_at(t, str_at(s, ","), (double)c.b);
    s = str_at(s, "]");
    e->len = (size_t)(s - e->s);
    e->c = c;
    memcpy(o, e->s, e->len);
    return o + e->len;
}

/* A vertex record in JSON (inlined in on_stage's loop: the most records). */
static inline ALWAYS_INLINE void json_vertex(walker *w, const rec *r)
{
    pt_trace *t = w->t;
    struct vspell *ve = &w->vspell[r->v % VSPELL_N];
    char *o = opening(w, OPEN_VERTEX, LIT("{\"type\":\"vertex\""));

    o = u64_at(t, str_at(o, ",\"v\":"), r->v);
    o = vnum_at(w, skey_at(w, o, r->st), ve, 0, r->p.x);
    o = vnum_at(w, str_at(o, ",\"y\":"), ve, 1, r->p.y);
    o = vnum_at(w, str_at(o, ",\"z\":"), ve, 2, r->p.z);
    if (w->w4) o = vnum_at(w, str_at(o, ",\"w\":"), ve, 3, r->p.w);
    if (r->has_color) o = color_json_at(w, o, r->color);
    if (r->from) {
        o = str_at(str_at(o, ",\"from\":{\"stage\":\""), r->from);
        o = u64_at(t, str_at(o, "\",\"segment\":"), r->from_prim);
        o = str_at(str_at(o, ",\"edge\":\""), r->edge);
        o = json_num_at(t, str_at(o, "\",\"t\":"), r->t);
        o = str_at(o, "}");
    }
    if (!r->explain) {
        done(w, str_at(o, "}\n"));
        return;
    }
    done(w, o);
    w->sb.len = 0;
    pt_sbuf_add(&w->sb, ",\"explain\":");
    pt_sbuf_add_json(&w->sb, r->explain);
    if (w->sb.failed) w->failed = 1;
    else put(t, w->sb.s, w->sb.len);
    put(t, LIT("}\n"));
}

static void fmt_json(walker *w, const rec *r)
{
    pt_trace *t = w->t;
    char *o;

    if (r->kind == R_WARN) {
        o = opening(w, OPEN_WARN, LIT("{\"type\":\"warning\""));
        o = str_at(str_at(o, ",\"warning\":\""), r->warning);
        done(w, str_at(o, "\"}\n"));
        return;
    }
    if (r->kind == R_PRIM) {
        static const struct pt_trace_frag keys[] = {
            KEY(",\"kind\":\"point\",\"v\":["), KEY("],\"c\":["), KEY("],\"radius\":"), KEY(""),
            KEY(",\"kind\":\"line\",\"v\":["), KEY(","), KEY("],\"c\":["), KEY(","), KEY("]")};
        o = opening(w, OPEN_PRIM, LIT("{\"type\":\"primitive\""));
        o = prim_at(t, u64_at(t, str_at(o, ",\"primitive\":"), r->v), r->prim, keys);
        o = u64_at(t, str_at(o, ",\"pixels\":"), r->pixels);
        done(w, str_at(o, "}\n"));
        return;
    }
    json_vertex(w, r);
}

/* Text: " p12    " or " v12    ": the letter, the number left-aligned in 6. */
static char *who_at(const pt_trace *t, char *o, const char *k, uint64_t n)
{
    char *e = u64_at(t, str_at(o, k), n), *end = o + strlen(k) + 6;

    for (; e < end; e++) *e = ' ';
    return e;
}

static void fmt_text(walker *w, const rec *r)
{
    pt_trace *t = w->t;
    char *o = opening(w, OPEN_NAMES, "", 0);

    if (r->kind == R_WARN) {
        o = str_at(str_at(o, " warning: "), r->warning);
        done(w, str_at(o, "\n"));
        return;
    }
    if (r->kind == R_PRIM) {
        static const struct pt_trace_frag keys[] = {
            KEY(" drawn        point v"), KEY(" c"), KEY(" radius "), KEY(""),
            KEY(" drawn        line v"), KEY(" v"), KEY(" c"), KEY(" c"), KEY("")};
        o = prim_at(t, who_at(t, o, " p", r->v), r->prim, keys);
        o = u64_at(t, str_at(o, ": "), r->pixels);
        done(w, str_at(o, " pixels\n"));
        return;
    }
    o = who_at(t, o, " v", r->v);
    o = num_text_at(w, skey_at(w, o, r->st), r->p.x);
    o = num_text_at(w, str_at(o, "  y ="), r->p.y);
    o = num_text_at(w, str_at(o, "  z ="), r->p.z);
    if (w->w4) o = num_text_at(w, str_at(o, "  w ="), r->p.w);
    if (r->has_color) {
        o = fixed_at(w, str_at(o, "  rgb = "), (double)r->color.r, KEPT_RGB, 6);
        o = fixed_at(w, str_at(o, " "), (double)r->color.g, KEPT_RGB, 6);
        o = fixed_at(w, str_at(o, " "), (double)r->color.b, KEPT_RGB, 6);
    }
    if (r->from) {
        o = str_at(str_at(o, "  from "), r->from);
        o = u64_at(t, str_at(o, " of segment "), r->from_prim);
        o = str_at(str_at(o, " at "), r->edge);
        o = str_at(o, ", t = ");
        o += pt_fmt_shortest(o, r->t);
    }
    done(w, str_at(o, "\n"));
    if (r->explain) {                       /* under the record, as renderer 4's */
        put(t, LIT("              "));
        puts_(t, r->explain);
        put(t, LIT("\n"));
    }
}

static void fmt_csv(walker *w, const rec *r)
{
    pt_trace *t = w->t;
    char *o;

    if (r->kind != R_VERTEX) return;             /* CSV: vertex rows only */
    o = opening(w, OPEN_NAMES, "", 0);
    o = num_csv_at(t, skey_at(w, u64_at(t, o, r->v), r->st), r->p.x);
    o = num_csv_at(t, str_at(o, ","), r->p.y);
    o = num_csv_at(t, str_at(o, ","), r->p.z);
    o = str_at(o, ",");
    if (w->w4) o = num_csv_at(t, o, r->p.w);
    o = str_at(o, ",");
    if (r->has_color) {
        o = num_csv_at(t, o, (double)r->color.r);
        o = num_csv_at(t, str_at(o, ","), (double)r->color.g);
        o = num_csv_at(t, str_at(o, ","), (double)r->color.b);
    } else o = str_at(o, ",,");
    if (r->from) {
        o = str_at(str_at(o, ","), r->from);
        o = u64_at(t, str_at(o, ","), r->from_prim);
        o = str_at(str_at(o, ","), r->edge);
        o = num_csv_at(t, str_at(o, ","), r->t);
    } else o = str_at(o, ",,,,");
    done(w, str_at(o, "\n"));
}

static void emit(walker *w, const rec *r)
{
    if (!w->ln.taken || w->failed || !names(w, r)) return;
    switch (w->fmt) {
    case PT_FORMAT_JSONL: fmt_json(w, r); break;
    case PT_FORMAT_CSV: fmt_csv(w, r); break;
    default: fmt_text(w, r); break;
    }
}

/* ===== the walker ===== */

/* Start a record of kind k about position pos. */
static void rec_init(rec *r, rkind k, const pt_course_pos *pos)
{
    memset(r, 0, sizeof *r);
    r->kind = k;
    r->model = pos->sm->name;
    r->position = pos->pos_name;
}

static const struct origin *origin_of(const walker *w, uint32_t v)
{
    size_t k;
    for (k = w->norg; k-- > 0;)
        if (w->org[k].v == v) return &w->org[k];
    return NULL;
}

/* --explain: record r's formula with its numbers (pt_cx_explain_rec), from
** the position's vertices after the stage before; o: where a clip stage's
** new vertex came from. */
static void explain(walker *w, rec *r, pt_course_stage st, const pt_course_pos *pos, size_t k,
                    const struct origin *o)
{
    const struct prev *pv = &w->prev[pos->index];
    pt_cx_rec x;

    memset(&x, 0, sizeof x);
    x.st = st;
    x.pos = pos;
    x.cur = r->p;
    if (k < pv->n) x.prev = pv->v[k];
    x.color = r->has_color ? &r->color : NULL;
    if (o) { x.cut = &o->cut; x.cut_prim = o->prim; }
    pt_cx_explain_rec(w->xbuf, sizeof w->xbuf, w->s, &w->cam, &x, "; ");
    r->explain = w->xbuf;
}

/* --explain: keep the position's vertices after stage st for the next. */
static void keep_prev(walker *w, const pt_course_pos *pos, const pt_rv_model *m)
{
    struct prev *pv = &w->prev[pos->index];
    pt_vec4 *v = realloc(pv->v, (m->nv ? m->nv : 1) * sizeof *v);

    if (!v) { w->failed = 1; return; }
    if (m->nv) memcpy(v, m->v, m->nv * sizeof *v);
    pv->v = v;
    pv->n = m->nv;
}

static void on_stage(void *ud, pt_course_stage st, const pt_course_pos *pos,
                     const pt_rv_model *m)
{
    walker *w = ud;
    size_t k, from = 0;
    const struct origin *o;
    rec r;

    if (st == PT_CST_NEARCLIP || st == PT_CST_CLIP) {   /* only the vertices it made */
        from = m->nv;
        for (k = 0; k < w->norg; k++)
            if (w->org[k].v < from) from = w->org[k].v;
    }
    if (!w->ln.taken) {                     /* another writer's piece: counted only */
        w->nvrec += m->nv - from;
        from = m->nv;
    }
    rec_init(&r, R_VERTEX, pos);            /* what the loop below sets again */
    r.st = st;                              /* for each record, the rest stays */
    if (from < m->nv && !names(w, &r)) from = m->nv;   /* their names: once */
    for (k = from; k < m->nv; k++) {
        r.v = (uint64_t)k + 1;
        r.p = m->v[k];
        r.has_color = k < m->nc;
        if (r.has_color) r.color = m->c[k];
        o = NULL;
        if (st == PT_CST_NEARCLIP || st == PT_CST_CLIP) {
            r.from = NULL;
            o = origin_of(w, (uint32_t)k);
            if (o) {
                r.from = stage_names[st];
                r.from_prim = o->prim;
                r.t = o->t;
                r.edge = edge_name(o->edge);
                r.has_color = o->c < m->nc;
                if (r.has_color) r.color = m->c[o->c];
            }
        }
        if (w->explain) explain(w, &r, st, pos, k, o);
        if (w->failed) break;
        if (w->fmt == PT_FORMAT_JSONL) json_vertex(w, &r);
        else emit(w, &r);
        w->nvrec++;
    }
    if (w->explain) keep_prev(w, pos, m);
    w->prim_no = 0;
    w->norg = 0;
    w->raster_no = 0;
}

static void clip_begin(void *ud, const pt_rv_model *m, const pt_rv_prim *p)
{
    walker *w = ud;
    (void)m; (void)p;
    w->prim_no++;
}

static void clip_cut(void *ud, const pt_rv_cut *c)
{
    walker *w = ud;

    if (w->norg == w->cap_org) {
        size_t cap = w->cap_org ? 2 * w->cap_org : 16;
        struct origin *o = realloc(w->org, cap * sizeof *o);
        if (!o) { w->failed = 1; return; }
        w->org = o;
        w->cap_org = cap;
    }
    w->org[w->norg].v = c->v_new;
    w->org[w->norg].c = c->c_new;
    w->org[w->norg].prim = w->prim_no;
    w->org[w->norg].t = c->t;
    w->org[w->norg].edge = c->edge;
    w->org[w->norg].cut = *c;
    w->norg++;
}

static void on_warn(void *ud, pt_course_warn k, const pt_course_pos *pos,
                    const pt_rv_model *m)
{
    walker *w = ud;
    rec r;

    (void)m;
    rec_init(&r, R_WARN, pos);
    switch (k) {
    case PT_CWN_NO_VERTICES: r.warning = "no_vertices"; break;
    case PT_CWN_NO_PRIMITIVES: r.warning = "no_primitives"; break;
    case PT_CWN_NO_COLORS: r.warning = "no_colors"; break;
    case PT_CWN_DUMP: return;
    case PT_CWN_DEFAULT_COLOR: r.warning = "default_color"; break;
    }
    emit(w, &r);
}

/* The most a pixel record writes after its opening: two integers of 20
** bytes and the key between them, then its tail, copied whole (PIXEL_TAIL). */
#define PIXEL_REST 160
_Static_assert(2 * 20 + 16 + PIXEL_TAIL <= PIXEL_REST, "a pixel record fits its room");

/* Make w->pix the opening of the pixel records of the primitive being drawn
** (w->pos, number w->raster_no + 1).  0 when out of memory. */
static NOINLINE int pixel_head(walker *w)
{
    static const char head[] = "{\"type\":\"pixel\"";
    pt_sbuf *p = &w->pix;
    char b[64], *e;
    size_t nh, nb;
    rec r;

    rec_init(&r, R_VERTEX, w->pos);          /* for its names (the kind plays no part) */
    if (!names(w, &r)) return 0;
    if (w->fmt == PT_FORMAT_JSONL) {
        nh = sizeof head - 1;
        e = u64_at(w->t, str_at(b, ",\"primitive\":"), w->raster_no + 1);
        e = str_at(e, ",\"x\":");
    } else {
        nh = 0;
        e = str_at(who_at(w->t, b, " p", w->raster_no + 1), " pixel        x_fb = ");
    }
    nb = (size_t)(e - b);
    w->pix_len = nh + w->names.len + nb;
    if (w->pix_len <= sizeof w->pix_fixed) {     /* the head, the names, the number */
        memcpy(w->pix_fixed, head, nh);
        memcpy(w->pix_fixed + nh, w->names.s, w->names.len);
        memcpy(w->pix_fixed + nh + w->names.len, b, nb);
    } else {                                     /* too long to copy by a fixed size */
        p->len = 0;
        pt_sbuf_addn(p, head, nh);
        pt_sbuf_addn(p, w->names.s, w->names.len);
        pt_sbuf_addn(p, b, nb);
        if (p->failed) { w->failed = 1; return 0; }
    }
    w->pix_made = 1;
    return 1;
}

/* The end of a pixel record after its y, for bytes b and coverage f, at o
** (JSON: ,"rgb":[R,G,B],"coverage":F}; text: rgb = R G B  coverage F);
** returns its end.  This function can't fail. */
static char *tail_at(walker *w, char *o, const unsigned char b[3], float f)
{
    pt_trace *t = w->t;

    if (w->fmt == PT_FORMAT_JSONL) {
        o = u64_at(t, str_at(o, ",\"rgb\":["), b[0]);
        o = u64_at(t, str_at(o, ","), b[1]);
        o = u64_at(t, str_at(o, ","), b[2]);
        o = json_num_at(t, str_at(o, "],\"coverage\":"), (double)f);
        return str_at(o, "}\n");
    }
    o = u64_at(t, str_at(o, "  rgb = "), b[0]);
    o = u64_at(t, str_at(o, " "), b[1]);
    o = u64_at(t, str_at(o, " "), b[2]);
    o = fixed_at(w, str_at(o, "  coverage "), (double)f, KEPT_COVERAGE, 4);
    return str_at(o, "\n");
}

/* The end of a pixel record for bytes b and coverage f (its bits fb), as
** tail_at writes it, made in its slot of w->tails unless the slot holds it:
** a segment's steps mostly write one colour at coverage 1, and an
** anti-aliased render's weights and the bytes they give are few (some
** hundreds in the bench's scene). */
static NOINLINE void tail_make(walker *w, struct tail *e, const unsigned char b[3], float f,
                               uint64_t key)
{
    e->len = (size_t)(tail_at(w, e->s, b, f) - e->s);
    assert(e->len <= (w->fmt == PT_FORMAT_JSONL ? PIXEL_TAIL_JSON : PIXEL_TAIL));
    e->key = key;
}

/* A tail's key: the coverage's bits, a bit that no empty slot has, the bytes. */
static inline uint64_t tail_key(const unsigned char b[3], float f)
{
    uint32_t fb;

    memcpy(&fb, &f, sizeof fb);
    return (uint64_t)fb << 32 | UINT64_C(1) << 24 | (uint64_t)b[0] << 16 | (uint64_t)b[1] << 8 | b[2];
}

static inline const struct tail *tail_of(walker *w, const unsigned char b[3], float f)
{
    uint64_t key = tail_key(b, f);
    struct tail *e = w->tail_last;              /* the record before's, most often */

    if (e->key == key) return e;
    e = &w->tails[(uint32_t)(key ^ key >> 32) * UINT32_C(0x9e3779b9) >> (32 - TAIL_BITS)];
    if (e->key != key) tail_make(w, e, b, f, key);
    w->tail_last = e;
    return e;
}

/* Pixel px's record after its opening, at o: x_fb, y_fb, its tail (of
** PIXEL_TAIL bytes, JSON's of PIXEL_TAIL_JSON); returns the end. */
static inline ALWAYS_INLINE char *pixel_rest_at(walker *w, char *o, const pt_rv_raster_par *par,
                                               const pt_rv_px_out *px, int jsonl)
{
    static const struct pt_trace_frag y_key[2] = {KEY("  y_fb = "), KEY(",\"y\":")};
    const struct tail *e;

    o = int_at(w->t, o, (int64_t)par->x_ul + px->x_vp, 0);
    o = int_at(w->t, slot_at(o, &y_key[jsonl]), (int64_t)par->y_ul + px->y_vp, 0);
    e = tail_of(w, px->b, px->coverage);
    if (jsonl) memcpy(o, e->s, PIXEL_TAIL_JSON);
    else memcpy(o, e->s, PIXEL_TAIL);
    return o + e->len;
}

/* The pixel records of n pixels px[] of the viewport, in order: each one's
** opening (one copy of a fixed size, or the long one), the pixel as x_fb and
** y_fb, the bytes written and the coverage (its tail, kept: tail_of).  All
** pixel records are written here, the rasterizer's runs (pt_rv_raster_ls.
** pixels) and its single pixel lines (on_pixel). */
static void on_pixels(void *ud, const pt_rv_raster_par *par, const pt_rv_px_out *px, size_t n)
{
    walker *w = ud;
    pt_trace *t = w->t;
    int jsonl = w->fmt == PT_FORMAT_JSONL;
    size_t k;
    char *o;

    assert(n <= PT_RV_RUN);
    if (w->failed || (!w->pix_made && !pixel_head(w))) return;
    if (w->pix_len > sizeof w->pix_fixed) {          /* a long opening */
        for (k = 0; k < n; k++) {
            put(t, w->pix.s, w->pix_len);
            done(w, pixel_rest_at(w, room(t, PIXEL_REST), par, &px[k], jsonl));
        }
        return;
    }
    o = room(t, n * (sizeof w->pix_fixed + PIXEL_REST));   /* 16 KiB at most */
    for (k = 0; k < n; k++) {
        memcpy(o, w->pix_fixed, sizeof w->pix_fixed);
        o = pixel_rest_at(w, o + w->pix_len, par, &px[k], jsonl);
    }
    done(w, o);
}

/* The rasterizer's pixel lines as pixel records: an anti-aliased step is
** two pixels, weighted 1 - f and f, f the fraction of the stepped y.  The
** records say the bytes written (b[]), so the rasterizer needs no gamma in
** float: the listener says bytes_only. */
static void on_pixel(void *ud, const pt_rv_pixel *px)
{
    pt_rv_px_out out[2];
    size_t n = 0;

    switch (px->kind) {
    case PT_RV_PX_POINT:
        if (px->clipped) break;
        /* fall through */
    case PT_RV_PX_STEP:
    case PT_RV_PX_END:
        out[n].x_vp = px->x_vp, out[n].y_vp = px->y_vp, out[n].coverage = 1.0f;
        memcpy(out[n++].b, px->b[0], 3);
        break;
    case PT_RV_PX_AA: {
        double y = px->transposed ? px->x_pp : px->y_pp;
        float f = (float)(y - (double)(int64_t)y);
        if (px->transposed) {
            out[n].x_vp = px->lo, out[n].y_vp = px->y_vp;
            out[n + 1].x_vp = px->hi, out[n + 1].y_vp = px->y_vp;
        } else {
            out[n].x_vp = px->x_vp, out[n].y_vp = px->lo;
            out[n + 1].x_vp = px->x_vp, out[n + 1].y_vp = px->hi;
        }
        out[n].coverage = 1.0f - f;
        out[n + 1].coverage = f;
        memcpy(out[n].b, px->b[0], 3);
        memcpy(out[n + 1].b, px->b[1], 3);
        n += 2;
        break;
    }
    }
    if (n) on_pixels(ud, px->par, out, n);
}

static void on_raster(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                      const pt_rv_prim *p)
{
    walker *w = ud;
    (void)m; (void)p;
    w->pos = pos;
    w->pix_made = 0;                          /* its pixels: a new opening */
}

static void on_drawn(void *ud, const pt_course_pos *pos, const pt_rv_model *m,
                     const pt_rv_prim *p, uint64_t n)
{
    walker *w = ud;
    rec r;

    (void)m;
    rec_init(&r, R_PRIM, pos);
    r.v = ++w->raster_no;
    r.prim = p;
    r.pixels = n;
    emit(w, &r);
    w->nprims++;
    w->npixels += n;
}

/* A double as a JSON record spells it (json_num_at), at the end of w->sb. */
static void num_json(walker *w, double x)
{
    char b[PT_NUMLEN + 2];
    pt_sbuf_addn(&w->sb, b, (size_t)(json_num_at(w->t, b, x) - b));
}

/* The header: the scene, its renderer, framebuffer, viewport and camera. */
static void header(walker *w, const pt_course_cam *c)
{
    const pt_scene *s = w->s;
    const pt_rv_camera *k = &c->cam;
    pt_sbuf *sb = &w->sb;

    if (w->fmt == PT_FORMAT_CSV) {
        pt_sbuf_add(sb, "model,position,v,stage,x,y,z,w,r,g,b,from,segment,edge,t\n");
    } else if (w->fmt == PT_FORMAT_JSONL) {
        pt_sbuf_addf(sb, "{\"type\":\"header\",\"version\":1,\"renderer\":%d,\"pipeline\":%d,"
                     "\"scene\":", s->renderer, s->pipeline2 ? 2 : 1);
        pt_sbuf_add_json(sb, s->path);
        pt_sbuf_addf(sb, ",\"framebuffer\":{\"w\":%d,\"h\":%d},\"viewport\":{\"x\":%d,\"y\":%d,"
                     "\"w\":%d,\"h\":%d},\"camera\":{\"projection\":\"%s\",\"l\":", s->fb_w,
                     s->fb_h, s->vp_x, s->vp_y, s->vp_w, s->vp_h,
                     k->perspective ? "perspective" : "orthographic");
        num_json(w, k->l); pt_sbuf_add(sb, ",\"r\":");
        num_json(w, k->r); pt_sbuf_add(sb, ",\"b\":");
        num_json(w, k->b); pt_sbuf_add(sb, ",\"t\":");
        num_json(w, k->t); pt_sbuf_add(sb, ",\"n\":");
        num_json(w, k->n); pt_sbuf_addf(sb, "},\"nearclip\":%s,\"antialias\":%s,\"gamma\":%s}\n",
                                          s->nearclip ? "true" : "false",
                                          s->antialias ? "true" : "false",
                                          s->gamma ? "true" : "false");
    } else {
        char b[5][PT_NUMLEN];
        pt_sbuf_add(sb, "# pipetrace trace of a course renderer's scene, format version 1\nscene        ");
        pt_sbuf_add_term(sb, s->path, strlen(s->path));
        pt_fmt_shortest(b[0], k->l); pt_fmt_shortest(b[1], k->r);
        pt_fmt_shortest(b[2], k->b); pt_fmt_shortest(b[3], k->t);
        pt_fmt_shortest(b[4], k->n);
        pt_sbuf_addf(sb, "\nrenderer     %d%s\nframebuffer  %d x %d\nviewport     %d x %d at "
                     "(x_ul, y_ul) = (%d, %d)\ncamera       %s, l r b t = %s %s %s %s, n = %s\n"
                     "switches     nearclip %s, antialias %s, gamma %s\n\n", s->renderer,
                     s->pipeline2 ? " (Pipeline2)" : "", s->fb_w, s->fb_h, s->vp_w, s->vp_h,
                     s->vp_x, s->vp_y, k->perspective ? "perspective" : "orthographic",
                     b[0], b[1], b[2], b[3], b[4], s->nearclip ? "on" : "off",
                     s->antialias ? "on" : "off", s->gamma ? "on" : "off");
    }
    if (sb->failed) w->failed = 1;
    else put(w->t, sb->s, sb->len);
    sb->len = 0;
}

static void summary(walker *w)
{
    char b[256];
    int n;

    if (w->fmt == PT_FORMAT_CSV) return;
    if (w->fmt == PT_FORMAT_JSONL)
        n = snprintf(b, sizeof b, "{\"type\":\"summary\",\"models\":%lu,\"vertex_records\":%llu,"
                     "\"primitives_drawn\":%llu,\"pixels\":%llu}\n", (unsigned long)w->s->nmodels,
                     (unsigned long long)w->nvrec, (unsigned long long)w->nprims,
                     (unsigned long long)w->npixels);
    else
        n = snprintf(b, sizeof b, "\nsummary\n  models %lu  vertex_records %llu  "
                     "primitives_drawn %llu  pixels %llu\n", (unsigned long)w->s->nmodels,
                     (unsigned long long)w->nvrec, (unsigned long long)w->nprims,
                     (unsigned long long)w->npixels);
    put(w->t, b, (size_t)n);
}

/* Set w up to write s's trace in format fmt to f.  0, or -1 when out of
** memory (then walker_free(w) still). */
static int walker_init(walker *w, FILE *f, const pt_scene *s, int fmt, int precision,
                       int explain)
{
    memset(w, 0, sizeof *w);
    w->s = s;
    w->fmt = fmt;
    w->precision = precision;
    w->w4 = s->renderer == 9;
    w->ln.taken = 1;
    pt_sbuf_init(&w->sb);
    pt_sbuf_init(&w->names);
    pt_sbuf_init(&w->pix);
    pt_course_camera(s, &w->cam);
    w->explain = explain;
    if (!(w->t = malloc(sizeof *w->t))) return -1;
    pt_trace_init(w->t, f, (pt_format)fmt, precision);
    w->ln.t = w->t;
    if (explain && !(w->prev = calloc(s->nmodels ? s->nmodels : 1, sizeof *w->prev))) return -1;
    skeys_make(w);
    w->tail_last = &w->tails[0];             /* empty: its key matches none */
    if (fmt == PT_FORMAT_JSONL && !(w->vspell = calloc(VSPELL_N, sizeof *w->vspell))) return -1;
    return 0;
}

static void walker_free(walker *w)
{
    free(w->t);
    free(w->vspell);
    pt_sbuf_free(&w->sb);
    pt_sbuf_free(&w->names);
    pt_sbuf_free(&w->pix);
    free(w->org);
    if (w->prev) {
        size_t k;
        for (k = 0; k < w->s->nmodels; k++) free(w->prev[k].v);
        free(w->prev);
    }
}

/* Render w's scene into fb with w listening: the header, the records, the
** summary, each when its piece is w's (cut into pieces for tlanes.h when
** its lane says, else all of them).  0, or -1 when out of memory. */
static int walk(void *ud, pt_fb *fb)
{
    walker *w = ud;
    pt_course_ls ls;
    pt_rv_raster_ls rls;
    int rc;

    memset(&rls, 0, sizeof rls);
    rls.pixel = on_pixel;
    rls.ud = w;
    rls.bytes_only = 1;
    rls.pixels = on_pixels;
    memset(&ls, 0, sizeof ls);
    ls.stage = on_stage;
    ls.drawn = on_drawn;
    ls.raster = on_raster;
    ls.raster_ls = w->fmt == PT_FORMAT_CSV ? NULL : &rls;   /* CSV: no pixel rows */
    ls.warn = on_warn;
    ls.nearclip.begin = clip_begin;
    ls.nearclip.cut = clip_cut;
    ls.nearclip.ud = w;
    ls.clip = ls.nearclip;
    pt_course_lane_ls(&ls, &w->ln);
    ls.ud = w;
    if (w->ln.taken) header(w, &w->cam);     /* piece 0: lane 0's */
    rc = pt_course_render(w->s, fb, &ls);
    if (rc == 0 && !w->failed && w->ln.taken) summary(w);   /* the last piece: lane 0's */
    pt_trace_flush(w->t);                    /* write errors: in ferror(f) */
    return rc != 0 || w->failed ? -1 : 0;
}

/* The trace on two threads: 0, -1 (out of memory), or 1 when no second
** thread is to be had (nothing has run). */
static int walk_lanes(FILE *f, const pt_scene *s, int fmt, int precision, int explain,
                      pt_course_cuts *cuts, pt_fb *fb)
{
    walker *w = calloc(2, sizeof *w);
    int rc = 1;

    if (!w) return 1;
    if (walker_init(&w[0], f, s, fmt, precision, explain) == 0 &&
        walker_init(&w[1], f, s, fmt, precision, explain) == 0) {
        void *ws[2];
        ws[0] = &w[0];
        ws[1] = &w[1];
        rc = pt_course_lanes(s, fb, cuts, walk, ws);
    }
    if (rc != 1 && w[0].t) cuts->failed = w[0].t->failed;
    walker_free(&w[0]);
    walker_free(&w[1]);
    free(w);
    return rc;
}

int pt_course_trace(FILE *f, const pt_scene *s, int fmt, int precision, int explain,
                    pt_course_cuts *cuts, pt_fb *fb, char *err, size_t errlen)
{
    walker w;
    int rc = cuts && cuts->threads == 2 ? walk_lanes(f, s, fmt, precision, explain, cuts, fb)
                                        : 1;

    if (rc == 1) {                           /* one thread */
        rc = walker_init(&w, f, s, fmt, precision, explain) == 0 ? walk(&w, fb) : -1;
        if (cuts && w.t) cuts->failed = w.t->failed;
        walker_free(&w);
    }
    if (rc != 0) snprintf(err, errlen, "pipetrace: out of memory");
    return rc;
}
