/*
** src/tools/main.c -- the pipetrace command: options, then parse -> plan -> run -> write
** See LICENSE for copyright and license.
**
** Exit status: 0 success, 1 usage error, 2 bad input or output error.  Only
** this file prints diagnostics or decides the exit status.
*/
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE          /* sbrk, madvise: heap_in_huge_pages() */
#define _GNU_SOURCE              /* sched_getaffinity: threads_wanted() */
#include <errno.h>
#include <signal.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#if defined(__linux__) && defined(__GLIBC__)
#include <malloc.h>
#include <sched.h>
#include <sys/mman.h>
#endif
#include "tools/cli.h"
#include "tools/commands.h"
#include "io/outfile.h"
#include "core/pipetrace.h"
#include "io/png.h"
#include "io/trace.h"
#include "io/tlanes.h"
#include "io/trace_kraft.h"
#include "io/trace_course.h"

#define PT_VERSION "0.1.0"


static const char usage[] =
"usage: pipetrace [SCENE] [options]\n"
"       pipetrace diff EXPECTED ACTUAL [--tol ABS] [--rel REL] [--show N] [--verdict]\n"
"                      [--scene SCENE] [--separating-scene FILE]\n"
"       pipetrace diff EXPECTED.ppm ACTUAL.ppm [--image-out FILE]\n"
"       pipetrace step [SCENE] [--vertex N] [--model NAME] [--all | --interactive]\n"
"                      [--compare-cameras] [--raw-lookat]\n"
"       pipetrace why [SCENE] X_FB Y_FB [--model NAME]\n"
"       pipetrace quiz [SCENE] [--vertex N | --seed S] [--model NAME] [--stage S]\n"
"                      [--json] [--interactive] [--grade DIR [--out FILE]]\n"
"       pipetrace accuracy [SCENE] [--repeat N] [--no-time] [--svg FILE]\n"
"       pipetrace journey [SCENE] --vertex N [--model NAME] [--svg FILE] [--html FILE]\n"
"                         [--image FILE]\n"
"       pipetrace stages [--camera classic|matrix]\n"
"       pipetrace shapes [NAME]\n"
"       pipetrace export java [SCENE] [-o FILE.java] [--pixels] [--debug LIST]\n"
"       pipetrace class EXPECTED DIR [--csv FILE] [--html FILE] [--jobs N]\n"
"                       [--tol ABS] [--rel REL]\n"
"Render SCENE (a .scene file or a plain .obj file; -: standard input; none:\n"
"the built-in scene) through the classic teaching pipeline and trace every\n"
"vertex at every stage:\n"
"  model -> camera -> image -> pixel -> viewport -> framebuffer -> index\n"
"or, for a scene with 'camera lookat', through the matrix camera:\n"
"  model -> world -> view -> clip -> cvv -> ndc -> screen -> viewport -> ...\n"
"\n"
"  --image FILE      write the rendered framebuffer: PNG when FILE ends in\n"
"                    .png (any case), else binary PPM (P6)\n"
"  --trace FILE      write the trace to FILE ('-': standard output)\n"
"  --format F        trace format: text (default), jsonl, csv; kraft: the\n"
"                    course renderer's debug log, kraft-pixels: with its pixels\n"
"  --kraft-debug L   the course's debug switches for its log, comma-separated:\n"
"                    scene, position, rasterize, clip, nearclip, all, none\n"
"                    (kraft: scene; kraft-pixels: scene,rasterize)\n"
"  --vertex N        trace only vertex N (1-based) of each model\n"
"  --model NAME      trace only the model NAME\n"
"  --stage NAME      trace only this stage (repeatable): model, camera, image,\n"
"                    pixel, viewport, framebuffer, index, or raster (pixels);\n"
"                    matrix camera: world, view, clip, cvv, ndc, screen too\n"
"  --all-stages      trace identity stages too (they are left out by default)\n"
"  --raw-lookat      matrix camera: keep the given up vector as it is (the\n"
"                    seed's matrix) instead of making it perpendicular\n"
"  --explain         under each vertex record, its formula with the numbers put in\n"
"  --precision N     digits after the point in the text format (0-17, default 6)\n"
"  --threads N       format the trace on N threads, 1 or 2 (default: 2 for a\n"
"                    large scene with two CPUs or more); the trace is the same\n"
"  --help            show this help\n"
"  --version         show the version\n"
"\n"
"With neither --image nor --trace the text trace goes to standard output.\n"
"Exit status: 0 success, 1 usage error, 2 bad input or output error.\n"
"Each command's --help says more.\n"
"Docs: docs/README.md, docs/scene-format.md, docs/trace-format.md, docs/cameras.md\n";

