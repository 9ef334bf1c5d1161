/*
** stages/pt_stage.h -- what every stage shares: vectors, stage ids, the trace record
** See LICENSE for copyright and license.
**
** A stage is a pure function from one coordinate space to the next.  It reports what
** it computed through a pt_sink: one pt_vrec per vertex, handed over as numbers (the
** stage never formats text and never knows where the record goes).  A NULL sink means
** "compute, do not report"; the value computed is the same either way.
**
** The stages, in pipeline order, with the suffix each space uses in code and trace:
**
**   model       (x_m,  y_m,  z_m)    the model's own coordinates, as in the scene
**   camera      (x_c,  y_c,  z_c)    s1: add the model's translation
**   image       (x_ip, y_ip, z_ip)   s2: project onto the image plane z = -1 (or 0)
**   pixel       (x_pp, y_pp)         s3: logical pixel plane [0.5, w+0.5) x [0.5, h+0.5)
**   viewport    (x_vp, y_vp)         s4: nearest logical pixel, y flipped, 0-based
**   framebuffer (x_fb, y_fb)         s5: offset by the viewport's upper-left corner
**   index       (idx)                s6: row-major position in the pixel array
*/
#ifndef PT_STAGE_H
#define PT_STAGE_H

#include <math.h>
#include <stdint.h>

typedef struct pt_vec3 { double x, y, z; } pt_vec3;
typedef struct pt_vec2 { double x, y; } pt_vec2;

/* A colour as the course's renderer carries it between stages: three floats
** in 0 .. 1 (java.awt.Color's components), kept unrounded so that a colour
** interpolated along a segment stays the float it was computed as. */
typedef struct pt_rgb { float r, g, b; } pt_rgb;

/* A pixel position.  ok == 0 means "no pixel": a coordinate was not finite or
** too large for rounding to an integer to mean anything (see
** s4_pixel2viewport.h).  The other coordinate may still have its value (x_pp
** infinite, y_pp = 22.99: y_vp is h - 23); then the one without is
** PT_PIX_NONE.  Ask pt_pix_has(), which counts {0, 0, 0} as neither. */
typedef struct pt_pix { int64_t x, y; int ok; } pt_pix;

/* The coordinate without value of a pixel whose other coordinate has one:
** 3 * 2^61, beyond every value a stage gives (below 2^62 + 2^31 in size) and
** far enough from 2^63 that adding a viewport's corner cannot overflow. */
#define PT_PIX_NONE ((int64_t)3 << 61)

/* 1 when coordinate k (0: x, 1: y) of p has a value.  This function can't fail. */
static inline int pt_pix_has(pt_pix p, int k)
{
    int64_t mine = k ? p.y : p.x, other = k ? p.x : p.y;

    return p.ok || (mine != PT_PIX_NONE && other == PT_PIX_NONE);
}

/* The stages.  Their numbers name rows of the tables (pt_stage_infos[]) and
** bits of masks, nothing more: which stages a pipeline has, and in which
** order, is its order (pt_classic_order[], pt_matrix_order[]; the pipelines,
** src/core/pipelines.h). */
typedef enum pt_stage {
    PT_STAGE_MODEL,              /* every pipeline's first */
    PT_STAGE_CAMERA,             /* the classic camera's: model -> camera */
    PT_STAGE_IMAGE,              /*   -> image -> pixel -> viewport */
    PT_STAGE_PIXEL,
    PT_STAGE_VIEWPORT,           /* both (their own viewport functions) */
    PT_STAGE_FRAMEBUFFER,        /* both: -> framebuffer -> index */
    PT_STAGE_INDEX,
    PT_STAGE_WORLD,              /* the matrix camera's own stages: */
    PT_STAGE_VIEW,               /*   model -> world -> view -> clip -> cvv */
    PT_STAGE_CLIP,               /*   -> ndc -> screen, then viewport, */
    PT_STAGE_CVV,                /*   framebuffer and index as above */
    PT_STAGE_NDC,
    PT_STAGE_SCREEN
} pt_stage;

/* How many stages there are (the tables' length): not a stage, so that a
** switch over pt_stage lists exactly the stages (-Wswitch-enum). */
#define PT_NSTAGES_ALL ((int)PT_STAGE_SCREEN + 1)

/* Flags of a pt_vrec. */
#define PT_REC_BEHIND  0x01u   /* image: z_c > 0 under a perspective camera */
#define PT_REC_INSIDE  0x02u   /* viewport: 0 <= x_vp < w and 0 <= y_vp < h */
#define PT_REC_NULL    0x04u   /* viewport, framebuffer, index: no value */
#define PT_REC_HAS_X   0x08u   /* with NULL (viewport, framebuffer): x still */
#define PT_REC_HAS_Y   0x10u   /*   has its value; y still has its value */
#define PT_REC_COLOR   0x20u   /* the record carries the vertex's colour */

