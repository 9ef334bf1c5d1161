/*
** src/core/pipeline.h -- plan the stages, run every vertex through them, rasterize
** See LICENSE for copyright and license.
**
** USAGE
**   pt_scene s;  pt_scene_load(&s, path, err, sizeof err);       parse
**   pt_options o;  pt_options_default(&o);  (set filters)
**   pt_plan p;  pt_plan_make(&p, &s, &o);                         plan
**   pt_fb fb;  pt_fb_init(&fb, s.fb_w, s.fb_h, s.background);     (optional)
**   pt_run(&s, &p, &o, &listener, &fb, &summary);                 run + rasterize
**   pt_plan_free(&p);  pt_fb_free(&fb);  pt_scene_free(&s);
**
**   pt_journey j;  pt_run_journey(&j, &s, &s.models[0], v, 0);    one vertex,
**                                                                 every stage
**
** The framebuffer is row-major, top row first: idx = y_fb * W + x_fb.
** Records reach the listener in this order: header; for each model in file
** order, the journey of each used vertex in vertex order (stage order within a
** vertex; a listener with a journey callback gets the whole pt_journey first,
** then the vertex's records); then for each model and segment, its pixel and
** clip records in step order (with a listener of steps, its setup record
** first and a step record before each step's pixel or clip record); then the
** summary.  With pt_options.model_by_model, each model's segment records come
** right after its own vertices', model by model.  Errors: only pt_scene_load() and pt_run()'s
** allocations can fail; they return -1 with a message, nothing here exits.
*/
#ifndef PT_PIPELINE_H
#define PT_PIPELINE_H

#include <stdint.h>
#include <stddef.h>
#include "core/scene.h"
#include "core/fb.h"
#include "core/vjourney.h"
#include "core/raster.h"
#include "stages/pt_matrix.h"
#include "core/pipelines.h"

/* What to compute and what to report. */
typedef struct pt_options {
    int all_stages;              /* 1: trace identity stages too (--all-stages) */
    const char *model;           /* trace only this model (--model), or NULL */
    uint64_t vertex;             /* trace only this 1-based vertex (--vertex), or 0 */
    unsigned stage_mask;         /* bit k: trace stage k (--stage); default all */
    int trace_raster;            /* 1: report pixel and clip records */
    int rasterize;               /* 1: draw the segments (image or raster trace) */
    int raw_lookat;              /* 1: the seed's look-at matrix, up not re-derived */
    int model_by_model;          /* 1: each model's raster records right after
                                 ** its vertices' (the course's log), not every
                                 ** model's vertices first */
    int every_vertex;            /* 1: trace the vertices no segment uses too (where
                                 ** they would land: step, quiz, why) */
    uint64_t piece_vertices;     /* where a listener's pieces are cut (pt_listener */
    uint64_t piece_segments;     /*   .piece): PT_PIECE_VERTICES etc. by default; */
    uint64_t piece_pixels;       /*   smaller in the tests, for many cuts (>= 1) */
} pt_options;

/* Why a stage is left out of a model's trace. */
typedef enum pt_why {
    PT_WHY_TRACED = 0,           /* not left out */
    PT_WHY_IDENTITY,             /* the stage is the identity for this model */
    PT_WHY_FILTER,               /* --stage chose other stages */
    PT_WHY_OTHER_CAMERA          /* a stage of the other camera model */
} pt_why;

/* The plan for one model: which stages it traces and which vertices it needs. */
typedef struct pt_model_plan {
    pt_why why[PT_NSTAGES_ALL];  /* PT_WHY_TRACED for each stage traced */
    const char *why_text[PT_NSTAGES_ALL];   /* reason in words, or NULL */
    pt_mat4 world;               /* matrix camera: the model's `world` lines, then
                                 ** its translate */
    unsigned char *used;         /* used[v]: some segment uses vertex v; owned */
    size_t nused;                /* number of used vertices */
    int selected;                /* 1: passes the --model filter */
    int hidden;                  /* 1: the course's renderer 4 (classic camera)
                                 ** skips it whole (hidden-position, hidden-model:
                                 ** Pipeline.render runs no stage of it): no vertex
                                 ** runs, no record, nothing drawn */
} pt_model_plan;

typedef struct pt_plan {
    const pt_pipeline *pipe;     /* the scene's pipeline */
    pt_model_plan *models;       /* one per scene model; owned */
    size_t nmodels;
    const pt_stage *order;       /* the pipeline's stages in pipeline order */
    int norder;                  /* how many */
    pt_mat4 view, proj;          /* matrix camera: View and Projection */
    int up_skewed;               /* matrix camera: the given up was not
                                 ** perpendicular to direction */
    int up_adjusted;             /* ... and was re-derived (not --raw-lookat) */
} pt_plan;

