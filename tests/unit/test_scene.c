/*
** tests/unit/test_scene.c -- tests of the scene parser (src/core/scene.c)
** See LICENSE for copyright and license.
**
** Run from the repository root (the fixtures are in tests/data/).  Ids:
**   scene-1  good scenes: values, defaults, polylines, faces, comments, BOM, ...
**   scene-2  numbers and integers that must be refused
**   scene-3  directives: arguments, order, duplicates, names, indices, viewport
**   scene-4  bytes: NUL, control characters, CR, invalid UTF-8
**   scene-5  files: load, obj includes, errors inside OBJ files
**   scene-6  a plain .obj wrapped in a default scene
**   scene-7  the API's edges: zeroed scenes, small or missing err buffers
** A few tests write a file under /tmp (pt_test_scene_*) and remove it again.
*/
#include <stdlib.h>
#include <string.h>

#include "testhelp.h"
#include "core/scene.h"

static char err[PT_ERRLEN];

/* Is *s empty, as after pt_scene_free()? */
static int is_empty(const pt_scene *s)
{
    return s->path == NULL && s->models == NULL && s->nmodels == 0
        && s->cap_models == 0 && s->fb_w == 0 && s->fb_h == 0
        && s->vp_w == 0 && s->perspective == 0 && s->from_obj == 0;
}

/* Parse text[0..len) as "t.scene".  *s starts as garbage on purpose. */
static int parse_n(pt_scene *s, const char *text, size_t len)
{
    memset(s, 0xA5, sizeof *s);
    err[0] = '\0';
    return pt_scene_parse(s, "t.scene", text, len, err, sizeof err);
}

static int parse(pt_scene *s, const char *text)
{
    return parse_n(s, text, strlen(text));
}

/* Check that parsing text[0..len) fails with a one-line message that begins
** with prefix and contains word, and leaves the scene empty. */
static void bad_n(const char *id, const char *text, size_t len,
                  const char *prefix, const char *word)
{
    pt_scene s;
    int r = parse_n(&s, text, len);
    int ok = r == -1 && strncmp(err, prefix, strlen(prefix)) == 0
        && strstr(err, word) != NULL && strchr(err, '\n') == NULL && is_empty(&s);

    PT_CHECK(id, ok);
    if (!ok)
        printf("    got %d: %s\n    want: %s ... %s\n", r, err, prefix, word);
    pt_scene_free(&s);
}

static void bad(const char *id, const char *text, const char *prefix,
                const char *word)
{
    bad_n(id, text, strlen(text), prefix, word);
}

/* Like bad(), for pt_scene_load(path). */
static void bad_load(const char *id, const char *path, const char *prefix,
                     const char *word)
{
    pt_scene s;
    int r, ok;

    memset(&s, 0xA5, sizeof s);
    err[0] = '\0';
    r = pt_scene_load(&s, path, err, sizeof err);
    ok = r == -1 && strncmp(err, prefix, strlen(prefix)) == 0
        && strstr(err, word) != NULL && strchr(err, '\n') == NULL && is_empty(&s);
    PT_CHECK(id, ok);
    if (!ok)
        printf("    got %d: %s\n    want: %s ... %s\n", r, err, prefix, word);
    pt_scene_free(&s);
}

/* Does model m have segment i == (a, b)? */
static int seg_is(const pt_model *m, size_t i, uint32_t a, uint32_t b)
{
    return i < m->nseg && m->seg[i].a == a && m->seg[i].b == b;
}

static int vec_is(pt_vec3 v, double x, double y, double z)
{
    return v.x == x && v.y == y && v.z == z;
}

/* Write the string text to path; returns 0 or -1. */
static int write_file(const char *path, const char *text)
{
    FILE *f = fopen(path, "wb");
    size_t len = strlen(text);
    int ok;

    if (f == NULL)
        return -1;
    ok = fwrite(text, 1, len, f) == len;
    return fclose(f) == 0 && ok ? 0 : -1;
}

/* A new string: head, then unit repeated n times, then tail. */
static char *repeat(const char *head, const char *unit, size_t n, const char *tail)
{
    size_t lh = strlen(head), lu = strlen(unit), lt = strlen(tail), i;
    char *s = malloc(lh + lu * n + lt + 1), *p;

    if (s == NULL)
        return NULL;
    memcpy(s, head, lh);
    p = s + lh;
    for (i = 0; i < n; i++, p += lu)
        memcpy(p, unit, lu);
    memcpy(p, tail, lt + 1);
    return s;
}

/* ------------------------------------------------------------ scene-1 */

static void test_defaults(void)
{
    pt_scene s;
    int r;

    r = parse(&s, "");
    PT_CHECK("scene-1.1 empty scene parses", r == 0);
    PT_CHECK("scene-1.1 empty scene: framebuffer 800x600", s.fb_w == 800 && s.fb_h == 600);
    PT_CHECK("scene-1.1 empty scene: viewport = whole framebuffer",
             s.vp_x == 0 && s.vp_y == 0 && s.vp_w == 800 && s.vp_h == 600);
    PT_CHECK("scene-1.1 empty scene: black background, perspective",
             s.background[0] == 0 && s.background[1] == 0 && s.background[2] == 0
             && s.perspective == 1);
    PT_CHECK("scene-1.1 empty scene: no models, not from obj, path kept",
             s.nmodels == 0 && s.from_obj == 0 && s.path && strcmp(s.path, "t.scene") == 0);
    pt_scene_free(&s);

    r = parse(&s, "# only a comment\n\n   \t \n#another\n");
    PT_CHECK("scene-1.2 comments and blank lines only", r == 0 && s.nmodels == 0 && s.fb_w == 800);
    pt_scene_free(&s);

    memset(&s, 0xA5, sizeof s);
    r = pt_scene_parse(&s, "t.scene", NULL, 0, err, sizeof err);
    PT_CHECK("scene-1.3 NULL text of length 0 is an empty scene", r == 0 && s.nmodels == 0);
    pt_scene_free(&s);

    r = parse(&s, "model m\n");
    PT_CHECK("scene-1.4 model defaults: white, untranslated, empty",
             r == 0 && s.nmodels == 1 && strcmp(s.models[0].name, "m") == 0
             && s.models[0].color[0] == 255 && s.models[0].color[1] == 255
             && s.models[0].color[2] == 255 && vec_is(s.models[0].translate, 0, 0, 0)
             && s.models[0].nv == 0 && s.models[0].nseg == 0);
    pt_scene_free(&s);
}

