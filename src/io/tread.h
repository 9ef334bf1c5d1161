/*
** src/io/tread.h -- read traces (JSON Lines or text) and images back into memory
** See LICENSE for copyright and license.
**
** The reader of what pipetrace writes, for `pipetrace diff`.  A whole file is
** read into one buffer; pt_tread_parse() turns it into three arrays of records
** (vertex, pixel, clip) plus the header, keeping every number as the trace
** gives it: exact doubles from JSON Lines, doubles rounded to --precision
** decimals from text (prec says how many).  Model names are interned in a
** pt_names table that several traces share, so one name has one id in all of
** them.  Skip and summary records and the stability warnings are checked for
** form and otherwise ignored: they follow from the records kept.  Nothing here
** prints; an error comes back as one "FILE:LINE:COL: error: ..." message.
**
** USAGE
**   pt_names nm = PT_NAMES_INIT;
**   char *buf; size_t len;
**   pt_tread_file(path, &buf, &len, err, sizeof err);    whole file, NUL-terminated
**   pt_tread_kind(buf, len)                              JSONL, text, CSV, image?
**   pt_tread t;  pt_tread_parse(&t, path, buf, len, &nm, err, sizeof err);
**   ... t.vx[k], t.px[k], t.cl[k], t.hdr ...
**   pt_tread_free(&t);  pt_names_free(&nm);  free(buf);
*/
#ifndef PT_TREAD_H
#define PT_TREAD_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"

/* ===== interned model names ===== */

/* A set of names, each with a dense id 0, 1, 2, ... in order of first sight. */
typedef struct pt_names {
    char *text;                  /* the names, each NUL-terminated; owned */
    size_t len, cap;             /* bytes used and allocated in text */
    size_t *off;                 /* off[id]: where name id starts in text; owned */
    size_t n, cap_off;           /* number of names; room in off */
    uint32_t *slot;              /* hash table: id + 1, or 0 for empty; owned */
    size_t nslot;                /* a power of two, > 2 n; 0 before first use */
} pt_names;

#define PT_NAMES_INIT {NULL, 0, 0, NULL, 0, 0, NULL, 0}

/* The id of s[0..n) in nm, adding it when new; a name a terminal must not get
** raw (pt_sbuf_term_plain()) is kept as pt_sbuf_add_term() writes it, so no
** name read from a trace can send escape sequences where diff prints it.
** Returns 0, or -1 when out of memory. */
int pt_names_intern(pt_names *nm, const char *s, size_t n, uint32_t *id);

/* The name with id (id < nm->n), NUL-terminated.  Valid until the next intern. */
const char *pt_names_get(const pt_names *nm, uint32_t id);

/* Free what nm owns and leave it empty.  This function can't fail. */
void pt_names_free(pt_names *nm);

/* ===== records ===== */

/* Vertex numbers with this bit stand for the points where the matrix camera
** clips a segment: v = PT_TCLIPV | (segment << 1) | end, end 0 or 1 in the
** order the trace gives them. */
#define PT_TCLIPV (UINT64_C(1) << 63)

/* One vertex record: a vertex at one stage, laid out as pt_stage_infos[stage]
** says (stages/pt_stage.h).  PT_REC_NULL marks an integer stage without value ("null" in JSON,
** "none" in text). */
typedef struct pt_tvrec {
    uint64_t v;                  /* 1-based vertex number, or a PT_TCLIPV one */
    uint32_t model;              /* name id */
    uint32_t line;               /* line of the file, at most UINT32_MAX */
    unsigned char stage;         /* pt_stage */
    unsigned char flags;         /* PT_REC_NULL, PT_REC_INSIDE, PT_REC_BEHIND */
    union {
        double d[4];             /* real-valued stages */
        int64_t n[4];            /* integer stages */
    } u;
} pt_tvrec;

/* One pixel record: a pixel the rasterizer wrote. */
typedef struct pt_tpix {
    int64_t x, y, i;             /* framebuffer pixel (x_fb, y_fb) and index */
    uint64_t seg;                /* 1-based segment number */
    uint32_t model;              /* name id */
    uint32_t line;               /* line of the file, at most UINT32_MAX */
} pt_tpix;

/* One clip record: a run of rasterizer steps outside the viewport. */
typedef struct pt_tclip {
    int64_t first[2], last[2];   /* viewport (x_vp, y_vp) of its first and last step */
    uint64_t count;              /* steps in the run */
    uint64_t seg;                /* 1-based segment number */
    size_t npix;                 /* pixel records before it in the file: its place */
    uint32_t model;              /* name id */
} pt_tclip;

/* A model as the header describes it.  With left_known set, a stage whose
** bit is clear in left_out is one the trace says it reports: a record of it
** missing for a vertex that has others is a stage that did not report. */
typedef struct pt_tmodel {
    uint32_t name;               /* name id */
    double t[3];                 /* translation (x_t, y_t, z_t) */
    unsigned left_out;           /* bit st: the header leaves stage st out */
    int left_known;              /* 1: the header says which stages it leaves out
                                 ** (text: always; JSON Lines: "left_out") */
} pt_tmodel;

