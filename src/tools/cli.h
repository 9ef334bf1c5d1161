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

#include <stdio.h>
#include "core/pipetrace.h"

/* The exit statuses of every command: the one table. */
#define PT_EXIT_OK     0         /* done; for diff: the two agree */
#define PT_EXIT_DIFFER 1         /* diff: the two differ; quiz: an answer wrong */
#define PT_EXIT_USAGE  1         /* a usage error */
#define PT_EXIT_INPUT  2         /* bad input, or an output that cannot be written */
#define PT_EXIT_TROUBLE 2        /* diff: trouble, a usage error too (as diff(1)) */
#define PT_EXIT_UNPROVEN 3       /* diff --verdict: no difference, but not every
                                 ** stage or the pixels were compared */

#if defined(__GNUC__) || defined(__clang__)
#define PT_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define PT_PRINTF_LIKE(f, a)
#endif

/* The one usage-error path: print "pipetrace CMD: MESSAGE" and "Try 'pipetrace
** CMD --help'." to standard error (cmd NULL: the render command, "pipetrace:
** MESSAGE", "Try 'pipetrace --help'.") and return PT_EXIT_USAGE. */
int pt_cli_usage(const char *cmd, const char *fmt, ...) PT_PRINTF_LIKE(2, 3);

/* What every command ends with: flush standard output and return rc, the
** command's exit status; when something written to standard output was lost
** (`pipetrace stages > /dev/full`), print "pipetrace CMD: cannot write to
** standard output: REASON" (cmd NULL: the render command) and return
** PT_EXIT_INPUT; when rc is PT_EXIT_INPUT already the command has said what
** went wrong, and nothing more is printed. */
int pt_cli_stdout(const char *cmd, int rc);

/* Load the scene at path ("-": standard input, named "<stdin>" in messages
** and the trace), or the built-in scene when path is NULL.  Returns 0,
** or PT_EXIT_INPUT after printing the FILE:LINE:COL message. */
int pt_cli_load(pt_scene *s, const char *path);

/* For a command that knows only renderer 4's scenes: when s is a scene of
** the course's renderer 7 or 9, print "pipetrace CMD: FILE: error: ..."
** (what renders it instead), free s and return PT_EXIT_INPUT; else 0. */
int pt_cli_course(pt_scene *s, const char *cmd);

/* The same for a trace or log read whole (buf, len bytes): when it is the
** course's log of a renderer 7 or 9 scene or pipetrace's trace of one,
** print "pipetrace CMD: PATH: error: ..." and return PT_EXIT_INPUT; else 0. */
int pt_cli_course_text(const char *path, const char *buf, size_t len, const char *cmd);

/* Refuse outputs that would destroy an input or each other: out[k] (given
** as option opt[k]; NULL: not given) naming the scene file (a scene "-": the
** file standard input reads) or another output, as pt_outfile_same() tells.
** Prints "OUT: error: ..." and returns PT_EXIT_INPUT, else returns 0. */
int pt_cli_outputs(const char *scene, const char *const *out, const char *const *opt, int n);

/* The same, once the scene s is read, for the OBJ files it read (device and
** inode, links followed).  Prints "OUT: error: OPT names 'OBJ', an OBJ file
** the scene reads; ..." and returns PT_EXIT_INPUT, else returns 0. */
int pt_cli_outputs_objs(const pt_scene *s, const char *const *out, const char *const *opt,
                        int n);

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

/* A whole decimal number in [lo, hi] from text into *out.  Returns 0; -1
** (no message) when text is not digits only (signs, spaces); -2 when it is
** but the number is outside [lo, hi] (however many digits).  Can't fail. */
int pt_cli_count(const char *text, uint64_t lo, uint64_t hi, uint64_t *out);

/* The largest vertex number: indices are 32-bit (docs/limits.md). */
#define PT_MAX_VERTEX 4294967295u

