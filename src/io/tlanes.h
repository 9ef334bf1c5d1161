/*
** src/io/tlanes.h -- one trace written by two threads, piece by piece, in order
** See LICENSE for copyright and license.
**
** Formatting a full trace costs more than the run that makes it.  The run
** cuts the trace into pieces (renderer 4's pt_run: pt_listener.piece; the
** course's renderers 7 and 9: pt_course_ls.piece); here two runs of the
** scene, one on each thread, share them: each piece goes to the run that
** reaches it first (the header's and the summary's to lane 0, which draws
** the image and counts the summary), is formatted by that lane's own writer
** (pt_trace), and its text goes to f in the order of the pieces:
**
**     lane 0: run(ud, 0)  pieces 0, 2, 3, 6 ..  --blocks--.
**                                                        +--> f
**     lane 1: run(ud, 1)  pieces 1, 4, 5 ..     --blocks--'
**
** The trace is the one a single writer makes, byte for byte, when both runs
** cut alike (where the scene alone says) and a writer keeps nothing from one
** piece to the next that changes a byte (what it keeps are caches, and the
** counts both runs make alike).  Memory stays bounded: PT_TLANES_BLOCKS
** blocks of PT_TRACE_BLOCK bytes a lane; a lane with none free waits for the
** other to write.
*/
#ifndef PT_TLANES_H
#define PT_TLANES_H

#include "core/pipetrace.h"
#include "io/trace.h"

/* Blocks a lane: a lane that runs ahead of the other keeps what it wrote
** until the pieces before are written, and waits when its blocks are full.
** A piece of the course's pixel records is up to 1 MB (4,096 anti-aliased
** steps), so with 4 the second lane waited: with 8 renderer 9's JSON Lines
** on two threads takes a few percent less time (renderer 4's the same), for
** at most 2 MiB more.  -DPT_TLANES_BLOCKS=N builds with N (docs/bench.md). */
#ifndef PT_TLANES_BLOCKS
#define PT_TLANES_BLOCKS 8
#endif

/* The lanes themselves, for any run that cuts its trace into pieces: run
** run(ud, 0) on this thread and run(ud, 1) on a second one at once, lane k
** writing with t[k] (pt_trace_init'ed to the same f, format and precision;
** nothing written yet).  Each run asks pt_tlanes_piece(t[k], n, last) at
** the start of each piece n (0, 1, ...; last = 1 for the last, the
** summary's) and writes that piece's records only when it says 1.
** Returns 0, or -1 when either run returned non-zero; write errors are
** then in t[0]->failed (and ferror(f)), the writers ready to be finished or
** freed.  Returns 1 when no second thread or no memory for its blocks is to
** be had: nothing has run, the caller runs on one thread. */
int pt_tlanes(pt_trace *const t[2], int (*run)(void *ud, int lane), void *ud);

/* Does the run of writer t (a lane's, in pt_tlanes) write piece n (last:
** the last piece)?  Lane 0 writes piece 0 and the last; the others go to
** the lane that asks first.  Blocks until there is room for the text. */
int pt_tlanes_piece(pt_trace *t, uint64_t n, int last);

/* pt_run(s, p, o, &l, fb, sum) with l the listener of trace writer t (made
** by pt_trace_init, its explain and student set; nothing written yet), the
** trace formatted on two threads (pt_tlanes).  Then call pt_trace_finish(t)
** as after a run on one thread.  When no second thread or no memory for its
** blocks is to be had, the run is pt_run's on this thread alone: nothing is
** lost.  Returns 0, or -1 when out of memory (as pt_run). */
int pt_tlanes_run(pt_trace *t, const pt_scene *s, const pt_plan *p, const pt_options *o,
                  pt_fb *fb, pt_summary *sum);

#endif
