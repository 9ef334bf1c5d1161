/*
** src/cmd_journey.c -- pipetrace journey: draw one vertex's way through the stages
** See LICENSE for copyright and license.
**
**   pipetrace journey [SCENE] --vertex N [--model NAME] [--svg FILE] [--html FILE]
**
** --svg writes one SVG picture with a panel per coordinate system; --html a
** self-contained page that shows one stage at a time with its formula and
** numbers, Prev/Next buttons and a choice of vertex (src/journey.h and
** src/journey_html.c draw them).  Files are written whole or not at all
** (src/outfile.h); "-" is standard output.  Only the classic camera is drawn:
** a scene with the matrix camera is refused with exit status 2.
*/
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "builtin.h"
#include "commands.h"
#include "journey.h"
#include "outfile.h"
#include "scene.h"

#define EXIT_USAGE 1
#define EXIT_INPUT 2

static const char usage[] =
"usage: pipetrace journey [SCENE] --vertex N [--model NAME] [--svg FILE] [--html FILE]\n"
"Draw vertex N (1-based) of model NAME (default: the first model that has a\n"
"vertex N) on its way from model coordinates to its element of the pixel\n"
"array, one panel per coordinate system.  SCENE defaults to the built-in scene.\n"
"\n"
"  --svg FILE     one SVG picture with all seven panels ('-': standard output)\n"
"  --html FILE    a self-contained page: one stage at a time with its formula\n"
"                 and numbers, Prev/Next buttons, every used vertex to choose\n"
"                 (at most 2000); it needs no network and no other file\n"
"\n"
"At least one of --svg and --html.  Only the classic camera (perspective or\n"
"orthographic) is drawn; a scene with the matrix camera exits with status 2.\n"
"Exit status: 0 success, 1 usage error, 2 bad input or output error.\n";

static int usage_error(const char *msg, const char *arg)
{
    fprintf(stderr, "pipetrace journey: %s%s\nTry 'pipetrace journey --help'.\n", msg, arg);
    return EXIT_USAGE;
}

/* Write the text in sb to path, whole or not at all.  Returns 0 or -1. */
static int write_file(const char *path, const pt_sbuf *sb)
{
    pt_outfile o = {NULL, NULL, NULL, NULL};
    char err[PT_ERRLEN];

    if (pt_outfile_open(&o, path, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace journey: %s\n", err);
        return -1;
    }
    if (fwrite(sb->s, 1, sb->len, o.f) != sb->len) {
        fprintf(stderr, "pipetrace journey: cannot write '%s'\n", path);
        pt_outfile_abort(&o);
        return -1;
    }
    if (pt_outfile_commit(&o, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace journey: %s\n", err);
        return -1;
    }
    return 0;
}

int pt_cmd_journey(int argc, char **argv)
{
    const char *path = NULL, *model = NULL, *svg = NULL, *html = NULL;
    unsigned long long v = 0;
    const pt_model *m = NULL;
    pt_scene s;
    pt_sbuf a, b;
    char err[PT_ERRLEN];
    size_t mi;
    int k, rc;

    for (k = 1; k < argc; k++) {
        const char *o = argv[k];

        if (!strcmp(o, "--help") || !strcmp(o, "-h")) { fputs(usage, stdout); return 0; }
        if (!strcmp(o, "--vertex") || !strcmp(o, "--model") || !strcmp(o, "--svg") ||
            !strcmp(o, "--html")) {
            const char *val;
            if (k + 1 >= argc) return usage_error("option needs a value: ", o);
            val = argv[++k];
            if (!strcmp(o, "--model")) model = val;
            else if (!strcmp(o, "--svg")) svg = val;
            else if (!strcmp(o, "--html")) html = val;
            else {
                char *end;
                errno = 0;
                v = strtoull(val, &end, 10);
                if (val[0] < '0' || val[0] > '9' || *end || errno || v < 1 || v > 4294967295ULL)
                    return usage_error("--vertex takes a vertex number >= 1, not ", val);
            }
        } else if (o[0] == '-' && o[1] != '\0') return usage_error("unknown option ", o);
        else if (path) return usage_error("more than one scene given: ", o);
        else path = o;
    }
    if (!v) return usage_error("--vertex N is required", "");
    if (!svg && !html) return usage_error("nothing to write: give --svg FILE or --html FILE", "");
    if (svg && html && !strcmp(svg, html)) return usage_error("--svg and --html name the same file: ", svg);

    rc = path ? pt_scene_load(&s, path, err, sizeof err)
              : pt_scene_parse(&s, "<builtin>", pt_builtin_scene,
                               strlen(pt_builtin_scene), err, sizeof err);
    if (rc != 0) { fprintf(stderr, "%s\n", err); return EXIT_INPUT; }
    if (s.matrix) {
        fprintf(stderr, "pipetrace journey: %s: the matrix camera (camera lookat) is not "
                "drawn; journey draws the classic camera's stages model -> camera -> image "
                "-> pixel -> viewport -> framebuffer -> index\n", s.path);
        pt_scene_free(&s);
        return EXIT_INPUT;
    }
    for (mi = 0; mi < s.nmodels && !m; mi++) {
        const pt_model *c = &s.models[mi];
        if (model ? !strcmp(model, c->name) : c->nv >= v) m = c;
    }
    if (!m || m->nv < v) {
        if (model && !m) fprintf(stderr, "pipetrace journey: %s has no model '%s'\n", s.path, model);
        else fprintf(stderr, "pipetrace journey: %s: no model%s%s has a vertex %llu\n", s.path,
                     model ? " " : "", model ? model : "", v);
        pt_scene_free(&s);
        return EXIT_INPUT;
    }

    pt_sbuf_init(&a);
    pt_sbuf_init(&b);
    rc = 0;
    if (svg && pt_journey_svg(&a, &s, m, v) != 0) rc = -1;
    if (!rc && html && pt_journey_html(&b, &s, m, v) != 0) rc = -1;
    if (rc) fputs("pipetrace journey: out of memory\n", stderr);
    /* both documents are complete before either file is touched */
    if (!rc && svg && write_file(svg, &a) != 0) rc = -1;
    if (!rc && html && write_file(html, &b) != 0) rc = -1;
    pt_sbuf_free(&a);
    pt_sbuf_free(&b);
    pt_scene_free(&s);
    return rc ? EXIT_INPUT : 0;
}
