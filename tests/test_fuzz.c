/*
** tests/test_fuzz.c -- corrupted scenes never crash, hang or leak
** See LICENSE for copyright and license.
**
** Take each example scene, corrupt it in many small ways with a fixed random
** sequence (so every run is the same), and feed the result to the parser; when
** it parses, run the whole pipeline.  Each outcome must be either 0 with a
** scene, or -1 with one "NAME:LINE:COL: error: " message.  Run under
** `make sanitize` this also proves there is no memory error or undefined
** behaviour on these inputs.
*/
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "testhelp.h"
#include "core/pipeline.h"

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

static void quiet_vertex(void *ud, const pt_vrec *r) { (void)ud; (void)r; }

static int run_one(const char *text, size_t len)
{
    pt_scene s;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    char err[PT_ERRLEN];

    if (pt_scene_parse(&s, "fuzz", text, len, err, sizeof err) != 0)
        return strncmp(err, "fuzz:", 5) == 0 && strstr(err, ": error: ") != NULL ? 1 : -1;
    pt_options_default(&o);
    o.all_stages = 1;
    memset(&l, 0, sizeof l);
    l.sink.vertex = quiet_vertex;
    if (pt_plan_make(&p, &s, &o) == 0) {
        pt_run(&s, &p, &o, &l, NULL, &sum);
        pt_plan_free(&p);
    }
    pt_scene_free(&s);
    return 0;
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
            r = run_one(buf, len);
            if (r == 0) good++;
            else if (r == 1) bad++;
            else malformed++;
        }
    }
    printf("test_fuzz: %d parsed, %d rejected\n", good, bad);
    PT_CHECK("fuzz-1.1 every rejection is one FILE:LINE:COL: error: message", malformed == 0);
    PT_CHECK("fuzz-1.2 the corruptions exercise both outcomes", good > 100 && bad > 100);
    return pt_test_report();
}
