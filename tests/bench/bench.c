/*
** tests/bench/bench.c -- how fast pipetrace is, next to a plain C program of the same formulas
** See LICENSE for copyright and license.
**
** `make bench` runs `build/bench build`.  It writes the benchmark scenes with
** tests/bench/benchgen.c (25,000 octagons: 200,000 vertices and segments in a
** 1920 x 1080 framebuffer; and 4 and 16 times as many), then times, in one
** run on one machine:
**   parse      pt_scene_load() in this process, against tests/bench/baseline.c's
**              fgets + strtod loop (the baseline reports its own times);
**   render     pt_run() with no listener into a framebuffer, warm, against the
**              baseline's render loop;
**   process    `pipetrace SCENE --image OUT.ppm` start to end, against
**              `baseline SCENE OUT.ppm` (and whether the two images agree);
**   traces     `pipetrace SCENE --image OUT.ppm --format F --trace /dev/null`
**              for JSON Lines, text and CSV, as MB/s and against the process
**              without a trace;
**   memory     the peak resident memory of the process at 800k vertices,
**              without a trace and with a JSON Lines trace (to a pipe), and
**              the page faults of the process at 200k;
**   scaling    the process's time per vertex at 200k, 800k and 3.2M vertices;
**   two CPUs   the untraced process and the JSON Lines trace on one thread
**              and on two (--threads 2, src/io/tlanes.c), in wall seconds,
**              for renderer 4's scene and the course's (below); this part
**              alone with `build/bench build two-cpus`;
**   course     the same octagons through the course's renderers 7 and 9
**              (9 with anti-aliasing and without): render in process and
**              whole process against the baseline's renderers 7 and 9, and
**              the traces (JSON Lines, text, CSV, the course's log) against
**              the untraced process, beside renderer 4's ratios;
**   Java       when `java` and `javac` are on the PATH and the course's jars
**              are in PT_COURSE_DIR (default ../shared/reference/course:
**              rendererN/KraftN.java and its jar), the course's own Java
**              renderers 4, 7 and 9 on the same scenes: the whole process
**              (the harness KraftN, no log) and the render in the JVM
**              (tests/bench/BenchKraft.java), and pipetrace's ratio to each.
** Each time is CPU time (user and system), the least of 5 runs (of 3 for the
** large scenes of the scaling rows, of 15 for the renders in process); the
** programs timed as whole processes at 200k take turns (spawn_rounds), so
** the ratios between them hold when the machine slows for a while.  All of
** it but the last part runs on one CPU, the one that renders the scene
** fastest: the cores of a virtual machine need not be alike (one may share
** its physical core with another machine's work), and a ratio of two
** programs timed on two different cores says little.  The last part is what
** a user waits for with both CPUs free: wall time, every CPU allowed, the
** least of 5 turns.  Figures depend on the machine: they are printed with
** their ratios and the targets of docs/bench.md, never asserted (the tests
** check results, not speed).
*/
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE          /* wait4: the child's peak memory */
#define _GNU_SOURCE              /* sched_setaffinity: one CPU for everything */
#include <fcntl.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/time.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>
#include "core/course.h"
#include "core/pipeline.h"

#define RUNS 5
#define RENDERS 15               /* renders in process (tests/bench/baseline.c too) */

static const char *dir;          /* the build directory */
static long faults;              /* page faults of the last process spawned */
static double wall;              /* its wall seconds, from fork to its end */

/* CPU time, not wall time: the machine may be shared, and a process that
** waits for the processor is not slower for it. */
static double now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double wall_now(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}

static double seconds(struct timeval tv)
{
    return (double)tv.tv_sec + (double)tv.tv_usec * 1e-6;
}

/* The least of n times: what the code costs when nothing else gets in its
** way (on a shared machine the median drifts with the load). */
static double least(const double *t, int n)
{
    double m = t[0];
    int k;

    for (k = 1; k < n; k++) if (t[k] < m) m = t[k];
    return m;
}

static void die(const char *what)
{
    fprintf(stderr, "bench: %s\n", what);
    exit(1);
}

