/*
** tests/fuzz/fuzz_scene.c -- fuzz target: the scene reader, then the whole run
** See LICENSE for copyright and license.
**
** The bytes are a .scene text; when it parses, the plan and the run follow
** with every stage traced (to a sink that drops the records), so what the
** parser lets through is checked by the pipeline too.
**
** An `obj PATH` line would read whatever PATH names on the host (/etc/passwd,
** /dev/zero, the fuzzer's own corpus).  So each one's PATH is replaced by one
** of the files of a private folder made for this process, the one a hash of
** PATH picks: an OBJ file, a text that is not OBJ, a directory, a FIFO, a
** name that does not exist.  An error that names one of them
** ("DIR/text.obj:1:1: error: ...") is as correct as one that names the scene.
*/
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "fuzz.h"
#include "core/pipeline.h"

#define NFIX 5
static const char *const fix_name[NFIX] = { "good.obj", "text.obj", "folder", "fifo", "none.obj" };
static char fix_dir[256];                    /* the private folder; "" until made */
static char fix_path[NFIX][320];

static void fix_remove(void)
{
    int k;

    for (k = 0; k < NFIX; k++) remove(fix_path[k]);      /* a folder too (POSIX) */
    rmdir(fix_dir);
}

/* Make the private folder and its files once.  Returns 0, or -1. */
static int fix_make(void)
{
    const char *tmp = getenv("TMPDIR");
    FILE *f;
    int k;

    if (fix_dir[0]) return 0;
    snprintf(fix_dir, sizeof fix_dir, "%s/pt-fuzz-scene-XXXXXX", tmp && tmp[0] ? tmp : "/tmp");
    if (!mkdtemp(fix_dir)) { fix_dir[0] = '\0'; return -1; }
    for (k = 0; k < NFIX; k++) snprintf(fix_path[k], sizeof fix_path[k], "%s/%s", fix_dir, fix_name[k]);
    atexit(fix_remove);
    if (!(f = fopen(fix_path[0], "w"))) return -1;
    fputs("# a tetrahedron\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nl 3 4\n", f);
    if (fclose(f) != 0 || !(f = fopen(fix_path[1], "w"))) return -1;
    fputs("root:x:0:0:root:/root:/bin/sh\n", f);
    if (fclose(f) != 0 || mkdir(fix_path[2], 0700) != 0 || mkfifo(fix_path[3], 0600) != 0)
        return -1;
    return 0;
}

/* data[0..size) with the PATH of each `obj PATH` line (the directive alone
** on its line before any '#', after spaces and tabs) replaced by a file of
** the private folder; *n gets its length.  NULL when out of memory. */
static char *sandboxed(const char *data, size_t size, size_t *n)
{
    size_t lines = 1, i, o = 0;
    char *out;

    for (i = 0; i < size; i++) lines += data[i] == '\n';
    if (!(out = malloc(size + lines * (sizeof fix_path[0] + 1)))) return NULL;
    for (i = 0; i < size; ) {
        size_t end = i, cut, p;
        unsigned h = 2166136261u;            /* FNV-1a of PATH */

        while (end < size && data[end] != '\n') end++;
        for (cut = i; cut < end && data[cut] != '#'; cut++) {}
        if (cut == end && cut > i && data[cut - 1] == '\r') cut--;    /* CRLF */
        for (p = i; p < cut && (data[p] == ' ' || data[p] == '\t'); p++) {}
        if (cut - p > 4 && !memcmp(data + p, "obj", 3) && (data[p + 3] == ' ' || data[p + 3] == '\t')) {
            size_t q = p + 3;
            while (q < cut && (data[q] == ' ' || data[q] == '\t')) q++;
            if (q < cut) {                   /* a PATH: one of the folder's files */
                for (; q < cut; q++) h = (h ^ (unsigned char)data[q]) * 16777619u;
                memcpy(out + o, data + i, p + 3 - i);
                o += p + 3 - i;
                o += (size_t)sprintf(out + o, " %s", fix_path[h % NFIX]);
                i = cut;
            }
        }
        memcpy(out + o, data + i, end + (end < size) - i);       /* the rest, LF too */
        o += end + (end < size) - i;
        i = end + (end < size);
    }
    *n = o;
    return out;
}

/* 1 when err is a correct refusal: one message for the scene or a folder file. */
static int message_ok(const char *err)
{
    int k;

    if (pt_fuzz_message_ok(err, "fuzz")) return 1;
    for (k = 0; k < NFIX; k++)
        if (pt_fuzz_message_ok(err, fix_path[k])) return 1;
    return 0;
}

static void drop_vertex(void *ud, const pt_vrec *r) { (void)ud; (void)r; }

int pt_fuzz_scene(const uint8_t *data, size_t size)
{
    pt_scene s;
    pt_options o;
    pt_plan p;
    pt_listener l;
    pt_summary sum;
    char err[PT_ERRLEN], *text;
    size_t n;
    int rc;

    if (fix_make() != 0 || !(text = sandboxed((const char *)data, size, &n)))
        return 0;                            /* no room to test in: not the reader's fault */
    err[0] = '\0';
    rc = pt_scene_parse(&s, "fuzz", text, n, err, sizeof err);
    free(text);
    if (rc != 0)
        return message_ok(err) ? 1 : -1;
    pt_options_default(&o);
    o.all_stages = 1;
    memset(&l, 0, sizeof l);
    l.sink.vertex = drop_vertex;
    if (pt_plan_make(&p, &s, &o) == 0) {
        pt_run(&s, &p, &o, &l, NULL, &sum);
        pt_plan_free(&p);
    }
    pt_scene_free(&s);
    return 0;
}

PT_FUZZ_TARGET(pt_fuzz_scene)
