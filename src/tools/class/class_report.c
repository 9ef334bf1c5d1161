/*
** src/tools/class/class_report.c -- pipetrace class: the table, the histograms, CSV and HTML
** See LICENSE for copyright and license.
**
** Every report is made from the rows alone (class.h), so the terminal, the
** CSV and the page say the same.  Names and messages come from the students'
** files: each goes out through the one escaping of its kind (sbuf.h:
** pt_sbuf_add_term, pt_sbuf_add_csv_untrusted, pt_sbuf_add_xml).  A histogram counts
** the rows whose verdict is FAIL: by the stage that goes wrong first, and by
** the mistake named ("unknown" and each "ambiguous: ..." a bar of its own),
** the bars largest first, ties by name, so the order never depends on the
** folder's order.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "tools/class/class.h"

#define CLASS_MAXBARS 64             /* bars a histogram keeps; the rest "other" */

const char *pt_class_verdict(const pt_class_row *r)
{
    if (r->why || (!r->has_t && !r->has_im)) return "UNREADABLE";
    if (r->has_im && r->im.status != 0) return "FAIL";  /* a differing image proves it */
    if (r->has_t && r->t.status == 3) return "NOT PROVEN";
    if (r->has_t && r->t.status != 0) return "FAIL";
    return "PASS";
}

/* buf (n bytes, a mistake as pt_class_mistake says it) with the mistake the
** image's diff against the student's own trace names, when it names one
** and buf does not say it yet: "-" becomes it, anything else gets "; " and
** it.  Returns buf. */
static const char *own_mistake(const pt_class_row *r, char *buf, size_t n)
{
    size_t len = strlen(buf);

    if (!r->has_own || r->own.nnamed != 1 || strstr(buf, r->own.named[0])) return buf;
    if (!strcmp(buf, "-")) snprintf(buf, n, "%s", r->own.named[0]);
    else if (len < n) snprintf(buf + len, n - len, "; %s", r->own.named[0]);
    return buf;
}

const char *pt_class_mistake(const pt_class_row *r, char *buf, size_t n)
{
    size_t len = 0;
    int k;

    const pt_diff_outcome *o = &r->t;

    if (!strcmp(pt_class_verdict(r), "FAIL") && (!r->has_t || r->t.status == 0 || r->t.status == 3) &&
        r->has_im && r->im.nnamed > 0)
        o = &r->im;                 /* only the image differs, and its diff names it */
    else if (strcmp(pt_class_verdict(r), "FAIL") || !r->has_t || r->t.status == 0 ||
             r->t.status == 3) {
        snprintf(buf, n, "-");
        return own_mistake(r, buf, n);
    }
    if (o->nnamed == 0) { snprintf(buf, n, "unknown"); return own_mistake(r, buf, n); }
    if (o->nnamed == 1) { snprintf(buf, n, "%s", o->named[0]); return own_mistake(r, buf, n); }
    len = (size_t)snprintf(buf, n, "ambiguous: ");
    for (k = 0; k < o->nnamed && k < PT_DIFF_MAXNAMED && len < n; k++)
        len += (size_t)snprintf(buf + len, n - len, "%s%s", k ? " or " : "", o->named[k]);
    if (o->nnamed > PT_DIFF_MAXNAMED && len < n)
        snprintf(buf + len, n - len, " or %d more", o->nnamed - PT_DIFF_MAXNAMED);
    return own_mistake(r, buf, n);
}

/* The first wrong stage, "image" when only the image differs, else "-". */
static const char *stage_of(const pt_class_row *r)
{
    if (strcmp(pt_class_verdict(r), "FAIL")) return "-";
    if (r->has_t && r->t.stage[0]) return r->t.stage;
    if (r->has_im && r->im.status) return "image";
    return "-";
}

/* "5/16" differing vertices of those compared, or "-". */
static void vertices_of(const pt_class_row *r, char *buf, size_t n)
{
    if (!r->has_t || r->t.status == 2) snprintf(buf, n, "-");
    else snprintf(buf, n, "%zu/%zu", r->t.differ + r->t.only, r->t.vertices + r->t.only);
}