/* The header: what the formulas need besides the vertex's own numbers. */
typedef struct pt_thdr {
    int have;                    /* 1: the trace has a header */
    int fb_w, fb_h;              /* framebuffer size W x H */
    int vp_x, vp_y, vp_w, vp_h;  /* viewport corner (x_ul, y_ul), size w x h */
    pt_pipe_id pipe;             /* the pipeline its camera word names */
    int perspective;             /* the classic camera's projection: 1:
                                 ** perspective, 0: orthographic (lookat: 1) */
    char student[256];           /* a student build's "student" line ("pixel=
                                 ** FILE#CKSUM ..."), cut to fit; "" otherwise */
    pt_tmodel *models;           /* in file order; owned */
    size_t nmodels, cap;         /* count and room */
} pt_thdr;

/* What a file holds, judged by its first bytes. */
typedef enum pt_tkind {
    PT_TK_UNKNOWN,               /* none of these */
    PT_TK_JSONL,                 /* a trace in JSON Lines: starts with '{' */
    PT_TK_TEXT,                  /* a text trace: "# pipetrace trace" */
    PT_TK_CSV,                   /* a CSV trace: "model,v,stage," */
    PT_TK_PPM,                   /* a binary PPM image: "P6" */
    PT_TK_PNG,                   /* a PNG image: its 8-byte signature */
    PT_TK_P3,                    /* a plain (ASCII) PPM image: "P3" */
    PT_TK_KRAFT                  /* the course renderer's debug log (--format
                                 ** kraft): "== Begin Rendering of Scene:" */
} pt_tkind;

/* A trace read back. */
typedef struct pt_tread {
    pt_tkind kind;               /* PT_TK_JSONL or PT_TK_TEXT */
    int prec;                    /* text: fewest digits after the point of any
                                 ** real number (17 when there is none);
                                 ** JSON Lines: -1, numbers are exact */
    pt_thdr hdr;
    pt_tvrec *vx; size_t nvx, cap_vx;    /* vertex records, file order; owned */
    pt_tpix *px; size_t npx, cap_px;     /* pixel records, file order; owned */
    pt_tclip *cl; size_t ncl, cap_cl;    /* clip records, file order; owned */
    uint64_t unread;             /* a course log: lines not read (a student's
                                 ** own output, lines of a kind not compared) */
    uint64_t unread_line;        /*   the first of them, 1-based (0: none) */
} pt_tread;

/* The largest file pt_tread_file() reads (1 GiB): more than the largest image
** (16384 x 16384 pixels, 768 MiB as P6 or PNG) and a trace of millions of
** records; it caps what a reader holds (docs/limits.md). */
#define PT_TREAD_MAX_BYTES ((size_t)1 << 30)

/* Read the whole file at path ("-": standard input) into a new buffer *buf of
** *len bytes plus a terminating NUL; the caller frees it.  A file that is not
** a binary image (P6, PNG) is read only up to the first chunk holding a NUL
** byte, which pt_tread_parse() then refuses; a file of more than
** PT_TREAD_MAX_BYTES is refused.  Returns 0, or -1 with a message in err. */
int pt_tread_file(const char *path, char **buf, size_t *len, char *err, size_t errlen);

/* pt_tread_file() with max (< SIZE_MAX - 1) in place of PT_TREAD_MAX_BYTES. */
int pt_tread_file_max(const char *path, size_t max, char **buf, size_t *len, char *err,
                      size_t errlen);

/* What buf[0..len) holds.  This function can't fail. */
pt_tkind pt_tread_kind(const char *buf, size_t len);

/* Parse the trace buf[0..len) (buf[len] == '\0'; JSON Lines or text, as
** pt_tread_kind() says), named path in messages, into *t; names go into nm.
** Returns 0, or -1 with "FILE:LINE:COL: error: ..." in err (then *t is empty).
** The caller frees *t with pt_tread_free() either way. */
int pt_tread_parse(pt_tread *t, const char *path, const char *buf, size_t len,
                   pt_names *nm, char *err, size_t errlen);

/* Free what *t owns.  This function can't fail. */
void pt_tread_free(pt_tread *t);

/* ===== images ===== */

/* An image to compare: a binary PPM (P6), a plain PPM (P3), or a PNG as
** pipetrace writes it (8-bit RGB, no interlace, stored deflate blocks: png.h).
** For P6, rgb points into the buffer it was parsed from; P3 and PNG are
** decoded into `owned`, which pt_image_free() frees. */
typedef struct pt_ppm {
    int w, h;                    /* size in pixels */
    int maxval;                  /* 1..255 (PNG: 255) */
    const unsigned char *rgb;    /* 3*w*h bytes, row-major, top row first */
    unsigned char *owned;        /* the decoded pixels, or NULL; owned */
    const char *format;          /* "P6", "P3" or "PNG" */
} pt_ppm;

/* Parse the image in buf[0..len) (buf[len] == '\0'), named path in messages,
** whichever of the three formats it is.  Returns 0, or -1 with "FILE:1:1:
** error: ..." in err, naming the formats read when it is none of them; then
** *img holds nothing to free.  Free a parsed image with pt_image_free(). */
int pt_image_parse(pt_ppm *img, const char *path, const char *buf, size_t len,
                   char *err, size_t errlen);

/* Free what *img owns.  This function can't fail. */
void pt_image_free(pt_ppm *img);

#endif