/* The subcommands, by name: main() dispatches on the first argument. */
static const struct command {
    const char *name;
    int (*run)(int argc, char **argv);
} commands[] = {
    {"diff", pt_cmd_diff}, {"step", pt_cmd_step}, {"why", pt_cmd_why},
    {"quiz", pt_cmd_quiz}, {"accuracy", pt_cmd_accuracy}, {"journey", pt_cmd_journey},
    {"stages", pt_cmd_stages}, {"shapes", pt_cmd_shapes}, {"export", pt_cmd_export},
    {"class", pt_cmd_class},
};
#define NCOMMANDS (sizeof commands / sizeof commands[0])

/* ===== options ===== */

typedef struct cli {
    const char *scene;           /* NULL: the built-in scene */
    const char *image;           /* --image, or NULL */
    const char *trace;           /* --trace, or NULL */
    pt_format fmt;
    int precision;
    int raster_chosen;           /* --stage raster given */
    int explain;                 /* --explain */
    int fmt_given;               /* 1: --format given */
    int kdbg_given;              /* 1: --kraft-debug given */
    unsigned kdbg;               /* the course's debug switches (PT_KDBG_*) */
    int threads;                 /* --threads, or 0: threads_wanted() decides */
    int staged;                  /* --stage given */
    pt_options opt;
} cli;

static int usage_error(const char *fmt, const char *arg)
{
    return pt_cli_usage(NULL, fmt, arg);
}

/* 1 after saying so when scene names no file but is near a command's name
** ("stpe": did you mean 'step'?), else 0. */
static int mistyped_command(const char *scene)
{
    char names[128], near[64];
    size_t len = 0, k;

    if (!strcmp(scene, "-") || access(scene, F_OK) == 0) return 0;
    for (k = 0; k < NCOMMANDS; k++)
        len += (size_t)snprintf(names + len, sizeof names - len, "%s ", commands[k].name);
    if (!pt_cli_nearest(scene, names, near, sizeof near)) return 0;
    pt_cli_usage(NULL, "no command or scene file '%s' (did you mean '%s'?)", scene, near);
    return 1;
}