static void test_values(void)
{
    pt_scene s;
    const pt_model *m;
    int r;

    r = parse(&s,
              "framebuffer 640 +480\n"
              "background 1 2 255\n"
              "viewport 10 20 300 400\n"
              "camera orthographic\n"
              "model cube\n"
              "translate -1.5 2e3 .25\n"
              "color 0 128 255\n"
              "v 0.1 -2.5e-3 +.5\n"
              "v 1. 1E+2 -0\n"
              "v 0.30000000000000004 4.9e-324 1e-400\n"
              "v 1 2 3 0.5\n");
    PT_CHECK("scene-1.5 full scene parses", r == 0);
    if (r != 0) {
        printf("    %s\n", err);
        return;
    }
    m = &s.models[0];
    PT_CHECK("scene-1.5 framebuffer 640 480 (with '+')", s.fb_w == 640 && s.fb_h == 480);
    PT_CHECK("scene-1.5 background", s.background[0] == 1 && s.background[1] == 2
             && s.background[2] == 255);
    PT_CHECK("scene-1.5 viewport", s.vp_x == 10 && s.vp_y == 20 && s.vp_w == 300 && s.vp_h == 400);
    PT_CHECK("scene-1.5 camera orthographic", s.perspective == 0);
    PT_CHECK("scene-1.5 translate parsed exactly", vec_is(m->translate, -1.5, 2000.0, 0.25));
    PT_CHECK("scene-1.5 color", m->color[0] == 0 && m->color[1] == 128 && m->color[2] == 255);
    PT_CHECK("scene-1.5 four vertices (w accepted)", m->nv == 4);
    PT_CHECK("scene-1.5 vertex values exact", m->nv == 4 && vec_is(m->v[0], 0.1, -2.5e-3, 0.5));
    PT_CHECK("scene-1.5 '1.' and 'E+2' forms", m->nv == 4 && vec_is(m->v[1], 1.0, 100.0, 0.0));
    PT_CHECK("scene-1.5 17 digits, subnormal, underflow to 0",
             m->nv == 4 && vec_is(m->v[2], 0.30000000000000004, 4.9e-324, 0.0));
    PT_CHECK("scene-1.5 w is ignored", m->nv == 4 && vec_is(m->v[3], 1, 2, 3));
    pt_scene_free(&s);

    r = parse(&s, "camera perspective\n");
    PT_CHECK("scene-1.6 camera perspective", r == 0 && s.perspective == 1);
    pt_scene_free(&s);

    r = parse(&s, "framebuffer 16384 1\nviewport 16383 0 1 1\n");
    PT_CHECK("scene-1.7 framebuffer and viewport at the limits",
             r == 0 && s.fb_w == 16384 && s.fb_h == 1 && s.vp_x == 16383);
    pt_scene_free(&s);
}

static void test_order(void)
{
    pt_scene s;
    int r;

    r = parse(&s, "model a\nv 0 0 0\nframebuffer 40 60\nv 1 1 1\n"
                  "viewport 10 20 30 40\nbackground 9 9 9\ncamera orthographic\n"
                  "model b\ncolor 1 1 1\nv 2 2 2\ntranslate 5 5 5\n");
    PT_CHECK("scene-1.8 scene directives after models, viewport fits exactly",
             r == 0 && s.fb_w == 40 && s.vp_w == 30 && s.nmodels == 2
             && s.models[0].nv == 2 && s.models[1].nv == 1
             && vec_is(s.models[1].translate, 5, 5, 5) && s.models[1].color[0] == 1);
    pt_scene_free(&s);

    r = parse(&s, "viewport 0 0 1000 700\nframebuffer 1000 700\n");
    PT_CHECK("scene-1.9 viewport before a larger framebuffer", r == 0 && s.vp_w == 1000);
    pt_scene_free(&s);

    r = parse(&s, "model a\ntranslate 1 2 3\ncolor 1 2 3\nmodel b\ntranslate 4 5 6\ncolor 4 5 6\n");
    PT_CHECK("scene-1.10 translate and color once per model, in each model",
             r == 0 && vec_is(s.models[0].translate, 1, 2, 3)
             && vec_is(s.models[1].translate, 4, 5, 6) && s.models[1].color[2] == 6);
    pt_scene_free(&s);
}

static void test_polylines(void)
{
    pt_scene s;
    const pt_model *m;
    int r;

    r = parse(&s, "model m\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                  "l 1 2 3\n"            /* 0-1 1-2 */
                  "f 1 2 3 4\n"          /* 0-1 1-2 2-3 3-0 */
                  "l -1 -4\n"            /* 3-0 */
                  "f 1/1 2//3 +3/4/5\n"  /* 0-1 1-2 2-0 */
                  "l 2 2\n");            /* 1-1: degenerate but fine */
    PT_CHECK("scene-1.11 polylines and faces parse", r == 0);
    if (r != 0) {
        printf("    %s\n", err);
        return;
    }
    m = &s.models[0];
    PT_CHECK("scene-1.11 segment count", m->nseg == 2 + 4 + 1 + 3 + 1);
    PT_CHECK("scene-1.12 polyline I-J, J-K", seg_is(m, 0, 0, 1) && seg_is(m, 1, 1, 2));
    PT_CHECK("scene-1.13 face closed last-first", seg_is(m, 2, 0, 1) && seg_is(m, 3, 1, 2)
             && seg_is(m, 4, 2, 3) && seg_is(m, 5, 3, 0));
    PT_CHECK("scene-1.14 negative indices count back", seg_is(m, 6, 3, 0));
    PT_CHECK("scene-1.15 v/vt/vn forms use the v part", seg_is(m, 7, 0, 1)
             && seg_is(m, 8, 1, 2) && seg_is(m, 9, 2, 0));
    PT_CHECK("scene-1.16 repeated index", seg_is(m, 10, 1, 1));
    pt_scene_free(&s);

    r = parse(&s, "model m\nv 0 0 0\nv 1 0 0\nl -1 -2\nv 2 0 0\nl -1 -2\n");
    PT_CHECK("scene-1.17 -1 is the latest vertex so far",
             r == 0 && seg_is(&s.models[0], 0, 1, 0) && seg_is(&s.models[0], 1, 2, 1));
    pt_scene_free(&s);

    r = parse(&s, "model a\nv 0 0 0\nv 1 1 1\nmodel b\nv 5 5 5\nv 6 6 6\nl 1 2\n");
    PT_CHECK("scene-1.18 indices count within the model",
             r == 0 && s.models[1].nseg == 1 && seg_is(&s.models[1], 0, 0, 1)
             && s.models[0].nseg == 0);
    pt_scene_free(&s);
}

static void test_text_forms(void)
{
    pt_scene s;
    char *text;
    int r;

    r = parse(&s, "\xEF\xBB\xBFmodel m\nv 1 2 3\n");
    PT_CHECK("scene-1.19 byte-order mark skipped", r == 0 && s.nmodels == 1
             && strcmp(s.models[0].name, "m") == 0);
    pt_scene_free(&s);

    r = parse(&s, "framebuffer 10 20\r\nmodel m\r\nv 1 2 3\r\nl 1 1\r\n\r\n");
    PT_CHECK("scene-1.20 CRLF line ends", r == 0 && s.fb_h == 20
             && strcmp(s.models[0].name, "m") == 0 && vec_is(s.models[0].v[0], 1, 2, 3)
             && s.models[0].nseg == 1);
    pt_scene_free(&s);

    r = parse(&s, "# head\nmodel m # the model\n  v 1 2 3#no space\n\t# indented\n"
                  "v 4 5 6 # w comes later\nl 1 2 # a segment\ncolor 1 2 3#c\n"
                  "# v 9 9 9\nmodel n#ame\n");
    PT_CHECK("scene-1.21 comments anywhere", r == 0 && s.nmodels == 2
             && s.models[0].nv == 2 && vec_is(s.models[0].v[0], 1, 2, 3)
             && s.models[0].nseg == 1 && s.models[0].color[2] == 3
             && strcmp(s.models[1].name, "n") == 0);
    pt_scene_free(&s);

    r = parse(&s, "model\tm\nv\t1 \t 2\t\t3   \n");
    PT_CHECK("scene-1.22 tabs separate tokens", r == 0 && strcmp(s.models[0].name, "m") == 0
             && vec_is(s.models[0].v[0], 1, 2, 3));
    pt_scene_free(&s);

    r = parse(&s, "model caf\xC3\xA9-\xE2\x82\xAC-\xF0\x9F\x98\x80\n");
    PT_CHECK("scene-1.23 UTF-8 model name", r == 0
             && strcmp(s.models[0].name, "caf\xC3\xA9-\xE2\x82\xAC-\xF0\x9F\x98\x80") == 0);
    pt_scene_free(&s);

    /* The text ends without a newline, right after a number: the parser must
    ** not read past the buffer (ASan and valgrind watch this one). */
    text = malloc(15);
    if (text != NULL) {
        memcpy(text, "model m\nv 1 2 3", 15);
        r = parse_n(&s, text, 15);
        PT_CHECK("scene-1.24 text not NUL-terminated, no final newline",
                 r == 0 && s.models[0].nv == 1 && vec_is(s.models[0].v[0], 1, 2, 3));
        pt_scene_free(&s);
        free(text);
    }
}