/* Run argv with standard output to out (a path, or NULL: a pipe whose bytes
** are counted into *bytes); return its CPU time (user and system), and the
** peak resident memory in KiB in *maxrss when not NULL. */
static double spawn(char *const argv[], const char *out, long *maxrss, double *bytes)
{
    int fd[2] = {-1, -1}, status;
    struct rusage ru;
    double t, t0 = wall_now();
    pid_t pid;

    if (!out && pipe(fd) != 0) die("pipe");
    pid = fork();
    if (pid < 0) die("fork");
    if (pid == 0) {
        int o = out ? open(out, O_WRONLY | O_CREAT | O_TRUNC, 0644) : fd[1];
        if (o < 0 || dup2(o, 1) < 0) _exit(127);
        if (fd[0] >= 0) close(fd[0]);
        execv(argv[0], argv);
        _exit(127);
    }
    if (!out) {
        char buf[1 << 16];
        ssize_t n;
        close(fd[1]);
        *bytes = 0;
        while ((n = read(fd[0], buf, sizeof buf)) > 0) *bytes += (double)n;
        close(fd[0]);
    }
    if (wait4(pid, &status, 0, &ru) != pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        fprintf(stderr, "bench: %s failed\n", argv[0]);
        exit(1);
    }
    wall = wall_now() - t0;
    t = seconds(ru.ru_utime) + seconds(ru.ru_stime);
    if (maxrss) *maxrss = ru.ru_maxrss;
    faults = ru.ru_minflt;
    return t;
}

/* The least CPU time of RUNS runs of each of the n programs argvs[i], output
** to /dev/null, into cpu[i]; or, with w not NULL, the least wall time into
** w[i] and the CPU time of that run into cpu[i].  The runs take turns (one
** of each, RUNS times): a machine that slows down for a while then slows
** them all alike, and their ratios hold where times taken one program after
** another drift. */
static void spawn_rounds(char *const *const argvs[], int n, double cpu[], double w[])
{
    int k, i;

    for (k = 0; k < RUNS; k++)
        for (i = 0; i < n; i++) {
            double u = spawn(argvs[i], "/dev/null", NULL, NULL);
            if (k == 0 || (w ? wall < w[i] : u < cpu[i])) {
                cpu[i] = u;
                if (w) w[i] = wall;
            }
        }
}

/* The least CPU time of 3 runs of argv: for the large scenes (seconds each). */
static double spawn_least(char *const argv[])
{
    double t = spawn(argv, "/dev/null", NULL, NULL), u;
    int k;

    for (k = 1; k < 3; k++) if ((u = spawn(argv, "/dev/null", NULL, NULL)) < t) t = u;
    return t;
}

static char *path(const char *name)
{
    static char buf[32][512];   /* a path stays valid for 31 more calls */
    static int next;
    char *p = buf[next++ % 32];

    snprintf(p, 512, "%s/%s", dir, name);
    return p;
}

/* path(name) in a buffer of its own, for as long as the bench runs. */
static char *lasting_path(const char *name)
{
    char *p = strdup(path(name));

    if (!p) die("out of memory");
    return p;
}

/* Write the scene of n octagons for renderer 4, 7 or 9 (benchgen) to
** B/NAME; flags "aa" (anti-aliasing), "case" (the course harness's case
** file), "aa case" or "".  Returns the path (allocated: it lives to the end). */
static char *make_scene(const char *name, const char *n, const char *renderer, const char *flags)
{
    char *argv[7], *out = path(name);
    int k = 4;

    argv[0] = path("benchgen");
    argv[1] = (char *)n;
    argv[2] = "1000";                           /* octagons a model */
    argv[3] = (char *)renderer;
    if (strstr(flags, "aa")) argv[k++] = "aa";
    if (strstr(flags, "case")) argv[k++] = "case";
    argv[k] = NULL;
    spawn(argv, out, NULL, NULL);
    if (!(out = strdup(out))) die("out of memory");     /* path()'s buffers are reused */
    return out;
}

/* The baseline's own figures: parse and render seconds. */
static void baseline(const char *scene, double *parse, double *render)
{
    char cmd[1200];
    FILE *p;

    snprintf(cmd, sizeof cmd, "'%s' '%s'", path("baseline"), scene);
    p = popen(cmd, "r");
    if (!p || fscanf(p, "parse %lf render %lf", parse, render) != 2) die("baseline failed");
    pclose(p);
}

