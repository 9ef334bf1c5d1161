/*
** src/io/tlanes.h -- one trace written by two threads, piece by piece, in order
** See LICENSE for copyright and license.
**
** Formatting a full trace costs more than the run that makes it.  pt_run cuts
** the trace into pieces (pt_listener.piece); here two runs of the scene, one
** on each thread, share them: each piece goes to the run that reaches it
** first (the header's and the summary's to lane 0, which draws the image and
** counts the summary), is formatted by that lane's own writer (pt_trace), and
** its text goes to f in the order of the pieces:
**
**     lane 0: pt_run(fb, summary)  pieces 0, 2, 3, 6 ..  --blocks--.
**                                                                 +--> f
**     lane 1: pt_run(no image)     pieces 1, 4, 5 ..     --blocks--'
**
** The trace is the one a single writer makes, byte for byte: a piece begins
** at a vertex's or a segment's first record, and a writer keeps nothing from
** one record to the next that changes a byte (what it keeps are caches).
** Memory stays bounded: PT_TLANES_BLOCKS blocks of PT_TRACE_BLOCK bytes a
** lane; a lane with none free waits for the other to write.
*/
#ifndef PT_TLANES_H
#define PT_TLANES_H

#include "core/pipetrace.h"
#include "io/trace.h"

#define PT_TLANES_BLOCKS 4

/* pt_run(s, p, o, &l, fb, sum) with l the listener of trace writer t (made
** by pt_trace_init, its explain and student set; nothing written yet), the
** trace formatted on two threads.  Then call pt_trace_finish(t) as after a
** run on one thread.  When no second thread or no memory for its blocks is
** to be had, the run is pt_run's on this thread alone: nothing is lost.
** Returns 0, or -1 when out of memory (as pt_run). */
int pt_tlanes_run(pt_trace *t, const pt_scene *s, const pt_plan *p, const pt_options *o,
                  pt_fb *fb, pt_summary *sum);

#endif
