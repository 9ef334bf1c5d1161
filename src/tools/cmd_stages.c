/*
** src/tools/cmd_stages.c -- pipetrace stages: the table of stages, as stages/ has it
** See LICENSE for copyright and license.
**
**   pipetrace stages
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
"usage: pipetrace stages\n"
"List the stages of both cameras: name, spaces, values, formula, meaning.\n";

/* "x_pp (x), y_pp (y)": the value names of info, with their JSON keys. */
static void put_values(const pt_stage_info *in)
{
    int k;

    for (k = 0; k < in->nreal + in->nint; k++)
        printf("%s%s (%s)", k ? ", " : "", in->coord[k], in->key[k]);
    printf(in->nreal ? ": reals\n" : ": integers\n");
}

static void put_stage(const char *camera, const pt_stage_info *in)
{
    printf("%-12s %s -> %s  [%s]\n", in->name, in->from, in->to, camera);
    printf("  values   ");
    put_values(in);
    printf("  formula  %s\n", in->formula);
    printf("  does     %s\n", in->what);
}

int pt_cmd_stages(int argc, char **argv)
{
    int k;

    if (argc > 1) {
        if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
            fputs(usage, stdout);
            return PT_EXIT_OK;
        }
        return pt_cli_usage("stages", "takes no arguments ('%s')", argv[1]);
    }
    for (k = 0; k < PT_NSTAGES_ALL; k++) {
        pt_stage st = pt_trace_order[k];
        int classic = 0, matrix = 0, j;

        for (j = 0; j < pt_classic_norder; j++) classic |= pt_classic_order[j] == st;
        for (j = 0; j < pt_matrix_norder; j++) matrix |= pt_matrix_order[j] == st;
        if (st == PT_STAGE_VIEWPORT) {          /* each camera has its own */
            put_stage("classic", &pt_stage_infos[st]);
            put_stage("matrix", &pt_matrix_viewport_info);
            continue;
        }
        put_stage(classic && matrix ? "both" : classic ? "classic" : "matrix",
                  &pt_stage_infos[st]);
    }
    return fflush(stdout) == 0 && !ferror(stdout) ? PT_EXIT_OK : PT_EXIT_INPUT;
}