/* Warnings a stage raises about the numbers it produced (docs/stability.md). */
#define PT_WARN_NONFINITE   0x01u  /* a result is infinite or not a number */
#define PT_WARN_CANCEL      0x02u  /* camera (world, view, clip): a sum such as
                                   ** x_m + x_t cancelled most digits */
#define PT_WARN_ILLCOND     0x04u  /* image (ndc): the divisor z_c (w_k) lost most
                                   ** digits; the quotient too */
#define PT_WARN_RANGE       0x08u  /* viewport: no integer pixel (|x_pp| >= 2^62) */
#define PT_WARN_OUTSIDE     0x10u  /* index: the pixel is outside the pixel array */
#define PT_NWARN            5      /* number of warning kinds */

/* More than half of a double's 53 bits lost is worth a warning. */
#define PT_BITS_LOST_WARN   26

/* One vertex at one stage.  Which fields hold values depends on the stage:
** model, camera, image use x y z; pixel uses x y; viewport and framebuffer use
** ix iy; index uses i.  PT_REC_NULL marks an integer result that does not exist
** (a pixel outside the framebuffer has no index); a viewport or framebuffer
** record without a pixel may keep one coordinate (PT_REC_HAS_X, PT_REC_HAS_Y):
** null is per value.  pt_rec_has() says which. */
typedef struct pt_vrec {
    pt_stage stage;            /* which stage produced it */
    unsigned flags;            /* PT_REC_* */
    unsigned warn;             /* PT_WARN_* */
    int digits_lost;           /* with CANCEL or ILLCOND: decimal digits lost */
    double x, y, z;            /* real-valued stages */
    double w;                  /* world, view, clip: the homogeneous w */
    unsigned code;             /* cvv: the outcode, PT_CVV_* bits */
    int64_t ix, iy;            /* viewport, framebuffer */
    int64_t i;                 /* index */
    pt_rgb color;              /* with PT_REC_COLOR: the vertex's colour */
} pt_vrec;

/* 1 when integer value k (0: ix or i, 1: iy) of a record with these flags
** (of r) has a value; the flags a pixel p gives its record (0, or PT_REC_NULL
** with PT_REC_HAS_X/Y for the coordinates that have one).  These functions
** can't fail. */
static inline int pt_flags_have(unsigned flags, int k)
{
    return !(flags & PT_REC_NULL) || (flags & (k ? PT_REC_HAS_Y : PT_REC_HAS_X)) != 0;
}

static inline int pt_rec_has(const pt_vrec *r, int k) { return pt_flags_have(r->flags, k); }

static inline unsigned pt_pix_flags(pt_pix p)
{
    if (p.ok) return 0;
    return PT_REC_NULL | (pt_pix_has(p, 0) ? PT_REC_HAS_X : 0u)
                       | (pt_pix_has(p, 1) ? PT_REC_HAS_Y : 0u);
}

/* Where stages send their records.  The driver sets which model and vertex the
** records belong to; stages see only this interface. */
typedef struct pt_sink {
    void (*vertex)(void *ud, const pt_vrec *r);   /* called once per record */
    void *ud;                                     /* passed back unchanged */
} pt_sink;

/* The numbers of the scene that the formulas use, for one model
** (the matrix camera uses w .. H; its matrices come apart, pt_matrix.h). */
typedef struct pt_stage_params {
    pt_vec3 translate;           /* (x_t, y_t, z_t): the model's translation */
    int perspective;             /* 1: perspective camera, 0: orthographic */
    int w, h;                    /* the viewport's size in pixels */
    int x_ul, y_ul;              /* its upper-left corner in the framebuffer */
    int W, H;                    /* the framebuffer's size */
} pt_stage_params;

/* Report r to sink (nothing when sink is NULL).  This function can't fail. */
static inline void pt_emit(const pt_sink *sink, const pt_vrec *r)
{
    if (sink) sink->vertex(sink->ud, r);
}

/* What a stage's values are, and where a pt_vrec keeps them: what the trace
** writers print and the readers parse, how quiz grades an answer, how explain
** writes a tuple.  A switch over it lists these four: a new kind of value is
** a new case in each (the compiler names them, -Wswitch-enum). */
typedef enum pt_value_kind {
    PT_VAL_REAL,                 /* nreal doubles: x, y, z, w in that order */
    PT_VAL_PIXEL,                /* two integers ix, iy; each may have no value
                                 ** (PT_REC_NULL with PT_REC_HAS_X/Y) */
    PT_VAL_INDEX,                /* one integer i, or none (PT_REC_NULL) */
    PT_VAL_OUTCODE               /* one unsigned code, PT_CVV_* bits; always one */
} pt_value_kind;

