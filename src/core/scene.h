/*
** src/core/scene.h -- the scene: framebuffer, viewport, camera, models; and its parser
** See LICENSE for copyright and license.
**
** A scene is what a .scene file (or a plain Wavefront .obj file) describes.  The
** parser checks every rule of docs/scene-format.md and either fills a pt_scene or
** reports the first problem as "FILE:LINE:COL: error: MESSAGE".
**
** Invariants of a loaded scene:
**   1 <= fb_w, fb_h <= PT_MAX_SIZE;  the viewport lies inside the framebuffer and
**   has size >= 1;  every segment's a and b are < the model's nv;  model names are
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
#include "core/pipelines.h"

#define PT_MAX_SIZE 16384        /* largest framebuffer width or height */
#define PT_ERRLEN   1024         /* room for one error message */

typedef struct pt_segment {
    uint32_t a, b;               /* 0-based vertex indices into the model's v[] */
} pt_segment;

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

/* Free what *s owns and leave it empty.  This function can't fail. */
void pt_scene_free(pt_scene *s);

#endif
