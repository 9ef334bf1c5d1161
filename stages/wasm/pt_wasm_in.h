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
** and cos table (pt_wasm_libm.h) the page may hand over.
*/
#ifndef PT_WASM_IN_H
#define PT_WASM_IN_H

enum {
    PT_WASM_IN_WORLD = 0, PT_WASM_IN_T = 16, PT_WASM_IN_EYE = 19, PT_WASM_IN_DIR = 22,
    PT_WASM_IN_UP = 25, PT_WASM_IN_FOV = 28, PT_WASM_IN_ASPECT, PT_WASM_IN_NEAR,
    PT_WASM_IN_FAR, PT_WASM_IN_V, PT_WASM_NIN = PT_WASM_IN_V + 3
};

#define PT_WASM_NSINCOS 1024

#endif
