/*
** src/io/tlanes.c -- one trace written by two threads, piece by piece, in order
** See LICENSE for copyright and license.
**
** Lanes.  A lane is a run of the caller's and a trace writer: renderer 4's
** pt_run (pt_tlanes_run, below), renderers 7 and 9's driver
** (io/trace_course.c).  Nothing here knows which.
**
** Taking.  `taken` counts the pieces given out: 1 at the start (piece 0, the
** header's, is lane 0's).  A lane reaches the pieces in order, so when it
** reaches piece n, taken >= n; it takes n when it moves taken from n to n + 1,
** which only the first lane there can do.  The last piece (the summary's) is
** lane 0's without asking.
**
** Writing.  A lane's writer fills a block; at the end of each piece it was
** given, and whenever the block is full, the block goes into the lane's queue
** as a chunk of that piece, and the writer gets a free block of the lane's
** (the lane waits when it has none).  A chunk is written when it is the lowest
** piece queued and the other lane can hand over nothing lower: it has ended,
** or its run is at that piece or past it (a lane hands its text over before it
** moves on).  Whichever thread finds such a chunk writes it, one thread at a
** time and without the mutex, so that the other keeps working; the block then
** goes back to its lane.  Everything under `mu` except the writes themselves.
*/
#include <errno.h>
#include <pthread.h>
#include <stdatomic.h>
#include <stdlib.h>
#include <string.h>
#include "io/tlanes.h"

typedef struct chunk {
    char *b;                     /* a block of the lane's */
    size_t len;                  /* its bytes of text */
    uint64_t piece;              /* the piece they belong to */
} chunk;

typedef struct lane {
    struct tlanes *q;
    int id;                      /* 0: the caller's thread, with image and summary */
    pt_trace *t;                 /* its writer */
    uint64_t piece;              /* the piece its writer's text belongs to */
    int rc;                      /* its run's result */
    /* under mu */
    uint64_t at;                 /* the piece its run is in, taken or not */
    int done;                    /* its run has ended, its text is handed over */
    chunk queue[PT_TLANES_BLOCKS];  /* handed over, not yet written: a ring */
    int head, count;
    char *spare[PT_TLANES_BLOCKS];  /* its free blocks */
    int nspare;
} lane;

typedef struct tlanes {
    pthread_mutex_t mu;
    pthread_cond_t written;      /* a chunk was written: its block is free */
    atomic_uint_fast64_t taken;  /* the pieces below it are given out */
    lane lanes[2];
    int writing;                 /* a thread is writing: the other leaves it be */
    int failed;                  /* the errno value of the first write that failed */
    FILE *f;
    int (*run)(void *ud, int lane);  /* each lane's run */
    void *ud;
} tlanes;

/* The lane whose first chunk is next in the trace, or NULL. */
static lane *next_chunk(tlanes *q)
{
    lane *a = &q->lanes[0], *b = &q->lanes[1], *w, *other;

    if (!a->count && !b->count) return NULL;
    w = !b->count || (a->count && a->queue[a->head].piece < b->queue[b->head].piece) ? a : b;
    other = w == a ? b : a;
    if (!other->done && other->at < w->queue[w->head].piece) return NULL;
    return w;
}

/* Write the chunks that can go, in order.  mu held. */
static void drain(tlanes *q)
{
    lane *w;

    if (q->writing) return;                 /* the writing thread looks again */
    q->writing = 1;
    while ((w = next_chunk(q)) != NULL) {
        chunk c = w->queue[w->head];
        int err = 0;

        w->head = (w->head + 1) % PT_TLANES_BLOCKS;
        w->count--;
        pthread_mutex_unlock(&q->mu);
        errno = 0;
        if (!q->failed && fwrite(c.b, 1, c.len, q->f) != c.len) err = errno ? errno : EIO;
        pthread_mutex_lock(&q->mu);
        if (err && !q->failed) q->failed = err;
        w->spare[w->nspare++] = c.b;
        pthread_cond_broadcast(&q->written);
    }
    q->writing = 0;
}

/* Hand ln's text over and give its writer a free block.  mu held. */
static void hand_over(tlanes *q, lane *ln)
{
    pt_trace *t = ln->t;
    chunk *c;

    if (!t->len) return;
    c = &ln->queue[(ln->head + ln->count) % PT_TLANES_BLOCKS];
    c->b = t->buf;
    c->len = t->len;
    c->piece = ln->piece;
    ln->count++;
    t->buf = NULL;
    t->len = 0;
    for (drain(q); !ln->nspare; drain(q)) pthread_cond_wait(&q->written, &q->mu);
    t->buf = ln->spare[--ln->nspare];
}

/* pt_trace.out: the writer's block is full. */
static void on_full(void *ud, pt_trace *t)
{
    lane *ln = ud;

    (void)t;
    pthread_mutex_lock(&ln->q->mu);
    hand_over(ln->q, ln);
    pthread_mutex_unlock(&ln->q->mu);
}

int pt_tlanes_piece(pt_trace *t, uint64_t n, int last)
{
    lane *ln = t->out_ud;
    tlanes *q = ln->q;
    int take;

    if (n == 0 || last) {
        take = ln->id == 0;
    } else {
        uint_fast64_t want = n;
        take = atomic_compare_exchange_strong(&q->taken, &want, n + 1);
    }
    pthread_mutex_lock(&q->mu);
    hand_over(q, ln);                       /* the text of the pieces before n */
    ln->at = n;
    if (take) ln->piece = n;
    drain(q);                               /* the other's may wait for this move */
    pthread_mutex_unlock(&q->mu);
    return take;
}