/* Fill *c from argv.  Returns -1 to go on, else the exit status. */
static int parse_args(cli *c, int argc, char **argv)
{
    int k, staged = 0;

    memset(c, 0, sizeof *c);
    pt_options_default(&c->opt);
    c->precision = 6;
    for (k = 1; k < argc; k++) {
        const char *a = argv[k];
        const char *val = k + 1 < argc ? argv[k + 1] : NULL;
        int takes = !strcmp(a, "--image") || !strcmp(a, "--trace") ||
                    !strcmp(a, "--format") || !strcmp(a, "--vertex") ||
                    !strcmp(a, "--model") || !strcmp(a, "--stage") ||
                    !strcmp(a, "--precision") || !strcmp(a, "--threads") ||
                    !strcmp(a, "--kraft-debug");

        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(usage, stdout); return 0; }
        if (!strcmp(a, "--version")) {
            char note[512];
            puts("pipetrace " PT_VERSION);
            if (pt_cli_student_note(note, sizeof note)) puts(note);
            return 0;
        }
        if (takes && !val) return usage_error("option '%s' needs a value", a);
        if (takes) k++;
        if (!strcmp(a, "--image")) c->image = val;
        else if (!strcmp(a, "--trace")) c->trace = val;
        else if (!strcmp(a, "--model")) c->opt.model = val;
        else if (!strcmp(a, "--kraft-debug")) {
            if (pt_kraft_debug_parse(val, &c->kdbg) != 0)
                return usage_error("--kraft-debug takes a comma-separated list of scene, "
                                   "position, rasterize, clip, nearclip, all, none, not '%s'",
                                   val);
            c->kdbg_given = 1;
        } else if (!strcmp(a, "--format")) {
            c->fmt_given = 1;
            if (!strcmp(val, "text")) c->fmt = PT_FORMAT_TEXT;
            else if (!strcmp(val, "jsonl")) c->fmt = PT_FORMAT_JSONL;
            else if (!strcmp(val, "csv")) c->fmt = PT_FORMAT_CSV;
            else if (!strcmp(val, "kraft")) c->fmt = PT_FORMAT_KRAFT;
            else if (!strcmp(val, "kraft-pixels")) c->fmt = PT_FORMAT_KRAFT_PIXELS;
            else return usage_error("unknown format '%s' (text, jsonl, csv, kraft, "
                                    "kraft-pixels)", val);
        } else if (!strcmp(a, "--vertex")) {
            if (pt_cli_vertex(NULL, val, &c->opt.vertex) != 0) return PT_EXIT_USAGE;
        } else if (!strcmp(a, "--precision")) {
            uint64_t p;
            if (pt_cli_count(val, 0, 17, &p) != 0)
                return usage_error("--precision takes 0 to 17, not '%s'", val);
            c->precision = (int)p;
        } else if (!strcmp(a, "--threads")) {
            uint64_t n;
            if (pt_cli_count(val, 1, 2, &n) != 0)
                return usage_error("--threads takes 1 or 2, not '%s'", val);
            c->threads = (int)n;
        } else if (!strcmp(a, "--stage")) {
            int st = pt_stage_by_name(val);
            if (!staged) { c->opt.stage_mask = 0; staged = 1; }
            if (!strcmp(val, "raster")) c->raster_chosen = 1;
            else if (st < 0) {
                char list[512];
                size_t len = 0, i;
                for (i = 0; i < PT_NSTAGES_ALL && len < sizeof list; i++)
                    len += (size_t)snprintf(list + len, sizeof list - len, "%s, ",
                                            pt_stage_infos[pt_trace_order[i]].name);
                return pt_cli_usage(NULL, "unknown stage '%s' (the stages: %sraster)", val, list);
            }
            else c->opt.stage_mask |= 1u << st;
        } else if (!strcmp(a, "--all-stages")) c->opt.all_stages = 1;
        else if (!strcmp(a, "--raw-lookat")) c->opt.raw_lookat = 1;
        else if (!strcmp(a, "--explain")) c->explain = 1;
        else if (a[0] == '-' && a[1] != '\0') return pt_cli_unknown(NULL, strstr(usage, "\n  --"), a);
        else if (c->scene) return usage_error("more than one scene given ('%s')", a);
        else if (mistyped_command(a)) return PT_EXIT_USAGE;
        else c->scene = a;
    }
    c->staged = staged;
    if (staged && !c->raster_chosen) c->opt.trace_raster = 0;
    if (c->kdbg_given && !c->fmt_given) c->fmt = PT_FORMAT_KRAFT;
    if (c->kdbg_given && c->fmt != PT_FORMAT_KRAFT && c->fmt != PT_FORMAT_KRAFT_PIXELS)
        return usage_error("--kraft-debug sets the switches of the course's log: "
                           "--format kraft or kraft-pixels, not %s",
                           c->fmt == PT_FORMAT_CSV ? "csv" :
                           c->fmt == PT_FORMAT_JSONL ? "jsonl" : "text");
    if (!c->kdbg_given)                     /* kraft: scene; kraft-pixels: + rasterize */
        c->kdbg = c->fmt == PT_FORMAT_KRAFT_PIXELS ? PT_KDBG_SCENE | PT_KDBG_RASTERIZE
                                                   : PT_KDBG_SCENE;
    if (c->explain && c->fmt == PT_FORMAT_CSV)
        return usage_error("--explain needs --format text or jsonl%s", "");
    if ((c->fmt == PT_FORMAT_KRAFT || c->fmt == PT_FORMAT_KRAFT_PIXELS) &&
        (staged || c->explain || c->opt.vertex || c->opt.model || c->opt.all_stages))
        return usage_error("--format %s logs the whole scene as the course's renderer "
                           "does: no --vertex, --model, --stage, --all-stages, --explain",
                           c->fmt == PT_FORMAT_KRAFT ? "kraft" : "kraft-pixels");
    if (!c->image && !c->trace) c->trace = "-";
    /* --vertex without --image: only that vertex's journey is computed */
    c->opt.rasterize = c->image != NULL || !c->opt.vertex;
    return -1;
}

/* ===== checks that need the scene ===== */