/* One untraced pt_run() of s into a fresh framebuffer (pt_course_render()
** for a scene of renderer 7 or 9): its CPU seconds. */
static double render_once(const pt_scene *s)
{
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    pt_fb fb;
    double t0, t;

    if (s->renderer == 7 || s->renderer == 9) {     /* the course's renderers */
        if (pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0) die("out of memory");
        t0 = now();
        if (pt_course_render(s, &fb, NULL) != 0) die("out of memory");
        t = now() - t0;
        pt_fb_free(&fb);
        return t;
    }
    pt_options_default(&o);
    memset(&l, 0, sizeof l);
    if (pt_plan_make(&p, s, &o) != 0 || pt_fb_init(&fb, s->fb_w, s->fb_h, s->background) != 0)
        die("out of memory");
    t0 = now();
    if (pt_run(s, &p, &o, &l, &fb, &sum) != 0) die("out of memory");
    t = now() - t0;
    pt_fb_free(&fb);
    pt_plan_free(&p);
    return t;
}

/* pt_scene_load() of path, the least of RUNS; the scene in *s. */
static double load(pt_scene *s, const char *path)
{
    double tp[RUNS], t0;
    char err[PT_ERRLEN];
    int k;

    for (k = 0; k < RUNS; k++) {
        t0 = now();
        if (pt_scene_load(s, path, err, sizeof err) != 0) die(err);
        tp[k] = now() - t0;
        if (k < RUNS - 1) pt_scene_free(s);
    }
    return least(tp, RUNS);
}

/* The untraced pt_run() of s in this process: the least of RENDERS, after
** one to warm up. */
static double render(const pt_scene *s)
{
    double tr[RENDERS];
    int k;

    render_once(s);
    for (k = 0; k < RENDERS; k++) tr[k] = render_once(s);
    return least(tr, RENDERS);
}

#ifdef __linux__
static cpu_set_t every_cpu, one_cpu;    /* this process's CPUs at the start; */
static int pinned;                      /*   the one pin_fastest() chose */
#endif

/* Let the processes spawned from now on run on every CPU this process had
** at the start (on = 1), or on the one pin_fastest() chose (on = 0).
** Returns how many CPUs that is. */
static int use_every_cpu(int on)
{
#ifdef __linux__
    if (pinned) {
        sched_setaffinity(0, sizeof every_cpu, on ? &every_cpu : &one_cpu);
        return on ? CPU_COUNT(&every_cpu) : 1;
    }
#endif
    (void)on;
    return (int)sysconf(_SC_NPROCESSORS_ONLN);
}

/* Run this process and its children on the CPU that renders scene fastest
** (the least of 3 untraced renders on each); say which in *note.  Linux
** only: elsewhere the scheduler decides. */
static void pin_fastest(const pt_scene *s, char *note, size_t n)
{
    snprintf(note, n, "the scheduler's choice");
#ifdef __linux__
    {
        cpu_set_t all, one;
        double best = 0;
        int c, k, fastest = -1, len = 0;

        if (sched_getaffinity(0, sizeof all, &all) != 0) return;
        for (c = 0; c < CPU_SETSIZE; c++) {
            double t = 0, u;
            if (!CPU_ISSET(c, &all)) continue;
            CPU_ZERO(&one);
            CPU_SET(c, &one);
            if (sched_setaffinity(0, sizeof one, &one) != 0) continue;
            for (k = 0; k < 3; k++) if ((u = render_once(s)) < t || k == 0) t = u;
            if (len < (int)n - 40)
                len += snprintf(note + len, n - (size_t)len, "%scpu %d %.1f ms", len ? ", " : "",
                                c, t * 1e3);
            if (fastest < 0 || t < best) { fastest = c; best = t; }
        }
        if (fastest < 0) { snprintf(note, n, "the scheduler's choice"); return; }
        CPU_ZERO(&one);
        CPU_SET(fastest, &one);
        sched_setaffinity(0, sizeof one, &one);
        every_cpu = all;
        one_cpu = one;
        pinned = 1;
        if (len < (int)n - 40) snprintf(note + len, n - (size_t)len, ": all on cpu %d", fastest);
    }
#endif
}

