/*
** src/tools/export_java.c -- the Java program of pipetrace export java
** See LICENSE for copyright and license.
**
** A model's parts are written as its nested classes' calls; primitives in
** file order, points among the segments where the scene has them.  A string
** constant holds at most 65535 bytes of modified UTF-8: a longer name is
** joined at run time from pieces of PIECE characters (String.join).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tools/export_java.h"
#include "io/numfmt.h"

#define PIECE 8000               /* characters of a long name a string constant */

enum { PART_VERTICES, PART_COLORS, PART_SEGMENTS, PART_MATRICES };
const char *const pt_export_parts[PT_EXPORT_NPARTS] = {"Vertices", "Colors", "Segments",
                                                       "Matrices"};

/* x as a Java double literal that reads back to exactly x ("-0.0", "1.5",
** "1e+300", "5e-324"): the shortest round trip, with ".0" added where it would
** otherwise read as an int. */
static void put_double(FILE *f, double x)
{
    char buf[PT_NUMLEN];

    pt_fmt_shortest(buf, x);
    fprintf(f, "%s%s", buf, strpbrk(buf, ".e") ? "" : ".0");
}

/* The characters p[0..end) (whole UTF-8 characters) as a Java string literal:
** printable ASCII as it is (names hold no '"' or '\\'), everything else as
** \\uXXXX escapes of its UTF-16 code units. */
static void put_literal(FILE *f, const unsigned char *p, const unsigned char *end)
{
    fputc('"', f);
    while (p < end) {
        unsigned long c = *p;
        int more = c >= 0xf0 ? 3 : c >= 0xe0 ? 2 : c >= 0xc0 ? 1 : 0;

        if (more)                /* the scene parser checked the UTF-8 */
            c &= 0x3fu >> more;
        for (p++; more > 0 && p < end; more--, p++)
            c = (c << 6) | (*p & 0x3fu);
        if (c >= 0x20 && c < 0x7f)
            fputc((int)c, f);
        else if (c < 0x10000)
            fprintf(f, "\\u%04lx", c);
        else
            fprintf(f, "\\u%04lx\\u%04lx", 0xd800 + ((c - 0x10000) >> 10),
                    0xdc00 + ((c - 0x10000) & 0x3ff));
    }
    fputc('"', f);
}

/* name as a Java string: one literal when its modified UTF-8 (a class file's
** string constants: 1 to 3 bytes a UTF-16 unit, 6 for a character past
** U+FFFF, which UTF-8 writes in 4) fits in a constant's 65535 bytes, else
** String.join("", ...) of literals of PIECE characters (at most 6 * PIECE
** bytes each), which is no constant expression, so javac does not fold it. */
static void put_string(FILE *f, const char *name)
{
    const unsigned char *p = (const unsigned char *)name, *end = p + strlen(name), *q;
    size_t bytes = 0, k;

    for (q = p; q < end; q++)
        bytes += (*q & 0xc0) == 0x80 ? 0 : *q >= 0xf0 ? 6 : *q >= 0xe0 ? 3 : *q >= 0xc0 ? 2 : 1;
    if (bytes <= 65535) {
        put_literal(f, p, end);
        return;
    }
    fputs("String.join(\"\"", f);
    while (p < end) {
        for (q = p, k = 0; q < end && k < PIECE; k++)
            for (q++; q < end && (*q & 0xc0) == 0x80; q++)
                ;
        fputs(",\n         ", f);
        put_literal(f, p, q);
        p = q;
    }
    fputc(')', f);
}

/* a[0 .. n) as Java double literals, separated by commas. */
static void put_vec(FILE *f, const double *a, int n)
{
    int i;

    for (i = 0; i < n; i++) {
        fputs(i ? ", " : "", f);
        put_double(f, a[i]);
    }
}

/* c as a java.awt.Color: new Color(R, G, B) when each component is an int
** colour's (k/255f, which getRGBComponents gives back), else the float
** constructor with literals that read back to exactly the floats. */
static void put_color(FILE *f, pt_rgb c)
{
    const float v[3] = {c.r, c.g, c.b};
    int k[3], i, ints = 1;

    for (i = 0; i < 3; i++) {
        float x = v[i] * 255.0f + 0.5f;

        k[i] = x >= 0.0f && x < 256.0f ? (int)x : -1;
        ints = ints && k[i] >= 0 && (float)k[i] / 255.0f == v[i];
    }
    if (ints) {
        fprintf(f, "new Color(%d, %d, %d)", k[0], k[1], k[2]);
        return;
    }
    fputs("new Color(", f);
    for (i = 0; i < 3; i++)
        fprintf(f, "%s%.9gf", i ? ", " : "", (double)v[i]);
    fputc(')', f);
}

