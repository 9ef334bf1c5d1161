/*
** src/tools/class/cmd_class.c -- pipetrace class: read the folder, run a diff per file
** See LICENSE for copyright and license.
**
** The order of work: EXPECTED (a scene is rendered once, by this program in
** a child process, into a private temporary folder: its JSON Lines trace with
** every stage and raster records, and its image); the folder's names, sorted
** byte by byte so every run lists the same rows; each name judged by lstat()
** and its first bytes (never opened unless it is a regular file or a link to
** one, opened without blocking); the diffs, each a forked child running
** pt_diff_run() with its standard output and error into a pipe and its
** pt_diff_outcome into a second one, at most --jobs at a time (per row its
** trace, its image, and, EXPECTED a scene, its image against its own trace:
** is it what the student's log drew?); then the
** report (class_report.c).
*/
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>
#include "io/outfile.h"
#include "io/tread.h"
#include "tools/cli.h"
#include "tools/commands.h"
#include "tools/class/class.h"

#define CLASS_MAXTEXT (1u << 20)     /* a diff's output kept for --html */
#define CLASS_MAXFILES 100000        /* names read from the folder */

static const char class_usage[] =
"usage: pipetrace class EXPECTED DIR [--csv FILE] [--html FILE] [--jobs N]\n"
"                      [--tol ABS] [--rel REL]\n"
"\n"
"Diff every student's file in DIR against EXPECTED, as `pipetrace diff` does\n"
"with its verdict, and report per student the verdict, the first wrong stage,\n"
"the mistake named (\"unknown\" when none explains everything, \"ambiguous: A\n"
"or B\" when several do) and the differing vertices and pixels; then how many\n"
"went wrong first at each stage and how many made each mistake.\n"
"\n"
"  EXPECTED     a scene (rendered here, with every stage and its pixels) or a\n"
"               trace or log that diff reads\n"
"  DIR          the students' files: traces (JSON Lines, text), the course's\n"
"               logs, images (PPM, PNG).  A student is a file name without its\n"
"               extension: alice.log and alice.ppm are one row, the image\n"
"               compared with EXPECTED's image and with the student's own\n"
"               log (EXPECTED a scene; a mistake only the latter names is\n"
"               added after \"; \").  Names that start with '.' are skipped;\n"
"               anything that cannot be read gets a row that says why.\n"
"               Nothing in DIR is written.\n"
"  --csv FILE   the table as CSV (RFC 4180); an ambiguous row's last cell is\n"
"               the scene diff printed to tell its mistakes apart\n"
"  --html FILE  a self-contained page: a bar chart per stage and per mistake,\n"
"               a row per student linking to that student's diff (and to\n"
"               that scene)\n"
"  --jobs N     diffs run at once (default 2)\n"
"  --tol ABS, --rel REL  as for diff\n"
"\n"
"Exit status: 0 every file was diffed or reported, 1 usage error, 2 EXPECTED\n"
"or DIR cannot be read, or an output cannot be written.\n"
"Docs: docs/teaching.md\n";

typedef struct copts {
    const char *csv, *html, *tol, *rel;
    int jobs;
} copts;

/* ===== EXPECTED ===== */

/* The kind of what path holds, from its first bytes; PT_TK_UNKNOWN when it
** is no trace, log or image (a scene, then).  Returns 0, or -1 with the reason
** in err. */
static int sniff(const char *path, pt_tkind *kind, char *err, size_t n)
{
    char head[64];
    struct stat st;
    ssize_t got;
    int fd = open(path, O_RDONLY | O_NONBLOCK);

    if (fd < 0) { snprintf(err, n, "%s", strerror(errno)); return -1; }
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        snprintf(err, n, "not a regular file");
        close(fd);
        return -1;
    }
    got = read(fd, head, sizeof head);
    close(fd);
    if (got < 0) { snprintf(err, n, "%s", strerror(errno)); return -1; }
    *kind = pt_tread_kind(head, (size_t)got);
    return 0;
}

