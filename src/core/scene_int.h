/*
** src/core/scene_int.h -- the scene parser's insides, shared by scene.c and scene_course.c
** See LICENSE for copyright and license.
**
** scene.c reads lines and holds the general directives; scene_course.c holds
** the directives of the course's renderers (docs/renderers.md) and their
** checks once the file is read.  Both report errors the same way: the first
** one as "FILE:LINE:COL: error: MESSAGE" in the parser's buffer, then -1.
*/
#ifndef PT_SCENE_INT_H
#define PT_SCENE_INT_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "stages/pt_stage.h"
#include "core/nameset.h"

/* (scene.h includes what scene.c includes: no cycle; the scene by its tags) */
struct pt_scene;
struct pt_model;

#if defined(__GNUC__)
#define PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PRINTF_LIKE(f, a)
#endif

/* Where the course's directives were seen (line and column, 0: not seen), for
** the checks that wait for the end of the file (which renderer). */
typedef struct pt_sc_at { size_t line, col; } pt_sc_at;

typedef struct pt_sc_course {
    pt_sc_at renderer, scene, vpbg, near, view, nearclip, antialias, gamma;
    pt_sc_at pipeline2;
    pt_sc_at cam_params;        /* a camera line with a view volume */
    pt_sc_at matrix;            /* the first `matrix` line */
    pt_sc_at point;             /* the first `point` line */
    pt_sc_at cindex;            /* the current model's highest colour index, */
    uint32_t cindex_max;        /*   its value + 1 (0: none) */
    size_t vcolor_line;         /* the current model's first `vcolor` line */
    size_t hidepos_line, hidemodel_line;
    double near_value;          /* `near N` */
} pt_sc_course;

#define MAX_VERTS  0x7fffffffu  /* per model: indices must fit in a uint32_t */
#define MAX_SEGS   0x7fffffffu  /* per model: a matching limit for segments */
#define QUOTE_MAX  40           /* bytes of a token quoted in a message */
#define QUOTE_BUF  (QUOTE_MAX + 4)
#define INT_CAP    INT64_C(100000000000000000)  /* integers saturate at +-1e17 */

/* A token: n bytes at p, inside the text buffer (not NUL-terminated). */
typedef struct token {
    const char *p;
    size_t n;
} token;

/* The unread part of one line: from p up to end, where end is the line end
** or the first '#', whichever comes first. */
typedef struct cursor {
    const char *p, *end;
} cursor;

/* One text being read: a .scene file, or an OBJ file (included or not). */
typedef struct source {
    const char *name;           /* file name for messages */
    const char *p, *end;        /* the unread text */
    const char *line;           /* start of the current line; columns count from here */
    size_t lineno;              /* number of the current line, 1-based */
    int obj;                    /* 1: OBJ mode (only v, l, f; other keywords ignored) */
    size_t base;                /* vertices the model had before this text began */
    FILE *f;                    /* a stream: the file; NULL: the text is in memory */
    int own;                    /* 1: f was opened here and is closed here */
    int included;               /* 1: an `obj` file: its text is quoted sparingly */
    char *buf;                  /* a stream: the window p..end lies in, owned */
    size_t cap;                 /* its size in bytes */
    int eof;                    /* 1: nothing more to read (always, in memory) */
    int errnum;                 /* errno of a read error, else 0 */
} source;

#define CHUNK 65536             /* a stream's window, at least */

/* What the parse of one scene remembers between lines. */
typedef struct parser {
    struct pt_scene *s;                /* the scene being filled */
    const char *dir;            /* obj paths are relative to dir[0..dirlen) */
    size_t dirlen;
    char *err;                  /* the caller's message buffer */
    size_t errlen;
    size_t fb_line, bg_line;    /* line of each once-per-scene directive, 0: none yet */
    size_t vp_line, cam_line;
    size_t proj_line;           /* line of `projection`, 0: none */
    size_t world_line;          /* line and column of the first `world`, 0: none */
    size_t world_col;
    size_t cam_col;             /* column of the camera's kind, for late checks */
    size_t proj_col[5];         /* columns of `projection`, fov, aspect, near, far */
    size_t vp_col;              /* column of `viewport`, for the late fit check */
    size_t translate_line;      /* once-per-model directives of the current model */
    size_t color_line;
    size_t *model_line;         /* model_line[i]: line of the `model` of s->models[i] */
    size_t cap_model_line;
    pt_nameset names;             /* the models' names -> their index in s->models */
    pt_sc_course course;        /* the course's directives (scene_course.c) */
} parser;

int pt_sc_fail_at(char *err, size_t errlen, const char *name, size_t line,
                  size_t col, const char *fmt, ...) PRINTF_LIKE(6, 7);
int pt_sc_fail(parser *ps, const source *src, const char *at,
               const char *fmt, ...) PRINTF_LIKE(4, 5);
const char *pt_sc_shown(const char *p, size_t n, char *buf);
int pt_sc_next_token(cursor *c, token *t);
int pt_sc_tok_is(const token *t, const char *w);
int pt_sc_number(parser *ps, const source *src, const token *t, const char *what,
                 double *out);
int pt_sc_numbers(parser *ps, const source *src, const token *a, size_t n,
                  const char *what, double *v);
int pt_sc_int(parser *ps, const source *src, const token *t, const char *what,
              int lo, int hi, int *out);
int pt_sc_take_args(parser *ps, const source *src, const token *dir, cursor *args,
                    token *arg, size_t lo, size_t hi, const char *noun, size_t *count);
int pt_sc_once(parser *ps, const source *src, const token *dir, size_t *seen);
int pt_sc_rgb(parser *ps, const source *src, const token *dir, cursor *args,
              const char *what, unsigned char rgb[3]);
int pt_sc_index(parser *ps, const source *src, const token *t, uint32_t *out);
struct pt_model *pt_sc_model(parser *ps);
int pt_sc_room(parser *ps, const source *src, const char *at, void **arr,
               size_t n, size_t *cap, size_t size, size_t max, const char *what);
void *pt_sc_grow(void *p, size_t *cap, size_t size, size_t max);
/* Refuse a name t (what: "model", "position", "scene") with a format
** character (bidirectional and other invisible ones).  0, or -1. */
int pt_sc_name_chars(parser *ps, source *src, const token *t, const char *what);

/* The course's directives (scene_course.c). */
int pt_sc_renderer(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_scene_name(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_vp_background(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_near(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_view(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_switch(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_pipeline2(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_matrix(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_vcolor(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_segment(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_point(parser *ps, source *src, const token *dir, cursor *args);
int pt_sc_hidden(parser *ps, source *src, const token *dir, cursor *args);
/* `camera perspective|orthographic ...` with a view volume, and the -fov forms
** (a[0] the kind, n words in a[]). */
int pt_sc_camera_volume(parser *ps, source *src, const token *a, size_t n);
/* `model NAME POSITION`: the position's name. */
int pt_sc_position(parser *ps, source *src, const token *t);
/* The translation as renderer 9's Matrix.translate (SET), in file order. */
int pt_sc_translate_op(parser *ps, source *src, const token *dir, pt_vec3 t);
/* A model ends (a new `model`, or the end of the file): its colour indices
** must be in its colour list. */
int pt_sc_end_model(parser *ps, const char *name);
/* The whole file is read: the directives fit the renderer, defaults filled. */
int pt_sc_finish_course(parser *ps, const char *name);
/* Defaults of the course's fields (start of a scene). */
void pt_sc_start_course(struct pt_scene *s);
/* Free the model's course lists.  This function can't fail. */
void pt_sc_free_model(struct pt_model *m);

#endif
