/*
** src/tools/cmd_quiz.c -- pipetrace quiz: compute a vertex's journey yourself
** See LICENSE for copyright and license.
**
**   pipetrace quiz [SCENE] [--vertex N | --seed S] [--model NAME] [--stage S]
**                  [--json] [--interactive] [--grade DIR [--out FILE]]
**
** Asks for each stage's values in pipeline order, one line of standard input
** per stage ("camera: x_c y_c z_c = ? "), and checks each answer against the
** reference stages' numbers (pt_explain_reference(), src/io/explain.h): in a
** student build (make STAGE_x=FILE.c) the student's stage is not the answer
** key, and a line under the first says so.  Real numbers are right within 1e-6
** absolute or 1e-6 relative; pixel coordinates and the index must be exact;
** "none" answers a value that does not exist.  A wrong answer gets the formula
** with the numbers put in, and the quiz goes on from the right value, so one
** slip costs one stage.  End of input ends the quiz with the score so far.
** At a terminal (or with --interactive) an answer that cannot be read as the
** stage's numbers is asked again, neither counted nor answered; from a file
** it counts as wrong for that stage only, and lines starting with '#' are
** skipped.  --grade DIR grades every answer sheet in DIR (one answer a line,
** as above; a byte-order mark, CRLF, blank lines and comments passed over)
** and writes a CSV of scores, a row a sheet; on a sheet, a wrong answer that
** the reference stage gives from the sheet's own answer before it "follows"
** and counts, so one slip costs one stage there too; a file that is not a
** sheet (not UTF-8 text, over SHEET_MAX, a broken link) gets a row and a note.  Exit status: 0 all right, 1 some
** wrong or unanswered, 2 trouble (bad input, an unreadable sheet, a write error).
** Without --vertex a used vertex is picked at random: --seed S makes the pick
** repeatable (xorshift64*, below); without it the seed is the time.
** A scene of the course's renderer 7 or 9 has questions of its own
** (tools/quiz79.h), asked by ask79() and graded by grade79() (a sheet's
** unreadable line is a FILE:LINE:COL error there); the folder, the CSV
** and the score are shared.
*/
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "tools/commands.h"
#include "tools/cli.h"
#include "tools/quiz79.h"
#include "io/explain.h"
#include "io/outfile.h"
#include "io/sbuf.h"
#include "core/pipetrace.h"

#define TOL        1e-6          /* absolute and relative tolerance for doubles */
#define FOLLOWS    2             /* a result: follows from the answer before */
#define SHEET_MAX  (1L << 20)    /* an answer sheet's size, at most (bytes) */

static const char usage[] =
"usage: pipetrace quiz [SCENE] [--vertex N | --seed S] [--model NAME] [--stage S]\n"
"                      [--json] [--interactive] [--grade DIR [--out FILE]]\n"
"Ask for vertex N's values at every stage, from model coordinates to the\n"
"pixel-array index, one line of standard input per stage, and check them.\n"
"Real numbers are right within 1e-6 absolute or 1e-6 relative; pixel\n"
"coordinates and the index must be exact; write 'none' for a value that does\n"
"not exist.  Without --vertex a used vertex is picked at random (--seed S:\n"
"repeatably).  SCENE defaults to the built-in scene.\n"
"A scene of the course's renderer 7 or 9 asks for the vertex's end of its\n"
"first segment: model, (world,) view, camera, nearclip (t x y z, none or\n"
"dropped), image, clip (edge t x y: x=+1, x=-1, y=+1 or y=-1; a line a cut;\n"
"none or dropped), pixel, viewport and color (the bytes the segment leaves\n"
"there); an answer sheet's line it cannot read is a FILE:LINE:COL error.\n"
"\n"
"  --stage S        ask for stage S only (given the stage before it)\n"
"  --json           print only the score, per stage, as one JSON line\n"
"  --interactive    as at a terminal: an answer that cannot be read as the\n"
"                   stage's numbers is asked again (from a file it counts as\n"
"                   wrong for that stage; lines starting with # are skipped)\n"
"  --grade DIR      grade every answer sheet in DIR (one answer a line) and\n"
"                   write a CSV of scores, a row per sheet (needs --vertex or\n"
"                   --seed, so that every sheet answers the same vertex);\n"
"                   an answer that follows from the sheet's own wrong answer\n"
"                   before it is marked follows and counts\n"
"  --out FILE       where --grade writes the CSV (default: standard output)\n"
"\n"
"Exit status: 0 all right, 1 some answer wrong or missing, 2 trouble (bad\n"
"input, an unreadable sheet, an output that cannot be written).\n"
"Docs: docs/step-why-quiz.md, docs/teaching.md\n";

/* xorshift64* (Vigna, 2016): small, and the same numbers on every platform. */
static uint64_t xorshift(uint64_t *st)
{
    uint64_t x = *st;

    x ^= x >> 12;
    x ^= x << 25;
    x ^= x >> 27;
    *st = x;
    return x * 0x2545F4914F6CDD1DULL;
}

/* Split an answer into numbers (spaces, tabs or commas between them); "none"
** sets none[k].  Returns how many, or -1 when a token is not a number or there
** are more than max. */
static int parse_answer(const char *line, double *v, int *none, int max)
{
    int n = 0;

    for (;;) {
        char tok[64], *end;
        size_t len = 0;

        while (*line == ' ' || *line == '\t' || *line == ',') line++;
        if (!*line) return n;
        while (line[len] && line[len] != ' ' && line[len] != '\t' && line[len] != ',') len++;
        if (n == max || len >= sizeof tok) return -1;
        memcpy(tok, line, len);
        tok[len] = '\0';
        line += len;
        none[n] = !strcmp(tok, "none");
        v[n] = 0;
        if (!none[n]) {
            v[n] = strtod(tok, &end);
            if (end == tok || *end) return -1;
        }
        n++;
    }
}