/* --model must name a model, and --vertex N must exist in it (or, without
** --model, in some model). */
static int check_filters(const cli *c, const pt_scene *s)
{
    if (c->opt.vertex)                      /* looks the model up too */
        return pt_cli_vertex_model(s, NULL, c->opt.model, c->opt.vertex) ? 0 : PT_EXIT_INPUT;
    if (c->opt.model && !pt_cli_model(s, NULL, c->opt.model)) return PT_EXIT_INPUT;
    return 0;
}

/* ===== main ===== */

/* The scene's arrays (tens of MB for a large scene) in huge pages where
** Linux and glibc allow it: on a virtual machine each page fault costs
** microseconds, and drawing a scene of 200,000 vertices took some 2,400 of
** them in pages of 4 KiB, most for the scene's arrays.  The heap grows
** 256 MiB (of address space) at a time, large arrays stay in it rather than
** in mappings of their own, and its top is marked for huge pages: the same
** scene then takes some 570 faults, one of 3.2M vertices some 350.  The
** trace's second thread (tlanes.c) allocates from this heap too, not from an
** arena of its own in small pages (M_ARENA_MAX): it allocates little, and
** only as its run begins.  Only speed depends on it.  Where malloc is not
** glibc's heap (a sanitizer's, valgrind's), the block is not below the break
** and nothing is marked. */
static void heap_in_huge_pages(void)
{
#if defined(__linux__) && defined(__GLIBC__) && defined(MADV_HUGEPAGE)
    const uintptr_t huge = (uintptr_t)2 << 20, pad = (uintptr_t)256 << 20;
    uintptr_t lo, hi;
    void *p;

    mallopt(M_MMAP_THRESHOLD, (int)pad);
    mallopt(M_TOP_PAD, (int)pad);
    mallopt(M_ARENA_MAX, 1);
    if (!(p = malloc(1))) return;           /* the heap now reaches sbrk(0) */
    lo = ((uintptr_t)p + huge - 1) & ~(huge - 1);
    hi = (uintptr_t)sbrk(0) & ~(huge - 1);
    if (hi > lo && hi - lo <= 2 * pad) madvise((void *)lo, hi - lo, MADV_HUGEPAGE);
    free(p);
#endif
}

/* The threads the trace is formatted on (tlanes.h): --threads, else 2 when
** this process may run on two CPUs or more (not under `taskset -c 1`) and
** scene s has more vertices than one piece of the trace holds (renderer 4's
** or renderers 7 and 9's; a smaller one's trace is a piece or two: a second
** thread would only wait). */
static int threads_wanted(const cli *c, const pt_scene *s)
{
    long cpus = sysconf(_SC_NPROCESSORS_ONLN);
    uint64_t nv = 0;
    size_t k;

    if (c->threads) return c->threads;
    for (k = 0; k < s->nmodels; k++) nv += s->models[k].nv;
    if (nv <= (s->renderer == 7 || s->renderer == 9 ? PT_COURSE_PIECE_VERTICES
                                                     : PT_PIECE_VERTICES)) return 1;
#if defined(__linux__) && defined(CPU_COUNT)
    {
        cpu_set_t set;
        if (sched_getaffinity(0, sizeof set, &set) == 0) cpus = CPU_COUNT(&set);
    }
#endif
    return cpus >= 2 ? 2 : 1;
}

