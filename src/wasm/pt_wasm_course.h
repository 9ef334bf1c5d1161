/*
** src/wasm/pt_wasm_course.h -- where the page puts a course scene's inputs for the module
** See LICENSE for copyright and license.
**
** pt_wasm_course_in() (src/wasm/pt_wasm.c) returns an array of doubles:
** the camera (l, r, b, t, n), the translation (renderer 7) or the view
** vector (renderer 9), the position's matrix (renderer 9: column by column,
** x y z w), then the model as the driver built it: nv vertices (x, y, z,
** w), nc colours (r, g, b, each a float), np primitives (kind 0 a segment,
** 1 a point; v0, v1, c0, c1, 0-based; radius).  The stages are numbered as
** core/course.h's pt_course_stage (journey_wasm.c checks it).
*/
#ifndef PT_WASM_COURSE_H
#define PT_WASM_COURSE_H

enum {
    PT_WASM_CIN_L, PT_WASM_CIN_R, PT_WASM_CIN_B, PT_WASM_CIN_T, PT_WASM_CIN_N,
    PT_WASM_CIN_MOVE = 5,        /* 3: translation (r7) or view vector (r9) */
    PT_WASM_CIN_MATRIX = 8,      /* 16 */
    PT_WASM_CIN_MODEL = 24       /* the model from here */
};

enum {
    PT_WASM_CST_MODEL, PT_WASM_CST_WORLD, PT_WASM_CST_VIEW, PT_WASM_CST_CAMERA,
    PT_WASM_CST_NEARCLIP, PT_WASM_CST_IMAGE, PT_WASM_CST_CLIP, PT_NCOURSE
};

#endif