/* a is b, within the tolerance (non-finite: the same value). */
static int close_enough(double a, double b)
{
    if (isnan(b)) return isnan(a);
    if (!isfinite(b)) return a == b;
    return fabs(a - b) <= TOL || fabs(a - b) <= TOL * fabs(b);
}

/* How an answer to a stage is graded, by the kind of its values (the stage
** table's kind): integers must be exact, reals within the tolerance.
** Whether "none" is an answer is the stage's (pt_stage_nullable()). */
static const int exact_kind[] = {
    [PT_VAL_REAL] = 0,           /* close_enough() */
    [PT_VAL_PIXEL] = 1,          /* x y, each may be none */
    [PT_VAL_INDEX] = 1,          /* idx, or none */
    [PT_VAL_OUTCODE] = 1,        /* code */
};

/* 1 for the stages whose values are integers: they must be exact. */
static int int_stage(pt_stage st)
{
    return exact_kind[pt_stage_infos[st].kind];
}

/* 1 when n answers (none[k]: "none") have the form of an answer to stage st:
** its number of values, or for an integer stage that may lack them, 1 to that
** many "none".  Right or wrong is check()'s question. */
static int readable(pt_stage st, const int *none, int n)
{
    int k, nones = 0;

    for (k = 0; k < n && k < 4; k++) nones += none[k];     /* at most 4 values */
    if (n == pt_coord_count(st)) return 1;
    return pt_stage_nullable(st) && n >= 1 && n <= pt_coord_count(st) &&
           nones == n;
}

/* 1 when the n answers are the values of r, stage st's record. */
static int check_rec(const pt_vrec *r, pt_stage st, const double *v, const int *none, int n)
{
    int k, want = pt_coord_count(st);

    if (int_stage(st) && (r->flags & PT_REC_NULL)) {
        for (k = 0; k < n; k++)
            if (!none[k]) return 0;
        return n >= 1 && n <= want;
    }
    if (n != want) return 0;
    for (k = 0; k < n; k++) {
        double e = pt_stage_infos[st].nint ? (double)pt_rec_int(r, k)
                 : k == 0 ? r->x : k == 1 ? r->y : k == 2 ? r->z : r->w;
        if (none[k]) return 0;
        if (int_stage(st) ? v[k] != e : !close_enough(v[k], e)) return 0;
    }
    return 1;
}

/* 1 when the n answers are stage st's values in j. */
static int check(const pt_journey *j, pt_stage st, const double *v, const int *none, int n)
{
    return check_rec(&j->rec[st], st, v, none, n);
}

/* The record of stage st that the n answers v (none[k]: "none") say, for the
** reference stage after it to take in.  0 when they are not its form. */
static int answer_rec(pt_stage st, const double *v, const int *none, int n, pt_vrec *r)
{
    const pt_stage_info *in = &pt_stage_infos[st];
    int k;

    if (!readable(st, none, n)) return 0;
    memset(r, 0, sizeof *r);
    r->stage = st;
    if (in->kind == PT_VAL_REAL) {
        for (k = 0; k < n; k++) if (none[k]) return 0;
        r->x = v[0]; r->y = n > 1 ? v[1] : 0; r->z = n > 2 ? v[2] : 0; r->w = n > 3 ? v[3] : 0;
        return 1;
    }
    for (k = 0; k < n; k++)             /* whole numbers only, or none */
        if (!none[k] && (v[k] != floor(v[k]) || fabs(v[k]) > 9e15)) return 0;
    if (in->kind == PT_VAL_PIXEL) {
        r->ix = none[0] ? 0 : (int64_t)v[0];
        r->iy = n < 2 || none[1] ? 0 : (int64_t)v[1];
        if (n < 2 || none[0] || none[1])
            r->flags = PT_REC_NULL | (n >= 2 && !none[0] ? PT_REC_HAS_X : 0u)
                                   | (n >= 2 && !none[1] ? PT_REC_HAS_Y : 0u);
    } else if (in->kind == PT_VAL_INDEX) {
        r->i = none[0] ? 0 : (int64_t)v[0];
        if (none[0]) r->flags = PT_REC_NULL;
    } else {
        r->code = (unsigned)v[0];
    }
    return 1;
}

/* One quiz: which stages are asked, how, and what came of each. */
typedef struct quiz {
    const pt_journey *j;
    int first, last;             /* the stages asked: j->order[first..last] */
    FILE *in;                    /* the answers */
    int interactive;             /* ask again what cannot be read */
    int grading;                 /* a sheet: a wrong answer that follows from
                                 ** the sheet's own answer before it counts */
    int talk;                    /* print questions and verdicts (else silent) */
    int echo;                    /* print each answer read (input not a terminal) */
    const pt_q79 *z;             /* renderers 7 and 9: their questions (else NULL) */
    int result[PT_NSTAGES_ALL + PT_Q79_MAX];  /* by order index: 1 right, 0 wrong, -1
                                 ** unanswered, FOLLOWS: wrong, but what the
                                 ** stage gives from the sheet's own answer
                                 ** before it (one slip costs one stage) */
} quiz;

/* "camera: x_c y_c z_c = ? " */
static void prompt(const pt_journey *j, pt_stage st)
{
    int k;

    printf("\n%s:", pt_stage_infos[st].name);
    for (k = 0; k < pt_coord_count(st); k++) printf(" %s", pt_coord_name(st, k));
    printf(" = ? ");
    fflush(stdout);
    (void)j;
}