static void pixels_of(const pt_class_row *r, char *buf, size_t n)
{
    if (!r->has_t || !r->t.px_compared) snprintf(buf, n, "-");
    else snprintf(buf, n, "%zu", r->t.px_missing + r->t.px_extra);
}

static void image_of(const pt_class_row *r, char *buf, size_t n)
{
    if (!r->has_im || !r->im.images) snprintf(buf, n, "-");
    else snprintf(buf, n, "%zu", r->im.img_differ);
}

/* ===== histograms ===== */

typedef struct bar {
    char name[400];
    size_t n;
} bar;

typedef struct hist {
    bar b[CLASS_MAXBARS + 1];    /* the last: "other" */
    size_t nb, max;
} hist;

static void count(hist *h, const char *name)
{
    size_t k;

    for (k = 0; k < h->nb; k++)
        if (!strcmp(h->b[k].name, name)) break;
    if (k == h->nb) {
        if (h->nb == CLASS_MAXBARS) {
            k = CLASS_MAXBARS;
            snprintf(h->b[k].name, sizeof h->b[k].name, "other");
        } else {
            snprintf(h->b[k].name, sizeof h->b[k].name, "%s", name);
            h->nb++;
        }
    }
    h->b[k].n++;
}

static int by_count(const void *pa, const void *pb)
{
    const bar *a = pa, *b = pb;
    if (a->n != b->n) return a->n > b->n ? -1 : 1;
    return strcmp(a->name, b->name);
}

/* The two histograms of c: by stage (0) and by mistake (1). */
static void histograms(const pt_class *c, hist h[2])
{
    size_t k;
    char m[400];

    memset(h, 0, 2 * sizeof *h);
    for (k = 0; k < c->nrow; k++) {
        const pt_class_row *r = &c->row[k];
        if (strcmp(pt_class_verdict(r), "FAIL")) continue;
        count(&h[0], stage_of(r));
        if (strcmp(pt_class_mistake(r, m, sizeof m), "-")) {
            char *one = m, *sep;            /* "A; B": a bar each */
            while ((sep = strstr(one, "; ")) != NULL) {
                *sep = '\0';
                count(&h[1], one);
                one = sep + 2;
            }
            count(&h[1], one);
        }
    }
    for (k = 0; k < 2; k++) {
        size_t j, nb = h[k].nb + (h[k].b[CLASS_MAXBARS].n > 0);
        if (h[k].b[CLASS_MAXBARS].n) h[k].b[h[k].nb] = h[k].b[CLASS_MAXBARS];
        h[k].nb = nb;
        qsort(h[k].b, nb, sizeof h[k].b[0], by_count);
        for (j = 0; j < nb; j++)
            if (h[k].b[j].n > h[k].max) h[k].max = h[k].b[j].n;
    }
}

static const char *const hist_title[2] = {"first wrong stage", "mistake"};

/* ===== terminal ===== */

static void term(pt_sbuf *sb, const char *t)
{
    pt_sbuf_add_term(sb, t, strlen(t));
}

/* Append t made safe, padded with spaces to width w. */
static void term_pad(pt_sbuf *sb, const char *t, size_t w)
{
    size_t before = sb->len;
    term(sb, t);
    while (sb->len - before < w && !sb->failed) pt_sbuf_add(sb, " ");
}

/* The width t takes once made safe (bytes; the table is aligned in bytes). */
static size_t term_len(const char *t)
{
    pt_sbuf s;
    size_t n;

    pt_sbuf_init(&s);
    term(&s, t);
    n = s.len;
    pt_sbuf_free(&s);
    return n;
}