/* Matrix op as a Java expression of renderer 9's Matrix builders. */
static void put_matop(FILE *f, const pt_matop *op)
{
    int i;

    switch (op->kind) {
    case PT_MATOP_IDENTITY:
        fputs("Matrix.identity()", f);
        return;
    case PT_MATOP_TRANSLATE:
        fputs("Matrix.translate(", f);
        put_vec(f, op->a, 3);
        break;
    case PT_MATOP_SCALE:
        fputs("Matrix.scale(", f);
        put_vec(f, op->a, 3);
        break;
    case PT_MATOP_ROTATE:
        fputs("Matrix.rotate(", f);
        put_vec(f, op->a, 4);
        break;
    case PT_MATOP_ROWS:
        fputs("Matrix.buildFromRows(", f);
        for (i = 0; i < 4; i++) {
            fputs(i ? "),\n               new Vector(" : "new Vector(", f);
            put_vec(f, op->a + 4 * i, 4);
        }
        fputc(')', f);
        break;
    }
    fputc(')', f);
}

/* Primitive i of model m in file order, its segments with its points among
** them (a point after the `after` segments before it); *np counts the points
** written so far (so i - *np the segments). */
static void put_primitive(FILE *f, const pt_model *m, size_t i, size_t *np)
{
    size_t k = i - *np;

    if (*np >= m->npts || m->pts[*np].after > k) {
        const pt_segment *g = &m->seg[k];

        if (g->ca == g->a && g->cb == g->b)
            fprintf(f, "         m.addPrimitive(new LineSegment(%lu, %lu));\n",
                    (unsigned long)g->a, (unsigned long)g->b);
        else
            fprintf(f, "         m.addPrimitive(new LineSegment(%lu, %lu, %lu, %lu));\n",
                    (unsigned long)g->a, (unsigned long)g->b, (unsigned long)g->ca,
                    (unsigned long)g->cb);
    } else {
        const pt_point *q = &m->pts[(*np)++];

        if (q->radius == 0 && q->c == q->v)
            fprintf(f, "         m.addPrimitive(new Point(%lu));\n", (unsigned long)q->v);
        else if (q->radius == 0)
            fprintf(f, "         m.addPrimitive(new Point(%lu, %lu));\n",
                    (unsigned long)q->v, (unsigned long)q->c);
        else
            fprintf(f, "         { final Point q = new Point(%lu, %lu); q.radius = %d; "
                    "m.addPrimitive(q); }\n", (unsigned long)q->v, (unsigned long)q->c,
                    q->radius);
    }
}

/* Of model m, part kind's item i: a vertex, colour, primitive (np: see
** put_primitive) or matrix op. */
static void put_item(FILE *f, const pt_model *m, int kind, size_t i, size_t *np)
{
    static const char *const mul[] = {
        "         p.transform(p.getMatrix().times(", "         p.transform((",
        "         p.transform(("};
    double v[3];

    switch (kind) {
    case PART_VERTICES:
        v[0] = m->v[i].x, v[1] = m->v[i].y, v[2] = m->v[i].z;
        fputs("         m.addVertex(new Vertex(", f);
        put_vec(f, v, 3);
        fputs("));\n", f);
        break;
    case PART_COLORS:
        fputs("         m.addColor(", f);
        put_color(f, m->colors[i]);
        fputs(");\n", f);
        break;
    case PART_SEGMENTS:
        put_primitive(f, m, i, np);
        break;
    case PART_MATRICES:
        fputs(mul[m->ops[i].mul], f);
        put_matop(f, &m->ops[i]);
        fputs(m->ops[i].mul == PT_MATMUL_PRE ? ").times(p.getMatrix()));\n" : "));\n", f);
        break;
    }
}