/* The render command for a scene of the course's renderer 7 or 9
** (core/course.h): its image, its log (--format kraft, kraft-pixels,
** --kraft-debug) or pipetrace's trace of it. */
static int run_course(const cli *c, const pt_scene *s)
{
    pt_fb fb = {0, 0, NULL};
    pt_outfile tout = {NULL, NULL, NULL, NULL}, iout = {NULL, NULL, NULL, NULL};
    char err[PT_ERRLEN];
    int rc = 0, kraft = c->fmt == PT_FORMAT_KRAFT || c->fmt == PT_FORMAT_KRAFT_PIXELS;
    pt_course_cuts cuts;

    memset(&cuts, 0, sizeof cuts);
    cuts.threads = threads_wanted(c, s);

    if (c->staged || c->opt.vertex || c->opt.model || c->opt.all_stages ||
        c->opt.raw_lookat) {
        fprintf(stderr, "pipetrace: %s: error: renderer %d scenes are traced whole: no "
                "--vertex, --model, --stage, --all-stages, --raw-lookat\n",
                s->path, s->renderer);
        return PT_EXIT_INPUT;
    }
    if (pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0) {
        snprintf(err, sizeof err, "pipetrace: out of memory");
        rc = 1;
    }
    if (!rc && c->trace) {
        if (pt_outfile_open(&tout, c->trace, err, sizeof err) != 0) rc = 1;
        else if ((kraft ? pt_course_log(tout.f, s, c->kdbg, &cuts, &fb, err, sizeof err)
                        : pt_course_trace(tout.f, s, (int)c->fmt, c->precision, c->explain,
                                          &cuts, &fb, err, sizeof err)) != 0)
            rc = 1;
        else {
            errno = cuts.failed;            /* what the first write that failed said */
            if (fflush(tout.f) != 0 || ferror(tout.f) || cuts.failed) {
                snprintf(err, sizeof err, "cannot write the trace to '%s': %s", c->trace,
                         errno ? strerror(errno) : "a write failed");
                rc = 1;
            }
        }
    } else if (!rc && pt_course_render(s, &fb, NULL) != 0) {
        snprintf(err, sizeof err, "pipetrace: out of memory");
        rc = 1;
    }
    if (!rc && c->image) {
        if (pt_outfile_open(&iout, c->image, err, sizeof err) != 0) rc = 1;
        else if ((pt_path_is_png(c->image) ? pt_fb_write_png(&fb, iout.f)
                                           : pt_fb_write_ppm(&fb, iout.f)) != 0) {
            snprintf(err, sizeof err, "cannot write '%s'", c->image);
            rc = 1;
        } else if (pt_outfile_commit(&iout, err, sizeof err) != 0) rc = 1;
    }
    if (!rc && c->trace && pt_outfile_commit(&tout, err, sizeof err) != 0) rc = 1;
    if (rc) {
        fprintf(stderr, "%s%s\n", strncmp(err, "pipetrace:", 10) ? "pipetrace: " : "", err);
        pt_outfile_abort(&iout);
        pt_outfile_abort(&tout);
    }
    pt_fb_free(&fb);
    return rc ? PT_EXIT_INPUT : 0;
}