void pt_class_text(pt_sbuf *sb, const pt_class *c)
{
    size_t k, wname = 7, wstage = 11, wm = 7, npass = 0, nfail = 0, nnp = 0, nbad = 0;
    char m[400], v[48], p[32], im[32];
    hist h[2];
    int t;

    for (k = 0; k < c->nrow; k++) {
        const pt_class_row *r = &c->row[k];
        size_t n = term_len(r->name);
        const char *vd = pt_class_verdict(r);
        if (n > wname) wname = n;
        if (strlen(stage_of(r)) > wstage) wstage = strlen(stage_of(r));
        n = term_len(pt_class_mistake(r, m, sizeof m));
        if (n > wm) wm = n;
        npass += !strcmp(vd, "PASS");
        nfail += !strcmp(vd, "FAIL");
        nnp += !strcmp(vd, "NOT PROVEN");
        nbad += !strcmp(vd, "UNREADABLE");
    }
    pt_sbuf_add(sb, "pipetrace class: ");
    term(sb, c->dir);
    pt_sbuf_addf(sb, ", %zu student%s, against ", c->nrow, c->nrow == 1 ? "" : "s");
    term(sb, c->expected);
    pt_sbuf_add(sb, c->scene ? " (rendered: every stage, its pixels and its image)\n\n" : "\n\n");
    term_pad(sb, "student", wname + 2);
    pt_sbuf_add(sb, "verdict     ");
    term_pad(sb, "first wrong", wstage + 2);
    term_pad(sb, "mistake", wm + 2);
    pt_sbuf_add(sb, "vertices  pixels  image\n");
    for (k = 0; k < c->nrow; k++) {
        const pt_class_row *r = &c->row[k];
        term_pad(sb, r->name, wname + 2);
        term_pad(sb, pt_class_verdict(r), 12);
        if (r->why) {
            term(sb, r->why);
            pt_sbuf_add(sb, "\n");
            continue;
        }
        term_pad(sb, stage_of(r), wstage + 2);
        term_pad(sb, pt_class_mistake(r, m, sizeof m), wm + 2);
        vertices_of(r, v, sizeof v);
        pixels_of(r, p, sizeof p);
        image_of(r, im, sizeof im);
        pt_sbuf_addf(sb, "%-8s  %-6s  %s\n", v, p, im);
    }
    pt_sbuf_addf(sb, "\n%zu passed, %zu failed, %zu not proven, %zu unreadable\n", npass, nfail,
                 nnp, nbad);
    histograms(c, h);
    for (t = 0; t < 2; t++) {
        size_t w = 0;
        if (!h[t].nb) continue;
        pt_sbuf_addf(sb, "\nfailed, by %s:\n", hist_title[t]);
        for (k = 0; k < h[t].nb; k++)
            if (term_len(h[t].b[k].name) > w) w = term_len(h[t].b[k].name);
        for (k = 0; k < h[t].nb; k++) {
            size_t len = (h[t].b[k].n * 40 + h[t].max - 1) / h[t].max, j;
            pt_sbuf_add(sb, "  ");
            term_pad(sb, h[t].b[k].name, w + 2);
            pt_sbuf_addf(sb, "%4zu  ", h[t].b[k].n);
            for (j = 0; j < len; j++) pt_sbuf_add(sb, "#");
            pt_sbuf_add(sb, "\n");
        }
    }
}

/* The separating scene the row's trace diff printed (between its marker
** lines, when its mistakes are ambiguous): its first byte, its length into
** *n; NULL when there is none. */
static const char *sep_scene(const pt_class_row *r, size_t *n)
{
    static const char begin[] = "#---- begin separating scene ----\n",
                      end[] = "#---- end separating scene ----\n";
    const char *a, *b;

    if (!r->text[0].len || !(a = strstr(r->text[0].s, begin))) return NULL;
    a += sizeof begin - 1;
    if (!(b = strstr(a, end))) return NULL;
    *n = (size_t)(b - a);
    return a;
}

/* ===== CSV ===== */

/* A CSV cell has no value where a table shows "-" (a cell that starts with
** '-' would be a formula's). */
static const char *dash(const char *t)
{
    return strcmp(t, "-") ? t : "";
}