static int is_image(pt_tkind k)
{
    return k == PT_TK_PPM || k == PT_TK_P3 || k == PT_TK_PNG;
}

/* Render scene into the files trace (JSON Lines) and image with this very
** program: every stage of renderer 4 and the matrix camera (renderers 7 and
** 9 trace every stage anyway).  Returns 0, or the exit status after the
** scene's own message. */
static int render_expected(const char *scene, const char *trace, const char *image)
{
    int status, whole;
    pid_t pid;
    pt_scene s;

    if ((status = pt_cli_load(&s, scene)) != 0) return status;
    whole = s.renderer == 7 || s.renderer == 9;
    pt_scene_free(&s);

    fflush(stdout);
    fflush(stderr);
    pid = fork();
    if (pid < 0) { perror("pipetrace class: fork"); return PT_EXIT_INPUT; }
    if (pid == 0) {
        char *argv[] = {"pipetrace", (char *)scene, "--format", "jsonl", "--trace",
                        (char *)trace, "--image", (char *)image, "--all-stages", NULL};
        if (whole) argv[8] = NULL;
        int devnull = open("/dev/null", O_WRONLY);
        if (devnull >= 0) dup2(devnull, 1);     /* the summary of --trace */
        execv("/proc/self/exe", argv);
        fprintf(stderr, "pipetrace class: cannot run /proc/self/exe: %s\n", strerror(errno));
        _exit(PT_EXIT_INPUT);
    }
    if (waitpid(pid, &status, 0) < 0) return PT_EXIT_INPUT;
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return 0;
    return WIFEXITED(status) && WEXITSTATUS(status) ? WEXITSTATUS(status) : PT_EXIT_INPUT;
}

/* ===== the folder ===== */

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* What is at dir/name, when it is no file to diff: "a directory", "a broken
** symbolic link", ...; NULL for a regular file (or a link to one) whose
** first bytes say *kind. */
static const char *judge(const char *dir, const char *name, pt_tkind *kind, char *why, size_t n)
{
    char path[4096];
    struct stat st;

    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (lstat(path, &st) != 0) { snprintf(why, n, "%s", strerror(errno)); return why; }
    if (S_ISLNK(st.st_mode) && stat(path, &st) != 0) {
        snprintf(why, n, errno == ELOOP ? "a symbolic link in a loop" :
                 errno == ENOENT ? "a broken symbolic link" : "%s", strerror(errno));
        return why;
    }
    if (S_ISDIR(st.st_mode)) return "a folder, not read";
    if (!S_ISREG(st.st_mode)) return "not a regular file (a FIFO, socket or device), not read";
    if (sniff(path, kind, why, n) != 0) return why;
    return NULL;
}

/* The row named name (the stem), made when new with file's own name as the key. */
static pt_class_row *row_for(pt_class *c, size_t *cap, const char *name, size_t len)
{
    size_t k;
    pt_class_row *r;

    for (k = 0; k < c->nrow; k++)
        if (strlen(c->row[k].name) == len && !memcmp(c->row[k].name, name, len))
            return &c->row[k];
    if (c->nrow == *cap) {
        size_t ncap = *cap ? 2 * *cap : 64;
        pt_class_row *nr = realloc(c->row, ncap * sizeof *nr);
        if (!nr) return NULL;
        c->row = nr;
        *cap = ncap;
    }
    r = &c->row[c->nrow];
    memset(r, 0, sizeof *r);
    pt_sbuf_init(&r->text[0]);
    pt_sbuf_init(&r->text[1]);
    pt_sbuf_init(&r->text[2]);
    if (!(r->name = malloc(len + 1))) return NULL;
    memcpy(r->name, name, len);
    r->name[len] = '\0';
    c->nrow++;
    return r;
}