/* The value of --vertex, 1 .. PT_MAX_VERTEX, into *out.  Returns 0, or
** PT_EXIT_USAGE after printing why not (out of range, or not a number, with
** the range) as pt_cli_usage() does for cmd. */
int pt_cli_vertex(const char *cmd, const char *val, uint64_t *out);

/* The word of text nearest to arg, into out (n bytes): when arg starts with
** '-', the options ("--name") text mentions, else its words of letters.
** Nearest by edit distance (a swap of two neighbours counts as one edit),
** the first of equals; only one within 2 edits, and fewer edits than arg has
** letters.  Returns 1, or 0 with out empty when none is that near.  This
** function can't fail. */
int pt_cli_nearest(const char *arg, const char *text, char *out, size_t n);

/* The unknown-option error: "pipetrace CMD: unknown option 'ARG'", with "(did
** you mean '--NAME'?)" when usage mentions a near one, and the "Try" line.
** Returns PT_EXIT_USAGE. */
int pt_cli_unknown(const char *cmd, const char *usage, const char *arg);

/* The stages a student build replaces, by the Makefile's names, separated by
** spaces ("pixel viewport"); "" in the reference build.  Written by the
** Makefile into $B/buildinfo.c (make STAGE_pixel=FILE.c: docs/teaching.md). */
extern const char pt_student_stages[];

/* The files of a student build, "NAME=FILE#CKSUM" a stage (FILE: its name
** without folders; CKSUM: cksum's CRC of the file, 8 hex digits), separated
** by spaces; "" in the reference build.  Every trace header carries it (the
** "student" line). */
extern const char pt_student_files[];

/* "student build: the viewport stage is yours (make STAGE_viewport=...)" (two
** stages: "the pixel and viewport stages are yours (make STAGE_pixel=...
** STAGE_viewport=...)") into buf of n bytes.  Returns 1, or 0 with buf empty in
** the reference build.  This function can't fail. */
int pt_cli_student_note(char *buf, size_t n);

/* ===== output wrapped to the terminal's width ===== */

/* The width to wrap at: COLUMNS when it holds a whole number >= 20, else the
** terminal's own width (ioctl TIOCGWINSZ) when standard output is a terminal,
** else 0: no wrapping (a file or a pipe gets the same bytes every run). */
int pt_cli_width(void);

/* Write line[0..n) (no newline in it) to f, broken at spaces into lines of at
** most width characters; never inside a word, so no number is split (a word
** longer than the room runs over), and not between "=" and what follows it.
** Continued lines start at the line's second column (where the text after a
** run of two or more spaces begins, as in "  here     x_pp = ..."), or 4 past
** its own indentation.  width 0: the line as it is.  This function can't fail. */
void pt_cli_wrap_line(FILE *f, const char *line, size_t n, int width);

/* A command's output, wrapped.  pt_cli_out_open() sets f to a memory stream
** when pt_cli_width() is not 0 (else to stdout); the command writes to f;
** pt_cli_out_flush() writes what came so far to standard output, each line
** wrapped (call it before reading input); pt_cli_out_close() flushes and
** ends.  Returns 0, or -1 when standard output could not be written. */
typedef struct pt_cli_out {
    FILE *f;                     /* where the command writes */
    int width;                   /* 0: f is stdout, nothing wrapped */
    char *buf;                   /* the memory stream's text; owned */
    size_t len;                  /*   and its length */
} pt_cli_out;

void pt_cli_out_open(pt_cli_out *o);
int pt_cli_out_flush(pt_cli_out *o);
int pt_cli_out_close(pt_cli_out *o);

/* Read one line of standard input into b (newline and a trailing CR dropped;
** the rest of a too long line is skipped).  echo: print it, so that a
** transcript driven through a pipe reads like a terminal session (step and
** quiz).  Returns 0, or -1 at end of input. */
int pt_cli_read_line(char *b, size_t n, int echo);

/* The same from the stream f (quiz --grade reads answer sheets). */
int pt_cli_read_line_from(FILE *f, char *b, size_t n, int echo);

#endif