void pt_class_csv(pt_sbuf *sb, const pt_class *c)
{
    size_t k;
    char m[400], v[48], p[32], im[32];

    pt_sbuf_add(sb, "student,trace,image,verdict,first_wrong_stage,mistake,vertices_differing,"
                "pixels_differing,image_pixels_differing,note,separating_scene\r\n");
    for (k = 0; k < c->nrow; k++) {
        const pt_class_row *r = &c->row[k];
        vertices_of(r, v, sizeof v);
        pixels_of(r, p, sizeof p);
        image_of(r, im, sizeof im);
        pt_sbuf_add_csv_untrusted(sb, r->name);
        pt_sbuf_add(sb, ",");
        pt_sbuf_add_csv_untrusted(sb, r->trace ? r->trace : "");
        pt_sbuf_add(sb, ",");
        pt_sbuf_add_csv_untrusted(sb, r->image ? r->image : "");
        pt_sbuf_addf(sb, ",%s,", pt_class_verdict(r));
        pt_sbuf_add_csv(sb, r->why ? "" : dash(stage_of(r)));
        pt_sbuf_add(sb, ",");
        pt_sbuf_add_csv(sb, r->why ? "" : dash(pt_class_mistake(r, m, sizeof m)));
        pt_sbuf_addf(sb, ",%s,%s,%s,", r->why ? "" : dash(v), r->why ? "" : dash(p),
                     r->why ? "" : dash(im));
        pt_sbuf_add_csv_untrusted(sb, r->why ? r->why : "");
        pt_sbuf_add(sb, ",");
        {
            size_t n;
            const char *sc = sep_scene(r, &n);
            char *cell = sc ? malloc(n + 1) : NULL;
            if (cell) {
                memcpy(cell, sc, n);
                cell[n] = '\0';
                pt_sbuf_add_csv(sb, cell);      /* pipetrace's own text: its lines kept */
            } else if (sc) {
                sb->failed = 1;
            }
            free(cell);
        }
        pt_sbuf_add(sb, "\r\n");
    }
}

/* ===== HTML ===== */

/* One bar chart of h as inline SVG. */
static void svg_chart(pt_sbuf *sb, const hist *h, const char *title, const char *id)
{
    size_t k, rowh = 22, height = 30 + rowh * h->nb;

    pt_sbuf_addf(sb, "<figure id=\"%s\"><figcaption>Failed, by ", id);
    pt_sbuf_add_xml(sb, title);
    pt_sbuf_addf(sb, "</figcaption>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"760\" "
                 "height=\"%zu\" viewBox=\"0 0 760 %zu\" role=\"img\">\n", height, height);
    for (k = 0; k < h->nb; k++) {
        size_t y = 10 + rowh * k, w = h->max ? h->b[k].n * 400 / h->max : 0;
        pt_sbuf_addf(sb, "<g class=\"bar\" data-count=\"%zu\"><text x=\"300\" y=\"%zu\" "
                     "text-anchor=\"end\">", h->b[k].n, y + 15);
        pt_sbuf_add_xml(sb, h->b[k].name);
        pt_sbuf_addf(sb, "</text><rect x=\"310\" y=\"%zu\" width=\"%zu\" height=\"18\"/>"
                     "<text x=\"%zu\" y=\"%zu\">%zu</text></g>\n", y + 2, w ? w : 1,
                     316 + w, y + 15, h->b[k].n);
    }
    pt_sbuf_add(sb, "</svg></figure>\n");
}

