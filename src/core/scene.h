/*
** src/core/scene.h -- the scene: framebuffer, viewport, camera, models; and its parser
** See LICENSE for copyright and license.
**
** A scene is what a .scene file (or a plain Wavefront .obj file) describes.  The
** parser checks every rule of docs/scene-format.md and either fills a pt_scene or
** reports the first problem as "FILE:LINE:COL: error: MESSAGE".
**
** Invariants of a loaded scene:
**   1 <= fb_w, fb_h <= PT_MAX_SIZE;  1 <= vp_w, vp_h <= PT_MAX_SIZE and
**   -PT_MAX_SIZE <= vp_x, vp_y <= PT_MAX_SIZE: the viewport may stick out of
**   the framebuffer (the course's renderers draw it so), but with the matrix
**   camera it lies inside;  every segment's a and b are < the model's nv;  model names are
**   unique, non-empty, valid UTF-8 with no control characters;  every coordinate
**   is finite;  with matrix set, pt_lookat() and pt_perspective() accept the
**   camera's parameters.
*/
#ifndef PT_SCENE_H
#define PT_SCENE_H

#include <stddef.h>
#include <stdio.h>
#include <stdint.h>
#include "stages/pt_mat4.h"
#include "stages/r9_matrix.h"
#include "core/pipelines.h"

#define PT_MAX_SIZE 16384        /* largest framebuffer width or height */
#define PT_ERRLEN   1024         /* room for one error message */

typedef struct pt_segment {
    uint32_t a, b;               /* 0-based vertex indices into the model's v[] */
    uint32_t ca, cb;             /* 0-based colour indices (`segment I J CI CJ`;
                                 ** `l`, `f` and `segment I J`: a and b) */
} pt_segment;

/* A point (`point I [C [RADIUS]]`).  The course draws a model's primitives in
** file order; a point drawn after the first `after` segments keeps it. */
typedef struct pt_point {
    uint32_t v;                  /* 0-based vertex index */
    uint32_t c;                  /* 0-based colour index (default v) */
    int radius;                  /* Point.radius, default 0; < 0 draws nothing */
    size_t after;                /* how many of seg[] come before it in the file */
} pt_point;

typedef struct pt_model {
    char *name;                  /* unique, owned */
    pt_vec3 translate;           /* (x_t, y_t, z_t), default 0 0 0 */
    unsigned char color[3];      /* line color, default 255 255 255 */
    pt_vec3 *v;                  /* vertices, model coordinates, owned */
    size_t nv, cap_v;            /* count and capacity of v */
    pt_segment *seg;             /* segments in file order, owned */
    size_t nseg, cap_seg;        /* count and capacity of seg */
    pt_mat4 world;               /* product of the `world` lines, identity if none;
                                 ** the matrix camera appends `translate` */
    /* the course's renderers (docs/renderers.md): */
    char *position;              /* the Position's name (`model NAME POSITION`),
                                 ** owned; NULL: the model's name */
    pt_rgb *colors;              /* the colour list (`vcolor`, `vcolor-float`),
                                 ** owned; empty: one `color` a vertex (white
                                 ** by default, as the course adds it) */
    size_t ncolors, cap_colors;
    int colors_given;            /* 1: the model has `color` or `vcolor` lines
                                 ** (else the course warns and adds white) */
    pt_point *pts;               /* points in file order, owned */
    size_t npts, cap_pts;
    int hidden_position;         /* `hidden-position`: Position.visible = false */
    int hidden_model;            /* `hidden-model`: Model.visible = false */
    pt_matop *ops;               /* renderer 9: the position's matrix, as
                                 ** operations in file order, owned */
    size_t nops, cap_ops;
} pt_model;

typedef struct pt_scene {
    char *path;                  /* file name as given, or "<builtin>"; owned */
    int fb_w, fb_h;              /* framebuffer size, default 800 600 */
    unsigned char background[3]; /* default 0 0 0 */
    int vp_x, vp_y, vp_w, vp_h;  /* viewport upper-left corner and size */
    int perspective;             /* 1: camera perspective (default), 0: orthographic */
    pt_pipe_id pipe;             /* the pipeline: PT_PIPE_MATRIX with `camera
                                 ** lookat` (+ projection), else PT_PIPE_CLASSIC */
    pt_vec3 eye, dir, up;        /* matrix camera: position, direction, up vector */
    int target;                  /* 1: `camera lookat-target`: dir = at - eye */
    pt_vec3 at;                  /* with target: the point looked at */
    double fov;                  /* vertical field of view, degrees, in (0, 180) */
    double aspect;               /* aspect ratio w/h > 0 (`auto`: viewport w/h) */
    int aspect_auto;             /* 1: the scene said `auto` */
    double znear, zfar;          /* 0 < znear < zfar */
    int from_obj;                /* 1: a plain .obj wrapped in a default scene */
    pt_vec3 obj_translate;       /* with from_obj: the translation chosen */
    pt_model *models;            /* in file order, owned */
    size_t nmodels, cap_models;  /* count and capacity of models */
    /* the course's renderers (docs/renderers.md): */
    int renderer;                /* 4 (default), 7 or 9 */
    char *scene_name;            /* `scene NAME`, owned; NULL: "" */
    unsigned char vp_background[3];  /* `viewport-background`, default background */
    double cam_l, cam_r, cam_b, cam_t;  /* renderers 7, 9: the Camera's view
                                 ** rectangle (l/f .. t/f; default -1 1 -1 1) */
    double cam_n;                /* the z of its near plane: -0.1 perspective,
                                 ** +1 orthographic, -N after `near N` */
    pt_vec3 view;                /* renderer 9: `view X Y Z` (camera.translate) */
    int nearclip;                /* NearClip.doNearClipping, default 1 */
    int antialias;               /* Rasterize.doAntiAliasing, default 0 */
    int gamma;                   /* Rasterize.doGamma, default 1 */
    int pipeline2;               /* 1: renderer 9's Pipeline2 */
    char **objs;                 /* the paths `obj` lines read, in order, owned: an
                                 ** output must not overwrite them */
    size_t nobjs;                /* their count */
} pt_scene;

/* Load the scene in the file at path.  A name ending in ".obj" (any case) is read
** as a plain Wavefront OBJ file and wrapped in a default scene (see
** docs/scene-format.md).  On success returns 0 and fills *s, which the caller
** frees with pt_scene_free().  On error returns -1, writes one message
** "FILE:LINE:COL: error: ..." (no newline) to err and leaves *s empty. */
int pt_scene_load(pt_scene *s, const char *path, char *err, size_t errlen);

/* Like pt_scene_load() for the open stream f, read as a stream as a file is
** (never whole) and not closed; name is used in messages and as s->path, and
** `obj` paths are relative to the current directory.  For standard input. */
int pt_scene_read(pt_scene *s, FILE *f, const char *name, char *err, size_t errlen);

/* Like pt_scene_load() for scene text already in memory (len bytes, need not be
** NUL-terminated); name is used in messages and as s->path, and `obj` paths are
** relative to the current directory. */
int pt_scene_parse(pt_scene *s, const char *name, const char *text, size_t len,
                   char *err, size_t errlen);

/* 1 when the viewport of s lies inside its framebuffer, else 0.  This
** function can't fail. */
int pt_scene_vp_inside(const pt_scene *s);

/* Free what *s owns and leave it empty.  This function can't fail. */
void pt_scene_free(pt_scene *s);

#endif
