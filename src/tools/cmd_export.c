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
** so vertices, colours, primitives and matrix operations go, a chunk at a
** time, into small nested classes of their own (each class file has its own
** constants), and each model is built by a nested class of its own (M1, M2,
** ...), which main calls: main grows by a call a model, each model's class by
** a call a chunk (src/tools/export_java.c writes them).  Past MAX_MODELS
** models or MAX_PARTS chunks in one model the program would not compile, and
** is refused.  A string constant holds at most 65535 bytes of modified
** UTF-8: a longer name is joined at run time from pieces (String.join).
*/
#include <stdio.h>
#include <string.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "io/outfile.h"
#include "core/pipetrace.h"
#include "tools/export_java.h"

#define MAX_MODELS 10000         /* main: 4 bytes of code, ~3 constants a model */
#define MAX_PARTS 8000           /* a model's class: ~4 bytes, ~4 constants a chunk */

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
** digits, Part one of pt_export_parts[])?  The outer class may not share its name. */
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
    for (p = 0; p < PT_EXPORT_NPARTS; p++) {
        len = strlen(pt_export_parts[p]);
        if (n - i > len && memcmp(name + i, pt_export_parts[p], len) == 0)
            break;
    }
    if (p == PT_EXPORT_NPARTS)
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

/* The debug switches of the program (--debug): which of the course's flags
** it sets, as the course's harness names them. */
static const struct { const char *name; unsigned bit; } switches[] = {
    {"scene", PT_JDBG_SCENE}, {"position", PT_JDBG_POSITION}, {"rasterize", PT_JDBG_RASTERIZE},
    {"clip", PT_JDBG_CLIP}, {"nearclip", PT_JDBG_NEARCLIP},
};

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
            bits |= PT_JDBG_SCENE | PT_JDBG_POSITION | PT_JDBG_RASTERIZE | PT_JDBG_CLIP
                  | PT_JDBG_NEARCLIP;
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

        for (kind = 0; kind < PT_EXPORT_NPARTS; kind++) {
            n = pt_export_count(m, kind, s->renderer);
            parts += (n + PT_EXPORT_CHUNK - 1) / PT_EXPORT_CHUNK;
            items += n;
        }
        if (parts > MAX_PARTS) {
            fprintf(stderr, "pipetrace export: model %zu of %s has %zu vertices, colours, "
                    "primitives and matrix operations; a Java program takes at most %d of "
                    "them together in one model (docs/limits.md)\n", k + 1, s->path, items,
                    MAX_PARTS * PT_EXPORT_CHUNK);
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
    const char *path = NULL, *out = NULL, *cls = "PipetraceScene", *list = NULL;
    size_t ncls = 14;
    unsigned dbg = PT_JDBG_SCENE;
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
            dbg |= PT_JDBG_RASTERIZE;
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
    pt_export_java(o.f, &s, cls, ncls, out ? cls : "PipetraceScene.java", dbg);
    rc = pt_outfile_finish(&o, ferror(o.f), "pipetrace export") == 0 ? PT_EXIT_OK
                                                                      : PT_EXIT_INPUT;
    pt_scene_free(&s);
    return rc;
}
