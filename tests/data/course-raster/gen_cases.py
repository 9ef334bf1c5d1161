#!/usr/bin/env python3
# tests/data/course-raster/gen_cases.py -- the hand-made cases' .case files (edges, ties, points, NaN, viewports)
# See LICENSE for copyright and license.
# Writes NAME.case in the current folder; README.md says how they become test data.
import random
def xp(X, w): return repr((X - 0.5) * 2.001 / w - 1)
def V(X, Y, w, h, z=0.0): return 'v %s %s %s' % (xp(X, w), xp(Y, h), repr(z))
cases = {}
# 1. AA on every edge, edge rule, transposed, slopes +-1, non-black vp bg, vp offset
w, h = 16, 12
L = ['scene aa-edges', 'fb 20 15 10 20 30', 'vp 2 1 16 12 40 60 90', 'camera ortho', 'aa 1', 'gamma 1', 'debug all', 'model m']
pts = [(1, 12), (16, 12),   # top row: edge rule
       (16, 1), (16, 12),   # right column, transposed: edge rule
       (1, 1), (12, 12),    # slope 1
       (3, 11), (13, 1),    # slope -1
       (2, 2), (15, 7),     # generic
       (4, 1), (9, 12),     # transposed generic
       (1, 1), (16, 1)]     # bottom row
for X, Y in pts: L.append(V(X, Y, w, h))
L += ['c 255 0 0', 'c 0 255 0', 'c 0 0 255', 'c 255 255 0', 'c 0 255 255', 'c 255 0 255', 'c 200 100 50',
      'c 10 20 30', 'c 128 129 130', 'c 129 128 127', 'c 255 255 255', 'c 0 0 0', 'c 17 34 51', 'c 240 230 220']
for i in range(0, len(pts), 2): L.append('l %d %d' % (i, i + 1))
cases['aa-edges'] = L
# 2. AA off, gamma off: slopes exactly +-1, ties of y at k+0.5 (m = 1/2, 3/2 transposed), reversed ends
w, h = 16, 12
L = ['scene ties', 'fb 16 12', 'camera ortho', 'aa 0', 'gamma 0', 'debug all', 'model m']
pts = [(1, 1), (9, 5), (9, 5), (1, 1), (2, 10), (10, 6), (3, 2), (9, 11), (12, 12), (1, 1), (14, 2), (6, 10),
       (5, 5), (5, 5), (7, 3), (7, 3)]
for X, Y in pts: L.append(V(X, Y, w, h))
L += ['c 0 0 0', 'c 255 255 255', 'c 128 0 0', 'c 129 1 255', 'c 10 200 30', 'c 11 201 31', 'c 255 0 0', 'c 0 0 255',
      'c 1 2 3', 'c 250 251 252', 'c 100 100 100', 'c 101 103 105', 'c 7 7 7', 'c 9 9 9', 'c 50 60 70', 'c 80 90 100']
for i in range(0, len(pts), 2): L.append('l %d %d' % (i, i + 1))
cases['ties'] = L
# 3. colour ties (java.awt.Color of k+0.5 products), gamma off: last pixels, degenerate, points
L = ['scene color-ties', 'fb 12 8', 'camera ortho', 'aa 0', 'gamma 0', 'debug all', 'model m']
for X, Y in [(1, 1), (3, 1), (1, 3), (5, 3), (2, 6), (2, 6), (8, 2), (8, 2), (10, 7), (12, 7)]: L.append(V(X, Y, 12, 8))
L += ['cf 0.50392157 0.5019608 0.49803922', 'c 129 128 127', 'c 128 129 130', 'cf 0.50392157 0.6 0.0019607844',
      'cf 0.0019607844 0.9980392 0.50392157', 'c 0 0 0', 'cf 0.50392157 0.50392157 0.50392157', 'c 1 1 1',
      'cf 0.25 0.75 0.125', 'cf 0.0 1.0 0.5']
L += ['l 0 1', 'l 2 3', 'l 4 5', 'p 6', 'p 7 6 0', 'l 8 9']
cases['color-ties'] = L
# 4. points of radius 0..4 at the corners and the centre, vp offset, gamma on
L = ['scene points', 'fb 14 12 5 5 5', 'vp 2 2 10 8 20 0 40', 'camera ortho', 'aa 0', 'gamma 1', 'debug all', 'model m']
w, h = 10, 8
for X, Y in [(1, 1), (10, 1), (1, 8), (10, 8), (5, 4)]: L.append(V(X, Y, w, h))
L += ['c 255 0 0', 'c 0 255 0', 'c 0 0 255', 'c 255 255 0', 'c 0 255 255']
L += ['p 0 0 0', 'p 1 1 1', 'p 2 2 2', 'p 3 3 3', 'p 4 4 4', 'p 0 4 -1']
cases['points'] = L
# 5. NaN vertices: nearclip off, perspective, vertices on the camera plane; viewport at the bottom
L = ['scene nan-bad', 'fb 12 10', 'vp 0 4 12 6 0 0 80', 'camera persp', 'nearclip 0', 'aa 0', 'gamma 1', 'debug all', 'model m']
L += ['v 0.0 0.0 0.0', 'v 0.5 0.2 -1.0', 'v 0.0 0.0 0.0', 'v -0.3 0.9 -1.0', 'v 0.0 0.0 0.0']
L += ['c 255 0 0', 'c 0 255 0', 'c 0 0 255', 'c 255 255 0', 'c 255 255 255']
L += ['l 0 1', 'l 2 3', 'p 4 4 1']
cases['nan-bad'] = L
# 6. NaN with AA on
L2 = [x.replace('nan-bad', 'nan-bad-aa').replace('aa 0', 'aa 1') for x in L]
cases['nan-bad-aa'] = L2
# 7. viewport past the framebuffer: rows wrap, Bad pixel coordinate from clearVP and lines
L = ['scene vp-past', 'fb 10 8 0 0 0', 'vp 6 5 8 6 60 30 10', 'camera ortho', 'aa 0', 'gamma 1', 'debug all', 'model m']
w, h = 8, 6
for X, Y in [(1, 1), (8, 6), (8, 1), (1, 6), (2, 3)]: L.append(V(X, Y, w, h))
L += ['c 255 0 0', 'c 0 255 0', 'c 0 0 255', 'c 255 255 0', 'c 0 255 255']
L += ['l 0 1', 'l 2 3', 'p 4 4 2']
cases['vp-past'] = L
# 8. AA, gamma off, a random fan
random.seed(7)
L = ['scene aa-fan', 'fb 24 18', 'vp 0 0 24 18 255 255 255', 'camera ortho', 'aa 1', 'gamma 0', 'debug all', 'model m']
n = 24
for i in range(n): L.append('v %r %r 0.0' % (random.uniform(-1, 1), random.uniform(-1, 1)))
for i in range(n): L.append('c %d %d %d' % tuple(random.randrange(256) for _ in range(3)))
for i in range(0, n, 2): L.append('l %d %d' % (i, i + 1))
cases['aa-fan'] = L
for k, L in cases.items():
    open(k + '.case', 'w').write('\n'.join(L) + '\n')
