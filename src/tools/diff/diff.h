/*
** src/tools/diff/diff.h -- what the files of pipetrace diff share (internal to src/tools/diff/)
** See LICENSE for copyright and license.
**
** pipetrace diff, file by file, in the order a trace diff runs:
**   cmd_diff.c   the options, loading both files, the trace diff's driver
**   dimage.c     two images, pixel by pixel
**   dsummary.c   the intro and the headers; silent and one-sided stages; the
**                summary paragraph
**   dvertex.c    the vertex table and the comparison, vertex by vertex
**   dfit.c       the hypotheses (the catalogue's known mistakes, src/tools/
**                catalogue.h, and patterns read off the numbers), each tested on
**                every vertex; the verdict
**   dexplain.c   one hypothesis on one vertex; a vertex's first difference
**                explained
**   dpixels.c    the lit pixels, and the rasterizer replayed on a segment
**   dprint.c     numbers, paragraphs, names
**   dseparate.c  where known mistakes are ambiguous: a scene that tells them
**                apart (dseparate.h), renderer 4's, printed and written;
**                dseparate79.c renderers 7 and 9's; dsearch.c the search
**   d79.c        the traces and logs of renderers 7 and 9 (their own reader,
**                io/tread79.h, and catalogue, tools/catalogue79.h)
** The types below are diff's own (short names, never seen outside this
** folder); the functions between the files start pt_diff_.  Functions that
** print write to standard output; none can fail unless it says so.
*/
#ifndef PT_DIFF_H
#define PT_DIFF_H

#include <stddef.h>
#include <stdint.h>
#include "core/pipetrace.h"
#include "io/numfmt.h"
#include "io/tread.h"
#include "tools/cli.h"
#include "tools/catalogue.h"
#include "tools/diff/doutcome.h"

#define PT_DIFF_NONE UINT32_MAX          /* no record */

/* The command line. */
typedef struct dopts {
    const char *path[2];         /* EXPECTED, ACTUAL */
    double tol, rel;             /* tolerance for doubles */
    const char *image_out;       /* --image-out, or NULL */
    size_t show;                 /* vertices and pixels listed */
    int verdict;                 /* --verdict: end with a verdict paragraph */
    const char *scene;           /* --scene: the headers of traces without one */
    const char *sep_out;         /* --separating-scene: where the scene goes, or NULL */
    pt_diff_outcome *out;        /* the findings as data (pt_diff_run), never NULL */
} dopts;

/* A growing string for paragraphs. */
typedef struct pbuf {
    char b[2048];
    size_t n;
} pbuf;

/* One vertex of either trace: where each side's record of each stage is. */
typedef struct vent {
    uint64_t v;                  /* 1-based vertex number */
    uint32_t model;              /* name id */
    uint32_t rec[2][PT_NSTAGES_ALL];   /* index into side's vx[], or PT_DIFF_NONE */
} vent;

/* Open addressing over entries in order of first sight (EXPECTED's first). */
typedef struct vtab {
    vent *e;                     /* entries; owned */
    size_t n, cap;
    uint32_t *slot;              /* entry index + 1, or 0; owned */
    size_t nslot;                /* power of two > 2 n */
} vtab;

/* A hypothesis: one stage computed some wrong way.  It is named only when it
** reproduces ACTUAL on every vertex (dfit.c): where the traces differ and
** where they agree. */
enum { PT_DIFF_H_MISTAKE, PT_DIFF_H_OFFSET, PT_DIFF_H_FLOAT };
typedef struct dhyp {
    int stage;                   /* pt_stage it is made in */
    int kind;                    /* PT_DIFF_H_* */
    const pt_mistake *mk;        /* PT_DIFF_H_MISTAKE: the catalogue's */
    double off[3];               /* PT_DIFF_H_OFFSET: added to a real stage's values */
    int64_t ioff[2];             /* ... to an integer stage's */
    char name[96];               /* what was done */
    char how[320];               /* the formula, and why it goes wrong */
    size_t repro;                /* differing vertices it reproduces */
    size_t kept;                 /* agreeing vertices it leaves as they are */
    int full;                    /* 1: it explains every vertex */
} dhyp;

#define PT_DIFF_MAXHYP (PT_NMISTAKES + 16)