/* Print why an answer to st was wrong, the formula with the numbers, and the
** value the quiz goes on from.  n < 0: it was not numbers at all. */
static void say_wrong(const pt_journey *j, pt_stage st, int n)
{
    char b[PT_EXPLAINLEN];
    int want = pt_coord_count(st);

    if (n < 0)                              /* only an integer stage may have none */
        printf("  wrong: expected %d number%s%s\n", want, want > 1 ? "s" : "",
               pt_stage_nullable(st) ? ", or none" : "");
    else if (n != want && !(j->rec[st].flags & PT_REC_NULL))
        printf("  wrong: expected %d number%s, found %d\n", want, want > 1 ? "s" : "", n);
    else printf("  wrong\n");
    printf("  %s\n", st == j->order[0] ? "the scene gives:" : pt_journey_info(j, st)->formula);
    pt_explain_stage(b, sizeof b, j, st, "\n    ");
    printf("    %s\n", b);
    pt_explain_values(b, sizeof b, j, st);
    printf("  go on with %s\n", b);
}

/* Ask q's stages in turn, filling q->result. */
static void ask(quiz *q)
{
    const pt_journey *j = q->j;
    char line[1024], b[PT_EXPLAINLEN];
    double pv[4] = {0, 0, 0, 0};            /* the answer before, as read */
    int pnone[4] = {0, 0, 0, 0}, pn = -1, i;

    for (i = 0; i < j->norder; i++) q->result[i] = -1;
    for (i = q->first; i <= q->last; i++) {
        pt_stage st = j->order[i];
        double v[4] = {0, 0, 0, 0};
        int none[4] = {0, 0, 0, 0}, n, ok;

        if (q->talk) prompt(j, st);
        for (;;) {
            if (pt_cli_read_line_from(q->in, line, sizeof line, q->echo) != 0) {
                if (q->talk) printf("\n(end of input)\n");
                return;
            }
            if (!q->interactive && line[0] == '#') continue;    /* a note on a sheet */
            n = parse_answer(line, v, none, 4);
            if (!q->interactive || (n >= 0 && readable(st, none, n))) break;
            if (q->talk) {                  /* not counted, the answer not shown */
                int k, want = pt_coord_count(st);
                printf("  (not read: write %d number%s for", want, want > 1 ? "s" : "");
                for (k = 0; k < want; k++) printf(" %s", pt_coord_name(st, k));
                printf("%s, separated by spaces or commas; try again)\n",
                       pt_stage_nullable(st) ? ", or none" : "");
                prompt(j, st);
            }
        }
        ok = n >= 0 && check(j, st, v, none, n);
        if (!ok && q->grading && n >= 0 && i > 0 && q->result[i - 1] != 1
            && q->result[i - 1] >= 0 && pt_pipeline_ref(j->pipe, st)) {
            pt_vrec in, out;                /* a slip carried forward is no new slip */
            if (answer_rec(j->order[i - 1], pv, pnone, pn, &in)
                && pt_ref_stage(st, &j->par, &in, &out) && check_rec(&out, st, v, none, n))
                ok = FOLLOWS;
        }
        memcpy(pv, v, sizeof pv);
        memcpy(pnone, none, sizeof pnone);
        pn = n;
        q->result[i] = ok;
        if (!q->talk) continue;
        if (ok) {
            pt_explain_values(b, sizeof b, j, st);
            printf("  correct: %s\n", b);
        } else say_wrong(j, st, n);
    }
}

/* Question i's formula and the numbers put in, as say_wrong() shows renderer 4's. */
static void say_worked79(const pt_q79 *z, int i)
{
    char b[PT_EXPLAINLEN], *big;
    const char *f = pt_q79_formula(z, i);
    size_t n;

    printf("  %s\n", f ? f : "the scene gives:");
    n = pt_q79_worked(z, i, b, sizeof b, "\n    ");
    if (n >= sizeof b && (big = malloc(n + 1)) != NULL) {    /* the colour's can be longer */
        pt_q79_worked(z, i, big, n + 1, "\n    ");
        printf("    %s\n", big);
        free(big);
    } else if (n) printf("    %s\n", b);
}

/* Ask q's questions of renderers 7 and 9 in turn, filling q->result: as
** ask() does, the right answer given after a wrong one. */
static void ask79(quiz *q)
{
    char line[1024], b[512];
    int i;

    for (i = 0; i < pt_q79_count(q->z); i++) q->result[i] = -1;
    for (i = q->first; i <= q->last; i++) {
        int r, col = 0;
        const char *why = NULL;

        if (q->talk) printf("\n%s: %s = ? ", pt_q79_name(q->z, i), pt_q79_values(q->z, i));
        fflush(stdout);
        for (;;) {
            if (pt_cli_read_line_from(q->in, line, sizeof line, q->echo) != 0) {
                if (q->talk) printf("\n(end of input)\n");
                return;
            }
            if (!q->interactive && line[0] == '#') continue;    /* a note on a sheet */
            r = pt_q79_grade(q->z, i, line, q->result, NULL, &col, &why);
            if (r >= 0 || !q->interactive) break;
            if (q->talk) {                  /* not counted */
                printf("  (not read: column %d: %s; write %s, separated by spaces or "
                       "commas; try again)\n", col, why, pt_q79_values(q->z, i));
                printf("\n%s: %s = ? ", pt_q79_name(q->z, i), pt_q79_values(q->z, i));
                fflush(stdout);
            }
        }
        q->result[i] = r > 0;
        if (!q->talk) continue;
        pt_q79_answer(q->z, i, b, sizeof b);
        if (r > 0) printf("  correct: %s\n", b);
        else {
            if (r < 0) printf("  wrong: column %d: %s\n", col, why);
            else printf("  wrong\n");
            say_worked79(q->z, i);
            printf("  go on with %s = %s\n", pt_q79_values(q->z, i), b);
        }
    }
}