/* Counts for the summary record. */
typedef struct pt_summary {
    uint64_t models;             /* models in the scene */
    uint64_t vertices;           /* vertices in the scene */
    uint64_t vertices_unused;    /* used by no segment: not transformed */
    uint64_t vertices_traced;    /* journeys reported */
    uint64_t segments;           /* segments in the scene */
    uint64_t segments_degenerate;/* both ends round to one pixel */
    uint64_t segments_skipped;   /* an endpoint has no pixel (not finite, huge) */
    uint64_t segments_culled;    /* matrix camera: wholly outside the view volume */
    uint64_t pixels;             /* pixels written (inside the viewport) */
    uint64_t clipped;            /* steps clipped (outside the viewport), and */
    uint64_t clipped_hi;         /* its carries: the count is clipped_hi * 2^64 +
                                 ** clipped (one segment has fewer than 2^64
                                 ** steps, but several can add up to more) */
    uint64_t clip_runs;          /* clip records */
    uint64_t behind;             /* traced vertices behind a perspective camera */
    uint64_t warnings[PT_NWARN]; /* records raised with warning k (traced or not);
                                 ** counted when the listener has a sink or a
                                 ** summary, else 0: nobody listens, no record */
    int rasterized;              /* 1: the segments were drawn */
} pt_summary;

/* Who hears what the pipeline does.  Any callback may be NULL. */
typedef struct pt_listener {
    void (*header)(void *ud, const pt_scene *s, const pt_plan *p);
    void (*vertex_begin)(void *ud, const pt_model *m, uint64_t v);  /* 1-based v */
    pt_sink sink;                                   /* the stages' records */
    void (*clipvertex_begin)(void *ud, const pt_model *m, uint64_t seg,
                             uint64_t from, uint64_t to, double t, pt_vec4 q);
                          /* matrix camera: the point q (clip coordinates) made
                          ** by clipping segment seg (from -> to, 1-based) at t;
                          ** its records follow */
    void (*journey)(void *ud, const pt_model *m, uint64_t v, const pt_journey *j);
                          /* a traced point's whole journey, every stage's record
                          ** (also those the trace leaves out), before its records
                          ** reach sink: v is the 1-based vertex, or 0 for a point
                          ** clipping made (after its clipvertex_begin).  NULL: no
                          ** journey is kept, which costs nothing */
    void (*pixels)(void *ud, const pt_model *m, uint64_t seg,       /* 1-based seg */
                   const pt_fb_pixel *px, size_t n);
                          /* pixels drawn, n >= 1 of them in step order: a
                          ** segment's come in one or more calls, and a clip
                          ** record of it comes after the pixels before it */
    void (*clip)(void *ud, const pt_model *m, uint64_t seg, uint64_t count,
                 pt_pix first, pt_pix last);
    void (*point_pixels)(void *ud, const pt_model *m, uint64_t pt,
                         const pt_fb_pixel *px, size_t n);
                          /* the classic camera (the course's renderer 4): the
                          ** pixels point pt (1-based, the model's points in
                          ** file order) draws, in the course's order, n >= 1 at
                          ** a time; between the segments' records where the
                          ** course draws the point.  Not in the summary's
                          ** pixel count */
    void (*setup)(void *ud, const pt_model *m, uint64_t seg, const pt_raster_setup *su);
    void (*step)(void *ud, const pt_model *m, uint64_t seg, const pt_raster_step *st);
                          /* the DDA's records of segment seg (core/raster.h):
                          ** its setup (also when it is skipped), then every
                          ** step, clipped ones included, each before its
                          ** pixels or clip record.  With either set, the
                          ** segments are walked step by step, without the
                          ** fast-forward past the viewport (pt_raster_walk) */
    void (*skip)(void *ud, const pt_model *m, uint64_t seg,      /* not drawn: */
                 uint64_t v, const char *why);      /* v: the endpoint at fault, 0: none */
    void (*note)(void *ud, const pt_model *m, uint64_t seg,      /* drawn, but not as */
                 uint64_t v, const char *what);     /* its ends say: the course's renderer
                                                    ** 4 rounded endpoint v (0: none) from
                                                    ** NaN or beyond the long range, or its
                                                    ** loop would not end (what says which);
                                                    ** before the segment's pixels */
    void (*summary)(void *ud, const pt_summary *sum);
    int (*piece)(void *ud, uint64_t n, int last);
                          /* NULL: every record comes to this listener.  Else
                          ** pt_run cuts the records into pieces, in the order
                          ** they come (PT_PIECE_*, below), and asks at the
                          ** start of each (n = 0, 1, ...; last = 1 for the
                          ** summary's, after the raster records) whether its
                          ** records come here: 1 when they do.  Where the cuts
                          ** fall depends on the scene and on which callbacks
                          ** are set, never on the answers, so that runs with
                          ** the same callbacks cut alike and can share a trace */
    void *ud;
} pt_listener;