/* (export_java.h) */
size_t pt_export_count(const pt_model *m, int kind, int renderer)
{
    return kind == PART_VERTICES ? m->nv : kind == PART_COLORS ? m->ncolors
         : kind == PART_SEGMENTS ? m->nseg + m->npts : renderer == 9 ? m->nops : 0;
}

/* The nested classes that fill model number k (mK, at position p): its
** vertices, colours, primitives and (renderer 9) matrix operations,
** PT_EXPORT_CHUNK calls a class (M{k}.add calls them). */
static void put_model_parts(FILE *f, const pt_model *m, size_t k, int renderer)
{
    static const char open[] = "   private static final class M%zu%s%zu\n   {\n"
                               "      static void into(final Model m, final Position p)\n"
                               "      {\n";
    static const char close[] = "      }\n   }\n\n";
    int kind;
    size_t i, n, np = 0;

    for (kind = 0; kind < PT_EXPORT_NPARTS; kind++) {
        n = pt_export_count(m, kind, renderer);
        for (i = 0; i < n; i++) {
            if (i % PT_EXPORT_CHUNK == 0) {
                fputs(i ? close : "", f);
                fprintf(f, open, k, pt_export_parts[kind], i / PT_EXPORT_CHUNK);
            }
            put_item(f, m, kind, i, &np);
        }
        if (n > 0)
            fputs(close, f);
    }
}

/* The Camera expression of scene s for its renderer. */
static void put_camera(FILE *f, const pt_scene *s)
{
    const double v[4] = {s->cam_l, s->cam_r, s->cam_b, s->cam_t};
    const double n0 = s->perspective ? -0.1 : 1.0;   /* the Camera's n without near */

    if (s->renderer == 4) {
        fprintf(f, "Camera.%s()", s->perspective ? "projPerspective" : "projOrtho");
        return;
    }
    fprintf(f, "Camera.%s(", s->perspective ? "projPerspective" : "projOrtho");
    put_vec(f, v, 4);
    fputc(')', f);
    if (memcmp(&s->cam_n, &n0, sizeof n0) != 0) {     /* changeNear(near): n = -near */
        fputs("\n                            .changeNear(", f);
        put_double(f, -s->cam_n);
        fputc(')', f);
    }
    if (s->renderer == 9 && (s->view.x != 0 || s->view.y != 0 || s->view.z != 0
                             || signbit(s->view.x) || signbit(s->view.y) || signbit(s->view.z))) {
        const double w[3] = {s->view.x, s->view.y, s->view.z};

        fputs("\n                            .translate(", f);
        put_vec(f, w, 3);
        fputc(')', f);
    }
}

/* M{k}: model k of scene s, its position, and their parts. */
static void put_model(FILE *f, const pt_scene *s, const pt_model *m, size_t k)
{
    int kind;
    size_t i;

    put_model_parts(f, m, k, s->renderer);
    fprintf(f, "   private static final class M%zu\n   {\n"
            "      static void add(final Scene scene)\n      {\n", k);
    fputs("         final Model m = new Model(", f);
    put_string(f, m->name);
    fputs(");\n         final Position p = new Position(m, ", f);
    put_string(f, m->position ? m->position : m->name);
    if (s->renderer != 9) {
        const double t[3] = {m->translate.x, m->translate.y, m->translate.z};

        fputs(", new Vector(", f);
        put_vec(f, t, 3);
        fputc(')', f);
    }
    fputs(");\n", f);
    for (kind = 0; kind < PT_EXPORT_NPARTS; kind++)
        for (i = 0; i * PT_EXPORT_CHUNK < pt_export_count(m, kind, s->renderer); i++)
            fprintf(f, "         M%zu%s%zu.into(m, p);\n", k, pt_export_parts[kind], i);
    if (m->ncolors == 0 && m->colors_given)
        fprintf(f, "         ModelShading.setColor(m, new Color(%d, %d, %d));\n",
                m->color[0], m->color[1], m->color[2]);
    if (m->hidden_position)
        fputs("         p.visible = false;\n", f);
    if (m->hidden_model)
        fputs("         m.visible = false;\n", f);
    fputs("         scene.addPosition(p);\n      }\n   }\n\n", f);
}

