/*
** src/io/trace_csv.c -- the trace as CSV: the vertex records only, a row each
** See LICENSE for copyright and license.
*/
#include <stdint.h>
#include <string.h>
#include "io/trace.h"
#include "io/trace_int.h"
#include "io/sbuf.h"

/* ===== header ===== */

/* The CSV header rows; see vertex_csv(). */
static const char csv_classic[] =
    "model,v,stage,x,y,z,inside,behind,i,warning,digits_lost\n";
static const char csv_matrix[] =
    "model,v,stage,x,y,z,w,code,planes,inside,i,segment,t,warning,digits_lost\n";

static void header_csv(pt_trace *t, const pt_scene *s, const pt_plan *p)
{
    if (t->student && *t->student) {        /* a student build: which stage files */
        puts_(t, "# student "); puts_(t, t->student); put(t, "\n", 1);
    }
    puts_(t, pt_scene_pipeline(s)->matrices ? csv_matrix : csv_classic);
    (void)p;
}

/* ===== vertex records ===== */

/* CSV rows, empty where a field does not apply, warning names joined by '|':
**   classic camera: model,v,stage,x,y,z,inside,behind,i,warning,digits_lost
**   matrix camera:  model,v,stage,x,y,z,w,code,planes,inside,i,segment,t,warning,
**                   digits_lost
** (planes joined by '|'; a point clipping made has no v, but its segment and t). */

/* The model's name as a CSV cell (pt_sbuf_add_csv(): a name such as "=1+1"
** or "a,b" is quoted, so no cell becomes a formula and no row is cut). */
static void model_cell(pt_trace *t, const pt_model *m)
{
    pt_sbuf cell;

    if (pt_sbuf_csv_plain(m->name)) { puts_(t, m->name); return; }
    pt_sbuf_init(&cell);
    pt_sbuf_add_csv(&cell, m->name);
    if (cell.s) puts_(t, cell.s);
    pt_sbuf_free(&cell);
}

/* 'm1,': how the vertex records of model m begin (pt_trace_vertex_prefix). */
static void vertex_opening(pt_trace *t, const pt_model *m)
{
    model_cell(t, m); put(t, ",", 1);
}

/* Names whose bits are set in bits, joined by sep, at o; returns the end. */
static char *names_at(char *o, unsigned bits, const char *const *names, int n, char sep)
{
    int k, first = 1;

    for (k = 0; k < n; k++) {
        if (!(bits & (1u << k))) continue;
        if (!first) *o++ = sep;
        first = 0;
        o = str_at(o, names[k]);
    }
    return o;
}

static void vertex_csv(pt_trace *t, const pt_vrec *r)
{
    /* the matrix camera's columns: w, the outcode, a clipped point's segment */
    int matrix = t->scene && pt_scene_pipeline(t->scene)->matrices;
    /* the stage's columns, read before any byte is stored (each may alias them) */
    const pt_stage_info *in = &pt_stage_infos[r->stage];
    const pt_value_kind kind = in->kind;
    const unsigned sflags = in->flags;
    int k, dims = in->nreal;
    const double v[4] = {r->x, r->y, r->z, r->w};
    char *o;

    if (!(o = vertex_opening_at(t, !t->clipv, vertex_opening))) {   /* 'm1,12' ('m1,' clipped) */
        model_cell(t, t->model);
        o = room(t, PT_ROW_REST);
        *o++ = ',';
        if (!t->clipv) o = u64_at(t, o, t->v);
    }
    *o++ = ',';
    o = frag_at(t, o, r->stage, 0);         /* the stage's name */
    for (k = 0; k < (matrix ? 4 : 3); k++) {            /* x,y,z[,w] */
        *o++ = ',';
        if (k < dims) o = short_at(t, o, v[k]);
        else if (k < 2 && kind == PT_VAL_PIXEL && pt_rec_has(r, k))
            o = int_at(t, o, k ? r->iy : r->ix, 0);
    }
    *o++ = ',';
    if (matrix) {                                       /* code,planes */
        if (kind == PT_VAL_OUTCODE) {
            o = int_at(t, o, r->code, 0);
            *o++ = ',';
            o = names_at(o, r->code, pt_cvv_names, PT_CVV_NPLANES, '|');
        } else {
            *o++ = ',';
        }
        *o++ = ',';
    }
    if (sflags & PT_REC_INSIDE) *o++ = r->flags & PT_REC_INSIDE ? '1' : '0';
    *o++ = ',';
    if (!matrix) {                                      /* behind */
        if (sflags & PT_REC_BEHIND) *o++ = r->flags & PT_REC_BEHIND ? '1' : '0';
        *o++ = ',';
    }
    if (kind == PT_VAL_INDEX && !(r->flags & PT_REC_NULL)) o = int_at(t, o, r->i, 0);
    *o++ = ',';
    if (matrix) {                                       /* segment,t */
        if (t->clipv) { o = u64_at(t, o, t->seg); *o++ = ','; o = short_at(t, o, t->t_clip); }
        else *o++ = ',';
        *o++ = ',';
    }
    o = names_at(o, r->warn, pt_warn_names, PT_NWARN, '|');
    *o++ = ',';
    if (r->warn & (PT_WARN_CANCEL | PT_WARN_ILLCOND)) o = int_at(t, o, r->digits_lost, 0);
    *o++ = '\n';
    t->len = (size_t)(o - t->buf);
}

static void on_vertex(void *ud, const pt_vrec *r)
{
    vertex_csv(ud, r);
}

/* No raster records, no summary: nobody listens to the rasterizer. */
const pt_trace_writer pt_trace_csv = {
    header_csv, on_vertex, NULL, NULL, NULL, NULL, NULL, NULL
};
