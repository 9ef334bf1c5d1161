/*
** src/tools/stage_names.c -- print the names of the stages a student may replace
** See LICENSE for copyright and license.
**
** A build helper, not part of pipetrace: the Makefile's student block compiles
** it with stages/pt_stage.c alone and runs it to learn which STAGE_NAME
** variables exist, so the names live in one place, pt_stage_infos[].  It
** prints the classic camera's stages after the model stage, in pipeline order,
** one a line: the k-th is the one stages/sK_*.c computes.
*/
#include <stdio.h>
#include "core/pipetrace.h"

int main(void)
{
    int k;

    for (k = 1; k < pt_classic_norder; k++)
        printf("%s\n", pt_stage_infos[pt_classic_order[k]].name);
    return fflush(stdout) != 0;
}
