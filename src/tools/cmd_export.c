/*
** src/tools/cmd_export.c -- pipetrace export java: the scene as a client of the course's renderer
** See LICENSE for copyright and license.
**
**   pipetrace export java [SCENE] [-o FILE.java] [--pixels] [--debug LIST]
**
** Writes a self-contained Java program for the scene's course renderer (4, 7
** or 9: the jar of the Java teaching renderer) that builds the same scene
** with its API, as the course's harness does -- a FrameBuffer with its
** background, Viewport and viewport background; the Scene with its name and
** Camera (renderer 4: projPerspective() or projOrtho(); 7 and 9: the view
** rectangle, changeNear, renderer 9's translate); for each model a Model with
** its Vertex list (the very doubles of the scene, written so that they read
** back exactly), its colour list (int or float java.awt.Colors; `color`:
** ModelShading.setColor, one a vertex), its LineSegments and Points in file
** order, and a Position (renderers 4, 7: its translation Vector; 9: its
** Matrix, built by the scene's operations in order) with the visible flags
** -- sets the renderer's switches (near clipping, anti-aliasing, gamma) and
** the debug flags asked for (scene.debug by default; --pixels adds
** Rasterize.debug), renders with Pipeline or Pipeline2, and writes the image
** as PPM to the file named on its command line.  Its standard error is then
** the course renderer's log of the scene.  The class is named after FILE
** (PipetraceScene on standard output).
**
** Java limits a method to 64 KiB of bytecode and a class to 65535 constants,
** so vertices, colours, primitives and matrix operations go, CHUNK at a time,
** into small nested classes of their own (each class file has its own
** constants), and each model is built by a nested class of its own (M1, M2,
** ...), which main calls: main grows by a call a model, each model's class by
** a call a chunk.  Past MAX_MODELS models or MAX_PARTS chunks in one model
** the program would not compile, and is refused.  A string constant holds at
** most 65535 bytes of modified UTF-8: a longer name is joined at run time
** from pieces (String.join).
*/
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "io/numfmt.h"
#include "io/outfile.h"
#include "core/pipetrace.h"

#define CHUNK 400                /* addVertex, addColor, ... calls a class */
#define MAX_MODELS 10000         /* main: 4 bytes of code, ~3 constants a model */
#define MAX_PARTS 8000           /* a model's class: ~4 bytes, ~4 constants a chunk */
#define PIECE 8000               /* characters of a long name a string constant */

/* A model's parts, each in classes MKPartI of CHUNK calls. */
enum { PART_VERTICES, PART_COLORS, PART_SEGMENTS, PART_MATRICES, NPARTS };
static const char *const part_names[NPARTS] = {"Vertices", "Colors", "Segments", "Matrices"};

/* The course's debug flags (--debug; the harness's names, below). */
#define DBG_SCENE     0x01u      /* scene.debug */
#define DBG_POSITION  0x02u      /* every Position.debug */
#define DBG_RASTERIZE 0x04u      /* Rasterize.debug */
#define DBG_CLIP      0x08u      /* Clip.debug (renderers 7, 9) */
#define DBG_NEARCLIP  0x10u      /* NearClip.debug (renderers 7, 9) */

static const char usage[] =
"usage: pipetrace export java [SCENE] [-o FILE.java] [--pixels] [--debug LIST]\n"
"Write a Java program for the scene's course renderer (4, 7 or 9) that builds\n"
"SCENE (default: the built-in scene) with its API, renders it with the debug\n"
"log on and writes the image as PPM to the file named on its command line.\n"
"Its standard error is the course renderer's log of the scene.\n"
"\n"
"  -o FILE.java   write FILE.java, class FILE (default: standard output,\n"
"                 class PipetraceScene)\n"
"  --pixels       also log every pixel (Rasterize.debug = true)\n"
"  --debug LIST   the debug flags to set, a comma-separated list of scene,\n"
"                 position, rasterize, clip, nearclip; all; none (default scene)\n"
"\n"
"Build and run it with the course's jar (renderer_7.jar, renderer_9.jar):\n"
"  javac -cp renderer_4.jar FILE.java && java -cp renderer_4.jar:. FILE [OUT.ppm]\n"
"Exit status: 0 success, 1 usage error, 2 bad input or output error.\n"
"Docs: docs/java.md\n";

