/*
** src/tools/cmd_stages.c -- pipetrace stages: the table of stages, as stages/ has it
** See LICENSE for copyright and license.
**
**   pipetrace stages [--camera classic|matrix]
**
** Prints every stage of both cameras from pt_stage_infos[] (stages/pt_stage.c),
** in the order a trace lists them: its name, the spaces it maps between, its
** values (name in text traces, key in JSON Lines and CSV), its formula and what
** it does.  The docs show this output, so they say what the code says.
*/
#include <stdio.h>
#include <string.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "core/pipetrace.h"

static const char usage[] =
"usage: pipetrace stages [--camera classic|matrix]\n"
"List the stages of both cameras (or of one): name, spaces, values, formula,\n"
"meaning.\n"
"Docs: docs/stages.md, docs/architecture.md\n";

/* "x_pp (x), y_pp (y)": the value names of info, with their JSON keys. */
static void put_values(const pt_stage_info *in)
{
    int k;

    for (k = 0; k < in->nreal + in->nint; k++)
        printf("%s%s (%s)", k ? ", " : "", in->coord[k], in->key[k]);
    printf(in->nreal ? ": reals\n" : ": integers\n");
}

/* Print in, a stage of camera ("classic", "matrix" or "both"), unless only
** the other camera's are wanted (want: NULL for all). */
static void put_stage(const char *camera, const pt_stage_info *in, const char *want)
{
    if (want && strcmp(camera, "both") != 0 && strcmp(camera, want) != 0) return;
    printf("%-12s %s -> %s  [%s]\n", in->name, in->from, in->to, camera);
    printf("  values   ");
    put_values(in);
    printf("  formula  %s\n", in->formula);
    printf("  does     %s\n", in->what);
}

int pt_cmd_stages(int argc, char **argv)
{
    const char *want = NULL;
    int k;

    for (k = 1; k < argc; k++) {
        if (!strcmp(argv[k], "--help") || !strcmp(argv[k], "-h")) {
            fputs(usage, stdout);
            return PT_EXIT_OK;
        }
        if (strcmp(argv[k], "--camera") != 0)
            return argv[k][0] == '-' ? pt_cli_unknown("stages", usage, argv[k])
                                     : pt_cli_usage("stages", "unknown argument '%s'", argv[k]);
        if (k + 1 >= argc || (strcmp(argv[k + 1], "classic") && strcmp(argv[k + 1], "matrix")))
            return pt_cli_usage("stages", "--camera takes classic or matrix");
        want = argv[++k];
    }
    for (k = 0; k < PT_NSTAGES_ALL; k++) {
        pt_stage st = pt_trace_order[k];
        int classic = 0, matrix = 0, j;

        for (j = 0; j < pt_classic_norder; j++) classic |= pt_classic_order[j] == st;
        for (j = 0; j < pt_matrix_norder; j++) matrix |= pt_matrix_order[j] == st;
        if (st == PT_STAGE_VIEWPORT) {          /* each camera has its own */
            put_stage("classic", &pt_stage_infos[st], want);
            put_stage("matrix", &pt_matrix_viewport_info, want);
            continue;
        }
        put_stage(classic && matrix ? "both" : classic ? "classic" : "matrix",
                  &pt_stage_infos[st], want);
    }
    return PT_EXIT_OK;              /* main() checks that standard output took it all */
}
