/*
** stages/rv_clip.h -- renderers 7 and 9: clip the image-plane model to the view rectangle -1..1
** See LICENSE for copyright and license.
**
** in/out: image-plane coordinates.  A segment (Clip_Line.java:227-470):
**   no |x| or |y| above 1: keep ("Trivial accept"; NaN compares false, so a
**     NaN end is kept);  both x > 1, both x < -1, both y > 1 or both y < -1:
**     drop ("Trivial delete");  else cut ONE edge and test again, the first
**     of x0>1, x1>1, x0<-1, x1<-1, y0>1, y1>1, y0<-1, else y1<-1:
**   x = e (e = +-1):  t = (e - x_o)/(x_i - x_o);  x = e;  y = (1 - t)*y_o + t*y_i
**   y = e:            t = (e - y_o)/(y_i - y_o);  x = (1 - t)*x_o + t*x_i;  y = e
**   t runs from the outside end o (0) to the inside end i (1); the new vertex
**   is (x, y, 0) (z = 0, not -1), its colour (1 - t_)*c_o + t_*c_i in float
**   (t_ = (float)t); both are appended even when the piece is then dropped
**   (a segment missing a corner leaves an orphan vertex).  A point is kept
**   iff !(|x| > 1 || |y| > 1).
**       (-1,1) +--------+ (1,1)       o outside, i inside:
**              |   i----*---o         * = (1, (1-t) y_o + t y_i)
**      (-1,-1) +--------+ (1,-1)
** Java recurses (clip(model, clipOneTime(model, ls))); this loops.
*/
#ifndef PT_RV_CLIP_H
#define PT_RV_CLIP_H
#include "rv_model.h"
/* Clip m's primitives to the square in place (vertices and colours appended,
** primitive list replaced); ls (may be NULL) hears each primitive, each cut
** and the final verdict.  0; -1 when out of memory, -2 when a new colour is
** one java.awt.Color refuses (the course's render throws), -3 when a segment
** needs more than 64 cuts (never seen; Java would recurse on); m's primitive
** list then holds what was kept so far. */
int pt_rv_clip(pt_rv_model *m, const pt_rv_clip_ls *ls);
#endif