#define NFMT 4
static const char *const fmts[NFMT] = {"jsonl", "text", "csv", "kraft"};

/* One scene's figures, for the rows of the course's renderers and Java's. */
typedef struct figures {
    const char *title;           /* "renderer 4", ... */
    const char *renderer;        /* "4", "7" or "9" */
    const char *flags;           /* benchgen's: "" or "aa" */
    char *scene;                 /* the scene */
    double render, proc;         /* pipetrace: render in process, whole process */
    double base_render, base_proc;   /* the plain C baseline's */
    double trace[NFMT];          /* each trace's time over the untraced process's */
} figures;

static void row(const char *what, double ours, double theirs, const char *unit,
                const char *target)
{
    printf("  %-28s %10.4f %-4s %10.4f %-4s %6.2fx   %s\n", what, ours, unit, theirs, unit,
           ours / theirs, target);
}

static int same_file(const char *a, const char *b)
{
    FILE *f = fopen(a, "rb"), *g = fopen(b, "rb");
    int c, d, same = f && g;

    while (same) {                      /* both ends, or the first difference */
        c = getc(f);
        d = getc(g);
        same = c == d;
        if (c == EOF || d == EOF) break;
    }
    if (f) fclose(f);
    if (g) fclose(g);
    return same;
}

/* The rows of a scene of the course's renderer 7 or 9: render in process
** and whole process against the baseline, images, the traces against the
** untraced process; each beside renderer 4's ratio (r4). */
static void course_rows(figures *f, const figures *r4)
{
    char *pt = path("pipetrace"), *ppm = path("bench-pt.ppm"), *bppm = path("bench-base.ppm");
    char *a[] = {pt, f->scene, "--image", ppm, NULL};
    char *b[] = {path("baseline"), f->scene, bppm, NULL};
    char *tr[NFMT][9], target[64];
    char *const *all[2 + NFMT];
    double t[2 + NFMT], bytes[NFMT], bp;
    pt_scene s;
    int k;

    load(&s, f->scene);
    f->render = render(&s);
    pt_scene_free(&s);
    baseline(f->scene, &bp, &f->base_render);
    for (k = 0; k < NFMT; k++) {                /* the traces, to /dev/null: */
        char *c[] = {pt, f->scene, "--image", ppm, "--format", (char *)fmts[k], "--trace",
                     "-", NULL};
        memcpy(tr[k], c, sizeof c);
        spawn(tr[k], NULL, NULL, &bytes[k]);    /* their bytes, counted once */
        tr[k][7] = "/dev/null";
        all[2 + k] = tr[k];
    }
    all[0] = a;
    all[1] = b;
    spawn_rounds(all, 2 + NFMT, t, NULL);
    f->proc = t[0];
    f->base_proc = t[1];
    printf("\nthe course's %s, the same octagons (%s)\n", f->title, f->scene);
    printf("  %-28s %15s %15s %7s   %s\n", "", "pipetrace", "plain C", "ratio",
           "target (renderer 4's)");
    snprintf(target, sizeof target, "<= 1.5x (%.2fx)", r4->render / r4->base_render);
    row("render, in process (warm)", f->render, f->base_render, "s", target);
    snprintf(target, sizeof target, "<= 1.3x (%.2fx)", r4->proc / r4->base_proc);
    row("whole process, image only", f->proc, f->base_proc, "s", target);
    printf("  %-28s %s\n", "images", same_file(ppm, bppm) ? "identical" : "DIFFER");
    for (k = 0; k < NFMT; k++) {
        f->trace[k] = t[2 + k] / f->proc;
        printf("  %-6s %8.1f MB  %8.4f s  %8.1f MB/s  %6.2fx the untraced process"
               "   (renderer 4: %.2fx)\n", fmts[k], bytes[k] / 1e6, t[2 + k],
               bytes[k] / t[2 + k] / 1e6, f->trace[k], r4->trace[k]);
    }
}

/* The full path of program name on the PATH, or NULL. */
static char *on_path(const char *name)
{
    static char buf[2][1024];
    static int next;
    const char *p = getenv("PATH");
    char *out = buf[next++ % 2];

    while (p && *p) {
        size_t n = strcspn(p, ":");
        snprintf(out, sizeof buf[0], "%.*s/%s", (int)n, p, name);
        if (n > 0 && access(out, X_OK) == 0) return out;
        p += n + (p[n] == ':');
    }
    return NULL;
}

