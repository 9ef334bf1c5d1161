/*
** tests/unit/test_fuzz.c -- corrupted scenes never crash, hang or leak; the fuzz corpus
** See LICENSE for copyright and license.
**
** Take each example scene, corrupt it in many small ways with a fixed random
** sequence (so every run is the same), and feed the result to the parser; when
** it parses, run the whole pipeline.  Each outcome must be either 0 with a
** scene, or -1 with one "NAME:LINE:COL: error: " message.  Run under
** `make sanitize` this also proves there is no memory error or undefined
** behaviour on these inputs.
**
** Then replay the regression corpus of the libFuzzer targets (tests/fuzz/):
** every file of tests/fuzz/corpus/TARGET/ through its target, with a plain
** main, so that no finding comes back even where clang is missing.
*/
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "tests/fuzz/fuzz.h"

static uint64_t state = 0x9E3779B97F4A7C15ULL;

static uint64_t next(void)
{
    state ^= state << 13; state ^= state >> 7; state ^= state << 17;
    return state;
}

static const char *const pieces[] = {
    " ", "\n", "\r\n", "\r", "#", "-", "+", "e", "e999", ".", "0", "-1", "1e400",
    "1e-320", "0x1p3", "nan", "inf", "99999999999999999999", "\xff", "\xc3\xa9",
    "\xef\xbb\xbf", "\t", "model", "model x", "v 1 2 3", "l 1 -1", "f 1/2/3 2//1 3",
    "viewport 0 0 1 1", "framebuffer 1 1", "camera orthographic", "obj", "/", "\0",
    "16385", "-2147483648", "4294967297", "v 1e300 -1e300 0\nl -1 -2", "l 1 2",
    "camera lookat 0 0 0 0 0 1 0 1 0\nprojection perspective 90 auto 1 9",
    "world rotate y 30", "world scale 0", "projection", "lookat", "auto",
};

/* One random edit of buf[0..*len): insert, delete or replace a few bytes. */
static void mutate(char *buf, size_t *len, size_t cap)
{
    size_t at = *len ? next() % *len : 0, n;
    const char *p = pieces[next() % (sizeof pieces / sizeof pieces[0])];
    size_t plen = p[0] ? strlen(p) : 1;

    switch (next() % 3) {
    case 0:                                  /* insert a piece */
        if (*len + plen > cap) return;
        memmove(buf + at + plen, buf + at, *len - at);
        memcpy(buf + at, p, plen);
        *len += plen;
        break;
    case 1:                                  /* delete a few bytes */
        n = next() % 8;
        if (at + n > *len) n = *len - at;
        memmove(buf + at, buf + at + n, *len - at - n);
        *len -= n;
        break;
    default:                                 /* overwrite one byte */
        if (*len) buf[at] = (char)(next() & 0xff);
    }
}

/* Replay every file of tests/fuzz/corpus/NAME through fn; returns how many
** files there were, and prints each one fn refused. */
static int replay(const char *name, int (*fn)(const uint8_t *, size_t), int *bad)
{
    char dir[256], path[1024];
    DIR *d;
    struct dirent *e;
    int files = 0;

    snprintf(dir, sizeof dir, "tests/fuzz/corpus/%s", name);
    if (!(d = opendir(dir))) return 0;
    while ((e = readdir(d)) != NULL) {
        FILE *in;
        char *buf;
        long n;
        if (e->d_name[0] == '.') continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        if (!(in = fopen(path, "rb"))) continue;
        if (fseek(in, 0, SEEK_END) != 0 || (n = ftell(in)) < 0 || fseek(in, 0, SEEK_SET) != 0 ||
            !(buf = malloc((size_t)n + 1)) ) { fclose(in); (*bad)++; continue; }
        if (fread(buf, 1, (size_t)n, in) != (size_t)n || fn((const uint8_t *)buf, (size_t)n) < 0) {
            printf("  %s: refused without a FILE:LINE:COL: error: message, or broke a promise\n",
                   path);
            (*bad)++;
        }
        free(buf);
        fclose(in);
        files++;
    }
    closedir(d);
    return files;
}

int main(void)
{
    static const char *const files[] = {
        "docs/examples/triangle.scene", "docs/examples/two-models.scene",
        "docs/examples/clip.scene", "docs/examples/behind.scene",
        "docs/examples/lookat-near.scene", "docs/examples/lookat-world.scene",
    };
    static char base[8192], buf[16384];
    size_t f;
    int k, good = 0, bad = 0, malformed = 0;

    for (f = 0; f < sizeof files / sizeof files[0]; f++) {
        FILE *in = fopen(files[f], "rb");
        size_t n = in ? fread(base, 1, sizeof base, in) : 0;
        if (in) fclose(in);
        PT_CHECK(files[f], n > 0);
        for (k = 0; k < 1500; k++) {
            size_t len = n, edits = 1 + next() % 4, e;
            int r;
            memcpy(buf, base, n);
            for (e = 0; e < edits; e++) mutate(buf, &len, sizeof buf);
            r = pt_fuzz_scene((const uint8_t *)buf, len);
            if (r == 0) good++;
            else if (r == 1) bad++;
            else malformed++;
        }
    }
    printf("test_fuzz: %d parsed, %d rejected\n", good, bad);
    PT_CHECK("fuzz-1.1 every rejection is one FILE:LINE:COL: error: message", malformed == 0);
    PT_CHECK("fuzz-1.2 the corruptions exercise both outcomes", good > 100 && bad > 100);
    {
        static const struct { const char *name; int (*fn)(const uint8_t *, size_t); } t[] = {
            { "scene", pt_fuzz_scene }, { "obj", pt_fuzz_obj },
            { "trace", pt_fuzz_trace }, { "image", pt_fuzz_image },
        };
        size_t i;
        for (i = 0; i < sizeof t / sizeof t[0]; i++) {
            int nbad = 0, n = replay(t[i].name, t[i].fn, &nbad);
            char d[128];
            printf("test_fuzz: tests/fuzz/corpus/%s: %d files\n", t[i].name, n);
            snprintf(d, sizeof d, "fuzz-2.%d the corpus of target %s is there", (int)i + 1, t[i].name);
            PT_CHECK(d, n > 0);
            snprintf(d, sizeof d, "fuzz-3.%d every file of tests/fuzz/corpus/%s passes", (int)i + 1,
                     t[i].name);
            PT_CHECK(d, nbad == 0);
        }
    }
    return pt_test_report();
}