/* Where pt_run cuts a trace into pieces (pt_listener.piece), by default
** (pt_options.piece_*): after every PT_PIECE_VERTICES vertices of the scene
** (used or not, traced or not), and among the segments, when their records
** can come (a listener of pixels, clipped steps or skips, or the matrix
** camera's clipping), once a piece's segments number PT_PIECE_SEGMENTS or
** would draw PT_PIECE_PIXELS pixels or more (a segment as many as its longer
** side in the pixel plane, at most the viewport's width plus height, plus
** one); the summary is a piece of its own.  A vertex piece is some 250 KB of
** JSON Lines; a segment piece, up to some 600 KB. */
#define PT_PIECE_VERTICES 1024
#define PT_PIECE_SEGMENTS 1024
#define PT_PIECE_PIXELS   8192

/* The pipelines (core/pipelines.h), indexed by pt_pipe_id; the one scene s
** names; the one named name ("classic", "matrix"), or NULL; the one a trace
** header's camera word names ("perspective" and "orthographic": classic,
** "lookat": matrix), or NULL.  These functions can't fail. */
extern const pt_pipeline pt_pipe_classic;
extern const pt_pipeline pt_pipe_matrix;
extern const pt_pipeline *const pt_pipelines[PT_NPIPES];
const pt_pipeline *pt_scene_pipeline(const pt_scene *s);
const pt_pipeline *pt_pipeline_by_name(const char *name);
const pt_pipeline *pt_pipeline_by_camera(const char *word);

/* The word the trace's header gives scene s's camera: "perspective",
** "orthographic" or "lookat"; and as the tools' headings name it, with the
** pipeline's title where the word is the pipeline's own: "lookat (matrix
** camera)", into buf (len bytes, at least PT_CAMERA_TITLE), which it returns.
** These functions can't fail. */
#define PT_CAMERA_TITLE 64
const char *pt_scene_camera_word(const pt_scene *s);
const char *pt_camera_word(const pt_pipeline *pl, int perspective);  /* the same */
const char *pt_scene_camera_title(const pt_scene *s, char *buf, size_t len);

/* Fill *par with the numbers of scene s that the classic stages use for its
** model m.  This function can't fail. */
void pt_stage_params_of(pt_stage_params *par, const pt_scene *s, const pt_model *m);

/* Point *mx at the matrices plan p holds for model k (matrix camera).  This
** function can't fail. */
void pt_matrices_of(pt_matrices *mx, const pt_plan *p, size_t k);

/* Defaults: everything traced, identity stages left out, raster traced. */
void pt_options_default(pt_options *o);

/* Decide, for each model, the stages to trace and the vertices to transform.
** Returns 0, or -1 when out of memory (then *p is empty). */
int pt_plan_make(pt_plan *p, const pt_scene *s, const pt_options *o);

/* Free what *p owns.  This function can't fail. */
void pt_plan_free(pt_plan *p);

/* Component i (0 red, 1 green, 2 blue) of colour ci of model m as the
** course's float, 0..1: its colour list (`vcolor`), or, when that is empty,
** its one `color` for every vertex (byte / 255f).  This function can't fail. */
float pt_model_color(const pt_model *m, uint32_t ci, int i);

/* Run the scene through the plan, drawing into fb when fb is not NULL and
** o->rasterize is set.  Fills *sum.  Returns 0, or -1 when out of memory.
** With l->piece, the pieces not taken still run what the rest needs: every
** vertex, and every segment when there is fb or l->summary; *sum is the
** scene's when l->summary is set, else it may count the pieces taken only. */
int pt_run(const pt_scene *s, const pt_plan *p, const pt_options *o,
           const pt_listener *l, pt_fb *fb, pt_summary *sum);

/* pt_run() of scene s with options o, planned here, drawing nothing, to
** listener l.  Returns 0, or -1 when out of memory. */
int pt_run_plain(const pt_scene *s, const pt_options *o, const pt_listener *l);

/* The journey of 1-based vertex v (1 <= v <= m->nv) of model m of scene s, as
** pt_run() computes it (raw_lookat as its option), used by a segment or not:
** pt_run() traces v alone and hands its journey over.  Under the matrix camera
** a vertex outside the view volume stops at the cvv.  Returns 0, or -1 when
** out of memory. */
int pt_run_journey(pt_journey *j, const pt_scene *s, const pt_model *m, uint64_t v,
                   int raw_lookat);

/* The journeys of every vertex of model m of scene s, from one pt_run():
** element k is vertex k + 1's (as pt_run_journey()).  Returns an array of
** m->nv journeys (at least one element) the caller frees, or NULL when out of
** memory. */
pt_journey *pt_run_journeys(const pt_scene *s, const pt_model *m, int raw_lookat);

#endif
