/*
** src/io/trace_head.c -- the pieces the text and JSON Lines headers and summaries share
** See LICENSE for copyright and license.
*/
#include <stdint.h>
#include "io/trace.h"
#include "io/trace_int.h"

/* ===== header ===== */

/* See trace_int.h. */
const char *pt_trace_camera_name(const pt_scene *s)
{
    return pt_scene_camera_word(s);
}

/* See trace_int.h. */
void pt_trace_vec3_json(pt_trace *t, pt_vec3 v)
{
    put(t, "[", 1); put_json_num(t, v.x); put(t, ",", 1); put_json_num(t, v.y);
    put(t, ",", 1); put_json_num(t, v.z); put(t, "]", 1);
}

/* A point as the matrix camera's text lines write it: (x, y, z). */
static void put_vec3_text(pt_trace *t, pt_vec3 v)
{
    put(t, "(", 1); put_short(t, v.x); puts_(t, ", "); put_short(t, v.y);
    puts_(t, ", "); put_short(t, v.z); put(t, ")", 1);
}

/* See trace_int.h. */
void pt_trace_mat(pt_trace *t, const pt_mat4 *m, int json)
{
    const char *sep = json ? "," : " ";
    int i, j;

    if (json) put(t, "[", 1);
    for (i = 0; i < 4; i++) {
        if (i) put(t, sep, 1);
        put(t, "[", 1);
        for (j = 0; j < 4; j++) {
            if (j) put(t, sep, 1);
            if (json) put_json_num(t, m->m[i][j]);
            else put_short(t, m->m[i][j]);
        }
        put(t, "]", 1);
    }
    if (json) put(t, "]", 1);
}

/* See trace_int.h. */
void pt_trace_rgb(pt_trace *t, const unsigned char c[3], const char *sep)
{
    put_i64(t, c[0]); puts_(t, sep); put_i64(t, c[1]); puts_(t, sep); put_i64(t, c[2]);
}

/* See trace_int.h. */
void pt_trace_camera(pt_trace *t, const pt_scene *s, const pt_plan *p, int json)
{
    static const char *const vec_label[2][3] = {
        {" eye ", " direction ", " up "},
        {",\"lookat\":{\"eye\":", ",\"direction\":", ",\"up\":"}};
    static const char *const num_label[2][4] = {
        {"\nprojection   perspective fov ", " aspect ", " near ", " far "},
        {"},\"projection\":{\"fov\":", ",\"aspect\":", ",\"near\":", ",\"far\":"}};
    static const char *const mat_label[2][2] = {
        {"\nview         ", "\nprojection   "},
        {"},\"view\":", ",\"projection_matrix\":"}};
    const pt_vec3 vec[3] = {s->eye, s->dir, s->up};
    const double num[4] = {s->fov, s->aspect, s->znear, s->zfar};
    const pt_mat4 *mat[2] = {&p->view, &p->proj};
    void (*put_vec)(pt_trace *, pt_vec3) = json ? pt_trace_vec3_json : put_vec3_text;
    void (*put_num)(pt_trace *, double) = json ? put_json_num : put_short;
    int k;

    for (k = 0; k < 3; k++) { puts_(t, vec_label[json][k]); put_vec(t, vec[k]); }
    if (json) {
        puts_(t, ",\"up_perpendicular\":"); puts_(t, p->up_skewed ? "false" : "true");
        puts_(t, ",\"up_adjusted\":"); puts_(t, p->up_adjusted ? "true" : "false");
    } else if (p->up_adjusted) {
        puts_(t, "\n  warning    up is not perpendicular to direction: re-derived"
                 " (--raw-lookat keeps it)");
    } else if (p->up_skewed) {
        puts_(t, "\n  warning    up is not perpendicular to direction: kept as given"
                 " (--raw-lookat), so View is not orthonormal");
    }
    for (k = 0; k < 4; k++) { puts_(t, num_label[json][k]); put_num(t, num[k]); }
    for (k = 0; k < 2; k++) { puts_(t, mat_label[json][k]); pt_trace_mat(t, mat[k], json); }
}

/* ===== summary ===== */

/* See trace_int.h. */
void pt_trace_counts(const pt_summary *sum, pt_trace_count c[PT_TRACE_NCOUNTS])
{
    const pt_trace_count all[PT_TRACE_NCOUNTS] = {
        {"models", 0, sum->models}, {"vertices", 0, sum->vertices},
        {"vertices_unused", 0, sum->vertices_unused},
        {"vertices_traced", 0, sum->vertices_traced}, {"segments", 0, sum->segments},
        {"segments_degenerate", 0, sum->segments_degenerate},
        {"segments_skipped", 0, sum->segments_skipped},
        {"segments_culled", 0, sum->segments_culled}, {"pixels", 0, sum->pixels},
        {"clipped", sum->clipped_hi, sum->clipped}, {"clip_runs", 0, sum->clip_runs},
        {"behind", 0, sum->behind},
    };
    int k;

    for (k = 0; k < PT_TRACE_NCOUNTS; k++) c[k] = all[k];
}