/* How many of q's stages were answered, and how many right. */
static int score(const quiz *q, int *answered)
{
    int i, right = 0;

    *answered = 0;
    for (i = q->first; i <= q->last; i++) {
        *answered += q->result[i] >= 0;
        right += q->result[i] == 1 || q->result[i] == FOLLOWS;
    }
    return right;
}

/* The k-th (0-based) used vertex of the models passing the filter. */
static int pick(const pt_scene *s, const char *model, uint64_t k,
                const pt_model **m, unsigned long long *v)
{
    size_t mi, j;

    for (mi = 0; mi < s->nmodels; mi++) {
        const pt_model *c = &s->models[mi];
        if (model && strcmp(model, c->name)) continue;
        for (j = 0; j < c->nv; j++)
            if (pt_vertex_used(c, j + 1) && k-- == 0) { *m = c; *v = j + 1; return 0; }
    }
    return -1;
}

/* ===== grading a folder of answer sheets ===== */

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* A sheet as text: its bytes checked and cleaned, an answer a line.  A
** byte-order mark, CR before LF, blank lines and comments ('#' to the end of
** the line) are dropped, as a teacher reading the sheet would skip them.
** numbered: each line kept starts with where it was in the sheet, "LINE
** COL\t" (its first character's), for errors that name the place.
** Returns NULL, or why the sheet cannot be read as text. */
static const char *clean_sheet(const char *t, size_t n, pt_sbuf *out, int numbered)
{
    size_t i = 0, k, line = 1;

    for (k = 0; k < n; k++)
        if (t[k] == '\0') return "not a text file (a word processor's? save it as plain text)";
    for (k = 0; k < n; ) {
        int len = (unsigned char)t[k] < 0x80 ? 1 : pt_sbuf_utf8_len((const unsigned char *)t + k);
        if (len == 0 || k + (size_t)len > n) return "not UTF-8 text";
        k += (size_t)len;
    }
    if (n >= 3 && !memcmp(t, "\xEF\xBB\xBF", 3)) i = 3;
    while (i < n) {
        size_t e = i, end, start = i;
        while (e < n && t[e] != '\n') e++;
        end = e;
        for (k = i; k < end; k++) if (t[k] == '#') { end = k; break; }
        while (end > i && (t[end - 1] == '\r' || t[end - 1] == ' ' || t[end - 1] == '\t')) end--;
        while (i < end && (t[i] == ' ' || t[i] == '\t')) i++;
        if (end > i) {
            if (numbered)               /* where it was: "LINE COL\t" */
                pt_sbuf_addf(out, "%zu %zu\t", line, i - start + 1);
            pt_sbuf_addn(out, t + i, end - i);
            pt_sbuf_add(out, "\n");
        }
        i = e + 1;
        line++;
    }
    return NULL;
}

/* Read the answer sheet at path (a folder entry; a link is followed) into
** *text, cleaned (numbered: as clean_sheet() says).  Returns NULL, or why it cannot be graded ("" for an entry
** that is not a sheet at all: a folder). */
static const char *read_sheet(const char *path, pt_sbuf *text, int numbered)
{
    static char why[160];
    struct stat st;
    char *buf;
    ssize_t got;
    size_t len = 0;
    const char *bad;
    int fd;

    if (lstat(path, &st) != 0) return strerror(errno);
    if (S_ISLNK(st.st_mode) && stat(path, &st) != 0)
        return errno == ELOOP ? "a symbolic link that loops" : errno == ENOENT
               ? "a broken symbolic link (its target is missing)" : strerror(errno);
    if (S_ISDIR(st.st_mode)) return "";
    if (!S_ISREG(st.st_mode)) return "not a regular file";
    if ((fd = open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY)) < 0) return strerror(errno);
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) { close(fd); return "not a regular file"; }
    if (st.st_size > SHEET_MAX) {
        close(fd);
        snprintf(why, sizeof why, "larger than %ld bytes: not an answer sheet", SHEET_MAX);
        return why;
    }
    if (!(buf = malloc((size_t)SHEET_MAX + 1))) { close(fd); return "out of memory"; }
    while (len <= (size_t)SHEET_MAX &&
           (got = read(fd, buf + len, (size_t)SHEET_MAX + 1 - len)) != 0) {
        if (got < 0) {
            if (errno == EINTR) continue;
            snprintf(why, sizeof why, "%s", strerror(errno));
            free(buf);
            close(fd);
            return why;
        }
        len += (size_t)got;
    }
    close(fd);
    if (len > (size_t)SHEET_MAX) {      /* it grew while read */
        free(buf);
        snprintf(why, sizeof why, "larger than %ld bytes: not an answer sheet", SHEET_MAX);
        return why;
    }
    bad = clean_sheet(buf, len, text, numbered);
    free(buf);
    return bad ? bad : text->failed ? "out of memory" : NULL;
}

/* Grade the cleaned sheet text[0..n) into q->result. */
static void grade_text(quiz *q, const char *text, size_t n)
{
    int i;

    for (i = 0; i < q->j->norder; i++) q->result[i] = -1;
    if (n == 0) return;                 /* nothing answered */
    if (!(q->in = fmemopen((void *)text, n, "r"))) return;
    ask(q);
    fclose(q->in);
}

/* "pipetrace quiz: SHEET: WHY" on standard error, the sheet's name safe for
** a terminal (a student chose it). */
static void sheet_message(const char *name, const char *why)
{
    pt_sbuf m;

    pt_sbuf_init(&m);
    pt_sbuf_add(&m, "pipetrace quiz: ");
    pt_sbuf_add_term(&m, name, strlen(name));
    pt_sbuf_addf(&m, ": %s\n", why);
    if (!m.failed) fputs(m.s, stderr);
    pt_sbuf_free(&m);
}