static char *dup_str(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

/* Read the folder into c->row.  Returns 0, or the exit status after the message. */
static int read_folder(pt_class *c)
{
    DIR *d = opendir(c->dir);
    struct dirent *e;
    char **names = NULL, why[256];
    size_t n = 0, cap = 0, rcap = 0, k;
    int rc = 0;

    if (!d) {
        fprintf(stderr, "pipetrace class: %s: error: %s\n", c->dir, strerror(errno));
        return PT_EXIT_INPUT;
    }
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.') continue;
        if (n == CLASS_MAXFILES) {
            fprintf(stderr, "pipetrace class: %s: error: more than %d files\n", c->dir,
                    CLASS_MAXFILES);
            rc = PT_EXIT_INPUT;
            break;
        }
        if (n == cap) {
            char **nn = realloc(names, (cap = cap ? 2 * cap : 64) * sizeof *nn);
            if (!nn) { rc = -1; break; }
            names = nn;
        }
        if (!(names[n] = dup_str(e->d_name))) { rc = -1; break; }
        n++;
    }
    closedir(d);
    if (rc == 0) qsort(names, n, sizeof *names, by_name);
    for (k = 0; k < n && rc == 0; k++) {
        pt_tkind kind = PT_TK_UNKNOWN;
        const char *bad = judge(c->dir, names[k], &kind, why, sizeof why);
        const char *dot = strrchr(names[k], '.');
        size_t stem = dot && dot != names[k] ? (size_t)(dot - names[k]) : strlen(names[k]);
        pt_class_row *r;
        /* an unreadable file, or a second trace of one stem, is a row of its own */
        if (bad) stem = strlen(names[k]);
        r = row_for(c, &rcap, names[k], stem);
        if (r && !bad && ((is_image(kind) && r->image) || (!is_image(kind) && r->trace)))
            r = row_for(c, &rcap, names[k], stem = strlen(names[k]));
        if (!r) { rc = -1; break; }
        if (bad) {
            if (!r->why && !(r->why = dup_str(bad))) rc = -1;
        } else if (is_image(kind)) {
            if (!(r->image = dup_str(names[k]))) rc = -1;
        } else if (!(r->trace = dup_str(names[k]))) {
            rc = -1;
        }
    }
    for (k = 0; k < n; k++) free(names[k]);
    free(names);
    if (rc < 0) fputs("pipetrace class: out of memory\n", stderr);
    return rc < 0 ? PT_EXIT_INPUT : rc;
}

/* ===== the diffs ===== */

typedef struct job {
    pid_t pid;
    int text, res;               /* the pipes' read ends */
    pt_class_row *r;
    int image;                   /* 0: the trace's diff, 1: the image's, 2: the
                                 ** image's against the row's own trace */
} job;

/* Start the diff of r's trace (image 0) or image (1) against exp, or of
** r's image against r's own trace (2, exp unused); an image's diff gets the
** scene (NULL: none) so that it can name a picture moved by the viewport's
** corner.  Returns 0, or -1 (fork or pipe failed: the row says so). */
static int start(job *j, const copts *o, const char *dir, const char *exp, pt_class_row *r,
                 int image, const char *scene)
{
    int tp[2], rp[2];
    char path[4096], own[4096];

    snprintf(path, sizeof path, "%s/%s", dir, image ? r->image : r->trace);
    snprintf(own, sizeof own, "%s/%s", dir, r->trace ? r->trace : "");
    if (pipe(tp) != 0) return -1;
    if (pipe(rp) != 0) { close(tp[0]); close(tp[1]); return -1; }
    fflush(stdout);
    fflush(stderr);
    j->pid = fork();
    if (j->pid < 0) {
        close(tp[0]); close(tp[1]); close(rp[0]); close(rp[1]);
        return -1;
    }
    if (j->pid == 0) {
        char *argv[14];
        int argc = 0, rc;
        pt_diff_outcome out;
        close(tp[0]);
        close(rp[0]);
        dup2(tp[1], 1);
        dup2(tp[1], 2);
        close(tp[1]);
        argv[argc++] = "diff";
        if (!image) argv[argc++] = "--verdict";
        argv[argc++] = "--show";
        argv[argc++] = "3";
        if (o->tol) { argv[argc++] = "--tol"; argv[argc++] = (char *)o->tol; }
        if (o->rel) { argv[argc++] = "--rel"; argv[argc++] = (char *)o->rel; }
        if (image && scene) { argv[argc++] = "--scene"; argv[argc++] = (char *)scene; }
        argv[argc++] = image == 2 ? own : (char *)exp;
        argv[argc++] = path;
        argv[argc] = NULL;
        rc = pt_diff_run(argc, argv, &out);
        fflush(stdout);
        fflush(stderr);
        if (write(rp[1], &out, sizeof out) != (ssize_t)sizeof out) _exit(PT_EXIT_INPUT);
        _exit(rc);
    }
    close(tp[1]);
    close(rp[1]);
    j->text = tp[0];
    j->res = rp[0];
    j->r = r;
    j->image = image;
    return 0;
}