/* Everything one trace diff needs. */
typedef struct dctx {
    const dopts *o;
    pt_names nm;                 /* model names of both traces */
    pt_tread t[2];               /* EXPECTED, ACTUAL */
    vtab vt;
    double (*tr)[3];             /* tr[model id]: translation from EXPECTED's header */
    unsigned char *has_tr;       /* has_tr[model id]: 1 when tr is known */
    /* counts */
    size_t agree, differ, only[2];
    size_t first_at[PT_NSTAGES_ALL];    /* vertices that first differ at each stage */
    size_t first_ex[PT_NSTAGES_ALL];    /* 1 + vt index of the first of them, or 0 */
    size_t stage_only[2][PT_NSTAGES_ALL];   /* records without a partner */
    size_t shown;                /* vertices listed */
    dhyp hy[PT_DIFF_MAXHYP];     /* the hypotheses tested (dfit.c) */
    size_t nhy;
    int verdict;                 /* hy[] index of the one that explains all, or -1 */
    int nfull;                   /* hypotheses (by name) that explain all */
    int swapped;                 /* hy index that explains all with the sides
                                 ** swapped, or -1 */
    dhyp swap_hy;                /* ... that hypothesis, its fit swapped */
    size_t fit_differ, fit_agree;   /* the vertices the fits count */
    int px_shift;                /* 1: ACTUAL's lit pixels are EXPECTED's moved */
    int64_t px_d[2];             /* ... by (dx, dy) */
    size_t px_out;               /* ... this many of them out of the framebuffer */
    size_t agree_clip, differ_clip;     /* of agree and differ: matrix clip points */
    unsigned *silent[2];         /* silent[s][model id]: bit st when side s has no
                                 ** record of stage st for that model though its
                                 ** header does not leave st out and the other side
                                 ** has them: the stage did not report; owned */
    size_t silent_recs[2][PT_NSTAGES_ALL];  /* the other side's records it lacks */
} dctx;

/* What the raster check found. */
typedef struct rstat {
    size_t segs_differ;          /* segments whose pixels differ */
    size_t hits[PT_NRASTER_MISTAKES];   /* ... that each rasterizer mistake reproduces */
    size_t apart[PT_NRASTER_MISTAKES];  /* ... where a mistake with a twin lights
                                 ** other pixels or clip records than its twin */
    size_t breaks[PT_NRASTER_MISTAKES]; /* segments both traces light alike (and
                                 ** clip alike) that each mistake, replayed,
                                 ** would light or clip otherwise; counted
                                 ** when every vertex agrees */
    int first_set;               /* 1: first_* below are set */
    uint32_t first_model;        /* the first differing segment */
    uint64_t first_seg;
    int64_t ends[4];             /* its rounded endpoints X0 Y0 X1 Y1 */
    int ends_ok;                 /* 1: ends verified by replaying EXPECTED */
    size_t own_tried;            /* differing segments replayed from ACTUAL's
                                 ** own end pixels by the reference rasterizer */
    size_t own_bad;              /* ... whose pixels it does not give */
    uint32_t own_model;          /* the first of those */
    uint64_t own_seg;
    size_t own_misfit[PT_NRASTER_MISTAKES];  /* segments replayed from ACTUAL's
                                 ** own end pixels (those that differ, and those
                                 ** both light alike) whose pixels each mistake
                                 ** of the viewport stage the DDA asks does not
                                 ** draw, its own way back giving the ends */
} rstat;

/* 1 when stage st holds doubles, 0 when integers. */
static inline int pt_diff_is_real(int st) { return pt_stage_infos[st].nreal > 0; }

/* Name of value k of stage st, as the text trace writes it: "x_pp". */
static inline const char *pt_diff_coord_name(int st, int k) { return pt_stage_infos[st].coord[k]; }

/* 1 when |x| < 2^62: sums and differences of two such numbers, or one and a
** size, cannot overflow.  pipetrace's own integers always are (PT_PIX_LIMIT);
** a trace from elsewhere may hold anything. */
static inline int pt_diff_small(int64_t x)
{
    return x > -(INT64_C(1) << 62) && x < (INT64_C(1) << 62);
}

/* ===== dprint.c ===== */

/* "EXPECTED", "ACTUAL": side 0 and side 1. */
extern const char *const pt_diff_side[2];