static void test_long_lines(void)
{
    pt_scene s;
    char *text;
    int r;

    /* 51200 indices: a line of 100 KiB + 3 bytes */
    text = repeat("model m\nv 0 0 0\nv 1 1 1\nl", " 1 2", 25600, "\n");
    r = text ? parse(&s, text) : -1;
    PT_CHECK("scene-1.25 l line of 100 KiB", r == 0 && s.models[0].nseg == 51199
             && seg_is(&s.models[0], 51198, 0, 1));
    pt_scene_free(&s);
    free(text);

    text = repeat("# ", "comment ", 12800, "\nmodel m\n");
    r = text ? parse(&s, text) : -1;
    PT_CHECK("scene-1.26 comment of 100 KiB", r == 0 && s.nmodels == 1);
    pt_scene_free(&s);
    free(text);

    /* "1" and 102400 zeros, times 10^-102400: exactly 1 */
    text = repeat("model m\nv 1", "0", 102400, "e-102400 -0.5 2\n");
    r = text ? parse(&s, text) : -1;
    PT_CHECK("scene-1.27 number of 100 KiB", r == 0 && vec_is(s.models[0].v[0], 1, -0.5, 2));
    pt_scene_free(&s);
    free(text);

    text = repeat("model ", "n", 102400, "\n");
    r = text ? parse(&s, text) : -1;
    PT_CHECK("scene-1.28 model name of 100 KiB", r == 0 && strlen(s.models[0].name) == 102400);
    pt_scene_free(&s);
    free(text);

    text = repeat("model m\nv 0 0 0\nl 1 ", "1", 102400, "\n");
    r = text ? parse(&s, text) : -1;
    PT_CHECK("scene-1.29 huge index is an error, not an overflow",
             r == -1 && strncmp(err, "t.scene:3:5: error: index 111", 29) == 0
             && strstr(err, "...") != NULL && strlen(err) < 200);
    pt_scene_free(&s);
    free(text);
}

/* ------------------------------------------------------------ scene-2 */

static void test_numbers(void)
{
    bad("scene-2.1 decimal comma rejected", "model m\nv 1 2 1,5\n",
        "t.scene:2:7: error:", "'1,5' is not a decimal number");
    bad("scene-2.2 hex integer rejected", "model m\nv 0x10 0 0\n",
        "t.scene:2:3: error:", "'0x10' is not a decimal number");
    bad("scene-2.3 hex float rejected", "model m\nv 0 0x1p3 0\n",
        "t.scene:2:5: error:", "'0x1p3' is not a decimal number");
    bad("scene-2.4 inf rejected", "model m\nv inf 0 0\n",
        "t.scene:2:3: error:", "not a decimal number");
    bad("scene-2.5 nan rejected", "model m\nv 0 0 nan\n",
        "t.scene:2:7: error:", "not a decimal number");
    bad("scene-2.6 infinity rejected", "model m\nv -Infinity 0 0\n",
        "t.scene:2:3: error:", "not a decimal number");
    bad("scene-2.7 suffix rejected", "model m\nv 1f 0 0\n",
        "t.scene:2:3: error:", "'1f' is not a decimal number");
    bad("scene-2.8 lone point rejected", "model m\nv . 0 0\n",
        "t.scene:2:3: error:", "not a decimal number");
    bad("scene-2.9 exponent without digits", "model m\nv 1e 0 0\n",
        "t.scene:2:3: error:", "not a decimal number");
    bad("scene-2.10 exponent sign without digits", "model m\nv 1e+ 0 0\n",
        "t.scene:2:3: error:", "not a decimal number");
    bad("scene-2.11 double sign", "model m\nv --1 0 0\n",
        "t.scene:2:3: error:", "not a decimal number");
    bad("scene-2.12 two points", "model m\nv 1.2.3 0 0\n",
        "t.scene:2:3: error:", "not a decimal number");
    bad("scene-2.13 sign alone", "model m\nv - 0 0\n",
        "t.scene:2:3: error:", "not a decimal number");
    bad("scene-2.14 overflow to infinity", "model m\nv 0 0 1e400\n",
        "t.scene:2:7: error:", "coordinate '1e400' is not finite");
    bad("scene-2.15 negative overflow", "model m\nv -1e400 0 0\n",
        "t.scene:2:3: error:", "not finite");
    bad("scene-2.16 translation overflow", "model m\ntranslate 0 1e999 0\n",
        "t.scene:2:13: error:", "translation '1e999' is not finite");
    bad("scene-2.17 w checked too", "model m\nv 0 0 0 w\n",
        "t.scene:2:9: error:", "not a decimal number");
    bad("scene-2.18 integer out of range, no overflow",
        "framebuffer 99999999999999999999 600\n",
        "t.scene:1:13: error:", "out of range");
    bad("scene-2.19 negative integer out of range",
        "framebuffer 800 -99999999999999999999999999\n",
        "t.scene:1:17: error:", "out of range");
    bad("scene-2.20 integer with a point", "framebuffer 800.0 600\n",
        "t.scene:1:13: error:", "'800.0' is not an integer");
    bad("scene-2.21 hex integer", "background 0 0x10 0\n",
        "t.scene:1:14: error:", "not an integer");
    bad("scene-2.22 integer with exponent", "framebuffer 8e2 600\n",
        "t.scene:1:13: error:", "not an integer");
    bad("scene-2.23 framebuffer width 0", "framebuffer 0 600\n",
        "t.scene:1:13: error:", "framebuffer width 0 is out of range (1..16384)");
    bad("scene-2.24 framebuffer height 16385", "framebuffer 800 16385\n",
        "t.scene:1:17: error:", "out of range");
    bad("scene-2.25 background 256", "background 0 256 0\n",
        "t.scene:1:14: error:", "out of range");
    bad("scene-2.26 color -1", "model m\ncolor 0 0 -1\n",
        "t.scene:2:11: error:", "out of range");
    bad("scene-2.27 color 1.0", "model m\ncolor 1.0 0 0\n",
        "t.scene:2:7: error:", "not an integer");
    bad("scene-2.28 viewport x -16385", "viewport -16385 0 10 10\n",
        "t.scene:1:10: error:", "out of range");
    bad("scene-2.29 viewport width 0", "viewport 0 0 0 10\n",
        "t.scene:1:14: error:", "out of range");
    bad("scene-2.30 empty sign integer", "framebuffer + 600\n",
        "t.scene:1:13: error:", "not an integer");
    bad("scene-2.31 long bad token quoted short",
        "model m\nv 0 0 xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx\n",
        "t.scene:2:7: error: 'xxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxxx...'", "not a decimal");
}

/* ------------------------------------------------------------ scene-3 */

