/*
** src/core/shapes.h -- the course's model library: `shape NAME ARGS...` in a scene
** See LICENSE for copyright and license.
**
** The Java teaching renderer (renderer 4, package renderer.models_L) builds its
** wireframe models -- Sphere, Cylinder, Torus, Cube, ... -- from a few numbers.
** pt_shape_make() builds the same vertices in the same order and the same line
** segments, so a scene can say `shape sphere 1 15 8` where a student's Java
** client says `new Sphere(1, 15, 8)`, and both renderers see one model.  The
** arguments come in the Java constructor's order; a shorter overload takes the
** defaults the Java one passes on.  pt_shapes[] is the one table of names,
** parameters, defaults and the Java classes: `pipetrace shapes` prints it and
** `pipetrace export java` names the classes from it.
**
** Each coordinate is computed in IEEE double with the Java expression's order of
** operations.  Where the formula has Math.sin or Math.cos, libm's result may
** differ from Java's in the last bit (tests/unit/test_shapes.c counts such cases).
*/
#ifndef PT_SHAPES_H
#define PT_SHAPES_H

#include <stddef.h>
#include <stdint.h>
#include "stages/pt_stage.h"

#define PT_SHAPE_MAXP 4               /* most parameters of any shape */
#define PT_SHAPE_MAXV 4194304u        /* most vertices (and segments) one shape may add */

/* One shape of the library.  param[k] is a real ('r' in kind[k]) or a Java int
** ('i'); with fewer arguments than nparam, parameter k takes dflt[k] (a number,
** or the name of an earlier parameter whose value it copies).  arities has bit
** c set when c arguments are accepted (the Java overloads). */
typedef struct pt_shape_info {
    const char *name;                 /* the word after `shape`: "sphere" */
    const char *java;                 /* the Java class in renderer.models_L: "Sphere" */
    int nparam;                       /* parameters of the longest overload */
    const char *param[PT_SHAPE_MAXP]; /* their names, in the constructor's order */
    char kind[PT_SHAPE_MAXP];         /* 'r': double, 'i': int */
    const char *dflt[PT_SHAPE_MAXP];  /* defaults for the shorter overloads */
    unsigned arities;                 /* bit c: c arguments are accepted */
    const char *what;                 /* one line: what it builds and what refuses */
} pt_shape_info;

extern const pt_shape_info pt_shapes[];   /* in `pipetrace shapes` order */
extern const int pt_nshapes;

/* The entry of pt_shapes[] called name[0..n), or NULL.  This function can't fail. */
const pt_shape_info *pt_shape_find(const char *name, size_t n);

/* The argument counts in arities as words, "0, 1 or 3", into buf (len >= 32
** holds any).  This function can't fail. */
void pt_shape_counts(unsigned arities, char *buf, size_t len);

/* A shape built: its vertices and segments (0-based indices into v), owned. */
typedef struct pt_shape {
    pt_vec3 *v;                       /* vertices, in the Java model's order */
    size_t nv;
    uint32_t (*seg)[2];               /* segments: vertex indices, in its order */
    size_t nseg;
} pt_shape;

/* Build into *sh the shape described by the text p[0..end): "NAME ARGS..."
** (what follows the word `shape` on its line, without the comment).  Returns
** 0 (free *sh with pt_shape_free()), or -1 with a one-line message (no
** position) in err, *sh untouched, and *at set to the byte of p[0..end) the
** message is about (left alone when it is about the whole line: the caller
** sets *at to the word `shape` first).  The caller appends the shape to a
** model, offsetting the segments' indices by the vertices it had before. */
int pt_shape_make(pt_shape *sh, const char *p, const char *end, const char **at,
                  char *err, size_t errlen);

/* Free what *sh owns and leave it empty.  This function can't fail. */
void pt_shape_free(pt_shape *sh);

#endif
