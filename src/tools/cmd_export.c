/*
** src/tools/cmd_export.c -- pipetrace export java: the scene as a client of the course's renderer
** See LICENSE for copyright and license.
**
**   pipetrace export java [SCENE] [-o FILE.java] [--pixels]
**
** Writes a self-contained Java program for the course's renderer 4 (the jar
** of the Java teaching renderer) that builds the same scene with its API --
** Scene and Camera, a Model for each model with its Vertex list (the very doubles of
** the scene, written so that they read back exactly), its LineSegments and
** its color (ModelShading.setColor: one color a vertex), a Position with the
** model's translation, a FrameBuffer with its background and Viewport --
** turns on the debug log (scene.debug; with --pixels Rasterize.debug too),
** renders, and writes the image as PPM to the file named on its command line.
** Its standard error is then renderer 4's log of the scene, which a student
** compares with their own renderer's.  The class is named after FILE
** (PipetraceScene on standard output).
**
** Java limits a method to 64 KiB of bytecode and a class to 65535 constants,
** so vertices and segments go, CHUNK at a time, into small nested classes of
** their own (each class file has its own constants), and each model is built
** by a nested class of its own (M1, M2, ...), which main calls: main grows by
** a call a model, each model's class by a call a chunk.  Past MAX_MODELS
** models or MAX_PARTS chunks in one model the program would not compile, and
** is refused.  A string constant holds at most 65535 bytes of modified UTF-8:
** a longer model name is joined at run time from pieces (String.join).
*/
#include <stdio.h>
#include <string.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "io/numfmt.h"
#include "io/outfile.h"
#include "core/pipetrace.h"

#define CHUNK 400                /* addVertex or addPrimitive calls a class */
#define MAX_MODELS 10000         /* main: 4 bytes of code, ~3 constants a model */
#define MAX_PARTS 8000           /* a model's class: ~4 bytes, ~4 constants a chunk */
#define PIECE 8000               /* characters of a long name a string constant */

static const char usage[] =
"usage: pipetrace export java [SCENE] [-o FILE.java] [--pixels]\n"
"Write a Java program for the course's renderer 4 that builds SCENE (default:\n"
"the built-in scene) with its API, renders it with the debug log on and writes\n"
"the image as PPM to the file named on its command line.  Its standard error\n"
"is renderer 4's log of the scene.\n"
"\n"
"  -o FILE.java   write FILE.java, class FILE (default: standard output,\n"
"                 class PipetraceScene)\n"
"  --pixels       also log every pixel (Rasterize.debug = true)\n"
"\n"
"Build and run it with the course's jar:\n"
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
    "String", "Object", "System",
};

