/*
** tests/unit/test_tread.c -- the trace and image readers: caps, bytes, every cut
** See LICENSE for copyright and license.
**
** What pipetrace diff reads must never make it hang, eat memory or fail
** without saying why.  Files: a file of more than the cap is refused before
** it is read, a stream past the cap as soon as it passes it, a text file only
** up to its first NUL byte (so /dev/zero ends at once).  Bytes: NUL bytes and
** invalid UTF-8 are refused at their line and column.  Cuts: each example
** scene's trace, written here in text and in JSON Lines, and its image as
** P6, P3 and PNG, cut at the end and in the middle of every line (images:
** after every byte); each cut is read or refused with a "FILE:LINE:COL:
** error: ..." message, and a text trace cut anywhere before its last line is
** refused (it ends with its summary).
*/
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "testhelp.h"
#include "tests/fuzz/fuzz.h"
#include "core/pipeline.h"
#include "io/png.h"
#include "io/trace.h"
#include "io/tread.h"

static char tmpdir[] = "/tmp/pt-test-tread-XXXXXX";

/* Write n bytes of s to the file name in tmpdir; returns its path. */
static const char *put(const char *name, const char *s, size_t n)
{
    static char path[256];
    FILE *f;

    snprintf(path, sizeof path, "%s/%s", tmpdir, name);
    if ((f = fopen(path, "wb")) != NULL) {
        fwrite(s, 1, n, f);
        fclose(f);
    }
    return path;
}

/* Parse buf[0..len) (NUL-terminated here) as a trace.  0 when read, 1 when
** refused with a good message whose line is at most maxline, -1 otherwise;
** the message goes to err. */
static int parse(const char *buf, size_t len, size_t maxline, char *err, size_t errlen)
{
    pt_names nm = PT_NAMES_INIT;
    pt_tread t;
    char *b = malloc(len + 1);
    int rc;

    if (!b) return -1;
    memcpy(b, buf, len);
    b[len] = '\0';
    err[0] = '\0';
    rc = pt_tread_parse(&t, "cut", b, len, &nm, err, errlen);
    if (rc != 0)
        rc = pt_fuzz_message_ok(err, "cut") && strtoul(err + 4, NULL, 10) <= maxline ? 1 : -1;
    pt_tread_free(&t);
    pt_names_free(&nm);
    free(b);
    return rc;
}

/* ===== files: the cap, NUL bytes ===== */

static void test_files(void)
{
    static char big[300000];
    char err[1024], *buf;
    size_t len;
    FILE *p;
    int rc;

    rc = pt_tread_file("/dev/zero", &buf, &len, err, sizeof err);
    PT_CHECK("tread-1.1 /dev/zero: read up to its first chunk", rc == 0 && len <= (1 << 17));
    if (rc == 0) {
        PT_CHECK("tread-1.2 /dev/zero: refused by the parser",
                 parse(buf, len, 1, err, sizeof err) == 1 && strstr(err, "cut:1:1: error:"));
        free(buf);
    }
    big[0] = '{';
    memset(big + 1, 'x', sizeof big - 1);
    big[100000] = '\0';
    rc = pt_tread_file(put("nul.jsonl", big, sizeof big), &buf, &len, err, sizeof err);
    PT_CHECK("tread-1.3 a text file is read only up to the chunk with its first NUL",
             rc == 0 && len >= 100000 && len < sizeof big);
    if (rc == 0) free(buf);
    memcpy(big, "P6 100 1000 255\n", 16);
    rc = pt_tread_file(put("zeros.ppm", big, sizeof big), &buf, &len, err, sizeof err);
    PT_CHECK("tread-1.4 a binary PPM is read whole, NUL bytes and all",
             rc == 0 && len == sizeof big);
    if (rc == 0) free(buf);
    rc = pt_tread_file_max(put("cap.ppm", big, 1001), 1000, &buf, &len, err, sizeof err);
    PT_CHECK("tread-1.5 a file of more than the cap is refused",
             rc == -1 && strstr(err, "cap.ppm:1:1: error: the file is larger than 1000 bytes"));
    rc = pt_tread_file_max(put("cap.ppm", big, 1000), 1000, &buf, &len, err, sizeof err);
    PT_CHECK("tread-1.6 a file of the cap's size is read", rc == 0 && len == 1000);
    if (rc == 0) free(buf);
    fflush(stdout);
    if ((p = popen("printf P6; head -c 300000 /dev/zero", "r")) != NULL) {
        int saved = dup(0);
        dup2(fileno(p), 0);
        rc = pt_tread_file_max("-", 200000, &buf, &len, err, sizeof err);
        PT_CHECK("tread-1.7 a stream past the cap is refused",
                 rc == -1 && strstr(err, "-:1:1: error: the file is larger than 200000 bytes"));
        if (rc == 0) free(buf);
        dup2(saved, 0);
        close(saved);
        pclose(p);
    }
}

