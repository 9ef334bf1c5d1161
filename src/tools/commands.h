/*
** src/tools/commands.h -- the subcommands of pipetrace besides rendering
** See LICENSE for copyright and license.
**
** Each takes the arguments after its name (argv[0] is the subcommand's name)
** and returns the exit status: 0 success, 1 usage error or "differs"
** (diff), 2 bad input.  Each lives in src/tools/cmd_NAME.c or in a folder
** src/tools/NAME/.
*/
#ifndef PT_COMMANDS_H
#define PT_COMMANDS_H

int pt_cmd_diff(int argc, char **argv);   /* compare two traces or two images */
int pt_cmd_step(int argc, char **argv);   /* one vertex, one stage at a time */
int pt_cmd_why(int argc, char **argv);    /* which segments lit a pixel, or why not */
int pt_cmd_quiz(int argc, char **argv);   /* ask a vertex's values stage by stage */
int pt_cmd_accuracy(int argc, char **argv);  /* error against run time, per arithmetic */
int pt_cmd_journey(int argc, char **argv);   /* draw one vertex's journey: SVG, HTML */
int pt_cmd_stages(int argc, char **argv);    /* the table of stages */
int pt_cmd_shapes(int argc, char **argv);    /* the course's models for `shape` */
int pt_cmd_export(int argc, char **argv);    /* the scene as a Java client of renderer 4 */
int pt_cmd_class(int argc, char **argv);     /* a folder of students against EXPECTED */

#endif