/* The first line of what the child printed, for a row that has no verdict. */
static char *first_line(const pt_sbuf *t)
{
    size_t n = 0;
    char *s;

    while (n < t->len && t->s[n] != '\n') n++;
    if (!(s = malloc(n + 1))) return NULL;
    memcpy(s, t->s, n);
    s[n] = '\0';
    return s;
}

/* In t, every occurrence of from replaced by to.  Returns 0, or -1 out of memory. */
static int replace_all(pt_sbuf *t, const char *from, const char *to)
{
    pt_sbuf n;
    size_t lf = strlen(from), k = 0;
    const char *hit;

    if (!t->len || !lf || !strstr(t->s, from)) return 0;
    pt_sbuf_init(&n);
    while ((hit = strstr(t->s + k, from)) != NULL) {
        pt_sbuf_addn(&n, t->s + k, (size_t)(hit - (t->s + k)));
        pt_sbuf_add(&n, to);
        k = (size_t)(hit - t->s) + lf;
    }
    pt_sbuf_add(&n, t->s + k);
    if (n.failed) { pt_sbuf_free(&n); return -1; }
    pt_sbuf_free(t);
    *t = n;
    return 0;
}

/* Finish job j (its text read to the end): its outcome into the row. */
static void finish(const pt_class *c, job *j)
{
    pt_diff_outcome out;
    ssize_t got = read(j->res, &out, sizeof out);
    int status = 0, k;
    pt_class_row *r = j->r;
    char shown[4200];

    snprintf(shown, sizeof shown, "%s (rendered)", c->expected);

    close(j->res);
    close(j->text);
    while (waitpid(j->pid, &status, 0) < 0 && errno == EINTR) {}
    if (got != (ssize_t)sizeof out || !WIFEXITED(status)) {
        char why[64];
        snprintf(why, sizeof why, "diff stopped%s%d",
                 WIFSIGNALED(status) ? " by signal " : " with status ",
                 WIFSIGNALED(status) ? WTERMSIG(status) : WEXITSTATUS(status));
        if (!r->why) r->why = dup_str(why);
        return;
    }
    for (k = 0; k < 2; k++)                 /* no temporary names in a report */
        if (c->rendered[k] && replace_all(&r->text[j->image], c->rendered[k], shown) != 0) {
            if (!r->why) r->why = dup_str("out of memory");
            return;
        }
    if (j->image == 2) { r->own = out; r->has_own = 1; return; }  /* only its name counts */
    if (j->image) { r->im = out; r->has_im = 1; }
    else { r->t = out; r->has_t = 1; }
    if (out.status == PT_EXIT_INPUT && !r->why) r->why = first_line(&r->text[j->image]);
}