/* The render command, or the subcommand argv[1] names. */
static int run(int argc, char **argv)
{
    cli c;
    pt_scene s;
    pt_plan plan;
    pt_fb fb = {0, 0, NULL};
    size_t k;
    pt_summary sum;
    pt_listener l;
    pt_trace *tr = NULL;
    pt_outfile tout = {NULL, NULL, NULL, NULL}, iout = {NULL, NULL, NULL, NULL};
    char err[PT_ERRLEN];
    int rc, kraft;

    for (k = 0; argc > 1 && k < NCOMMANDS; k++)
        if (strcmp(argv[1], commands[k].name) == 0) return commands[k].run(argc - 1, argv + 1);
    rc = parse_args(&c, argc, argv);
    if (rc >= 0) return rc;
    {
        const char *out[2] = {c.trace, c.image}, *opt[2] = {"--trace", "--image"};
        if (pt_cli_outputs(c.scene, out, opt, 2) != 0) return PT_EXIT_INPUT;
    }

    if (pt_cli_load(&s, c.scene) != 0) return PT_EXIT_INPUT;
    {
        const char *out[2] = {c.trace, c.image}, *opt[2] = {"--trace", "--image"};
        if (pt_cli_outputs_objs(&s, out, opt, 2) != 0) { pt_scene_free(&s); return PT_EXIT_INPUT; }
    }
    if (s.renderer == 7 || s.renderer == 9) {
        rc = run_course(&c, &s);
        pt_scene_free(&s);
        return rc;
    }
    if (s.nmodels == 0)
        fprintf(stderr, "pipetrace: warning: %s has no models: nothing to trace or draw\n", s.path);
    rc = check_filters(&c, &s);
    if (rc) { pt_scene_free(&s); return rc; }
    if (pt_plan_make(&plan, &s, &c.opt) != 0) {
        fputs("pipetrace: out of memory\n", stderr);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }

    memset(&l, 0, sizeof l);
    rc = 0;
    kraft = c.fmt == PT_FORMAT_KRAFT || c.fmt == PT_FORMAT_KRAFT_PIXELS;
    if (c.trace && kraft) {                 /* written after the run, below */
        if (pt_outfile_open(&tout, c.trace, err, sizeof err) != 0) rc = 1;
    } else if (c.trace) {
        tr = malloc(sizeof *tr);
        if (!tr) { snprintf(err, sizeof err, "pipetrace: out of memory"); rc = 1; }
        else if (pt_outfile_open(&tout, c.trace, err, sizeof err) != 0) rc = 1;
        else {
            /* the trace hands over blocks of 256 KiB: one write(2) each,
            ** not stdio's split into its buffer's size and the rest */
            setvbuf(tout.f, NULL, _IONBF, 0);
            pt_trace_init(tr, tout.f, c.fmt, c.precision);
            tr->explain = c.explain;
            tr->student = pt_student_files;
            pt_trace_listener(tr, &l);
        }
    }
    if (!rc && c.image && pt_fb_init(&fb, s.fb_w, s.fb_h, s.background) != 0) {
        snprintf(err, sizeof err, "pipetrace: out of memory");
        rc = 1;
    }
    if (!rc && (tr && threads_wanted(&c, &s) == 2
                ? pt_tlanes_run(tr, &s, &plan, &c.opt, c.image ? &fb : NULL, &sum)
                : pt_run(&s, &plan, &c.opt, &l, c.image ? &fb : NULL, &sum)) != 0) {
        snprintf(err, sizeof err, "pipetrace: out of memory");
        rc = 1;
    }
    if (!rc && c.trace && kraft &&
        pt_kraft_write(tout.f, &s, c.kdbg, err, sizeof err) != 0)
        rc = 1;
    else if (!rc && c.trace && kraft) {
        errno = 0;                          /* what the last write said, if one failed */
        if (fflush(tout.f) != 0 || ferror(tout.f)) {
            snprintf(err, sizeof err, "cannot write the trace to '%s': %s", c.trace,
                     errno ? strerror(errno) : "a write failed");
            rc = 1;
        }
    }
    if (!rc && tr && pt_trace_finish(tr) != 0) {
        snprintf(err, sizeof err, "cannot write the trace to '%s': %s", c.trace,
                 strerror(tr->failed));
        rc = 1;
    }
    if (!rc && c.image) {
        if (pt_outfile_open(&iout, c.image, err, sizeof err) != 0) rc = 1;
        else if ((pt_path_is_png(c.image) ? pt_fb_write_png(&fb, iout.f)
                                          : pt_fb_write_ppm(&fb, iout.f)) != 0) {
            snprintf(err, sizeof err, "cannot write '%s'", c.image);
            rc = 1;
        } else if (pt_outfile_commit(&iout, err, sizeof err) != 0) rc = 1;
    }
    if (!rc && c.trace && pt_outfile_commit(&tout, err, sizeof err) != 0) rc = 1;
    if (rc) {
        fprintf(stderr, "%s%s\n", strncmp(err, "pipetrace:", 10) ? "pipetrace: " : "", err);
        pt_outfile_abort(&iout);
        pt_outfile_abort(&tout);
    }
    if (!rc && c.opt.raw_lookat && !pt_scene_pipeline(&s)->matrices)
        fprintf(stderr, "pipetrace: note: --raw-lookat changes nothing: the scene uses the "
                "%s\n", pt_scene_pipeline(&s)->title);
    if (!rc && c.opt.vertex && !c.image && sum.vertices_traced == 0)
        fprintf(stderr, "pipetrace: note: vertex %llu is used by no segment, so it "
                "is not transformed\n", (unsigned long long)c.opt.vertex);
    free(tr);
    pt_fb_free(&fb);
    pt_plan_free(&plan);
    pt_scene_free(&s);
    return rc ? PT_EXIT_INPUT : 0;
}

/* Is name a subcommand? */
static int command(const char *name)
{
    size_t k;

    for (k = 0; k < NCOMMANDS; k++)
        if (strcmp(name, commands[k].name) == 0) return 1;
    return 0;
}

int main(int argc, char **argv)
{
    int rc;

    /* A closed pipe ends the run at its first write, quietly, as SIGPIPE does
    ** by default, even when the caller ignored the signal (which a child
    ** inherits): else a whole trace would be formatted into a dead pipe,
    ** each write failing with EPIPE (tests/cli/hostile.sh hostile-6). */
    signal(SIGPIPE, SIG_DFL);
    heap_in_huge_pages();
    rc = run(argc, argv);
    return pt_cli_stdout(argc > 1 && command(argv[1]) ? argv[1] : NULL, rc);
}