static void test_directives(void)
{
    static const char *const need_model[] = {
        "translate 1 2 3", "color 1 2 3", "v 1 2 3", "l 1 2", "f 1 2 3", "obj x.obj"
    };
    char text[64], word[64];
    size_t i;

    bad("scene-3.1 unknown directive", "model m\n  foo 1 2\n",
        "t.scene:2:3: error:", "unknown directive 'foo'");
    bad("scene-3.2 OBJ-only keyword in a scene", "model m\nvt 0 0\n",
        "t.scene:2:1: error:", "unknown directive 'vt'");
    bad("scene-3.3 directives are case-sensitive", "Model m\n",
        "t.scene:1:1: error:", "unknown directive 'Model'");
    for (i = 0; i < sizeof need_model / sizeof need_model[0]; i++) {
        size_t n = strcspn(need_model[i], " ");
        snprintf(text, sizeof text, "# c\n%s\nmodel m\n", need_model[i]);
        snprintf(word, sizeof word, "'%.*s' before any 'model'", (int)n, need_model[i]);
        bad("scene-3.4 model directive before any model", text, "t.scene:2:1: error:", word);
    }

    bad("scene-3.5 duplicate framebuffer",
        "framebuffer 10 10\nmodel m\nframebuffer 10 10\n",
        "t.scene:3:1: error:", "duplicate 'framebuffer' (first at line 1)");
    bad("scene-3.6 duplicate viewport", "viewport 0 0 1 1\n\nviewport 0 0 1 1\n",
        "t.scene:3:1: error:", "duplicate 'viewport' (first at line 1)");
    bad("scene-3.7 duplicate background", "model m\nbackground 1 1 1\n background 1 1 1\n",
        "t.scene:3:2: error:", "duplicate 'background' (first at line 2)");
    bad("scene-3.8 duplicate camera, after models",
        "camera perspective\nmodel a\nmodel b\ncamera perspective\n",
        "t.scene:4:1: error:", "duplicate 'camera' (first at line 1)");
    bad("scene-3.9 duplicate translate in a model",
        "model m\ntranslate 0 0 0\nv 1 1 1\ntranslate 1 1 1\n",
        "t.scene:4:1: error:", "duplicate 'translate' (first at line 2)");
    bad("scene-3.10 duplicate color in a model",
        "model a\ncolor 1 1 1\nmodel m\ncolor 1 1 1\nv 1 1 1\ncolor 2 2 2\n",
        "t.scene:6:1: error:", "duplicate 'color' (first at line 4)");
    bad("scene-3.11 duplicate model name", "model a\nmodel b\n\nmodel a\n",
        "t.scene:4:7: error:", "duplicate model name 'a' (first at line 1)");
    bad("scene-3.12 model name with '\"'", "model a\"b\n",
        "t.scene:1:8: error:", "may not contain '\"'");
    bad("scene-3.13 model name with '\\'", "model a\\b\n",
        "t.scene:1:8: error:", "may not contain '\\'");
    bad("scene-3.14 model name with ','", "model ,ab\n",
        "t.scene:1:7: error:", "may not contain ','");

    bad("scene-3.15 model without a name", "model\n",
        "t.scene:1:1: error:", "expected 1 name after 'model', found 0");
    bad("scene-3.16 model name and position, then a third word", "model a b c\n",
        "t.scene:1:11: error:", "expected at most 2 names after 'model', found 3");
    bad("scene-3.17 framebuffer with 1 number", "framebuffer 800\n",
        "t.scene:1:1: error:", "expected 2 integers after 'framebuffer', found 1");
    bad("scene-3.18 framebuffer with 3 numbers", "framebuffer 8 6 4\n",
        "t.scene:1:17: error:", "expected 2 integers after 'framebuffer', found 3");
    bad("scene-3.19 v with 2 numbers", "model m\nv 1 2\n",
        "t.scene:2:1: error:", "expected 3 numbers after 'v', found 2");
    bad("scene-3.20 v with 5 numbers", "model m\nv 1 2 3 4 5\n",
        "t.scene:2:11: error:", "expected at most 4 numbers after 'v', found 5");
    bad("scene-3.21 v with nothing", "model m\nv   # none\n",
        "t.scene:2:1: error:", "found 0");
    bad("scene-3.22 camera without a type", "camera\n",
        "t.scene:1:1: error:", "expected 1 word after 'camera', found 0");
    bad("scene-3.23 unknown camera", "camera fisheye\n",
        "t.scene:1:8: error:", "unknown camera 'fisheye'");
    bad("scene-3.24 viewport with 3 numbers", "viewport 0 0 10\n",
        "t.scene:1:1: error:", "expected 4 integers after 'viewport', found 3");
    bad("scene-3.25 background with 4 numbers", "background 1 2 3 4\n",
        "t.scene:1:18: error:", "found 4");
    bad("scene-3.26 translate with 2 numbers", "model m\ntranslate 1 2\n",
        "t.scene:2:1: error:", "expected 3 numbers after 'translate', found 2");
    bad("scene-3.27 color with 4 numbers", "model m\ncolor 1 2 3 4\n",
        "t.scene:2:13: error:", "expected 3 integers after 'color', found 4");
    bad("scene-3.28 camera with 2 words", "camera perspective orthographic\n",
        "t.scene:1:8: error:", "expected L R B T [FOCAL] after 'camera perspective', found 1");
}

static void test_indices(void)
{
    const char *four = "model m\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
    char text[256];

    bad("scene-3.29 l with 1 index", "model m\nv 0 0 0\nl 1\n",
        "t.scene:3:1: error:", "expected at least 2 indices after 'l', found 1");
    bad("scene-3.30 l with no index", "model m\nl\n",
        "t.scene:2:1: error:", "expected at least 2 indices after 'l', found 0");
    bad("scene-3.31 f with 2 indices", "model m\nv 0 0 0\nv 1 1 1\nf 1 2\n",
        "t.scene:4:1: error:", "expected at least 3 indices after 'f', found 2");

    snprintf(text, sizeof text, "%sl 0 1\n", four);
    bad("scene-3.32 index 0", text, "t.scene:6:3: error:",
        "index 0 is not valid (indices start at 1)");
    snprintf(text, sizeof text, "%sl 1 5\n", four);
    bad("scene-3.33 index past the end", text, "t.scene:6:5: error:",
        "index 5 refers past the 4 vertices defined so far");
    snprintf(text, sizeof text, "%sf 1 2 -5\n", four);
    bad("scene-3.34 negative index before the start", text, "t.scene:6:7: error:",
        "index -5 refers before the first of the 4 vertices");
    bad("scene-3.35 forward reference", "model m\nv 0 0 0\nl 1 2\nv 1 1 1\n",
        "t.scene:3:5: error:", "index 2 refers past the 1 vertex defined so far");
    bad("scene-3.36 indices of an earlier model are not in scope",
        "model a\nv 0 0 0\nv 1 1 1\nmodel b\nl 1 2\n",
        "t.scene:5:3: error:", "past the 0 vertices");
    snprintf(text, sizeof text, "%sl 1 99999999999999999999\n", four);
    bad("scene-3.37 huge index", text, "t.scene:6:5: error:",
        "index 99999999999999999999 refers past");
    snprintf(text, sizeof text, "%sl 1 -99999999999999999999\n", four);
    bad("scene-3.38 huge negative index", text, "t.scene:6:5: error:", "refers before");
    snprintf(text, sizeof text, "%sl 1 x\n", four);
    bad("scene-3.39 index not a number", text, "t.scene:6:5: error:",
        "'x' is not a vertex index");
    snprintf(text, sizeof text, "%sl 1 1.5\n", four);
    bad("scene-3.40 index with a point", text, "t.scene:6:5: error:", "not a vertex index");
    snprintf(text, sizeof text, "%sf 1/ 2 3\n", four);
    bad("scene-3.41 index form '1/'", text, "t.scene:6:3: error:", "not a vertex index");
    snprintf(text, sizeof text, "%sf 1 2// 3\n", four);
    bad("scene-3.42 index form '2//'", text, "t.scene:6:5: error:", "not a vertex index");
    snprintf(text, sizeof text, "%sf 1 2 /3\n", four);
    bad("scene-3.43 index form '/3'", text, "t.scene:6:7: error:", "not a vertex index");
    snprintf(text, sizeof text, "%sf 1/2/3/4 2 3\n", four);
    bad("scene-3.44 index form with three '/'", text, "t.scene:6:3: error:",
        "not a vertex index");
    snprintf(text, sizeof text, "%sf 1/a 2 3\n", four);
    bad("scene-3.45 texture index not a number", text, "t.scene:6:3: error:",
        "not a vertex index");
    snprintf(text, sizeof text, "%sf 1//2.0 2 3\n", four);
    bad("scene-3.46 normal index not an integer", text, "t.scene:6:3: error:",
        "not a vertex index");
    snprintf(text, sizeof text, "%sf 0/1/1 2 3\n", four);
    bad("scene-3.47 index 0 in a v/vt/vn form", text, "t.scene:6:3: error:",
        "index 0 is not valid");
}