/* Run every diff, at most o->jobs at a time.  Returns 0, or -1 out of memory. */
static int run_all(pt_class *c, const copts *o, const char *exp_trace, const char *exp_image)
{
    job run[16];
    struct pollfd pf[16];
    size_t next = 0, k;
    int nrun = 0, phase = 0;        /* next: the row; phase 0 its trace, 1 its image,
                                    ** 2 its image against its trace */
    char buf[65536];

    for (;;) {
        while (nrun < o->jobs && next < c->nrow) {
            pt_class_row *r = &c->row[next];
            int image = phase;
            if (phase < 2) phase++; else { phase = 0; next++; }
            if (r->why) continue;
            if (!image && !r->trace) continue;
            if (image && (!r->image || !exp_image)) continue;
            if (image == 2 && (!r->trace || !c->scene)) continue;
            if (start(&run[nrun], o, c->dir, image ? exp_image : exp_trace, r, image,
                      c->scene ? c->expected : NULL) != 0) {
                if (!r->why) r->why = dup_str("cannot start a diff (no processes or pipes left)");
                continue;
            }
            nrun++;
        }
        if (nrun == 0) break;
        for (k = 0; k < (size_t)nrun; k++) {
            pf[k].fd = run[k].text;
            pf[k].events = POLLIN;
        }
        if (poll(pf, (nfds_t)nrun, -1) < 0) {
            if (errno == EINTR) continue;
            return -1;
        }
        for (k = (size_t)nrun; k-- > 0;) {
            ssize_t got;
            if (!(pf[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
            got = read(run[k].text, buf, sizeof buf);
            if (got > 0) {
                pt_sbuf *t = &run[k].r->text[run[k].image];
                if (t->len < CLASS_MAXTEXT) pt_sbuf_addn(t, buf, (size_t)got);
                if (t->failed) return -1;
                continue;
            }
            if (got < 0 && errno == EINTR) continue;
            finish(c, &run[k]);
            run[k] = run[--nrun];
        }
    }
    return 0;
}

/* ===== the command ===== */

static int parse_args(copts *o, const char **pos, int argc, char **argv)
{
    int k, npos = 0;

    memset(o, 0, sizeof *o);
    o->jobs = 2;
    for (k = 1; k < argc; k++) {
        const char *a = argv[k], *val;
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) { fputs(class_usage, stdout); return 0; }
        if (!strcmp(a, "--csv") || !strcmp(a, "--html") || !strcmp(a, "--jobs") ||
            !strcmp(a, "--tol") || !strcmp(a, "--rel")) {
            int rc = pt_cli_value("class", argc, argv, &k, &val);
            if (rc >= 0) return rc;
            if (!strcmp(a, "--csv")) o->csv = val;
            else if (!strcmp(a, "--html")) o->html = val;
            else if (!strcmp(a, "--tol")) o->tol = val;
            else if (!strcmp(a, "--rel")) o->rel = val;
            else {
                uint64_t j;
                if (pt_cli_count(val, 1, 16, &j) != 0)
                    return pt_cli_usage("class", "--jobs takes a count from 1 to 16, not '%s'", val);
                o->jobs = (int)j;
            }
            continue;
        }
        if (a[0] == '-' && a[1]) return pt_cli_unknown("class", class_usage, a);
        if (npos == 2) return pt_cli_usage("class", "one EXPECTED and one DIR, not also '%s'", a);
        pos[npos++] = a;
    }
    if (npos < 2) return pt_cli_usage("class", "%s", "name EXPECTED and DIR");
    return -1;
}

/* 1 when path would be written into dir (its folder is dir). */
static int inside(const char *path, const char *dir)
{
    char folder[4096];
    const char *slash = strrchr(path, '/');
    struct stat a, b;

    if (!slash) snprintf(folder, sizeof folder, ".");
    else snprintf(folder, sizeof folder, "%.*s", (int)(slash - path + (slash == path)), path);
    return stat(folder, &a) == 0 && stat(dir, &b) == 0 && a.st_dev == b.st_dev &&
           a.st_ino == b.st_ino;
}

/* Write sb to path (whole or not at all).  Returns 0, or PT_EXIT_INPUT. */
static int write_out(const char *path, const pt_sbuf *sb)
{
    pt_outfile of;
    char err[512];

    if (pt_outfile_open(&of, path, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace class: %s\n", err);
        return PT_EXIT_INPUT;
    }
    if (sb->len) fwrite(sb->s, 1, sb->len, of.f);
    return pt_outfile_finish(&of, 0, "pipetrace class") ? PT_EXIT_INPUT : 0;
}

static void free_class(pt_class *c)
{
    size_t k;

    for (k = 0; k < c->nrow; k++) {
        free(c->row[k].name);
        free(c->row[k].trace);
        free(c->row[k].image);
        free(c->row[k].why);
        pt_sbuf_free(&c->row[k].text[0]);
        pt_sbuf_free(&c->row[k].text[1]);
        pt_sbuf_free(&c->row[k].text[2]);
    }
    free(c->row);
}

int pt_cmd_class(int argc, char **argv)
{
    copts o;
    const char *pos[2] = {NULL, NULL}, *outs[2];
    pt_class c;
    pt_tkind kind = PT_TK_UNKNOWN;
    char err[256], tmp[4096] = "", exp_trace[4200], exp_image[4200];
    const char *td = getenv("TMPDIR");
    pt_sbuf sb;
    int rc, k;

    rc = parse_args(&o, pos, argc, argv);
    if (rc >= 0) return rc;
    memset(&c, 0, sizeof c);
    c.expected = pos[0];
    c.dir = pos[1];
    outs[0] = o.csv;
    outs[1] = o.html;
    for (k = 0; k < 2; k++) {
        if (!outs[k]) continue;
        if (inside(outs[k], c.dir) || pt_outfile_same(outs[k], c.expected)) {
            fprintf(stderr, "pipetrace class: %s: error: %s; class writes nothing there\n",
                    outs[k], pt_outfile_same(outs[k], c.expected) ? "that is EXPECTED"
                    : "that is in the class's folder");
            return PT_EXIT_INPUT;
        }
    }
    if (sniff(c.expected, &kind, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace class: %s: error: %s\n", c.expected, err);
        return PT_EXIT_INPUT;
    }
    if (is_image(kind)) {
        fprintf(stderr, "pipetrace class: %s: error: EXPECTED is an image; give the scene "
                "(or a trace) the class rendered\n", c.expected);
        return PT_EXIT_INPUT;
    }
    snprintf(exp_trace, sizeof exp_trace, "%s", c.expected);
    if (kind == PT_TK_UNKNOWN) {            /* a scene */
        snprintf(tmp, sizeof tmp, "%s/pipetrace-class-XXXXXX", td && *td ? td : "/tmp");
        if (!mkdtemp(tmp)) {
            fprintf(stderr, "pipetrace class: cannot make a temporary folder in %s: %s\n",
                    td && *td ? td : "/tmp", strerror(errno));
            return PT_EXIT_INPUT;
        }
        snprintf(exp_trace, sizeof exp_trace, "%s/expected.jsonl", tmp);
        snprintf(exp_image, sizeof exp_image, "%s/expected.ppm", tmp);
        if ((rc = render_expected(c.expected, exp_trace, exp_image)) != 0) goto done;
        c.scene = c.have_image = 1;
        c.rendered[0] = exp_trace;
        c.rendered[1] = exp_image;
    }
    if ((rc = read_folder(&c)) != 0) goto done;
    if (run_all(&c, &o, exp_trace, c.have_image ? exp_image : NULL) != 0) {
        fputs("pipetrace class: out of memory\n", stderr);
        rc = PT_EXIT_INPUT;
        goto done;
    }
    pt_sbuf_init(&sb);
    pt_class_text(&sb, &c);
    if (!sb.failed && sb.len) fwrite(sb.s, 1, sb.len, stdout);
    rc = sb.failed ? PT_EXIT_INPUT : 0;
    for (k = 0; k < 2 && rc == 0; k++) {
        if (!outs[k]) continue;
        sb.len = 0;
        if (k == 0) pt_class_csv(&sb, &c);
        else pt_class_html(&sb, &c);
        rc = sb.failed ? PT_EXIT_INPUT : write_out(outs[k], &sb);
    }
    pt_sbuf_free(&sb);
    rc = pt_cli_stdout("class", rc);
done:
    if (tmp[0]) {                           /* the temporary folder's files only */
        unlink(exp_trace);
        unlink(exp_image);
        rmdir(tmp);
    }
    free_class(&c);
    return rc;
}