/* The name of q's question i. */
static const char *stage_name(const quiz *q, int i)
{
    return q->z ? pt_q79_name(q->z, i) : pt_stage_infos[q->j->order[i]].name;
}

/* "PATH:LINE:COL: error: WHY" on standard error, the path safe for a terminal. */
static void sheet_error(const char *path, long line, long col, const char *why)
{
    pt_sbuf m;

    pt_sbuf_init(&m);
    pt_sbuf_add_term(&m, path, strlen(path));
    if (line > 0) pt_sbuf_addf(&m, ":%ld:%ld", line, col);
    pt_sbuf_addf(&m, ": error: %s\n", why);
    if (!m.failed) fputs(m.s, stderr);
    pt_sbuf_free(&m);
}

/* Grade the sheet at path of renderers 7 and 9, its text cleaned with
** numbered lines ("LINE COL\tanswer"), into q->result.  Returns NULL, or
** the note for its row; *trouble is 1 when an answer could not be read (an
** error on standard error for each, FILE:LINE:COL). */
static const char *grade79(quiz *q, const char *path, char *text, int *trouble)
{
    static char note[200];
    const char *lines[PT_Q79_MAX + 1], *byq[PT_Q79_MAX];
    long at[PT_Q79_MAX + 1][2];
    int i, n = 0, nq = q->last - q->first + 1;
    char *p = text, *why = NULL;

    for (i = 0; i < pt_q79_count(q->z); i++) { q->result[i] = -1; byq[i] = NULL; }
    while (*p && n <= nq) {                 /* one more than asked: too many */
        char *e = strchr(p, '\n'), *tab = strchr(p, '\t');
        *e = '\0';
        at[n][0] = strtol(p, NULL, 10);
        at[n][1] = strtol(strchr(p, ' ') + 1, NULL, 10);
        lines[n++] = tab + 1;
        p = e + 1;
    }
    if (pt_q79_r4_sheet(q->z, lines, n)) {
        size_t len = 0;
        len += (size_t)snprintf(note + len, sizeof note - len, "a sheet of renderer 4's quiz "
                                "(model, camera, image, pixel, viewport, framebuffer, index); "
                                "this scene is the course's renderer %d, whose quiz asks",
                                pt_q79_renderer(q->z));
        for (i = 0; i < nq && len < sizeof note; i++)
            len += (size_t)snprintf(note + len, sizeof note - len, "%s %s", i ? "," : "",
                                    pt_q79_name(q->z, i));
        sheet_error(path, 0, 0, note);
        *trouble = 1;
        return note;
    }
    for (i = 0; i < n && i < nq; i++) {     /* line i answers question first + i */
        int col, k = q->first + i;
        const char *bad;
        byq[k] = lines[i];
        q->result[k] = pt_q79_grade(q->z, k, lines[i], q->result, byq, &col, &bad);
        if (q->result[k] < 0) {
            char m[160];
            snprintf(m, sizeof m, "%s (%s): %s", pt_q79_name(q->z, k), pt_q79_values(q->z, k), bad);
            sheet_error(path, at[i][0], at[i][1] + col - 1, m);
            if (!why) {
                snprintf(note, sizeof note, "line %ld: %s (%s): %s", at[i][0],
                         pt_q79_name(q->z, k), pt_q79_values(q->z, k), bad);
                why = note;
            }
            q->result[k] = 0;
            byq[k] = NULL;                  /* nothing follows from it */
            *trouble = 1;
        }
    }
    if (n > nq) {
        char m[120];
        snprintf(m, sizeof m, "more answers than the quiz's %d questions", nq);
        sheet_error(path, at[nq][0], at[nq][1], m);
        if (!why) {
            snprintf(note, sizeof note, "line %ld: %s", at[nq][0], m);
            why = note;
        }
        *trouble = 1;
    }
    return why;
}