static void test_viewport(void)
{
    static const char lookat[] = "camera lookat 0 0 5 0 0 -1 0 1 0\n"
                                 "projection perspective 60 auto 0.1 100\n";
    char text[512];
    pt_scene s;
    int r;

    /* the course's renderers draw a viewport that sticks out (setViewport
    ** checks nothing): on any side, wholly outside, larger than the
    ** framebuffer, negative corners down to -PT_MAX_SIZE */
    r = parse(&s, "viewport 10 10 800 600\n");
    PT_CHECK("scene-3.48 viewport sticking out of the default framebuffer: taken",
             r == 0 && s.vp_x == 10 && s.vp_y == 10 && s.vp_w == 800 && s.vp_h == 600 &&
             !pt_scene_vp_inside(&s));
    pt_scene_free(&s);
    r = parse(&s, "model m\n  viewport -5 -7 100 100\nv 0 0 0\nframebuffer 50 200\n");
    PT_CHECK("scene-3.49 negative corner, a later framebuffer",
             r == 0 && s.vp_x == -5 && s.vp_y == -7 && s.fb_w == 50 && !pt_scene_vp_inside(&s));
    pt_scene_free(&s);
    r = parse(&s, "renderer 7\nframebuffer 40 60\nviewport -16384 16384 16384 16384\n");
    PT_CHECK("scene-3.50 renderer 7: wholly outside, at the limits",
             r == 0 && s.vp_x == -16384 && s.vp_y == 16384 && s.vp_w == 16384);
    pt_scene_free(&s);
    r = parse(&s, "renderer 9\nframebuffer 40 60\nviewport 30 -2 40 70\n");
    PT_CHECK("scene-3.51 renderer 9: wider and taller than the framebuffer",
             r == 0 && s.vp_w == 40 && s.vp_h == 70);
    pt_scene_free(&s);
    r = parse(&s, "framebuffer 40 60\nviewport 10 20 30 40\n");
    PT_CHECK("scene-3.52 a viewport that fits exactly is inside",
             r == 0 && pt_scene_vp_inside(&s));
    pt_scene_free(&s);
    bad("scene-3.53 viewport x beyond the limit", "viewport 16385 0 1 1\n",
        "t.scene:1:10: error:", "out of range");
    bad("scene-3.54 viewport y below the limit", "viewport 0 -16385 1 1\n",
        "t.scene:1:12: error:", "out of range");
    bad("scene-3.55 viewport height 0", "viewport -3 0 1 0\n",
        "t.scene:1:17: error:", "out of range");
    /* the matrix camera keeps the rule */
    snprintf(text, sizeof text, "%sviewport 10 10 800 600\n", lookat);
    bad("scene-3.56 matrix camera: a viewport sticking out is refused", text,
        "t.scene:3:1: error:", "viewport 10 10 800 600 does not fit in the 800x600 framebuffer "
        "(the matrix camera");
    snprintf(text, sizeof text, "model m\n  viewport 0 0 100 100\nv 0 0 0\n%sframebuffer 50 200\n",
             lookat);
    bad("scene-3.57 ... checked against a later framebuffer", text,
        "t.scene:2:3: error:", "does not fit in the 50x200 framebuffer");
    snprintf(text, sizeof text, "%sframebuffer 40 60\nviewport -1 0 30 40\n", lookat);
    bad("scene-3.58 ... a negative corner too", text, "t.scene:4:1: error:", "does not fit");
    snprintf(text, sizeof text, "%sframebuffer 40 60\nviewport 10 20 30 40\n", lookat);
    r = parse(&s, text);
    PT_CHECK("scene-3.59 ... one inside is taken", r == 0 && pt_scene_vp_inside(&s));
    pt_scene_free(&s);
}

/* An obj file of text that is no OBJ: the error is at its 1:1 and quotes
** none of the text (the file could be /etc/passwd or a key). */
static void obj_secret(const char *id, const char *text)
{
    FILE *f = fopen("/tmp/pt_test_scene_secret.obj", "w");
    pt_scene s;
    int r, ok;

    if (f != NULL) {
        fputs(text, f);
        fclose(f);
    }
    err[0] = '\0';
    r = parse(&s, "model m\nobj /tmp/pt_test_scene_secret.obj\n");
    ok = r == -1 && strncmp(err, "/tmp/pt_test_scene_secret.obj:1:1: error: not an OBJ "
                            "statement", 61) == 0
        && strstr(err, "secret-first") == NULL && strstr(err, "secretsecret") == NULL
        && strstr(err, "Word") == NULL && strstr(err, "root") == NULL;
    PT_CHECK(id, ok);
    if (!ok)
        printf("    got %d: %s\n", r, err);
    pt_scene_free(&s);
    remove("/tmp/pt_test_scene_secret.obj");
}

static void test_obj_lines(void)
{
    bad("scene-3.52 obj without a path", "model m\nobj\n",
        "t.scene:2:1: error:", "expected a file name after 'obj'");
    bad("scene-3.53 obj with only a comment", "model m\nobj   # nothing\n",
        "t.scene:2:1: error:", "expected a file name");
    bad("scene-3.54 obj file missing (relative to the current directory)",
        "model m\nobj  tests/data/no_such.obj  # c\n",
        "t.scene:2:6: error:", "cannot read 'tests/data/no_such.obj'");
    bad("scene-3.55 obj path is a directory", "model m\nobj tests/data\n",
        "t.scene:2:5: error:", "cannot read 'tests/data'");
    /* 2025 issue 31: `obj /dev/zero` was read until its first NUL, and an
    ** obj FIFO blocked forever; obj reads regular files only (tests/cli/cli.sh
    ** cli-7.1 has the FIFO). */
    bad("scene-3.56 obj of a character device (/dev/zero) is refused at once",
        "model m\nobj /dev/zero\n", "t.scene:2:5: error:",
        "cannot read '/dev/zero': it is a character device, not a regular file");
    bad("scene-3.57 ... and so is /dev/null", "model m\nobj /dev/null\n",
        "t.scene:2:5: error:", "it is a character device, not a regular file");
    /* 2025 issue 31: `obj /etc/passwd` printed its first line in the error. */
    obj_secret("scene-3.58 a line of an obj file that is not OBJ is not quoted",
               "root:x:0:0:secret-first-line\n");
    obj_secret("scene-3.59 ... nor is a long word", "secretsecretsecretsecret\n");
    obj_secret("scene-3.60 ... nor a word of other characters", "p4ss-Word!\n");
}

/* ------------------------------------------------------------ scene-4 */