/* The course's Java renderers on the scenes of fig[0..n-1], beside
** pipetrace's figures of the same scenes; skipped, with a line that says
** why, without java, javac or the course's jars. */
static void java_rows(const figures *fig, int n)
{
    const char *course = getenv("PT_COURSE_DIR");
    char *java = on_path("java"), *javac = on_path("javac");
    int k;

    if (!course || !*course) course = "../shared/reference/course";
    printf("\nthe course's Java renderers, the same octagons (%s): CPU seconds, the whole\n"
           "process the least of 3, the render in the JVM the least of %d\n", course, RENDERS);
    if (!java || !javac) {
        printf("  skipped: no java and javac on the PATH\n");
        return;
    }
    printf("  %-26s %10s %10s %7s   %10s %10s %7s   %s\n", "", "Java", "pipetrace", "ratio",
           "Java", "pipetrace", "ratio", "images");
    printf("  %-26s %10s %10s %7s   %10s %10s\n", "", "process", "process", "", "render",
           "render");
    for (k = 0; k < n; k++) {
        const figures *f = &fig[k];
        char jar[600], harness[600], classes[600], cp[1300], cmd[4000], name[64], cls[16];
        char flags[16], *kase, *jppm = path("bench-java.ppm"), *ppm = path("bench-pt.ppm");
        char *pt = path("pipetrace");
        char *img[] = {pt, f->scene, "--image", ppm, NULL};
        double tj, rj = -1;
        FILE *p;

        snprintf(jar, sizeof jar, "%s/renderer%s/renderer%s%s.jar", course, f->renderer,
                 f->renderer[0] == '4' ? "" : "_", f->renderer);
        snprintf(harness, sizeof harness, "%s/renderer%s/Kraft%s.java", course, f->renderer,
                 f->renderer);
        if (access(jar, R_OK) != 0 || access(harness, R_OK) != 0) {
            printf("  %-26s skipped: no %s (PT_COURSE_DIR names the course's folder)\n",
                   f->title, access(jar, R_OK) != 0 ? jar : harness);
            continue;
        }
        snprintf(name, sizeof name, "bench-java%s", f->renderer);
        snprintf(classes, sizeof classes, "%s", path(name));
        snprintf(cmd, sizeof cmd, "mkdir -p '%s' && '%s' -nowarn -cp '%s' -d '%s' '%s' "
                 "tests/bench/BenchKraft.java > /dev/null 2>&1", classes, javac, jar, classes,
                 harness);
        if (system(cmd) != 0) {
            printf("  %-26s skipped: javac could not compile %s with tests/bench/BenchKraft.java\n",
                   f->title, harness);
            continue;
        }
        snprintf(cp, sizeof cp, "%s:%s", jar, classes);
        snprintf(name, sizeof name, "bench-r%s%s.case", f->renderer, f->flags);
        snprintf(flags, sizeof flags, "%s case", f->flags);
        kase = make_scene(name, "25000", f->renderer, flags);
        snprintf(cls, sizeof cls, "Kraft%s", f->renderer);
        {
            char *argv[] = {java, "-cp", cp, cls, kase, jppm, path("bench-java.log"),
                            "debug=none", NULL};
            tj = spawn_least(argv);
        }
        spawn(img, "/dev/null", NULL, NULL);
        snprintf(cmd, sizeof cmd, "'%s' -cp '%s' BenchKraft '%s' %d", java, cp, kase, RENDERS);
        p = popen(cmd, "r");
        if (!p || fscanf(p, "render %lf", &rj) != 1) rj = -1;
        if (p) pclose(p);
        printf("  %-26s %10.4f %10.4f %6.2fx   ", f->title, tj, f->proc, f->proc / tj);
        if (rj > 0) printf("%10.4f %10.4f %6.2fx", rj, f->render, f->render / rj);
        else printf("%10s %10.4f %7s", "failed", f->render, "");
        printf("   %s\n", same_file(ppm, jppm) ? "identical" : "DIFFER");
        remove(jppm);
        remove(path("bench-java.log"));
    }
}