void pt_export_java(FILE *f, const pt_scene *s, const char *cls, size_t ncls,
                     const char *file, unsigned dbg)
{
    const char *jar = s->renderer == 4 ? "renderer_4.jar" : s->renderer == 7 ? "renderer_7.jar"
                                                                            : "renderer_9.jar";
    const unsigned char *bg = s->background, *vbg = s->vp_background;
    size_t k;
    const char *c;

    fprintf(f, "// %.*s.java -- written by pipetrace export java from ", (int)ncls, cls);
    for (c = s->path; *c; c++)   /* javac reads \u escapes even in comments */
        fputc(*c >= 0x20 && *c < 0x7f && *c != '\\' ? *c : '?', f);
    fputc('\n', f);
    fprintf(f, "// The scene built with the course's renderer %d API, rendered with its debug\n"
            "// log on (standard error); the image goes, as PPM, to the file named as the\n"
            "// first argument.  Build and run with the course's jar:\n", s->renderer);
    fprintf(f, "//   javac -cp %s %s\n", jar, file);
    fprintf(f, "//   java -cp %s:. %.*s [OUT.ppm]\n", jar, (int)ncls, cls);
    fputs("import java.awt.Color;\n"
          "import renderer.scene.*;\n"
          "import renderer.scene.primitives.LineSegment;\n"
          "import renderer.scene.primitives.Point;\n"
          "import renderer.scene.util.ModelShading;\n"
          "import renderer.framebuffer.FrameBuffer;\n"
          "import renderer.pipeline.Pipeline;\n", f);
    if (s->pipeline2)
        fputs("import renderer.pipeline.Pipeline2;\n", f);
    if (s->renderer != 4)
        fputs("import renderer.pipeline.NearClip;\n"
              "import renderer.pipeline.Clip;\n", f);
    fputs("import renderer.pipeline.Rasterize;\n\n", f);
    fprintf(f, "public class %.*s\n{\n", (int)ncls, cls);
    for (k = 0; k < s->nmodels; k++)
        put_model(f, s, &s->models[k], k + 1);
    fputs("   public static void main(String[] args)\n   {\n", f);
    fprintf(f, "      final FrameBuffer fb = new FrameBuffer(%d, %d, new Color(%d, %d, %d));\n",
            s->fb_w, s->fb_h, bg[0], bg[1], bg[2]);
    fprintf(f, "      fb.setViewport(%d, %d, %d, %d);\n", s->vp_x, s->vp_y, s->vp_w, s->vp_h);
    if (memcmp(bg, vbg, 3) != 0)
        fprintf(f, "      fb.vp.setBackgroundColorVP(new Color(%d, %d, %d));\n",
                vbg[0], vbg[1], vbg[2]);
    fputs("      fb.vp.clearVP();\n", f);
    fputs("      final Scene scene = new Scene(", f);
    put_string(f, s->scene_name ? s->scene_name : "");
    fputs(", ", f);
    put_camera(f, s);
    fputs(");\n", f);
    for (k = 0; k < s->nmodels; k++)
        fprintf(f, "      M%zu.add(scene);\n", k + 1);
    if (s->renderer != 4)
        fprintf(f, "      NearClip.doNearClipping = %s;\n", s->nearclip ? "true" : "false");
    fprintf(f, "      Rasterize.doAntiAliasing = %s;\n", s->antialias ? "true" : "false");
    fprintf(f, "      Rasterize.doGamma = %s;\n", s->gamma ? "true" : "false");
    fprintf(f, "      scene.debug = %s;\n", dbg & PT_JDBG_SCENE ? "true" : "false");
    if (dbg & PT_JDBG_POSITION)
        fputs("      for (final Position p : scene.positionList) p.debug = true;\n", f);
    fprintf(f, "      Rasterize.debug = %s;\n", dbg & PT_JDBG_RASTERIZE ? "true" : "false");
    if (s->renderer != 4)
        fprintf(f, "      Clip.debug = %s;\n      NearClip.debug = %s;\n",
                dbg & PT_JDBG_CLIP ? "true" : "false", dbg & PT_JDBG_NEARCLIP ? "true" : "false");
    fprintf(f, "      %s.render(scene, fb.vp);\n"
            "      if (args.length > 0)\n"
            "         fb.dumpFB2File(args[0]);\n"
            "   }\n"
            "}\n", s->pipeline2 ? "Pipeline2" : "Pipeline");
}