static void test_bytes(void)
{
    static const char nul[] = "model m\nv 1 \0 2\n";
    static const char nul_comment[] = "model m # \0\n";

    bad_n("scene-4.1 NUL byte", nul, sizeof nul - 1, "t.scene:2:5: error:", "NUL byte");
    bad_n("scene-4.2 NUL byte in a comment", nul_comment, sizeof nul_comment - 1,
          "t.scene:1:11: error:", "NUL byte");
    bad("scene-4.3 control character", "model m\x01\n", "t.scene:1:8: error:",
        "control character 0x01");
    bad("scene-4.4 escape", "# \x1b[31m red\n", "t.scene:1:3: error:", "control character 0x1b");
    bad("scene-4.5 DEL", "model m\nv 1 2 3\x7f\n", "t.scene:2:8: error:",
        "control character 0x7f");
    bad("scene-4.6 form feed is not a separator", "model\x0cm\n", "t.scene:1:6: error:",
        "control character 0x0c");
    bad("scene-4.7 lone CR inside a line", "model m\nv 1\r2 3\r\n",
        "t.scene:2:4: error:", "carriage return");
    bad("scene-4.8 old Mac line ends", "model m\rv 1 2 3\r", "t.scene:1:8: error:",
        "carriage return");
    bad("scene-4.9 CR at the very end", "model m\r", "t.scene:1:8: error:",
        "carriage return");
    bad("scene-4.10 CR CR LF", "model m\r\r\n", "t.scene:1:8: error:", "carriage return");
    bad("scene-4.11 byte 0xff", "model m\nv 1 2 3 # \xff\n", "t.scene:2:11: error:",
        "invalid UTF-8 byte 0xff");
    bad("scene-4.12 Latin-1 in a comment", "# caf\xe9 au lait\n", "t.scene:1:6: error:",
        "invalid UTF-8");
    bad("scene-4.13 stray continuation byte", "model \x80\n", "t.scene:1:7: error:",
        "invalid UTF-8 byte 0x80");
    bad("scene-4.14 overlong 2-byte form", "model \xC0\x80\n", "t.scene:1:7: error:",
        "overlong");
    bad("scene-4.15 overlong 3-byte form", "model a\xE0\x80\xAF\n", "t.scene:1:8: error:",
        "overlong");
    bad("scene-4.16 overlong 4-byte form", "model \xF0\x8F\xBF\xBF\n", "t.scene:1:7: error:",
        "overlong");
    bad("scene-4.17 surrogate", "model \xED\xA0\x80\n", "t.scene:1:7: error:", "surrogate");
    bad("scene-4.18 beyond U+10FFFF", "model \xF4\x90\x80\x80\n", "t.scene:1:7: error:",
        "beyond U+10FFFF");
    bad("scene-4.19 byte 0xf5", "model \xF5\x80\x80\x80\n", "t.scene:1:7: error:",
        "invalid UTF-8 byte 0xf5");
    bad("scene-4.20 truncated sequence before a space", "model \xE2\x82 x\n",
        "t.scene:1:7: error:", "truncated");
    bad("scene-4.21 truncated sequence at the end of the text", "model a\xF0\x9F\x98",
        "t.scene:1:8: error:", "truncated");
    bad("scene-4.22 C1 control character", "model a\xC2\x85\n", "t.scene:1:8: error:",
        "control character U+0085");
    bad("scene-4.23 columns on line 1 count after the BOM", "\xEF\xBB\xBFmodel a,b\n",
        "t.scene:1:8: error:", "may not contain ','");
    bad("scene-4.24 BOM only at the very start", "model m\n\xEF\xBB\xBFv 1 2 3\n",
        "t.scene:2:1: error:", "unknown directive");
    bad("scene-4.25 bad byte reported before the line's syntax", "foo \x01\n",
        "t.scene:1:5: error:", "control character");
    bad("scene-4.26 bad byte on a later line after a good one", "model m\n\n\n\x02",
        "t.scene:4:1: error:", "control character 0x02");
}

/* ------------------------------------------------------------ scene-5 */

static void test_files(void)
{
    pt_scene s;
    const pt_model *m;
    char *text;
    int r;

    r = pt_scene_load(&s, "tests/data/include.scene", err, sizeof err);
    PT_CHECK("scene-5.1 scene with an obj include loads", r == 0);
    if (r == 0) {
        m = &s.models[0];
        PT_CHECK("scene-5.1 path and framebuffer", strcmp(s.path, "tests/data/include.scene") == 0
                 && s.fb_w == 320 && s.vp_w == 320 && s.vp_h == 240 && s.from_obj == 0);
        PT_CHECK("scene-5.2 own vertices, then the file's, in order", m->nv == 10
                 && vec_is(m->v[0], 10, 0, 0) && vec_is(m->v[2], -1, -1, -1)
                 && vec_is(m->v[9], -1, 1, 1));
        PT_CHECK("scene-5.3 obj indices offset by the model's earlier vertices",
                 m->nseg == 14 && seg_is(m, 0, 2, 3) && seg_is(m, 3, 5, 2)
                 && seg_is(m, 4, 6, 7) && seg_is(m, 8, 2, 3) && seg_is(m, 11, 6, 2));
        PT_CHECK("scene-5.4 negative indices in an obj count back within the file",
                 seg_is(m, 12, 9, 2));
        PT_CHECK("scene-5.5 scene indices after the include count all vertices",
                 seg_is(m, 13, 0, 9));
        PT_CHECK("scene-5.6 lines after the include still belong to the model",
                 m->color[0] == 255 && m->color[1] == 0);
    } else {
        printf("    %s\n", err);
    }
    pt_scene_free(&s);

    r = parse(&s, "model m\nv 7 7 7\nobj tests/data/tri.obj\n");
    PT_CHECK("scene-5.7 <builtin>-style text: obj relative to the current directory",
             r == 0 && s.models[0].nv == 4 && seg_is(&s.models[0], 0, 1, 2)
             && seg_is(&s.models[0], 2, 3, 1));
    pt_scene_free(&s);

    r = write_file("/tmp/pt_test_scene_abs.obj", "v 0 0 0\nv 1 1 1\nl 1 2\n");
    r = r == 0 ? parse(&s, "model m\nobj /tmp/pt_test_scene_abs.obj\n") : -1;
    PT_CHECK("scene-5.8 absolute obj path used as is", r == 0 && s.models[0].nv == 2);
    pt_scene_free(&s);
    remove("/tmp/pt_test_scene_abs.obj");
    bad_load("scene-5.8b ... /dev/null: not a regular file", "tests/data/absolute.scene",
             "tests/data/absolute.scene:2:5: error:", "not a regular file");

    bad_load("scene-5.9 missing scene file", "tests/data/no_such.scene",
             "tests/data/no_such.scene:1:1: error: cannot read file:", "No such file");
    bad_load("scene-5.10 directory as scene", "tests/data",
             "tests/data:1:1: error: cannot read file:", "directory");
    bad_load("scene-5.11 missing obj: error at the obj line, column of the path",
             "tests/data/missing_include.scene",
             "tests/data/missing_include.scene:2:7: error: cannot read "
             "'tests/data/no_such.obj':", "No such file");
    bad_load("scene-5.12 error inside an obj names the obj file, own indices",
             "tests/data/bad_include.scene",
             "tests/data/bad_index.obj:3:5: error:",
             "index 3 refers past the 2 vertices defined so far in this file");

    /* more than 64 KiB through a file: the reader's buffer must grow */
    text = repeat("model m\nv 0 0 0\nl", " 1", 60000, "\n");
    r = text != NULL ? write_file("/tmp/pt_test_scene_big.scene", text) : -1;
    PT_CHECK("scene-5.13 write a 120 KB scene to /tmp", r == 0);
    r = pt_scene_load(&s, "/tmp/pt_test_scene_big.scene", err, sizeof err);
    PT_CHECK("scene-5.13 load a 120 KB scene with one long line",
             r == 0 && s.models[0].nseg == 59999);
    pt_scene_free(&s);
    remove("/tmp/pt_test_scene_big.scene");
    free(text);

    r = write_file("/tmp/pt_test_scene_bad.obj", "v 0 0 0\nv 1 1 1\nvt 0 0\nf 1 2\n");
    PT_CHECK("scene-5.14 write an obj to /tmp", r == 0);
    bad("scene-5.14 f with 2 indices inside an obj", "model m\nobj /tmp/pt_test_scene_bad.obj\n",
        "/tmp/pt_test_scene_bad.obj:4:1: error:", "expected at least 3 indices");
    r = write_file("/tmp/pt_test_scene_bad.obj", "v 0 0 0\nv 1 1 1\nfoo 1 2\nl 1 2\n");
    bad("scene-5.15 a statement that is not OBJ is an error inside an obj",
        "model m\nobj /tmp/pt_test_scene_bad.obj\n",
        "/tmp/pt_test_scene_bad.obj:3:1: error:", "unknown OBJ statement 'foo'");
    r = write_file("/tmp/pt_test_scene_bad.obj", "v 0 0 0\nobj other.obj\n");
    bad("scene-5.16 ... and so is 'obj': OBJ files do not include others",
        "model m\nobj /tmp/pt_test_scene_bad.obj\n",
        "/tmp/pt_test_scene_bad.obj:2:1: error:", "unknown OBJ statement 'obj'");
    remove("/tmp/pt_test_scene_bad.obj");
}