/* Grade every entry of dir (not those starting with '.'), in name order, as
** answer sheets for q's stages, into a CSV written to out: a row a sheet,
** 1, 0, "follows" or empty (unanswered) a stage, the score, and a note that
** says why a sheet could not be graded.  Folders are passed over.  Returns
** the exit status. */
static int grade(quiz *q, const char *dir, const char *out)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char **names = NULL, path[4096];
    size_t n = 0, cap = 0, k;
    int i, rc = PT_EXIT_OK, bad = 0, of = q->last - q->first + 1;
    pt_sbuf sb, text;
    pt_outfile o = {NULL, NULL, NULL, NULL};
    char err[PT_ERRLEN];

    if (!d) { fprintf(stderr, "pipetrace quiz: --grade %s: cannot read the folder\n", dir); return PT_EXIT_INPUT; }
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.') continue;
        if (n == cap) {
            char **nn = realloc(names, (cap = cap ? 2 * cap : 16) * sizeof *names);
            if (!nn) { bad = 1; break; }
            names = nn;
        }
        if (!(names[n] = malloc(strlen(e->d_name) + 1))) { bad = 1; break; }
        strcpy(names[n++], e->d_name);
    }
    closedir(d);
    if (!bad && n) qsort(names, n, sizeof *names, by_name);
    for (k = 0; k < n && !bad && strcmp(out, "-") != 0; k++) {
        struct stat so, si;             /* the scores must not overwrite a sheet */
        if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, names[k]) < sizeof path
            && stat(out, &so) == 0 && stat(path, &si) == 0
            && so.st_dev == si.st_dev && so.st_ino == si.st_ino) {
            sheet_message(out, "--out would overwrite an answer sheet of the folder it grades");
            bad = 2;
        }
    }
    if (bad == 2) {
        for (k = 0; k < n; k++) free(names[k]);
        free(names);
        return PT_EXIT_INPUT;
    }
    pt_sbuf_init(&sb);
    pt_sbuf_add(&sb, "sheet");
    for (i = q->first; i <= q->last; i++) {
        pt_sbuf_add(&sb, ",");
        pt_sbuf_add(&sb, stage_name(q, i));
    }
    pt_sbuf_add(&sb, ",right,of,note\n");
    q->grading = 1;
    for (k = 0; k < n && !bad; k++) {
        const char *why;
        int right, answered, trouble = 0;

        if ((size_t)snprintf(path, sizeof path, "%s/%s", dir, names[k]) >= sizeof path)
            why = "its path is too long";
        else {
            pt_sbuf_init(&text);
            why = read_sheet(path, &text, q->z != NULL);
            if (!why && q->z) why = grade79(q, path, text.s ? text.s : "", &trouble);
            else if (!why) grade_text(q, text.s ? text.s : "", text.len);
            pt_sbuf_free(&text);
        }
        if (why && !*why) continue;     /* a folder: not a sheet */
        pt_sbuf_add_csv_untrusted(&sb, names[k]);
        if (trouble) rc = PT_EXIT_INPUT;
        if (why && trouble) {           /* graded, with answers it could not read */
            for (i = q->first; i <= q->last; i++)
                pt_sbuf_add(&sb, q->result[i] < 0 ? "," : q->result[i] == FOLLOWS ? ",follows"
                                 : q->result[i] ? ",1" : ",0");
            right = score(q, &answered);
            pt_sbuf_addf(&sb, ",%d,%d,", right, of);
            pt_sbuf_add_csv_untrusted(&sb, why);
            pt_sbuf_add(&sb, "\n");
            continue;
        }
        if (why) {
            for (i = q->first; i <= q->last; i++) pt_sbuf_add(&sb, ",");
            pt_sbuf_addf(&sb, ",0,%d,", of);
            pt_sbuf_add_csv_untrusted(&sb, why);
            pt_sbuf_add(&sb, "\n");
            sheet_message(names[k], why);
            rc = PT_EXIT_INPUT;
            continue;
        }
        for (i = q->first; i <= q->last; i++)
            pt_sbuf_add(&sb, q->result[i] < 0 ? "," : q->result[i] == FOLLOWS ? ",follows"
                             : q->result[i] ? ",1" : ",0");
        right = score(q, &answered);
        pt_sbuf_addf(&sb, ",%d,%d,\n", right, of);
        if (rc == PT_EXIT_OK && right < of) rc = PT_EXIT_DIFFER;
    }
    for (k = 0; k < n; k++) free(names[k]);
    free(names);
    if (bad || sb.failed) {
        fputs("pipetrace quiz: out of memory\n", stderr);
        pt_sbuf_free(&sb);
        return PT_EXIT_INPUT;
    }
    if (n == 0) fprintf(stderr, "pipetrace quiz: warning: --grade %s: no answer sheets in it\n", dir);
    if (pt_outfile_open(&o, out, err, sizeof err) != 0) {
        fprintf(stderr, "pipetrace quiz: %s\n", err);
        pt_sbuf_free(&sb);
        return PT_EXIT_INPUT;
    }
    if (sb.len) fwrite(sb.s, 1, sb.len, o.f);
    pt_sbuf_free(&sb);
    if (pt_outfile_finish(&o, ferror(o.f) != 0, "pipetrace quiz") != 0) return PT_EXIT_INPUT;
    return rc;
}

/* ===== the command ===== */

/* The score as one JSON line: per stage 1, 0 or null (unanswered). */
static void print_json(const quiz *q, const pt_scene *s, const pt_model *m,
                       unsigned long long v)
{
    pt_sbuf sb;
    int i, right, answered;

    pt_sbuf_init(&sb);
    pt_sbuf_add(&sb, "{\"scene\":");
    pt_sbuf_add_json(&sb, s->path);
    pt_sbuf_add(&sb, ",\"model\":");
    pt_sbuf_add_json(&sb, m->name);
    pt_sbuf_addf(&sb, ",\"vertex\":%llu,\"stages\":[", v);
    for (i = q->first; i <= q->last; i++)
        pt_sbuf_addf(&sb, "%s{\"stage\":\"%s\",\"score\":%s}", i > q->first ? "," : "",
                     stage_name(q, i),
                     q->result[i] < 0 ? "null" : q->result[i] ? "1" : "0");
    right = score(q, &answered);
    pt_sbuf_addf(&sb, "],\"right\":%d,\"answered\":%d,\"of\":%d}\n", right, answered,
                 q->last - q->first + 1);
    if (sb.failed) fputs("pipetrace quiz: out of memory\n", stderr);
    else fputs(sb.s, stdout);
    pt_sbuf_free(&sb);
}

/* The stages of journey j, "model, camera, ..." into buf. */
static void stage_list(char *buf, size_t n, const pt_journey *j)
{
    size_t len = 0;
    int i;

    buf[0] = '\0';
    for (i = 0; i < j->norder && len < n; i++)
        len += (size_t)snprintf(buf + len, n - len, "%s%s", i ? ", " : "",
                                pt_stage_infos[j->order[i]].name);
}

/* q to read its answers from standard input: asked again when unreadable
** at a terminal or with --interactive (inter), silent but for the score with
** --json, each answer echoed when the input is no terminal. */
static void from_stdin(quiz *q, int inter, int json)
{
    q->in = stdin;
    q->interactive = inter || isatty(STDIN_FILENO);
    q->talk = !json;
    q->echo = q->talk && !isatty(STDIN_FILENO);
}