/* x as the shortest decimal that reads back to it, in buf; returns buf. */
const char *pt_diff_num(double x, char buf[PT_NUMLEN]);

/* Print text as one paragraph wrapped at 78 columns, each line after lead. */
void pt_diff_para(const char *lead, const char *text);

/* Append to s what printf would print; text past its room is dropped. */
void pt_diff_add(pbuf *s, const char *fmt, ...) PT_PRINTF_LIKE(2, 3);

/* Append "SIDE has no STAGE records: the stage did not report them." to s. */
void pt_diff_no_records(pbuf *s, int side, int st);

/* "box v3", or for a point where the matrix camera clipped a segment "box s2
** (clipped end 1)", into buf of len bytes; returns buf. */
const char *pt_diff_who(const dctx *c, uint32_t model, uint64_t v, char *buf, size_t len);

/* ===== dimage.c ===== */

/* Compare two images pixel by pixel and print the result (and write o's
** --image-out).  Returns the exit status. */
int pt_diff_images(const dopts *o, const pt_ppm img[2]);

/* --scene SCENE, EXPECTED a student's own trace or log with pixel records,
** ACTUAL the image the same program wrote: is the image what the log drew,
** or its pixels without the viewport's corner (named)?  Returns the exit
** status (0 drawn, 1 not), or -1 out of memory. */
int pt_diff_own_image(const dopts *o, const pt_tread *t, const pt_ppm *img);

/* ===== dvertex.c ===== */

/* Fill c's vertex table from both sides.  Returns 0, PT_EXIT_INPUT on a
** duplicate record (message printed), -1 when out of memory. */
int pt_diff_fill_table(dctx *c);

/* EXPECTED's translations by model id into c->tr.  Returns 0, or -1 when out
** of memory. */
int pt_diff_fill_translations(dctx *c);

/* The slack of the number x read from side s: half a unit in the last printed
** digit of a text trace, plus strtod's half ulp; 0 for JSON Lines. */
double pt_diff_slack(const dctx *c, int s, double x);

/* 1 when a (EXPECTED) and b (ACTUAL) agree within the tolerance. */
int pt_diff_same_real(const dctx *c, double a, double b);

/* Append "x_pp expected 1.5, actual 2" for each value of stage st that
** differs between vertex e's records. */
void pt_diff_evidence(const dctx *c, const vent *e, int st, pbuf *s);

/* Compare vertex e, present on both sides, stage by stage; count it, and print
** and explain its first difference while fewer than --show are listed. */
void pt_diff_compare_vertex(dctx *c, const vent *e);

/* The first stage where vertex e differs, -1 when it agrees at every stage
** both sides hold, -2 when one side has none of its records. */
int pt_diff_first_stage(const dctx *c, const vent *e);

/* ===== dexplain.c ===== */

/* Hypothesis h on vertex e, with side ref (0; 1: the sides swapped) as the
** reference: its stage recomputed from ref's previous stage; *in, *from and
** *got get the input, its stage and the result.  Returns 1 when that gives
** the other side's record (within the tolerance and printed digits), 0 when
** not, -1 when it cannot be tested (records missing). */
int pt_diff_hyp_vertex(const dctx *c, const dhyp *h, const vent *e, int ref,
                       pt_cat_val *in, int *from, pt_cat_val *got);

/* Print what the hypotheses say of vertex e, whose first difference is at
** stage st. */
void pt_diff_explain(const dctx *c, const vent *e, int st);

/* Append the values of stage st in *v to sb: "x_pp = 1.5, y_pp = 2". */
void pt_diff_val_str(pbuf *sb, int st, const pt_cat_val *v);

/* ===== dfit.c ===== */

/* Make the hypotheses and test each on every vertex (c->hy, verdict,
** swapped).  Returns 0, or -1 when out of memory. */
int pt_diff_fit(dctx *c);

/* Print the hypotheses that reproduce any vertex, with their fit. */
void pt_diff_report_fit(const dctx *c);

/* Append the verdict to the summary paragraph s. */
void pt_diff_verdict(const dctx *c, pbuf *s);

/* Print --verdict's paragraph: pass, or where it goes wrong first (stage
** top, -1 when no vertex differs), the evidence and the mistake if one
** explains all.  px_differ: the lit pixels differ; rs: the raster check. */
void pt_diff_print_verdict(const dctx *c, int differ, int top, int px_differ, const rstat *rs);