/* ===== bytes: NUL and UTF-8 ===== */

static void test_bytes(void)
{
    static const char head[] = "# pipetrace trace, format version 1\n"
        "framebuffer  20 x 10, background 0 0 0\n";
    char text[256], err[1024];

    snprintf(text, sizeof text, "%smodel        tr\xc3\xa9: 3 vertices\n", head);
    PT_CHECK("tread-2.1 well-formed UTF-8 in a name passes the byte check",
             parse(text, strlen(text), 4, err, sizeof err) == 1 && !strstr(err, "UTF-8"));
    snprintf(text, sizeof text, "%smodel        tr\xe9: 3 vertices\n", head);
    PT_CHECK("tread-2.2 a Latin-1 byte is refused at its line and column",
             parse(text, strlen(text), 3, err, sizeof err) == 1 &&
             strstr(err, "cut:3:16: error: invalid UTF-8 sequence starting with byte 0xe9"));
    snprintf(text, sizeof text, "%smodel        tr\xed\xa0\x80: 3 vertices\n", head);
    PT_CHECK("tread-2.3 an encoded surrogate is refused",
             parse(text, strlen(text), 3, err, sizeof err) == 1 && strstr(err, "cut:3:16: error: invalid UTF-8"));
    snprintf(text, sizeof text, "{\"type\":\"vertex\",\"model\":\"a\xc0\xaf\"}\n");
    PT_CHECK("tread-2.4 an overlong form in JSON Lines is refused",
             parse(text, strlen(text), 1, err, sizeof err) == 1 && strstr(err, "cut:1:28: error: invalid UTF-8"));
    memcpy(text, "{\"type\":\"skip\"}\n{\"a\0", 20);
    PT_CHECK("tread-2.5 a NUL byte is refused at its line and column",
             parse(text, 20, 2, err, sizeof err) == 1 && strstr(err, "cut:2:4: error: NUL byte"));
}

/* ===== the readers' other limits (docs/limits.md) ===== */

