/*
** src/tools/journey/journey_wasm.h -- the journey page's sliders, recomputed by the stages in WebAssembly
** See LICENSE for copyright and license.
**
** The page of `pipetrace journey --html` gets a "recompute" section: sliders
** for the model's translation (x_t, y_t, z_t), the viewport's size and
** corner (w, h, x_ul, y_ul) and the framebuffer's size (W, H); for the
** matrix camera also fov, eye (eye_x, eye_y, eye_z), near and far.  Moving
** one runs the chosen vertex through the camera's stages again, in the
** page, by calling the project's own stage files compiled to WebAssembly
** (src/wasm/pt_wasm.c, built into $B/stages.wasm by the Makefile and
** embedded below as base64).  The page's script only moves numbers between
** the sliders and the module and prints them; it holds no formula.
**
** What the section offers (ids for the tests):
**   #live              the section; data-ready="1" once the module runs,
**                      data-wasm="no" when pipetrace was built without it
**   #s_x_t ... #s_H    the sliders (input type=range), one per parameter
**                      (#s_fov, #s_eye_x ... #s_far: the matrix camera's)
**   #livetable         a row per stage (data-stage="camera"); its cell
**                      data-values holds the stage's values, reals as 16 hex
**                      digits of their IEEE bits, integers in decimal,
**                      "none" for no value, separated by commas; "unreached"
**                      for a matrix stage past the cvv of a vertex outside
**   #livenote          what the numbers shown are
**   #reset             back to the scene's own numbers
** When a slider has moved, #coords shows the recomputed values of the shown
** stage; the panel and the texts "with the numbers" and "next" stay the
** scene's (they are drawn by pipetrace itself) and are dimmed.
*/
#ifndef PT_JOURNEY_WASM_H
#define PT_JOURNEY_WASM_H

#include "io/sbuf.h"
#include "core/pipetrace.h"
#include "io/explain_course.h"

/* $B/stages.wasm as base64, one line an element, ended by NULL; only the
** NULL when pipetrace was built without clang and wasm-ld (or WASM=no).
** Written by the Makefile into $B/stages_wasm.c. */
extern const char *const pt_journey_wasm_b64[];

/* Append the recompute section for scene s (either camera) to a journey
** page, after its own script: the sliders, the scene's numbers in exact
** form, the module and the script, or, built without the module, a note
** that says so.  The script finds the page's #data, #vertex, #stage and
** #coords (journey_html.c).  On allocation failure sb->failed is set. */
void pt_journey_wasm(pt_sbuf *sb, const pt_scene *s);

/* The recompute section of a course scene's page (renderers 7 and 9,
** journey_course.c): sliders l, r, b, t, n (#s_l ... #s_n), the
** translation #s_x_t ... #s_z_t (renderer 7) or the view vector #s_view_x
** ... #s_view_z and, for the K-th operation of the position's matrix, a
** rotate's angle #s_angle_K, a translate's #s_tx_K, #s_ty_K, #s_tz_K, a
** scale's factor #s_scale_K (its three factors equal, as `scale S` gives
** them) or #s_sx_K, #s_sy_K, #s_sz_K, or rows' 16 entries #s_a00_K ...
** #s_a33_K (renderer 9), the viewport #s_w, #s_h, #s_x_ul, #s_y_ul and the
** framebuffer #s_W, #s_H (the viewport may stick out of it, as the course
** allows); #livetable's rows model, [world,] view, camera, nearclip,
** image, clip (x, y, z, w as IEEE bits, "none" before the vertex is made),
** viewport and framebuffer (integers, "none" outside the view square) and
** index (the pixel array's element the rasterizer writes, rows wrapping;
** "none" outside the array).  The module runs the position's whole model
** through the course's stages, so a vertex a clip makes is followed as
** well.  On allocation failure sb->failed is set. */
typedef struct pt_jwasm_course {
    const pt_cx_journey *j;      /* the camera, translation, matrix (any vertex's) */
    const pt_rv_model *m;        /* the position's model as the driver built it */
    const char *label[PT_NCST];  /* each stage's coordinates, "(x_c, y_c, z_c)" */
    const char *text[3];         /* the labels' "not yet" (near clip, clip) and
                                 ** the viewport's "none" texts */
    const pt_matop *ops;         /* renderer 9: the position's matrix operations */
    size_t nops;
} pt_jwasm_course;
void pt_journey_wasm_course(pt_sbuf *sb, const pt_scene *s, const pt_jwasm_course *c);

#endif