/* Print (and write to --separating-scene's file) the scene that tells the n
** mistakes names[] apart, all of them of the vertex stages' catalogue, or
** with pixels_only the rasterizer's (dseparate.c); noted in the outcome. */
void pt_diff_separate(const dctx *c, const char *const *names, size_t n, int pixels_only);

/* Note in out the stage (a name, or "pixels") where the verdict says the
** traces go wrong first. */
void pt_diff_outcome_stage(pt_diff_outcome *out, const char *stage);

/* Add name to out's mistakes that explain everything, once. */
void pt_diff_outcome_named(pt_diff_outcome *out, const char *name);

/* ===== dpixels.c ===== */

/* Compare the sets of lit pixels: the missing and extra ones into *nmiss and
** *nextra (a few of each listed), nlit[s] the distinct pixels of side s.
** Returns 0, or -1 when out of memory. */
int pt_diff_compare_pixels(dctx *c, size_t *nmiss, size_t *nextra, size_t nlit[2]);

/* Segment by segment: which differ, and which rounding mistake of the
** rasterizer reproduces ACTUAL's pixels from EXPECTED's endpoints, into *rs.
** Returns 0, or -1 when out of memory. */
int pt_diff_check_raster(dctx *c, rstat *rs);

/* The rasterizer's mistakes that reproduce every differing segment of rs,
** into named[] (indexes into pt_raster_mistakes), their number returned,
** but those that would change a segment the traces agree on.  A
** mistake and its twin that the trace never told apart (rs->apart 0) are
** both named: more than one is "ambiguous", never the usual one alone for a
** student who made the other.  This function can't fail. */
size_t pt_diff_raster_named(const rstat *rs, size_t named[PT_NRASTER_MISTAKES]);

/* The rasterizer run again (as the raster check runs it) on the segment
** whose rounded ends are ends[] = X0 Y0 X1 Y1 in a w x h viewport, each
** step's pixel from to_vp (NULL: the viewport stage), the loop's last step
** moved by steps (-1, 0, +1): sig[0] a hash of its pixels (viewport
** coordinates, step order), sig[1] of its clip records (none with steps).
** Returns 0, 1 when steps is not replayed (a segment that long), -1 when out
** of memory. */
int pt_diff_replay_sig(const int64_t ends[4], int w, int h, pt_raster_vp to_vp, int steps,
                       uint64_t sig[2]);

/* Append to s the rasterizer's mistake behind a vertex stage's: when the
** reference rasterizer does not draw ACTUAL's pixels from its own end pixels
** (a second mistake) and exactly one mistake of the viewport stage it asks
** each step does, in every segment (own_misfit 0), its name.  This function
** can't fail. */
void pt_diff_raster_second(const rstat *rs, pbuf *s);

/* Print the raster check's details for the first differing segment. */
void pt_diff_report_raster(const dctx *c, const rstat *rs);

/* ===== dsummary.c ===== */

/* Print both files, their formats and the tolerance. */
void pt_diff_print_intro(const dctx *c);

/* Print how the headers differ; returns 1 when they do. */
int pt_diff_compare_headers(const dctx *c);

/* Find the stages that did not report (c->silent).  Returns 0, or -1 when out
** of memory. */
int pt_diff_find_silent(dctx *c);

/* 1 when a stage of either side did not report. */
int pt_diff_silent_any(const dctx *c);

/* Print the vertices only one side has, the silent stages, the stages only
** one side holds. */
void pt_diff_report_one_sided(dctx *c);
void pt_diff_report_silent(const dctx *c);
void pt_diff_report_stage_only(const dctx *c);

/* Print the summary paragraph; returns the exit status. */
int pt_diff_summarize(dctx *c, int hdr_differ, size_t nmiss, size_t nextra,
                      const size_t nlit[2], int pixels_compared, const rstat *rs);

/* ===== d79.c ===== */

/* Diff two traces or logs of a renderer 7 or 9 scene, buf[s][0..len[s]) the
** text of o->path[s].  Returns the exit status, or -1 when out of memory. */
int pt_diff79(const dopts *o, char *const buf[2], const size_t len[2]);

#endif