static void test_limits(void)
{
    char text[512], err[1024];
    pt_ppm img;
    int k, n = 0;

    n += snprintf(text, sizeof text, "{\"type\":\"skip\",\"a\":");
    for (k = 0; k < 32; k++) text[n++] = '[';   /* 33 deep with the record's braces */
    for (k = 0; k < 32; k++) text[n++] = ']';
    n += snprintf(text + n, sizeof text - (size_t)n, "}\n");
    PT_CHECK("tread-5.1 JSON nested more than 32 deep is refused",
             parse(text, (size_t)n, 1, err, sizeof err) == 1 && strstr(err, "nested too deeply"));
    text[19] = ' ';                         /* one '[' less: 32 deep */
    text[n - 3] = ' ';
    PT_CHECK("tread-5.2 ... 32 deep is read", parse(text, (size_t)n, 1, err, sizeof err) == 0);
    n = snprintf(text, sizeof text, "{\"type\":\"pixel\",\"model\":\"m\",\"segment\":1,"
                 "\"x\":9223372036854775808,\"y\":0,\"i\":0}\n");
    PT_CHECK("tread-5.3 an integer beyond int64 is refused",
             parse(text, (size_t)n, 1, err, sizeof err) == 1 && strstr(err, "cut:1:45: error: integer out of range"));
    n = snprintf(text, sizeof text, "# pipetrace trace, format version 1\n"
                 "framebuffer  1000000001 x 10, background 0 0 0\n");
    PT_CHECK("tread-5.4 a framebuffer over 10^9 in a header is refused",
             parse(text, (size_t)n, 2, err, sizeof err) == 1 && strstr(err, "size out of range"));
    n = snprintf(text, sizeof text, "{\"type\":\"clipvertex\",\"model\":\"m\","
                 "\"segment\":4611686018427387904,\"stage\":\"cvv\",\"code\":0,\"planes\":[]}\n");
    PT_CHECK("tread-5.5 a segment number of 2^62 is refused",
             parse(text, (size_t)n, 1, err, sizeof err) == 1 && strstr(err, "segment number out of range"));
    strcpy(text, "P6 65536 1 255\n");
    PT_CHECK("tread-5.6 a PPM wider than 65535 is refused",
             pt_image_parse(&img, "img", text, strlen(text), err, sizeof err) == -1 &&
             strstr(err, "img:1:1: error: bad P6 header"));
    strcpy(text, "P6 2 1 256\nabcdef");
    PT_CHECK("tread-5.7 a PPM maxval over 255 is refused",
             pt_image_parse(&img, "img", text, strlen(text), err, sizeof err) == -1);
}

/* ===== cuts ===== */

/* Every cut of the trace s[0..n): at the end and in the middle of each line.
** text: a cut before the last line must be refused. */
static void cut_lines(const char *what, const char *s, size_t n, int text)
{
    char err[1024], d[300];
    size_t k, line = 1, start = 0, cuts = 0, bad = 0;

    for (k = 0; k < n; k++) {
        int rc;
        if (s[k] != '\n') continue;
        rc = parse(s, start + (k - start) / 2, line, err, sizeof err);      /* mid-line */
        if (rc < 0 || (text && rc == 0)) { if (!bad++) printf("  %s mid-line %zu: %s\n", what, line, err); }
        if (k + 1 < n) {
            rc = parse(s, k + 1, line + 1, err, sizeof err);                /* after the line */
            if (rc < 0 || (text && rc == 0)) { if (!bad++) printf("  %s after line %zu: %s\n", what, line, err); }
        }
        cuts += 2;
        start = k + 1;
        line++;
    }
    snprintf(d, sizeof d, "tread-3 %s: each of %zu cuts refused with a message%s", what, cuts,
             text ? "" : " or read");
    PT_CHECK(d, bad == 0 && cuts > 20);
    PT_CHECK("tread-3 the whole trace is read", parse(s, n, 1, err, sizeof err) == 0);
}

/* Every cut of the image s[0..n) after each byte: refused with a message
** (read only when what is cut off is whitespace). */
static void cut_bytes(const char *what, const char *s, size_t n)
{
    char err[1024], d[300], *b = malloc(n + 1);
    size_t k, bad = 0;
    pt_ppm img;

    if (!b) return;
    for (k = 0; k < n; k++) {
        memcpy(b, s, k);
        b[k] = '\0';
        err[0] = '\0';
        if (pt_image_parse(&img, "cut", b, k, err, sizeof err) == 0) {
            pt_image_free(&img);
            if (strspn(s + k, " \n") == n - k) continue;     /* only P3's last newline cut */
        } else if (pt_fuzz_message_ok(err, "cut")) continue;
        if (!bad++) printf("  %s cut after %zu bytes: %s\n", what, k, err[0] ? err : "read");
    }
    snprintf(d, sizeof d, "tread-4 %s: each of %zu cuts refused with a message", what, n);
    PT_CHECK(d, bad == 0 && n > 100);
    memcpy(b, s, n);
    b[n] = '\0';
    PT_CHECK("tread-4 the whole image is read", pt_image_parse(&img, "cut", b, n, err, sizeof err) == 0);
    pt_image_free(&img);
    free(b);
}