/* ------------------------------------------------------------ scene-6 */

/* Does every vertex of the model project inside [-0.5, 0.5]^2 (perspective)? */
static int in_view(const pt_model *m)
{
    size_t i;

    for (i = 0; i < m->nv; i++) {
        double x = m->v[i].x + m->translate.x;
        double y = m->v[i].y + m->translate.y;
        double z = m->v[i].z + m->translate.z;
        if (!(z < 0 && x / -z >= -0.5 && x / -z <= 0.5 && y / -z >= -0.5 && y / -z <= 0.5))
            return 0;
    }
    return 1;
}

static void test_plain_obj(void)
{
    pt_scene s;
    int r;

    r = pt_scene_load(&s, "tests/data/tri.obj", err, sizeof err);
    PT_CHECK("scene-6.1 plain obj loads", r == 0);
    if (r == 0) {
        PT_CHECK("scene-6.2 default scene around it", s.from_obj == 1 && s.fb_w == 800
                 && s.fb_h == 600 && s.vp_x == 0 && s.vp_w == 800 && s.vp_h == 600
                 && s.perspective == 1 && s.nmodels == 1
                 && strcmp(s.path, "tests/data/tri.obj") == 0);
        PT_CHECK("scene-6.3 model named after the file, white",
                 strcmp(s.models[0].name, "tri") == 0 && s.models[0].color[0] == 255
                 && s.models[0].color[2] == 255);
        PT_CHECK("scene-6.4 translation (-cx, -cy, -cz - rz - 2R)",
                 vec_is(s.obj_translate, -1, -2, -6)
                 && vec_is(s.models[0].translate, -1, -2, -6));
        PT_CHECK("scene-6.5 face read", s.models[0].nv == 3 && s.models[0].nseg == 3);
        PT_CHECK("scene-6.6 every vertex projects inside the view", in_view(&s.models[0]));
    }
    pt_scene_free(&s);

    r = pt_scene_load(&s, "tests/data/cube.obj", err, sizeof err);
    PT_CHECK("scene-6.7 cube: extras ignored, centred, in view", r == 0
             && s.models[0].nv == 8 && s.models[0].nseg == 13
             && vec_is(s.obj_translate, 0, 0, -3) && in_view(&s.models[0])
             && seg_is(&s.models[0], 12, 7, 0));
    pt_scene_free(&s);

    r = pt_scene_load(&s, "tests/data/UPPER.OBJ", err, sizeof err);
    PT_CHECK("scene-6.8 .OBJ in capitals; one vertex: R = 1",
             r == 0 && s.from_obj == 1 && strcmp(s.models[0].name, "UPPER") == 0
             && vec_is(s.obj_translate, -1, -2, -5));
    pt_scene_free(&s);

    r = pt_scene_load(&s, "tests/data/empty.obj", err, sizeof err);
    PT_CHECK("scene-6.9 obj without vertices: translation 0",
             r == 0 && s.from_obj == 1 && s.models[0].nv == 0
             && vec_is(s.obj_translate, 0, 0, 0) && strcmp(s.models[0].name, "empty") == 0);
    pt_scene_free(&s);

    bad_load("scene-6.10 error in a plain obj", "tests/data/bad_index.obj",
             "tests/data/bad_index.obj:3:5: error:", "index 3 refers past the 2 vertices");
    bad_load("scene-6.11 missing plain obj", "tests/data/no_such.obj",
             "tests/data/no_such.obj:1:1: error: cannot read file:", "No such file");

    r = write_file("/tmp/pt_test_scene_a,b.obj", "v 0 0 0\n");
    r = r == 0 ? pt_scene_load(&s, "/tmp/pt_test_scene_a,b.obj", err, sizeof err) : -1;
    PT_CHECK("scene-6.12 file name with ',' gives the model name 'obj'",
             r == 0 && strcmp(s.models[0].name, "obj") == 0);
    pt_scene_free(&s);
    remove("/tmp/pt_test_scene_a,b.obj");

    r = write_file("/tmp/pt_test_scene_huge.obj", "v 0 0 -1e308\nv 0 0 1e308\nv 1e308 0 0\n");
    bad_load("scene-6.13 coordinates too large to frame", "/tmp/pt_test_scene_huge.obj",
             "/tmp/pt_test_scene_huge.obj:1:1: error:", "too large");
    remove("/tmp/pt_test_scene_huge.obj");
    (void)r;
}

/* ------------------------------------------------------------ scene-7 */

static void test_api(void)
{
    pt_scene s;
    char small[8];
    int r;

    memset(&s, 0, sizeof s);
    pt_scene_free(&s);
    PT_CHECK("scene-7.1 pt_scene_free on a zeroed scene", is_empty(&s));
    pt_scene_free(&s);
    PT_CHECK("scene-7.2 pt_scene_free twice", is_empty(&s));

    r = pt_scene_parse(&s, "t.scene", "foo\n", 4, NULL, 0);
    PT_CHECK("scene-7.3 no err buffer: still fails cleanly", r == -1 && is_empty(&s));

    r = pt_scene_parse(&s, "t.scene", "foo\n", 4, small, sizeof small);
    PT_CHECK("scene-7.4 small err buffer: truncated, terminated",
             r == -1 && strcmp(small, "t.scene") == 0);

    r = pt_scene_parse(&s, "a\nb", "foo\n", 4, err, sizeof err);
    PT_CHECK("scene-7.5 the message stays one line", r == -1
             && strncmp(err, "a?b:1:1: error:", 15) == 0 && strchr(err, '\n') == NULL);

    r = pt_scene_parse(&s, NULL, "model m\nl 1 2\n", 14, err, sizeof err);
    PT_CHECK("scene-7.6 NULL name reads as <builtin>", r == -1
             && strncmp(err, "<builtin>:2:3: error:", 21) == 0);

    r = pt_scene_parse(&s, "x.obj", "model m\n", 8, err, sizeof err);
    PT_CHECK("scene-7.7 pt_scene_parse reads scene text even for a .obj name",
             r == 0 && s.nmodels == 1 && s.from_obj == 0);
    pt_scene_free(&s);
}

/* ===== the course's renderers' directives (scene_course.c) ===== */

