#!/usr/bin/env python3
# tests/data/course-raster/extract.py -- make a rasterizer test case from a course case
# See LICENSE for copyright and license.
#
# Usage: extract.py OUTDIR NAME CASE STAGES LOG PPM  (.gz or plain).  Writes
# OUTDIR/NAME.raster (the framebuffer, viewport, switches and each visible
# position's clipped model: its last "N.clipped" stage), NAME.rlog (every
# rasterizer line of the log, Bad pixel coordinate lines included) and
# NAME.ppm.  The tests read only these; this script is how they were made.
import gzip, re, sys

def lines(path):
    op = gzip.open if path.endswith('.gz') else open
    with op(path, 'rt') as f:
        return f.read().split('\n')

def main():
    out, name, case, stages, log, ppm = sys.argv[1:7]
    fb = None; aa = 0; gamma = 1; debug = 'all'
    for ln in lines(case):
        t = ln.split()
        if not t or t[0].startswith('#'): continue
        if t[0] == 'fb':
            fb = [int(x) for x in t[1:3]] + ([int(x) for x in t[3:6]] if len(t) >= 6 else [0, 0, 0])
        elif t[0] == 'aa': aa = int(t[1])
        elif t[0] == 'gamma': gamma = int(t[1])
        elif t[0] == 'debug': debug = ' '.join(t[1:])
        elif t[0] == 'model': break
    rdebug = int('all' in debug.split() or 'rasterize' in debug.split())
    res = ['# %s' % name, 'fb %d %d %d %d %d' % tuple(fb), None,
           'aa %d' % aa, 'gamma %d' % gamma, 'debug %d' % rdebug]
    pos = []            # [name, visible, {stage: (V, C, P)}]
    for ln in lines(stages):
        t = ln.split()
        if not t: continue
        if t[0] == 'viewport':
            kv = dict(x.split('=') for x in t[1:])
            bg = kv['bg']
            res[2] = 'vp %s %s %s %s %d %d %d' % (kv['x'], kv['y'], kv['w'], kv['h'],
                                                 int(bg[0:2], 16), int(bg[2:4], 16), int(bg[4:6], 16))
        elif t[0] == 'position':
            vis = 'visible=false' not in t and 'modelVisible=false' not in t
            pos.append([t[1], vis, {}])
        elif t[0] in ('V', 'C', 'P') and t[1].endswith('.clipped'):
            st = pos[-1][2].setdefault(int(t[1].split('.')[0]), ([], [], []))
            if t[0] == 'V':
                st[0].append('v %s %s %s' % (t[3], t[4], t[5]))
            elif t[0] == 'C':
                st[1].append('c %s %s %s %s' % (t[3], t[4], t[5], t[6]))
            else:
                rest = ' '.join(t[2:])
                m = re.match(r'LineSegment: \(\[(\d+), (\d+)\], \[(\d+), (\d+)\]\)$', rest)
                if m:
                    st[2].append('l %s %s %s %s' % m.groups())
                else:
                    m = re.match(r'Point: \(\[(\d+)\], \[(\d+)\]\) radius = (-?\d+)$', rest)
                    assert m, rest
                    st[2].append('p %s %s %s' % m.groups())
    for pname, vis, st in pos:
        if not vis or not st: continue
        v, c, p = st[max(st)]
        res += ['position ' + pname] + v + c + p
    with open('%s/%s.raster' % (out, name), 'w') as f:
        f.write('\n'.join(res) + '\n')
    pre = ('(x0_pp, y0_pp)', '(x1_pp, y1_pp)', 'Slope m', '(x0_vp, y0_vp)', '(x1_vp, y1_vp)',
           '(x_pp, y_pp)', 'fb_[', 'FrameBuffer: Bad pixel')
    with open('%s/%s.rlog' % (out, name), 'w') as f:
        for ln in lines(log):
            if ln.startswith(pre): f.write(ln + '\n')
    op = gzip.open if ppm.endswith('.gz') else open
    with op(ppm, 'rb') as fi, open('%s/%s.ppm' % (out, name), 'wb') as fo:
        fo.write(fi.read())

main()