/* The quiz of renderers 7 and 9 for vertex v of m (seed: the one it was
** picked with, or NULL), as pt_cmd_quiz() runs renderer 4's.  Returns the
** exit status. */
static int quiz79(const pt_scene *s, const pt_model *m, unsigned long long v,
                  const unsigned long long *seed, const char *stage, const char *dir,
                  const char *out, int json, int inter)
{
    pt_q79 *z = pt_q79_make(s, m, v);
    char b[512];
    quiz q;
    int k, n, rc = PT_EXIT_OK, right, answered, of;

    if (!z) return PT_EXIT_INPUT;
    n = pt_q79_count(z);
    memset(&q, 0, sizeof q);
    q.z = z;
    q.first = 0;
    q.last = n - 1;
    if (stage) {
        size_t len = 0;
        for (k = 0; k < n && strcmp(pt_q79_name(z, k), stage); k++) ;
        if (k == n || k == 0) {
            for (k = 0; k < n && len < sizeof b; k++)
                len += (size_t)snprintf(b + len, sizeof b - len, "%s%s", k ? ", " : "",
                                        pt_q79_name(z, k));
            fprintf(stderr, "pipetrace quiz: --stage %s: vertex %llu of model %s has no such "
                    "question after the first (its questions: %s)\n", stage, v, m->name, b);
            pt_q79_free(z);
            return PT_EXIT_INPUT;
        }
        q.first = q.last = k;
    }
    of = q.last - q.first + 1;
    if (dir) {
        rc = grade(&q, dir, out ? out : "-");
        pt_q79_free(z);
        return rc;
    }
    from_stdin(&q, inter, json);
    if (q.talk) {
        char cam[PT_CAMERA_TITLE];
        printf("pipetrace quiz: vertex %llu of model %s in %s (renderer %d)", v, m->name,
               s->path, s->renderer);
        if (seed) printf(" (picked with --seed %llu)", *seed);
        putchar('\n');
        printf("camera %s; nearclip %s, antialias %s, gamma %s\n",
               pt_scene_camera_title(s, cam, sizeof cam), s->nearclip ? "on" : "off",
               s->antialias ? "on" : "off", s->gamma ? "on" : "off");
        printf("viewport %d x %d at (x_ul, y_ul) = (%d, %d); framebuffer %d x %d\n",
               s->vp_w, s->vp_h, s->vp_x, s->vp_y, s->fb_w, s->fb_h);
        pt_q79_describe(z, b, sizeof b);
        printf("%s\n", b);
        if (q.first > 0) {
            pt_q79_answer(z, q.first - 1, b, sizeof b);
            printf("given: %s: %s = %s\n", pt_q79_name(z, q.first - 1),
                   pt_q79_values(z, q.first - 1), b);
        }
        printf("Answer each stage with its values on one line, separated by spaces or commas.\n"
               "Real numbers are right within 1e-6 absolute or 1e-6 relative; pixel\n"
               "coordinates and colour bytes must be exact; a clip's edge is x=+1, x=-1,\n"
               "y=+1 or y=-1; write none for a cut that does not happen, dropped for a\n"
               "segment the stage deletes.\n");
    }
    ask79(&q);
    right = score(&q, &answered);
    if (!q.talk) print_json(&q, s, m, v);
    else if (answered == of) printf("\nscore: %d/%d\n", right, of);
    else printf("\nscore: %d/%d (input ended after %d of %d stages)\n", right, answered,
                answered, of);
    if (right < of) rc = PT_EXIT_DIFFER;
    pt_q79_free(z);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("pipetrace quiz: cannot write to standard output\n", stderr);
        return PT_EXIT_INPUT;
    }
    return rc;
}