/* The peak resident memory of the teaching tools (why, journey, accuracy)
** beside the render command's, on spheres of the course's `shape` (the
** figures docs/limits.md gives). */
static void tool_memory_rows(char *pt)
{
    static const struct { const char *name, *shape; } sph[2] = {
        {"bench-sphere300.scene", "300 300"}, {"bench-sphere1400.scene", "1400 1400"}};
    char *scene[2], *out = path("bench-tool.out");
    int k, i;

    for (k = 0; k < 2; k++) {
        FILE *f = NULL;
        scene[k] = strdup(path(sph[k].name));
        if (!scene[k] || !(f = fopen(scene[k], "w"))) die("cannot write a sphere scene");
        fprintf(f, "model s\nshape sphere 1 %s\ntranslate 0 0 -3\n", sph[k].shape);
        if (fclose(f) != 0) die("cannot write a sphere scene");
    }
    printf("\npeak resident memory of the teaching tools, MiB (docs/limits.md)\n");
    for (k = 0; k < 2; k++) {
        char *runs[5][8] = {
            {pt, scene[k], "--image", out, NULL},
            {pt, "why", scene[k], "400", "300", NULL},
            {pt, "journey", scene[k], "--vertex", "1", "--image", out, NULL},
            {pt, "journey", scene[k], "--vertex", "1", "--svg", out, NULL},
            {pt, "accuracy", scene[k], "--no-time", NULL}};
        static const char *const what[5] = {
            "render --image", "why 400 300", "journey --vertex 1 --image",
            "journey --vertex 1 --svg", "accuracy --no-time"};
        printf("  shape sphere 1 %s:\n", sph[k].shape);
        for (i = 0; i < 5; i++) {
            long rss;

            spawn(runs[i], "/dev/null", &rss, NULL);
            printf("    %-30s %8.1f\n", what[i], (double)rss / 1024);
        }
        remove(scene[k]);
        free(scene[k]);
    }
    remove(out);
}

/* The untraced process and the JSON Lines trace of scene on one thread and
** on two, taking turns, with every CPU allowed: wall seconds, the least of
** RUNS, and the CPU seconds of that run; target: what renderer 4's aims at. */
static void two_cpu_rows(char *pt, char *scene, char *ppm, const char *target)
{
    char *a[] = {pt, scene, "--image", ppm, NULL};
    char *j1[] = {pt, scene, "--image", ppm, "--format", "jsonl", "--trace", "/dev/null",
                  "--threads", "1", NULL};
    char *j2[] = {pt, scene, "--image", ppm, "--format", "jsonl", "--trace", "/dev/null",
                  "--threads", "2", NULL};
    char *const *all[] = {a, j1, j2};
    double w[3], c[3];

    spawn_rounds(all, 3, c, w);
    printf("  %-28s %8.4f s  (%.4f s)\n", "untraced process", w[0], c[0]);
    printf("  %-28s %8.4f s  (%.4f s)  %6.2fx the untraced process\n",
           "jsonl, --threads 1", w[1], c[1], w[1] / w[0]);
    printf("  %-28s %8.4f s  (%.4f s)  %6.2fx the untraced process   (%s)\n",
           "jsonl, --threads 2", w[2], c[2], w[2] / w[0], target);
}

/* What a user waits for with both CPUs free: renderer 4's scene, then the
** course's renderers 7 and 9 (fig[1 .. 3]); with s800, the peak memory of
** renderer 4's trace on two threads at 800k vertices. */
static void two_cpus(figures fig[4], char *pt, char *ppm, char *s800)
{
    int cpus = use_every_cpu(1), k;

    printf("\nall %d CPUs: wall seconds, the least of %d (CPU seconds of that run)\n",
           cpus, RUNS);
    two_cpu_rows(pt, fig[0].scene, ppm, "target <= 2.0x");
    if (s800) {
        char *m2[] = {pt, s800, "--image", ppm, "--format", "jsonl", "--trace", "-",
                      "--threads", "2", NULL};
        long trss;
        double bytes;
        spawn(m2, NULL, &trss, &bytes);
        printf("  peak resident memory, 800,000 vertices, JSON Lines on two threads (to a\n"
               "  pipe): %.1f MiB\n", (double)trss / 1024);
    }
    for (k = 1; k < 4; k++) {
        printf(" the course's %s (%s)\n", fig[k].title, fig[k].scene);
        two_cpu_rows(pt, fig[k].scene, ppm, "renderer 4's target <= 2.0x");
    }
    use_every_cpu(0);
}