/* Fixed facts about a stage: the one table that trace writers and readers,
** explain, diff, step and the docs ask.  A stage's values are nreal doubles
** (pt_vrec x, y, z, w in that order) or nint integers (ix, iy; i for the
** index; code for the cvv), never both, as kind says; coord[k] names value k
** in code, text traces and docs ("x_pp"), key[k] in JSON Lines and CSV
** ("x").  flags are the PT_REC_* its records may carry besides PT_REC_COLOR:
** a writer prints the behind and inside flags, and null values, only for a
** stage that has them (a viewport record is "inside" or "outside", a camera
** record neither), and a reader accepts them only there. */
typedef struct pt_stage_info {
    const char *name;          /* trace name: "camera" */
    const char *from;          /* space it reads: "model" */
    const char *to;            /* space it writes: "camera" */
    const char *formula;       /* the formula as the trace and docs print it */
    const char *what;          /* what it does, in one sentence (pipetrace step) */
    int nreal, nint;           /* how many real and integer values */
    const char *coord[4];      /* value names: "x_pp", "y_pp" (NULL past the last) */
    const char *key[4];        /* JSON keys: "x", "y" */
    pt_value_kind kind;        /* what its values are */
    unsigned flags;            /* PT_REC_BEHIND, _INSIDE, _NULL, _HAS_X/Y it may set */
} pt_stage_info;

/* The table of all stages, indexed by pt_stage.  The viewport entry is the
** classic camera's; the matrix camera's viewport stage is described by
** pt_matrix_viewport_info. */
extern const pt_stage_info pt_stage_infos[PT_NSTAGES_ALL];
extern const pt_stage_info pt_matrix_viewport_info;

/* The stages of each camera in pipeline order, and how many. */
#define PT_CLASSIC_NORDER 7
#define PT_MATRIX_NORDER 10
extern const pt_stage pt_classic_order[PT_CLASSIC_NORDER];
extern const int pt_classic_norder;
extern const pt_stage pt_matrix_order[PT_MATRIX_NORDER];
extern const int pt_matrix_norder;

/* Every stage once, in the order a trace lists them: the classic camera's up
** to pixel, the matrix camera's up to screen, then the shared viewport,
** framebuffer and index. */
extern const pt_stage pt_trace_order[PT_NSTAGES_ALL];

/* The title the course's renderer gives stage st in its debug log ("0. Model",
** "3. Pixel-plane"; src/io/trace_kraft.c writes it, tread_kraft.c reads it),
** or NULL for a stage it does not log. */
extern const char *const pt_stage_course[PT_NSTAGES_ALL];

/* Integer value k of r as its stage's kind keeps it: ix (k = 0) or iy of a
** pixel, i of an index, code of an outcode; 0 for a real stage.  Whether it
** has a value is pt_rec_has()'s question.  This function can't fail. */
static inline int64_t pt_rec_int(const pt_vrec *r, int k)
{
    switch (pt_stage_infos[r->stage].kind) {
    case PT_VAL_PIXEL: return k ? r->iy : r->ix;
    case PT_VAL_INDEX: return r->i;
    case PT_VAL_OUTCODE: return (int64_t)r->code;
    case PT_VAL_REAL: break;
    }
    return 0;
}

/* 1 when stage st's integer values may have none (PT_REC_NULL): a pixel or
** an index, not an outcode.  This function can't fail. */
static inline int pt_stage_nullable(pt_stage st)
{
    return (pt_stage_infos[st].flags & PT_REC_NULL) != 0;
}

/* The number of values of stage st (nreal + nint).  This function can't fail. */
int pt_stage_nvalues(pt_stage st);

/* The pt_stage whose name is s, or -1. This function can't fail. */
int pt_stage_by_name(const char *s);

/* Name of warning bit k (0 <= k < PT_NWARN): "nonfinite", "cancellation", ... */
extern const char *const pt_warn_names[PT_NWARN];

/* Bits of precision lost when a value x was computed from operands whose
** magnitudes are at most scale: the rounding error of the operands is about
** ulp(scale), so only ilogb(scale) - ilogb(x) fewer bits of x are real.  0 when
** x is 0, not finite, or no smaller than scale.  This function can't fail. */
int pt_bits_lost(double scale, double x);

/* Decimal digits in `bits` bits, rounded down: bits * log10(2), computed in
** integers so every platform gives the same answer.  This function can't fail. */
int pt_bits_to_digits(int bits);

/* When more than PT_BITS_LOST_WARN of a result's bits were lost, flag r with
** warn (PT_WARN_CANCEL or PT_WARN_ILLCOND) and say how many decimal digits in
** r->digits_lost.  This function can't fail. */
void pt_warn_lost(pt_vrec *r, unsigned warn, int lost);

/* PT_WARN_NONFINITE when any of the n values is not finite, else 0.  Inline:
** every traced record of a stage with real values asks it. */
static inline unsigned pt_warn_nonfinite(const double *v, int n)
{
    int k;

    for (k = 0; k < n; k++)
        if (!isfinite(v[k])) return PT_WARN_NONFINITE;
    return 0;
}

#endif