/* Names a class of the program may not have: Java's reserved words, and the
** classes it uses (the class would hide them). */
static const char *const taken[] = {
    "abstract", "assert", "boolean", "break", "byte", "case", "catch", "char",
    "class", "const", "continue", "default", "do", "double", "else", "enum",
    "extends", "final", "finally", "float", "for", "goto", "if", "implements",
    "import", "instanceof", "int", "interface", "long", "native", "new",
    "package", "private", "protected", "public", "return", "short", "static",
    "strictfp", "super", "switch", "synchronized", "this", "throw", "throws",
    "transient", "try", "void", "volatile", "while", "true", "false", "null",
    "_", "var", "yield", "record", "sealed", "permits",
    "Color", "Scene", "Camera", "Model", "Vertex", "Vector", "Position",
    "LineSegment", "ModelShading", "FrameBuffer", "Pipeline", "Rasterize",
    "String", "Object", "System", "Point", "Matrix", "Pipeline2", "NearClip", "Clip",
};

/* Is name[0..n) a class the program makes itself: MK or MKPartI (K, I
** digits, Part one of part_names[])?  The outer class may not share its name. */
static int generated(const char *name, size_t n)
{
    size_t i = 1, d, p, len;

    if (n < 2 || name[0] != 'M')
        return 0;
    for (d = i; i < n && name[i] >= '0' && name[i] <= '9'; i++)
        ;
    if (i == d)
        return 0;
    if (i == n)
        return 1;                               /* MK */
    for (p = 0; p < NPARTS; p++) {
        len = strlen(part_names[p]);
        if (n - i > len && memcmp(name + i, part_names[p], len) == 0)
            break;
    }
    if (p == NPARTS)
        return 0;
    i += len;
    for (d = i; i < n && name[i] >= '0' && name[i] <= '9'; i++)
        ;
    return i > d && i == n;
}

/* The class name for path: its base name without ".java", when that is a Java
** identifier (ASCII letters, digits, '_' and '$', not starting with a digit)
** that is not taken.  Returns its length (name starts at *name), or 0. */
static size_t class_name(const char *path, const char **name)
{
    const char *base = strrchr(path, '/');
    size_t n, i;

    base = base ? base + 1 : path;
    n = strlen(base);
    if (n <= 5 || strcmp(base + n - 5, ".java") != 0)
        return 0;
    n -= 5;
    for (i = 0; i < n; i++) {
        char c = base[i];
        int letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '$';

        if (!letter && !(i > 0 && c >= '0' && c <= '9'))
            return 0;
    }
    for (i = 0; i < sizeof taken / sizeof taken[0]; i++)
        if (strlen(taken[i]) == n && memcmp(taken[i], base, n) == 0)
            return 0;
    if (generated(base, n))
        return 0;
    *name = base;
    return n;
}

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

/* The debug switches of the program (--debug): which of the course's flags
** it sets, as the course's harness names them. */
static const struct { const char *name; unsigned bit; } switches[] = {
    {"scene", DBG_SCENE}, {"position", DBG_POSITION}, {"rasterize", DBG_RASTERIZE},
    {"clip", DBG_CLIP}, {"nearclip", DBG_NEARCLIP},
};

static void put_vec(FILE *f, const char *sep, const double *a, int n)
{
    int i;

    for (i = 0; i < n; i++) {
        fputs(i ? ", " : sep, f);
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
        put_vec(f, "", op->a, 3);
        break;
    case PT_MATOP_SCALE:
        fputs("Matrix.scale(", f);
        put_vec(f, "", op->a, 3);
        break;
    case PT_MATOP_ROTATE:
        fputs("Matrix.rotate(", f);
        put_vec(f, "", op->a, 4);
        break;
    case PT_MATOP_ROWS:
        fputs("Matrix.buildFromRows(", f);
        for (i = 0; i < 4; i++) {
            fputs(i ? "),\n               new Vector(" : "new Vector(", f);
            put_vec(f, "", op->a + 4 * i, 4);
        }
        fputc(')', f);
        break;
    }
    fputc(')', f);
}