/* The image of fb as P3, into a new buffer of *n bytes. */
static char *plain_ppm(const pt_fb *fb, size_t *n)
{
    char *s = NULL;
    FILE *f = open_memstream(&s, n);
    size_t k;

    if (!f) return NULL;
    fprintf(f, "P3\n# plain\n%d %d\n255\n", fb->w, fb->h);
    for (k = 0; k < 3 * (size_t)fb->w * (size_t)fb->h; k++)
        fprintf(f, "%d%c", fb->rgb[k], k % 12 == 11 ? '\n' : ' ');
    fclose(f);
    return s;
}

/* Render the scene at path: its trace in fmt into *out (a new buffer of *n
** bytes), and with fb its image. */
static int render(const char *path, pt_format fmt, char **out, size_t *n, pt_fb *fb)
{
    pt_scene s;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    static pt_trace tr;
    char err[PT_ERRLEN];
    FILE *f;
    int rc = -1;

    *out = NULL;
    if (pt_scene_load(&s, path, err, sizeof err) != 0) return -1;
    pt_options_default(&o);
    if ((f = open_memstream(out, n)) != NULL && pt_plan_make(&p, &s, &o) == 0) {
        pt_trace_init(&tr, f, fmt, 6);
        pt_trace_listener(&tr, &l);
        if ((!fb || pt_fb_init(fb, s.fb_w, s.fb_h, s.background) == 0) &&
            pt_run(&s, &p, &o, &l, fb, &sum) == 0 && pt_trace_finish(&tr) == 0) rc = 0;
        pt_plan_free(&p);
    }
    if (f) fclose(f);
    pt_scene_free(&s);
    return rc;
}

int main(void)
{
    static const char *const scenes[] = {
        "docs/examples/triangle.scene", "docs/examples/clip.scene",
        "docs/examples/behind.scene", "docs/examples/two-models.scene",
        "docs/examples/lookat-near.scene", "docs/examples/compare-matrix.scene",
        "docs/examples/ortho.scene",
    };
    size_t k;

    if (!mkdtemp(tmpdir)) { printf("cannot make %s\n", tmpdir); return 1; }
    test_files();
    test_bytes();
    test_limits();
    for (k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        char *s, what[200];
        size_t n;
        snprintf(what, sizeof what, "%s, text", scenes[k]);
        PT_CHECK(what, render(scenes[k], PT_FORMAT_TEXT, &s, &n, NULL) == 0);
        if (s) cut_lines(what, s, n, 1);
        free(s);
        snprintf(what, sizeof what, "%s, JSON Lines", scenes[k]);
        PT_CHECK(what, render(scenes[k], PT_FORMAT_JSONL, &s, &n, NULL) == 0);
        if (s) cut_lines(what, s, n, 0);
        free(s);
    }
    {
        pt_fb fb;
        char *s, *t;
        size_t n;
        FILE *f;
        PT_CHECK("tread-4 render the triangle",
                 render("docs/examples/triangle.scene", PT_FORMAT_TEXT, &t, &n, &fb) == 0);
        free(t);
        if ((f = open_memstream(&s, &n)) != NULL) {
            pt_fb_write_ppm(&fb, f);
            fclose(f);
            cut_bytes("triangle as P6", s, n);
            free(s);
        }
        if ((f = open_memstream(&s, &n)) != NULL) {
            pt_fb_write_png(&fb, f);
            fclose(f);
            cut_bytes("triangle as PNG", s, n);
            free(s);
        }
        if ((s = plain_ppm(&fb, &n)) != NULL) cut_bytes("triangle as P3", s, n);
        free(s);
        pt_fb_free(&fb);
    }
    {
        char cmd[300];
        snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpdir);
        if (system(cmd) != 0) printf("cannot remove %s\n", tmpdir);
    }
    return pt_test_report();
}