int main(int argc, char **argv)
{
    static figures fig[4] = {{"renderer 4", "4", "", NULL, 0, 0, 0, 0, {0}},
                             {"renderer 7", "7", "", NULL, 0, 0, 0, 0, {0}},
                             {"renderer 9", "9", "", NULL, 0, 0, 0, 0, {0}},
                             {"renderer 9 with anti-aliasing", "9", "aa", NULL, 0, 0, 0, 0, {0}}};
    char *s200, *s800, *s3200, *pt = NULL, *ppm, *bppm;
    double bp, br, pp, pr, tproc, tbase, t800, t3200, bytes;
    long rss;
    char note[256];
    pt_scene scene;
    int k;

    dir = argc > 1 ? argv[1] : "build";
    setvbuf(stdout, NULL, _IOLBF, 0);           /* each line as it comes (minutes in all) */
    printf("pipetrace bench: CPU seconds, the least of %d runs; figures depend on the machine\n",
           RUNS);
    s200 = make_scene("bench-200k.scene", "25000", "4", "");
    s800 = make_scene("bench-800k.scene", "100000", "4", "");
    s3200 = make_scene("bench-3200k.scene", "400000", "4", "");
    fig[0].scene = s200;
    fig[1].scene = make_scene("bench-r7.scene", "25000", "7", "");
    fig[2].scene = make_scene("bench-r9.scene", "25000", "9", "");
    fig[3].scene = make_scene("bench-r9aa.scene", "25000", "9", "aa");
    pt = lasting_path("pipetrace");              /* kept to the end: path()'s */
    ppm = lasting_path("bench-pt.ppm");          /*   buffers are reused (the end */
    bppm = lasting_path("bench-base.ppm");       /*   removes ppm and bppm) */
    if (argc > 2 && strcmp(argv[2], "two-cpus") == 0) {    /* that part alone */
        two_cpus(fig, pt, ppm, NULL);
        remove(ppm);
        return 0;
    }

    load(&scene, s200);                         /* to choose the CPU with */
    pin_fastest(&scene, note, sizeof note);
    printf("one CPU for everything, the fastest at rendering (%s)\n", note);
    pt_scene_free(&scene);
    pp = load(&scene, s200);
    pr = render(&scene);
    pt_scene_free(&scene);
    baseline(s200, &bp, &br);
    printf("\nbenchmark scene %s: 200,000 vertices and segments, 1920 x 1080\n", s200);
    printf("  %-28s %15s %15s %7s   %s\n", "", "pipetrace", "plain C", "ratio", "target");
    row("parse, in process", pp, bp, "s", "<= 1.0x");
    row("render, in process (warm)", pr, br, "s", "<= 1.5x");
    {
        char *a[] = {pt, s200, "--image", ppm, NULL};
        char *b[] = {path("baseline"), s200, bppm, NULL};
        char *tr[NFMT][9];
        /* JSON Lines in its two parts, for where its time goes: the vertex
        ** records (--stage for each of the classic camera's stages, no raster
        ** records) and the raster records (pixels and clipped steps) */
        char *vx[8 + 2 * PT_CLASSIC_NORDER + 1] = {pt, s200, "--image", ppm, "--format", "jsonl",
                                            "--trace", "-"};
        char *rs[] = {pt, s200, "--image", ppm, "--format", "jsonl", "--trace", "-",
                      "--stage", "raster", NULL};
        char *const *all[4 + NFMT];
        double t[4 + NFMT], tbytes[NFMT], pbytes[2];
        for (k = 0; k < NFMT; k++) {            /* the traces, to /dev/null: */
            char *c[] = {pt, s200, "--image", ppm, "--format", (char *)fmts[k], "--trace",
                         "-", NULL};
            memcpy(tr[k], c, sizeof c);
            spawn(tr[k], NULL, NULL, &tbytes[k]);   /* their bytes, counted once */
            tr[k][7] = "/dev/null";
            all[2 + k] = tr[k];
        }
        for (k = 0; k < PT_CLASSIC_NORDER; k++) {   /* every classic stage */
            vx[8 + 2 * k] = "--stage";
            vx[9 + 2 * k] = (char *)pt_stage_infos[pt_classic_order[k]].name;
        }
        vx[8 + 2 * PT_CLASSIC_NORDER] = NULL;
        spawn(vx, NULL, NULL, &pbytes[0]);
        spawn(rs, NULL, NULL, &pbytes[1]);
        vx[7] = rs[7] = "/dev/null";
        all[0] = a;
        all[1] = b;
        all[2 + NFMT] = vx;
        all[3 + NFMT] = rs;
        spawn_rounds(all, 4 + NFMT, t, NULL);
        tproc = t[0];
        tbase = t[1];
        row("whole process, image only", tproc, tbase, "s", "<= 1.3x");
        printf("  %-28s %s\n", "images", same_file(ppm, bppm) ? "identical" : "DIFFER");
        spawn(a, "/dev/null", NULL, NULL);
        printf("  %-28s %10ld\n", "page faults, whole process", faults);
        printf("\ntraces of the same scene, whole process, to /dev/null\n");
        for (k = 0; k < NFMT; k++) {
            printf("  %-6s %8.1f MB  %8.4f s  %8.1f MB/s  %6.2fx the untraced process%s\n",
                   fmts[k], tbytes[k] / 1e6, t[2 + k], tbytes[k] / t[2 + k] / 1e6,
                   t[2 + k] / tproc,
                   k == 0 ? "   (one thread: two, below)" : k == 2 ? "   (target >= 400 MB/s)" : "");
            fig[0].trace[k] = t[2 + k] / tproc;
        }
        printf("  jsonl in parts, each its own run (the header in both):\n");
        for (k = 0; k < 2; k++)
            printf("    %-17s %8.1f MB  %8.4f s  %8.1f MB/s  %6.2fx, %+.4f s over untraced\n",
                   k == 0 ? "vertex records" : "raster records", pbytes[k] / 1e6,
                   t[2 + NFMT + k], pbytes[k] / t[2 + NFMT + k] / 1e6, t[2 + NFMT + k] / tproc,
                   t[2 + NFMT + k] - tproc);
        fig[0].render = pr;
        fig[0].base_render = br;
        fig[0].proc = tproc;
        fig[0].base_proc = tbase;
    }
    for (k = 1; k < 4; k++) course_rows(&fig[k], &fig[0]);
    {
        char *a[] = {pt, s800, "--image", ppm, NULL};
        char *b[] = {pt, s3200, "--image", ppm, NULL};
        char *c[] = {pt, s800, "--image", ppm, "--format", "jsonl", "--trace", "-", NULL};
        long trss;
        spawn(a, "/dev/null", &rss, NULL);
        printf("\npeak resident memory, 800,000 vertices: %.1f MiB   (target <= 60 MiB)\n",
               (double)rss / 1024);
        spawn(c, NULL, &trss, &bytes);
        printf("  with its JSON Lines trace (%.1f MB, to a pipe): %.1f MiB\n", bytes / 1e6,
               (double)trss / 1024);
        t800 = spawn_least(a);
        t3200 = spawn_least(b);
        printf("\nscaling, whole process, image only:\n");
        printf("  %9s vertices %8.4f s  %6.1f ns a vertex\n", "200,000", tproc, tproc / 2e5 * 1e9);
        printf("  %9s vertices %8.4f s  %6.1f ns a vertex  (%.2fx the 200k rate)\n", "800,000",
               t800, t800 / 8e5 * 1e9, (t800 / 8e5) / (tproc / 2e5));
        printf("  %9s vertices %8.4f s  %6.1f ns a vertex  (%.2fx the 200k rate)\n", "3,200,000",
               t3200, t3200 / 3.2e6 * 1e9, (t3200 / 3.2e6) / (tproc / 2e5));
    }
    two_cpus(fig, pt, ppm, s800);
    tool_memory_rows(pt);
    java_rows(fig, 4);
    remove(ppm);
    remove(bppm);
    return 0;
}