/* Primitive i of model m in file order (its segments with its points among
** them, each point after the `after` segments before it): 0 a segment, 1 a
** point, with its index in *k. */
static int primitive(const pt_model *m, size_t i, size_t *k)
{
    size_t p = 0;

    /* points before i: those whose after + their rank <= i */
    while (p < m->npts && m->pts[p].after + p < i)
        p++;
    if (p < m->npts && m->pts[p].after + p == i) {
        *k = p;
        return 1;
    }
    *k = i - p;
    return 0;
}

static void put_primitive(FILE *f, const pt_model *m, size_t i)
{
    size_t k;

    if (!primitive(m, i, &k)) {
        const pt_segment *g = &m->seg[k];

        if (g->ca == g->a && g->cb == g->b)
            fprintf(f, "         m.addPrimitive(new LineSegment(%lu, %lu));\n",
                    (unsigned long)g->a, (unsigned long)g->b);
        else
            fprintf(f, "         m.addPrimitive(new LineSegment(%lu, %lu, %lu, %lu));\n",
                    (unsigned long)g->a, (unsigned long)g->b, (unsigned long)g->ca,
                    (unsigned long)g->cb);
    } else {
        const pt_point *q = &m->pts[k];

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

/* Of model m, part kind's item i: a vertex, colour, primitive or matrix op. */
static void put_item(FILE *f, const pt_model *m, int kind, size_t i)
{
    static const char *const mul[] = {
        "         p.transform(p.getMatrix().times(", "         p.transform((",
        "         p.transform(("};
    double v[3];

    switch (kind) {
    case PART_VERTICES:
        v[0] = m->v[i].x, v[1] = m->v[i].y, v[2] = m->v[i].z;
        fputs("         m.addVertex(new Vertex(", f);
        put_vec(f, "", v, 3);
        fputs("));\n", f);
        break;
    case PART_COLORS:
        fputs("         m.addColor(", f);
        put_color(f, m->colors[i]);
        fputs(");\n", f);
        break;
    case PART_SEGMENTS:
        put_primitive(f, m, i);
        break;
    case PART_MATRICES:
        fputs(mul[m->ops[i].mul], f);
        put_matop(f, &m->ops[i]);
        fputs(m->ops[i].mul == PT_MATMUL_PRE ? ").times(p.getMatrix()));\n" : "));\n", f);
        break;
    }
}

/* How many items of part kind model m has. */
static size_t part_count(const pt_model *m, int kind, int renderer)
{
    return kind == PART_VERTICES ? m->nv : kind == PART_COLORS ? m->ncolors
         : kind == PART_SEGMENTS ? m->nseg + m->npts : renderer == 9 ? m->nops : 0;
}

/* The nested classes that fill model number k (mK, at position p): its
** vertices, colours, primitives and (renderer 9) matrix operations, CHUNK
** calls a class (M{k}.add calls them). */
static void put_model_parts(FILE *f, const pt_model *m, size_t k, int renderer)
{
    static const char open[] = "   private static final class M%zu%s%zu\n   {\n"
                               "      static void into(final Model m, final Position p)\n"
                               "      {\n";
    static const char close[] = "      }\n   }\n\n";
    int kind;
    size_t i, n;

    for (kind = 0; kind < NPARTS; kind++) {
        n = part_count(m, kind, renderer);
        for (i = 0; i < n; i++) {
            if (i % CHUNK == 0) {
                fputs(i ? close : "", f);
                fprintf(f, open, k, part_names[kind], i / CHUNK);
            }
            put_item(f, m, kind, i);
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
    put_vec(f, "", v, 4);
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
        put_vec(f, "", w, 3);
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
        put_vec(f, "", t, 3);
        fputc(')', f);
    }
    fputs(");\n", f);
    for (kind = 0; kind < NPARTS; kind++)
        for (i = 0; i < (part_count(m, kind, s->renderer) + CHUNK - 1) / CHUNK; i++)
            fprintf(f, "         M%zu%s%zu.into(m, p);\n", k, part_names[kind], i);
    if (m->ncolors == 0 && m->colors_given)
        fprintf(f, "         ModelShading.setColor(m, new Color(%d, %d, %d));\n",
                m->color[0], m->color[1], m->color[2]);
    if (m->hidden_position)
        fputs("         p.visible = false;\n", f);
    if (m->hidden_model)
        fputs("         m.visible = false;\n", f);
    fputs("         scene.addPosition(p);\n      }\n   }\n\n", f);
}

/* The program. */
static void put_java(FILE *f, const pt_scene *s, const char *cls, size_t ncls,
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
    fprintf(f, "      scene.debug = %s;\n", dbg & DBG_SCENE ? "true" : "false");
    if (dbg & DBG_POSITION)
        fputs("      for (final Position p : scene.positionList) p.debug = true;\n", f);
    fprintf(f, "      Rasterize.debug = %s;\n", dbg & DBG_RASTERIZE ? "true" : "false");
    if (s->renderer != 4)
        fprintf(f, "      Clip.debug = %s;\n      NearClip.debug = %s;\n",
                dbg & DBG_CLIP ? "true" : "false", dbg & DBG_NEARCLIP ? "true" : "false");
    fprintf(f, "      %s.render(scene, fb.vp);\n"
            "      if (args.length > 0)\n"
            "         fb.dumpFB2File(args[0]);\n"
            "   }\n"
            "}\n", s->pipeline2 ? "Pipeline2" : "Pipeline");
}

/* The flags of --debug's list (replacing *dbg's): 0, or -1 when an item is
** no switch's name. */
static int debug_flags(const char *list, unsigned *dbg)
{
    unsigned bits = 0;
    size_t i, n;
    const char *p = list;

    for (;;) {
        n = strcspn(p, ",");
        if (n == 3 && !memcmp(p, "all", 3))
            bits |= DBG_SCENE | DBG_POSITION | DBG_RASTERIZE | DBG_CLIP | DBG_NEARCLIP;
        else if (!(n == 4 && !memcmp(p, "none", 4))) {
            for (i = 0; i < sizeof switches / sizeof switches[0]; i++)
                if (strlen(switches[i].name) == n && !memcmp(switches[i].name, p, n))
                    break;
            if (i == sizeof switches / sizeof switches[0])
                return -1;
            bits |= switches[i].bit;
        }
        if (p[n] == '\0')
            break;
        p += n + 1;
    }
    *dbg = bits;
    return 0;
}

/* Refuse a scene whose program javac would refuse: more than MAX_MODELS
** models, or a model of more than MAX_PARTS chunks.  Returns 0, or
** PT_EXIT_INPUT after saying which. */
static int too_large(const pt_scene *s)
{
    size_t k;

    if (s->nmodels > MAX_MODELS) {
        fprintf(stderr, "pipetrace export: %s has %zu models; a Java program of more than "
                "%d would not compile (docs/limits.md)\n", s->path, s->nmodels, MAX_MODELS);
        return PT_EXIT_INPUT;
    }
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];
        size_t parts = 0, items = 0, n;
        int kind;

        for (kind = 0; kind < NPARTS; kind++) {
            n = part_count(m, kind, s->renderer);
            parts += (n + CHUNK - 1) / CHUNK;
            items += n;
        }
        if (parts > MAX_PARTS) {
            fprintf(stderr, "pipetrace export: model %zu of %s has %zu vertices, colours, "
                    "primitives and matrix operations; a Java program takes at most %d of "
                    "them together in one model (docs/limits.md)\n", k + 1, s->path, items,
                    MAX_PARTS * CHUNK);
            return PT_EXIT_INPUT;
        }
    }
    return 0;
}

/* Refuse -o out when it is the scene (path; "-": what standard input reads)
** or an OBJ file the scene read, by device and inode.  Returns 0, or
** PT_EXIT_INPUT after saying which. */
static int over_input(const pt_scene *s, const char *path, const char *out)
{
    const char *opt[1] = {"-o"}, *outs[1];
    size_t k;

    if (out == NULL)
        return 0;
    outs[0] = out;
    if (pt_cli_outputs(path, outs, opt, 1) != 0)
        return PT_EXIT_INPUT;
    for (k = 0; k < s->nobjs; k++)
        if (pt_outfile_same(out, s->objs[k])) {
            fprintf(stderr, "%s: error: -o names '%s', an OBJ file the scene reads; "
                    "writing it would destroy it\n", out, s->objs[k]);
            return PT_EXIT_INPUT;
        }
    return 0;
}

int pt_cmd_export(int argc, char **argv)
{
    const char *path = NULL, *out = NULL, *cls = "PipetraceScene", *list = NULL;
    size_t ncls = 14;
    unsigned dbg = DBG_SCENE;
    int k, rc;
    char err[PT_ERRLEN];
    pt_outfile o;
    pt_scene s;

    if (argc > 1 && (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h"))) {
        fputs(usage, stdout);
        return PT_EXIT_OK;
    }
    if (argc < 2 || strcmp(argv[1], "java") != 0)
        return pt_cli_usage("export", "the first argument is the language: java%s", "");
    for (k = 2; k < argc; k++) {
        if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) {
            fputs(usage, stdout);
            return PT_EXIT_OK;
        } else if (!strcmp(argv[k], "--pixels"))
            dbg |= DBG_RASTERIZE;
        else if (!strcmp(argv[k], "--debug")) {
            if (pt_cli_value("export", argc, argv, &k, &list) != -1)
                return PT_EXIT_USAGE;
            if (debug_flags(list, &dbg) != 0)
                return pt_cli_usage("export", "--debug takes a comma-separated list of "
                                    "scene, position, rasterize, clip, nearclip, all or "
                                    "none, not '%s'", list);
        } else if (!strcmp(argv[k], "-o")) {
            if (pt_cli_value("export", argc, argv, &k, &out) != -1)
                return PT_EXIT_USAGE;
            ncls = class_name(out, &cls);
            if (ncls == 0)
                return pt_cli_usage("export", "-o takes FILE.java, FILE a Java class "
                                    "name (letters, digits, '_', '$'; not a reserved "
                                    "word nor a class the program uses), not '%s'", out);
        } else if (argv[k][0] == '-' && argv[k][1] != '\0')
            return pt_cli_usage("export", "unknown option '%s'", argv[k]);
        else if (path != NULL)
            return pt_cli_usage("export", "more than one scene ('%s')", argv[k]);
        else
            path = argv[k];
    }
    if (pt_cli_load(&s, path) != 0)
        return PT_EXIT_INPUT;
    if (s.pipe == PT_PIPE_MATRIX) {
        fprintf(stderr, "pipetrace export: %s uses the %s (camera %s), "
                "which the course's renderers do not have\n", s.path,
                pt_scene_pipeline(&s)->title, pt_scene_camera_word(&s));
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    if (s.pipeline2 && s.renderer == 7) {
        fprintf(stderr, "pipetrace export: %s asks for Pipeline2, which renderer 7 does "
                "not have\n", s.path);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    if ((rc = too_large(&s)) != 0 || (rc = over_input(&s, path, out)) != 0) {
        pt_scene_free(&s);
        return rc;
    }
    if (pt_outfile_open(&o, out ? out : "-", err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace export: %s\n", err);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    put_java(o.f, &s, cls, ncls, out ? cls : "PipetraceScene.java", dbg);
    rc = pt_outfile_finish(&o, ferror(o.f), "pipetrace export") == 0 ? PT_EXIT_OK
                                                                      : PT_EXIT_INPUT;
    pt_scene_free(&s);
    return rc;
}
