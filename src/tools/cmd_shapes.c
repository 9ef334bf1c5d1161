/*
** src/tools/cmd_shapes.c -- pipetrace shapes: the course's models a scene can name
** See LICENSE for copyright and license.
**
**   pipetrace shapes [NAME]
**
** Prints every shape of pt_shapes[] (src/core/shapes.c), or the one called
** NAME: the line to write in a scene, the Java constructor it follows, how
** many arguments it takes, the defaults of the shorter overloads and what it
** builds.  docs/scene-format.md shows this output.
*/
#include <stdio.h>
#include <string.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "core/pipetrace.h"

static const char usage[] =
"usage: pipetrace shapes [NAME]\n"
"List the shapes a scene's 'shape NAME ARGS...' line builds (the course's\n"
"models, renderer.models_L): parameters, defaults, Java constructor.\n"
"Docs: docs/scene-format.md\n";

/* Print text indented by two spaces, wrapped at spaces to lines of at most
** 78 characters (a longer word stands alone on its line). */
static void put_wrapped(const char *text)
{
    const char *p = text;

    while (*p != '\0') {
        size_t n = strlen(p), cut = n;

        if (n > 76) {
            for (cut = 76; cut > 0 && p[cut] != ' '; cut--)
                ;
            if (cut == 0)
                cut = strcspn(p, " ");
        }
        printf("  %.*s\n", (int)cut, p);
        p += cut;
        while (*p == ' ')
            p++;
    }
}

/* Print one shape: its line in a scene, the Java constructor with its
** overloads and defaults, and what it builds. */
static void put_shape(const pt_shape_info *in)
{
    char counts[64];
    int k;

    printf("shape %s", in->name);
    for (k = 0; k < in->nparam; k++)
        printf(" %s", in->param[k]);
    printf("\n  %s(", in->java);
    for (k = 0; k < in->nparam; k++)
        printf("%s%s %s", k ? ", " : "", in->kind[k] == 'i' ? "int" : "double", in->param[k]);
    pt_shape_counts(in->arities, counts, sizeof counts);
    if (in->nparam == 0)
        printf(")\n  takes no arguments\n");
    else {
        printf(")\n  takes %s arguments; by default", counts);
        for (k = 0; k < in->nparam; k++)
            printf(" %s=%s", in->param[k], in->dflt[k]);
        printf("\n");
    }
    put_wrapped(in->what);
}

int pt_cmd_shapes(int argc, char **argv)
{
    const pt_shape_info *one = NULL;
    int k;

    for (k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) {
            fputs(usage, stdout);
            return PT_EXIT_OK;
        }
        if (one != NULL || argv[k][0] == '-')
            return pt_cli_usage("shapes", "unknown argument '%s'", argv[k]);
        one = pt_shape_find(argv[k], strlen(argv[k]));
        if (one == NULL)
            return pt_cli_usage("shapes", "no shape called '%s'", argv[k]);
    }
    for (k = 0; k < pt_nshapes; k++)
        if (one == NULL || one == &pt_shapes[k])
            put_shape(&pt_shapes[k]);
    return PT_EXIT_OK;              /* main() checks that standard output took it all */
}