static void test_course(void)
{
    static const char full[] =
        "renderer 9\nscene Demo\nframebuffer 40 30\nbackground 1 2 3\n"
        "viewport-background 10 20 30\ncamera perspective -1.5 1 -0.7 1.3 2\nnear 0.5\n"
        "view 0 0 1\nantialias on\ngamma off\nnearclip off\npipeline2\n"
        "model cube P1\nmatrix translate 0 0 -3\nmatrix-pre rotate y 30\n"
        "matrix-set rotate 45 1 1 0\nmatrix rows 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16\n"
        "translate 1 2 3\nmatrix scale 2\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nvcolor 255 0 51\nvcolor-float 0.5 0.25 1\n"
        "vcolor 0 0 0\nsegment 1 2 1 2\nsegment 2 3\npoint 1 2 3\nl 3 1\npoint -1\n"
        "hidden-model\nhidden-position\nmodel two\nv 0 0 -1\n";
    pt_scene s;
    const pt_model *m;
    int r = parse(&s, full);

    PT_CHECK("scene-4.1 every course directive parses", r == 0);
    if (r != 0) { printf("    %s\n", err); return; }
    m = &s.models[0];
    PT_CHECK("scene-4.2 renderer, scene name, switches",
             s.renderer == 9 && strcmp(s.scene_name, "Demo") == 0 && s.antialias == 1
             && s.gamma == 0 && s.nearclip == 0 && s.pipeline2 == 1);
    PT_CHECK("scene-4.3 viewport background and view vector",
             s.vp_background[0] == 10 && s.vp_background[2] == 30
             && vec_is(s.view, 0, 0, 1));
    PT_CHECK("scene-4.4 camera perspective L R B T F: each divided by F, n = -near",
             s.cam_l == -1.5 / 2 && s.cam_r == 1.0 / 2 && s.cam_b == -0.7 / 2
             && s.cam_t == 1.3 / 2 && s.cam_n == -0.5 && s.perspective == 1);
    PT_CHECK("scene-4.5 the position's name; the second model's defaults to none",
             strcmp(m->position, "P1") == 0 && s.models[1].position == NULL);
    PT_CHECK("scene-4.6 matrix operations in file order, translate as a SET",
             m->nops == 6 && m->ops[0].mul == PT_MATMUL_POST
             && m->ops[0].kind == PT_MATOP_TRANSLATE && m->ops[0].a[2] == -3
             && m->ops[1].mul == PT_MATMUL_PRE && m->ops[1].kind == PT_MATOP_ROTATE
             && m->ops[1].a[0] == 30 && m->ops[1].a[2] == 1 && m->ops[1].a[1] == 0
             && m->ops[2].mul == PT_MATMUL_SET && m->ops[2].a[3] == 0
             && m->ops[3].kind == PT_MATOP_ROWS && m->ops[3].a[15] == 16
             && m->ops[4].mul == PT_MATMUL_SET && m->ops[4].a[1] == 2
             && m->ops[5].kind == PT_MATOP_SCALE && m->ops[5].a[2] == 2);
    PT_CHECK("scene-4.7 colours: ints as c / 255f, floats kept",
             m->ncolors == 3 && m->colors[0].r == 1.0f && m->colors[0].b == 51.0f / 255.0f
             && m->colors[1].g == 0.25f && m->colors_given == 1);
    PT_CHECK("scene-4.8 segments with colour indices; l takes the vertices'",
             m->nseg == 3 && m->seg[0].ca == 0 && m->seg[0].cb == 1 && m->seg[1].ca == 1
             && m->seg[1].cb == 2 && m->seg[2].a == 2 && m->seg[2].ca == 2 && m->seg[2].cb == 0);
    PT_CHECK("scene-4.9 points: colour, radius and their place among the segments",
             m->npts == 2 && m->pts[0].v == 0 && m->pts[0].c == 1 && m->pts[0].radius == 3
             && m->pts[0].after == 2 && m->pts[1].v == 2 && m->pts[1].c == 2
             && m->pts[1].after == 3);
    PT_CHECK("scene-4.10 hidden flags; a model without colours says so",
             m->hidden_model && m->hidden_position && !s.models[1].hidden_model
             && s.models[1].colors_given == 0);
    pt_scene_free(&s);

    r = parse(&s, "renderer 7\ncamera orthographic-fov 90 2\nmodel a\ncolor 1 2 3\n");
    PT_CHECK("scene-4.11 orthographic-fov: t = tan(fovy/2), r = t * aspect, n = +1",
             r == 0 && s.perspective == 0 && s.cam_t == tan(((3.141592653589793 / 180.0) * 90)
             / 2.0) && s.cam_r == s.cam_t * 2 && s.cam_l == -s.cam_r && s.cam_n == 1.0
             && s.models[0].colors_given == 1 && s.vp_background[0] == 0);
    pt_scene_free(&s);
    r = parse(&s, "background 5 6 7\nmodel a\n");
    PT_CHECK("scene-4.12 renderer 4 by default: gamma and near clipping on, no AA, "
             "viewport background = background",
             r == 0 && s.renderer == 4 && s.gamma == 1 && s.nearclip == 1 && !s.antialias
             && s.vp_background[1] == 6 && s.cam_n == -0.1);
    pt_scene_free(&s);

    bad("scene-4.13 a colour index past the colours", "model a\nv 0 0 0\nv 1 1 1\n"
        "vcolor 1 2 3\nsegment 1 2 1 2\n", "t.scene:5:15: error:", "past the 1 color");
    bad("scene-4.14 l's colour past a colour list", "model a\nv 0 0 0\nv 1 1 1\n"
        "vcolor 1 2 3\nl 1 2\nmodel b\n", "t.scene:1:1: error:", "takes color 2");
    bad("scene-4.15 a float colour above 1", "model a\nvcolor-float 0 1.0000001 0\n",
        "t.scene:2:16: error:", "outside 0..1");
    bad("scene-4.16 color and vcolor", "model a\ncolor 1 2 3\nvcolor 1 2 3\n",
        "t.scene:3:1: error:", "not both");
    bad("scene-4.17 near in renderer 4", "model a\nnear 1\n", "t.scene:2:1: error:",
        "renderer 7 or 9");
    bad("scene-4.18 a view volume in renderer 4", "camera perspective -1 1 -1 1\n",
        "t.scene:1:8: error:", "renderer 7 or 9");
    bad("scene-4.19 view in renderer 7", "renderer 7\nview 0 0 1\n", "t.scene:2:1: error:",
        "renderer 9");
    bad("scene-4.20 matrix in renderer 7", "renderer 7\nmodel a\nmatrix identity\n",
        "t.scene:3:1: error:", "renderer 9");
    bad("scene-4.21 renderer 5", "renderer 5\n", "t.scene:1:10: error:", "4, 7 or 9");
    bad("scene-4.22 camera lookat in renderer 9", "renderer 9\ncamera lookat 0 0 0 0 0 -1 "
        "0 1 0\nprojection perspective 60 1 1 10\n", "t.scene:2:8: error:", "matrix camera");
    bad("scene-4.23 a bad matrix operation", "renderer 9\nmodel a\nmatrix rotate w 3\n",
        "t.scene:3:15: error:", "unknown axis");
    bad("scene-4.24 segment with 3 indices", "model a\nv 0 0 0\nsegment 1 1 1\n",
        "t.scene:3:13: error:", "0 or 2 color");
    bad("scene-4.25 a radius too large", "model a\nv 0 0 0\npoint 1 1 5000\n",
        "t.scene:3:11: error:", "radius");
    bad("scene-4.26 a switch that is not on or off", "gamma yes\n", "t.scene:1:7: error:",
        "on or off");
    bad("scene-4.27 a point under the matrix camera", "camera lookat 0 0 0 0 0 -1 0 1 0\n"
        "projection perspective 60 1 1 10\nmodel a\nv 0 0 0\npoint 1\n",
        "t.scene:5:1: error:", "course renderer");
    bad("scene-4.29 a scene name with U+202E", "scene a\xe2\x80\xae" "b\n", "t.scene:1:8: error:",
        "U+202E");
    bad("scene-4.28 perspective-fov without its numbers", "renderer 7\ncamera perspective-fov"
        " 60\n", "t.scene:2:8: error:", "FOVY ASPECT");
}

int main(void)
{
    test_defaults();
    test_values();
    test_order();
    test_polylines();
    test_text_forms();
    test_long_lines();
    test_numbers();
    test_directives();
    test_indices();
    test_viewport();
    test_obj_lines();
    test_bytes();
    test_files();
    test_plain_obj();
    test_api();
    test_course();
    return pt_test_report();
}
