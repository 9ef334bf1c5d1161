/*
** stages/wasm/pt_wasm_in.h -- where the matrix camera's inputs sit in the module's pt_wasm_in()
** See LICENSE for copyright and license.
**
** The journey page writes the matrix camera's inputs into the doubles at
** pt_wasm_in() (src/wasm/pt_wasm.c) before it calls pt_wasm_matrix_run():
** the model's `world` lines' matrix (row by row), its translate, the eye,
** the direction (with `camera lookat-target`, the point looked at), up, fov,
** aspect (unused when auto), near, far and the vertex.  The page learns the
** places from its data, which src/tools/journey/journey_wasm.c writes from
** this list: one list for both sides.  Likewise the most rows of the sin
** and cos table (pt_wasm_libm.h) the page may hand over, and the inputs of
** a course scene (renderers 7 and 9).
*/
#ifndef PT_WASM_IN_H
#define PT_WASM_IN_H

enum {
    PT_WASM_IN_WORLD = 0, PT_WASM_IN_T = 16, PT_WASM_IN_EYE = 19, PT_WASM_IN_DIR = 22,
    PT_WASM_IN_UP = 25, PT_WASM_IN_FOV = 28, PT_WASM_IN_ASPECT, PT_WASM_IN_NEAR,
    PT_WASM_IN_FAR, PT_WASM_IN_V, PT_WASM_NIN = PT_WASM_IN_V + 3
};

#define PT_WASM_NSINCOS 1024

/* The course's renderers 7 and 9: pt_wasm_course_in() returns an array of
** doubles: the camera (l, r, b, t, n), the translation (renderer 7) or the
** view vector (renderer 9), the position's matrix (renderer 9: column by
** column, x y z w), then the model as the driver built it: nv vertices (x,
** y, z, w), nc colours (r, g, b, each a float), np primitives (kind 0 a
** segment, 1 a point; v0, v1, c0, c1, 0-based; radius).  The stages are
** numbered as core/course.h's pt_course_stage (journey_wasm.c checks it). */
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

/* Renderer 9's position matrix from its operations instead (the angle and
** translation sliders): at pt_wasm_course_ops(n), per operation its
** pt_matmul, its pt_matop_kind and its 16 arguments. */
#define PT_WASM_COP 18
#define PT_WASM_NCOPS 64


#endif