/* A lane's run has ended: hand the rest over. */
static void lane_end(tlanes *q, lane *ln)
{
    pthread_mutex_lock(&q->mu);
    hand_over(q, ln);
    ln->done = 1;
    drain(q);
    pthread_mutex_unlock(&q->mu);
}

static void *lane1_run(void *arg)
{
    lane *ln = arg;
    tlanes *q = ln->q;

    ln->rc = q->run(q->ud, 1);
    lane_end(q, ln);
    return NULL;
}

/* Set lane k up with writer t and the blocks b[0 .. PT_TLANES_BLOCKS - 1) of
** its own besides t's. */
static void lane_init(tlanes *q, int k, pt_trace *t, char *b)
{
    lane *ln = &q->lanes[k];
    int j;

    ln->q = q;
    ln->id = k;
    ln->t = t;
    t->out = on_full;
    t->out_ud = ln;
    for (j = 0; j < PT_TLANES_BLOCKS - 1; j++) ln->spare[ln->nspare++] = b + (size_t)j * PT_TRACE_BLOCK;
}

/* Writer t as it was before its lane: its own block, empty. */
static void lane_off(pt_trace *t)
{
    t->out = NULL;
    t->out_ud = NULL;
    t->buf = t->block;
    t->len = 0;
}

int pt_tlanes(pt_trace *const t[2], int (*run)(void *ud, int lane), void *ud)
{
    tlanes *q = calloc(1, sizeof *q);
    char *blocks = malloc(2 * (PT_TLANES_BLOCKS - 1) * (size_t)PT_TRACE_BLOCK);
    pthread_t th;
    int locks = 0, rc;

    if (q && blocks) {
        locks = pthread_mutex_init(&q->mu, NULL) == 0;
        if (locks && pthread_cond_init(&q->written, NULL) != 0) {
            pthread_mutex_destroy(&q->mu);
            locks = 0;
        }
    }
    if (locks) {
        atomic_init(&q->taken, 1);
        q->f = t[0]->f;
        q->run = run;
        q->ud = ud;
        lane_init(q, 0, t[0], blocks);
        lane_init(q, 1, t[1], blocks + (PT_TLANES_BLOCKS - 1) * (size_t)PT_TRACE_BLOCK);
    }
    if (!locks || pthread_create(&th, NULL, lane1_run, &q->lanes[1]) != 0) {
        if (locks) {
            pthread_cond_destroy(&q->written);
            pthread_mutex_destroy(&q->mu);
            lane_off(t[0]);
            lane_off(t[1]);
        }
        free(blocks);
        free(q);
        return 1;
    }
    q->lanes[0].rc = run(ud, 0);
    lane_end(q, &q->lanes[0]);
    pthread_join(th, NULL);

    pthread_mutex_lock(&q->mu);             /* both ended: all is written */
    drain(q);
    pthread_mutex_unlock(&q->mu);
    if (q->failed && !t[0]->failed) t[0]->failed = q->failed;
    rc = q->lanes[0].rc != 0 || q->lanes[1].rc != 0 ? -1 : 0;
    lane_off(t[0]);
    lane_off(t[1]);
    pthread_cond_destroy(&q->written);
    pthread_mutex_destroy(&q->mu);
    free(blocks);
    free(q);
    return rc;
}

/* ===== renderer 4: pt_run on both lanes ===== */

typedef struct run4 {
    pt_trace *t[2];              /* each lane's writer */
    const pt_scene *s;
    const pt_plan *p;
    const pt_options *o;
    pt_fb *fb;                   /* lane 0's image, */
    pt_summary *sum;             /*   and its counts: the scene's */
    pt_summary sum1;             /* lane 1's counts: not the scene's */
} run4;

/* pt_listener.piece: the lanes' */
static int on_piece(void *ud, uint64_t n, int last)
{
    return pt_tlanes_piece(ud, n, last);
}

static int run4_lane(void *ud, int k)
{
    run4 *r = ud;
    pt_listener l;

    pt_trace_listener(r->t[k], &l);
    l.piece = on_piece;
    if (k) l.summary = NULL;                /* lane 0 counts and writes it */
    return pt_run(r->s, r->p, r->o, &l, k ? NULL : r->fb, k ? &r->sum1 : r->sum);
}

int pt_tlanes_run(pt_trace *t, const pt_scene *s, const pt_plan *p, const pt_options *o,
                  pt_fb *fb, pt_summary *sum)
{
    pt_trace *t1 = malloc(sizeof *t1);
    run4 r;
    int rc = 1;

    memset(&r, 0, sizeof r);
    if (t1) {
        pt_trace_init(t1, t->f, t->fmt, t->precision);
        t1->explain = t->explain;
        t1->student = t->student;
        t1->scene = s;                      /* on_header tells lane 0's only */
        t1->plan = p;
        r.t[0] = t; r.t[1] = t1;
        r.s = s; r.p = p; r.o = o;
        r.fb = fb;
        r.sum = sum;
        rc = pt_tlanes(r.t, run4_lane, &r);
    }
    free(t1);
    if (rc == 1) {                          /* one thread: the run as it is */
        pt_listener l;
        pt_trace_listener(t, &l);
        return pt_run(s, p, o, &l, fb, sum);
    }
    return rc;
}