/* Is name[0..n) a class the program makes itself: MK, MKVerticesI or
** MKSegmentsI (K, I digits)?  The outer class may not share its name. */
static int generated(const char *name, size_t n)
{
    size_t i = 1, d;

    if (n < 2 || name[0] != 'M')
        return 0;
    for (d = i; i < n && name[i] >= '0' && name[i] <= '9'; i++)
        ;
    if (i == d)
        return 0;
    if (i == n)
        return 1;                               /* MK */
    if (n - i > 8 && memcmp(name + i, "Vertices", 8) == 0)
        i += 8;
    else if (n - i > 8 && memcmp(name + i, "Segments", 8) == 0)
        i += 8;
    else
        return 0;
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

/* The nested classes that fill model number k (mK): its vertices and its
** segments, CHUNK calls a class (main calls them in put_java()). */
static void put_model_parts(FILE *f, const pt_model *m, size_t k)
{
    static const char open[] = "   private static final class M%zu%s%zu\n   {\n"
                               "      static void into(final Model m)\n      {\n";
    static const char close[] = "      }\n   }\n\n";
    size_t i;

    for (i = 0; i < m->nv; i++) {
        if (i % CHUNK == 0) {
            fputs(i ? close : "", f);
            fprintf(f, open, k, "Vertices", i / CHUNK);
        }
        fputs("         m.addVertex(new Vertex(", f);
        put_double(f, m->v[i].x);
        fputs(", ", f);
        put_double(f, m->v[i].y);
        fputs(", ", f);
        put_double(f, m->v[i].z);
        fputs("));\n", f);
    }
    if (m->nv > 0)
        fputs(close, f);
    for (i = 0; i < m->nseg; i++) {
        if (i % CHUNK == 0) {
            fputs(i ? close : "", f);
            fprintf(f, open, k, "Segments", i / CHUNK);
        }
        fprintf(f, "         m.addPrimitive(new LineSegment(%lu, %lu));\n",
                (unsigned long)m->seg[i].a, (unsigned long)m->seg[i].b);
    }
    if (m->nseg > 0)
        fputs(close, f);
}

/* The program. */
static void put_java(FILE *f, const pt_scene *s, const char *cls, size_t ncls,
                     const char *file, int pixels)
{
    size_t k, i;
    const char *c;

    fprintf(f, "// %.*s.java -- written by pipetrace export java from ", (int)ncls, cls);
    for (c = s->path; *c; c++)   /* javac reads \u escapes even in comments */
        fputc(*c >= 0x20 && *c < 0x7f && *c != '\\' ? *c : '?', f);
    fputc('\n', f);
    fputs("// The scene built with the course's renderer 4 API, rendered with its debug\n"
          "// log on (standard error); the image goes, as PPM, to the file named as the\n"
          "// first argument.  Build and run with the course's jar:\n", f);
    fprintf(f, "//   javac -cp renderer_4.jar %s\n", file);
    fprintf(f, "//   java -cp renderer_4.jar:. %.*s [OUT.ppm]\n", (int)ncls, cls);
    fputs("import java.awt.Color;\n"
          "import renderer.scene.*;\n"
          "import renderer.scene.primitives.LineSegment;\n"
          "import renderer.scene.util.ModelShading;\n"
          "import renderer.framebuffer.FrameBuffer;\n"
          "import renderer.pipeline.Pipeline;\n"
          "import renderer.pipeline.Rasterize;\n\n", f);
    fprintf(f, "public class %.*s\n{\n", (int)ncls, cls);
    for (k = 0; k < s->nmodels; k++) {
        const pt_model *m = &s->models[k];

        put_model_parts(f, m, k + 1);
        fprintf(f, "   private static final class M%zu\n   {\n"
                "      static void add(final Scene scene)\n      {\n", k + 1);
        fputs("         final Model m = new Model(", f);
        put_string(f, m->name);
        fputs(");\n", f);
        for (i = 0; i < (m->nv + CHUNK - 1) / CHUNK; i++)
            fprintf(f, "         M%zuVertices%zu.into(m);\n", k + 1, i);
        for (i = 0; i < (m->nseg + CHUNK - 1) / CHUNK; i++)
            fprintf(f, "         M%zuSegments%zu.into(m);\n", k + 1, i);
        fprintf(f, "         ModelShading.setColor(m, new Color(%d, %d, %d));\n",
                m->color[0], m->color[1], m->color[2]);
        fputs("         scene.addPosition(new Position(m, ", f);
        put_string(f, m->name);
        fputs(", new Vector(", f);
        put_double(f, m->translate.x);
        fputs(", ", f);
        put_double(f, m->translate.y);
        fputs(", ", f);
        put_double(f, m->translate.z);
        fputs(")));\n      }\n   }\n\n", f);
    }
    fputs("   public static void main(String[] args)\n   {\n", f);
    fprintf(f, "      final Scene scene = new Scene(\"\", Camera.%s());\n",
            s->perspective ? "projPerspective" : "projOrtho");
    fputs("      scene.debug = true;\n", f);
    fprintf(f, "      Rasterize.debug = %s;\n\n", pixels ? "true" : "false");
    for (k = 0; k < s->nmodels; k++)
        fprintf(f, "      M%zu.add(scene);\n", k + 1);
    if (s->nmodels > 0)
        fputs("\n", f);
    fprintf(f, "      final FrameBuffer fb = new FrameBuffer(%d, %d, new Color(%d, %d, %d));\n",
            s->fb_w, s->fb_h, s->background[0], s->background[1], s->background[2]);
    fprintf(f, "      fb.setViewport(%d, %d, %d, %d);\n", s->vp_x, s->vp_y, s->vp_w, s->vp_h);
    fputs("      Pipeline.render(scene, fb.vp);\n"
          "      if (args.length > 0)\n"
          "         fb.dumpFB2File(args[0]);\n"
          "   }\n"
          "}\n", f);
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

        if ((m->nv + CHUNK - 1) / CHUNK + (m->nseg + CHUNK - 1) / CHUNK > MAX_PARTS) {
            fprintf(stderr, "pipetrace export: model %zu of %s has %zu vertices and %zu "
                    "segments; a Java program takes at most %d of both together in one "
                    "model (docs/limits.md)\n", k + 1, s->path, m->nv, m->nseg,
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

    if (out == NULL)
        return 0;
    outs[0] = out;
    if (pt_cli_outputs(path, outs, opt, 1) != 0 || pt_cli_outputs_objs(s, outs, opt, 1) != 0)
        return PT_EXIT_INPUT;
    return 0;
}

int pt_cmd_export(int argc, char **argv)
{
    const char *path = NULL, *out = NULL, *cls = "PipetraceScene";
    size_t ncls = 14;
    int k, pixels = 0, rc;
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
            pixels = 1;
        else if (!strcmp(argv[k], "-o")) {
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
    if (pt_cli_course(&s, "export")) return PT_EXIT_INPUT;
    if (pt_scene_pipeline(&s) != &pt_pipe_classic) {
        fprintf(stderr, "pipetrace export: %s uses the %s (camera %s), "
                "which renderer 4 does not have\n", s.path, pt_scene_pipeline(&s)->title,
                pt_scene_camera_word(&s));
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
    put_java(o.f, &s, cls, ncls, out ? cls : "PipetraceScene.java", pixels);
    rc = pt_outfile_finish(&o, ferror(o.f), "pipetrace export") == 0 ? PT_EXIT_OK
                                                                      : PT_EXIT_INPUT;
    pt_scene_free(&s);
    return rc;
}