int pt_cmd_quiz(int argc, char **argv)
{
    const char *path = NULL, *model = NULL, *stage = NULL, *dir = NULL, *out = NULL;
    unsigned long long v = 0, seed = 0;
    int k, seeded = 0, picked = 0, json = 0, inter = 0, rc = PT_EXIT_OK;
    const pt_model *m = NULL;
    pt_journey run, j;                      /* the run's records, the reference's */
    pt_scene s;
    quiz q;
    uint64_t n;
    size_t mi;
    char list[512];
    pt_cli_args ca = {"quiz", usage, 1, NULL, NULL, 0};

    for (k = 1; k < argc; k++) {
        const char *a = argv[k];
        const char *val;
        int u;

        if (!strcmp(a, "--seed")) {
            if ((u = pt_cli_value("quiz", argc, argv, &k, &val)) >= 0) return u;
            if (pt_cli_count(val, 0, UINT64_MAX, &n))
                return pt_cli_usage("quiz", "--seed takes a whole number >= 0, not %s", val);
            seed = n;
            seeded = 1;
        } else if (!strcmp(a, "--stage")) {
            if ((u = pt_cli_value("quiz", argc, argv, &k, &stage)) >= 0) return u;
        } else if (!strcmp(a, "--grade")) {
            if ((u = pt_cli_value("quiz", argc, argv, &k, &dir)) >= 0) return u;
        } else if (!strcmp(a, "--out")) {
            if ((u = pt_cli_value("quiz", argc, argv, &k, &out)) >= 0) return u;
        } else if (!strcmp(a, "--json")) json = 1;
        else if (!strcmp(a, "--interactive")) inter = 1;
        else if ((u = pt_cli_arg(&ca, argc, argv, &k)) >= 0) return u;  /* SCENE, --vertex, ... */
    }
    path = ca.path;
    model = ca.model;
    v = ca.vertex;
    if (v && seeded) return pt_cli_usage("quiz", "--vertex and --seed exclude each other");
    if (dir && !v && !seeded)
        return pt_cli_usage("quiz", "--grade needs --vertex N or --seed S: every sheet answers the same vertex");
    if (dir && (json || inter)) return pt_cli_usage("quiz", "--grade writes a CSV: no --json, no --interactive");
    if (out && !dir) return pt_cli_usage("quiz", "--out is where --grade writes its CSV: give --grade DIR");
    if (stage && pt_stage_by_name(stage) < 0 && !pt_q79_stage_name(stage)) {
        int i;
        size_t len = 0;
        for (i = 0; i < PT_NSTAGES_ALL && len < sizeof list; i++)
            len += (size_t)snprintf(list + len, sizeof list - len, "%s%s", i ? ", " : "",
                                    pt_stage_infos[pt_trace_order[i]].name);
        return pt_cli_usage("quiz", "unknown stage '%s' (the stages: %s)", stage, list);
    }

    if (pt_cli_load(&s, path) != 0) return PT_EXIT_INPUT;
    if (stage && pt_stage_by_name(stage) < 0 && s.renderer != 7 && s.renderer != 9) {
        pt_scene_free(&s);
        return pt_cli_usage("quiz", "unknown stage '%s' (renderer 4's stages: model, camera, "
                            "image, pixel, viewport, framebuffer, index)", stage);
    }
    if (v) m = pt_cli_vertex_model(&s, "quiz", model, v);
    if ((v && !m) || (!v && model && !pt_cli_model(&s, "quiz", model))) {
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    if (!v) {
        uint64_t total = 0, st;
        size_t r;

        if (!seeded) seed = (unsigned long long)time(NULL);
        for (mi = 0; mi < s.nmodels; mi++)
            if (!model || !strcmp(model, s.models[mi].name))
                for (r = 0; r < s.models[mi].nv; r++)
                    total += (uint64_t)pt_vertex_used(&s.models[mi], r + 1);
        if (total == 0) {
            fprintf(stderr, "pipetrace quiz: %s: no segment uses any vertex%s%s\n", s.path,
                    model ? " of " : "", model ? model : "");
            pt_scene_free(&s);
            return PT_EXIT_INPUT;
        }
        st = seed ^ 0x9E3779B97F4A7C15ULL;
        if (st == 0) st = 1;
        xorshift(&st);
        pick(&s, model, xorshift(&st) % total, &m, &v);
        picked = 1;
    }

    if (s.renderer == 7 || s.renderer == 9) {
        rc = quiz79(&s, m, v, picked ? &seed : NULL, stage, dir, out, json, inter);
        pt_scene_free(&s);
        return rc;
    }
    if (pt_run_journey(&run, &s, m, v, 0) != 0) {
        fputs("pipetrace quiz: out of memory\n", stderr);
        pt_scene_free(&s);
        return PT_EXIT_INPUT;
    }
    pt_explain_reference(&j, &run);         /* a student's stage is not the answer */
    memset(&q, 0, sizeof q);
    q.j = &j;
    q.first = 0;
    q.last = j.norder - 1;
    if (stage) {
        int st = pt_stage_by_name(stage);
        for (k = 0; k < j.norder && (int)j.order[k] != st; k++) ;
        if (k == j.norder) {
            stage_list(list, sizeof list, &j);
            fprintf(stderr, "pipetrace quiz: --stage %s: vertex %llu of model %s does not go "
                    "through it (its stages: %s)\n", stage, v, m->name, list);
            pt_scene_free(&s);
            return PT_EXIT_INPUT;
        }
        q.first = q.last = k;
    }
    if (dir) {
        rc = grade(&q, dir, out ? out : "-");
        pt_scene_free(&s);
        return rc;
    }
    from_stdin(&q, inter, json);
    if (q.talk) {
        char t[PT_EXPLAINLEN], cam[PT_CAMERA_TITLE];
        int right, answered, of = q.last - q.first + 1;

        printf("pipetrace quiz: vertex %llu of model %s in %s", v, m->name, s.path);
        if (picked) printf(" (picked with --seed %llu)", seed);
        putchar('\n');
        if (pt_cli_student_note(t, sizeof t))
            printf("%s; the answers are checked against the reference stages\n", t);
        printf("camera %s; viewport %d x %d at (x_ul, y_ul) = (%d, %d); framebuffer %d x %d\n",
               pt_scene_camera_title(&s, cam, sizeof cam),
               s.vp_w, s.vp_h, s.vp_x, s.vp_y, s.fb_w, s.fb_h);
        pt_explain_next(t, sizeof t, &j, j.order[0]);     /* what the first stage hands on */
        printf("model %s: %s\n", m->name, t);
        if (q.first > 0) {
            pt_explain_values(t, sizeof t, &j, j.order[q.first - 1]);
            printf("given: %s\n", t);
        }
        if (!pt_vertex_used(m, v))
            printf("note: no segment uses this vertex, so the renderer does not transform it\n");
        printf("Answer each stage with its values on one line, separated by spaces or commas.\n"
               "Real numbers are right within 1e-6 absolute or 1e-6 relative; pixel\n"
               "coordinates and the index must be exact; write none for a value that does\n"
               "not exist.\n");
        ask(&q);
        right = score(&q, &answered);
        if (answered == of) printf("\nscore: %d/%d\n", right, of);
        else printf("\nscore: %d/%d (input ended after %d of %d stages)\n", right, answered,
                    answered, of);
        if (right < of) rc = PT_EXIT_DIFFER;
    } else {
        int answered;
        ask(&q);
        print_json(&q, &s, m, v);
        if (score(&q, &answered) < q.last - q.first + 1) rc = PT_EXIT_DIFFER;
    }
    pt_scene_free(&s);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fputs("pipetrace quiz: cannot write to standard output\n", stderr);
        return PT_EXIT_INPUT;
    }
    return rc;
}
