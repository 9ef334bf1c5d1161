/*
** src/tools/cli.h -- what every pipetrace command does with its arguments
** See LICENSE for copyright and license.
**
** Loading the scene named on the command line (or the built-in one), finding
** the model that has vertex N, reading a count.  These print their own
** diagnostics to standard error, prefixed "pipetrace CMD: ", and return the
** exit status to use; only main() and the cmd_*.c files call them.
*/
#ifndef PT_CLI_H
#define PT_CLI_H

#include "core/pipetrace.h"

/* The exit statuses of every command: the one table. */
#define PT_EXIT_OK     0         /* done; for diff: the two agree */
#define PT_EXIT_DIFFER 1         /* diff: the two differ */
#define PT_EXIT_USAGE  1         /* a usage error */
#define PT_EXIT_INPUT  2         /* bad input, or an output that cannot be written */
#define PT_EXIT_TROUBLE 2        /* diff: trouble, a usage error too (as diff(1)) */

#if defined(__GNUC__) || defined(__clang__)
#define PT_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PT_PRINTF_LIKE(f, a)
#endif

/* The one usage-error path: print "pipetrace CMD: MESSAGE" and "Try 'pipetrace
** CMD --help'." to standard error (cmd NULL: the render command, "pipetrace:
** MESSAGE", "Try 'pipetrace --help'.") and return PT_EXIT_USAGE. */
int pt_cli_usage(const char *cmd, const char *fmt, ...) PT_PRINTF_LIKE(2, 3);

/* Load the scene at path, or the built-in scene when path is NULL.  Returns 0,
** or PT_EXIT_INPUT after printing the FILE:LINE:COL message. */
int pt_cli_load(pt_scene *s, const char *path);

/* The model called name.  Prints "pipetrace CMD: --model NAME: ..." (cmd
** NULL: "pipetrace: --model ...") with the scene's model names and returns NULL
** when there is none. */
const pt_model *pt_cli_model(const pt_scene *s, const char *cmd, const char *name);

/* The model whose 1-based vertex v a command follows: the model called name,
** or (name NULL) the first model that has a vertex v.  Prints why and returns
** NULL when there is none; the message starts with the argument at fault
** ("--model NAME: ..." or "--vertex N: ...").  cmd names the command (NULL:
** the render command, "pipetrace: ..."). */
const pt_model *pt_cli_vertex_model(const pt_scene *s, const char *cmd,
                                    const char *name, uint64_t v);

/* The arguments the scene commands (step, quiz, journey, accuracy) share.
** Set cmd, usage and takes_vertex, and vertex to its default; pt_cli_arg()
** fills in the rest. */
typedef struct pt_cli_args {
    const char *cmd;             /* the command, for messages: "step", ... */
    const char *usage;           /* what --help prints */
    int takes_vertex;            /* 1: --vertex N and --model NAME are options */
    const char *path;            /* the SCENE argument, or NULL */
    const char *model;           /* --model NAME, or NULL */
    uint64_t vertex;             /* --vertex N (1 <= N < 2^32), or as set */
} pt_cli_args;

/* Read argv[*k], one argument that is none of the command's own options, as
** every scene command does: "--help" or "-h" (print a->usage), with
** takes_vertex "--vertex N" and "--model NAME" (*k moves past the value),
** any other "-..." (an unknown option), else the scene (only one).  Returns
** -1 when it took the argument, else what the command returns: 0 after
** --help, PT_EXIT_USAGE after printing the usage error. */
int pt_cli_arg(pt_cli_args *a, int argc, char **argv, int *k);

/* The value of the option argv[*k] into *val, *k moved to it.  Returns -1,
** or PT_EXIT_USAGE after printing "option needs a value" when it is last. */
int pt_cli_value(const char *cmd, int argc, char **argv, int *k, const char **val);

/* A whole decimal number in [lo, hi] from text into *out.  Returns 0, or -1
** (no message) for anything else: signs, spaces, overflow.  Can't fail. */
int pt_cli_count(const char *text, uint64_t lo, uint64_t hi, uint64_t *out);

/* The stages a student build replaces, by the Makefile's names, separated by
** spaces ("pixel viewport"); "" in the reference build.  Written by the
** Makefile into $B/buildinfo.c (make STAGE_pixel=FILE.c: docs/teaching.md). */
extern const char pt_student_stages[];

/* "student build: the viewport stage is yours (make STAGE_viewport=...)" (two
** stages: "the pixel and viewport stages are yours (make STAGE_pixel=...
** STAGE_viewport=...)") into buf of n bytes.  Returns 1, or 0 with buf empty in
** the reference build.  This function can't fail. */
int pt_cli_student_note(char *buf, size_t n);

/* Read one line of standard input into b (newline and a trailing CR dropped;
** the rest of a too long line is skipped).  echo: print it, so that a
** transcript driven through a pipe reads like a terminal session (step and
** quiz).  Returns 0, or -1 at end of input. */
int pt_cli_read_line(char *b, size_t n, int echo);

#endif