void pt_class_html(pt_sbuf *sb, const pt_class *c)
{
    size_t k, n;
    const char *sc;
    int t;
    char m[400], v[48], p[32], im[32];
    hist h[2];

    histograms(c, h);
    pt_sbuf_add(sb, "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                "<title>pipetrace class: ");
    pt_sbuf_add_xml(sb, c->dir);
    pt_sbuf_add(sb, "</title>\n<style>\nbody{font-family:sans-serif;margin:2em;max-width:70em}\n"
                "table{border-collapse:collapse}td,th{padding:.2em .6em;border-bottom:1px solid "
                "#ddd;text-align:left}\n.P{color:#1a7f37}.F{color:#c62828}"
                ".U,.NP{color:#8a6d00}\nrect{fill:#d62728}figure{margin:1em 0}"
                "figcaption{font-weight:bold}\npre{background:#f6f6f6;padding:.6em;"
                "white-space:pre-wrap}\n</style></head><body>\n<h1>pipetrace class: ");
    pt_sbuf_add_xml(sb, c->dir);
    pt_sbuf_add(sb, "</h1>\n<p>Against ");
    pt_sbuf_add_xml(sb, c->expected);
    pt_sbuf_addf(sb, "%s; %zu student%s.</p>\n", c->scene ? " (rendered)" : "", c->nrow,
                 c->nrow == 1 ? "" : "s");
    svg_chart(sb, &h[0], hist_title[0], "by-stage");
    svg_chart(sb, &h[1], hist_title[1], "by-mistake");
    pt_sbuf_add(sb, "<table id=\"students\">\n<tr><th>student</th><th>verdict</th><th>first "
                "wrong stage</th><th>mistake</th><th>vertices</th><th>pixels</th><th>image</th>"
                "</tr>\n");
    for (k = 0; k < c->nrow; k++) {
        const pt_class_row *r = &c->row[k];
        const char *vd = pt_class_verdict(r);
        vertices_of(r, v, sizeof v);
        pixels_of(r, p, sizeof p);
        image_of(r, im, sizeof im);
        pt_sbuf_addf(sb, "<tr class=\"student\"><td><a href=\"#diff-%zu\">", k + 1);
        pt_sbuf_add_xml(sb, r->name);
        pt_sbuf_addf(sb, "</a></td><td class=\"%c%s\">%s</td>", vd[0], vd[0] == 'N' ? "P" : "",
                     vd);
        if (r->why) {
            pt_sbuf_add(sb, "<td colspan=\"5\">");
            pt_sbuf_add_xml(sb, r->why);
            pt_sbuf_add(sb, "</td></tr>\n");
            continue;
        }
        pt_sbuf_add(sb, "<td>");
        pt_sbuf_add_xml(sb, stage_of(r));
        pt_sbuf_add(sb, "</td><td>");
        pt_sbuf_add_xml(sb, pt_class_mistake(r, m, sizeof m));
        if (sep_scene(r, &n))
            pt_sbuf_addf(sb, " (<a href=\"#scene-%zu\">a scene that tells them apart</a>)", k + 1);
        pt_sbuf_addf(sb, "</td><td>%s</td><td>%s</td><td>%s</td></tr>\n", v, p, im);
    }
    pt_sbuf_add(sb, "</table>\n");
    for (k = 0; k < c->nrow; k++) {
        const pt_class_row *r = &c->row[k];
        pt_sbuf_addf(sb, "<section id=\"diff-%zu\"><h2>", k + 1);
        pt_sbuf_add_xml(sb, r->name);
        pt_sbuf_add(sb, "</h2>\n<pre>");
        for (t = 0; t < 3; t++)
            if (r->text[t].len) pt_sbuf_add_xml(sb, r->text[t].s);
        if (!r->text[0].len && !r->text[1].len && r->why) pt_sbuf_add_xml(sb, r->why);
        pt_sbuf_add(sb, "</pre>\n");
        if ((sc = sep_scene(r, &n)) != NULL) {
            char *text = malloc(n + 1);
            if (!text) { sb->failed = 1; continue; }
            memcpy(text, sc, n);
            text[n] = '\0';
            pt_sbuf_addf(sb, "<h3 id=\"scene-%zu\">The separating scene</h3>\n<pre>", k + 1);
            pt_sbuf_add_xml(sb, text);
            pt_sbuf_add(sb, "</pre>\n");
            free(text);
        }
        pt_sbuf_add(sb, "</section>\n");
    }
    pt_sbuf_add(sb, "</body></html>\n");
}
