#!/usr/bin/env python3
# tests/data/course-raster/gen_random.py -- twelve random small scenes (rand-NN.case)
# See LICENSE for copyright and license.
# Writes NAME.case in the current folder; README.md says how they become test data.
import random
for k in range(12):
    rnd = random.Random(1000 + k)
    W, H = rnd.randint(6, 24), rnd.randint(5, 18)
    vw, vh = rnd.randint(3, W + 4), rnd.randint(3, H + 4)
    vx, vy = rnd.randint(0, W // 2 + 2), rnd.randint(0, H // 2 + 2)
    L = ['scene rand-%02d' % k, 'fb %d %d %d %d %d' % (W, H, rnd.randrange(256), rnd.randrange(256), rnd.randrange(256)),
         'vp %d %d %d %d %d %d %d' % (vx, vy, vw, vh, rnd.randrange(256), rnd.randrange(256), rnd.randrange(256)),
         rnd.choice(['camera persp', 'camera ortho', 'camera persp -0.8 1.2 -1.1 0.9', 'camera ortho -1.5 1.0 -1.0 1.3']),
         'nearclip %d' % rnd.randint(0, 1), 'aa %d' % rnd.randint(0, 1), 'gamma %d' % rnd.randint(0, 1),
         'debug all']
    if k % 4 == 3: L.append('pipeline 2')
    for m in range(rnd.randint(1, 2)):
        L.append('model m%d' % m)
        L.append('t %r %r %r' % (rnd.uniform(-0.3, 0.3), rnd.uniform(-0.3, 0.3), rnd.uniform(-3, -1)))
        n = rnd.randint(4, 10)
        for i in range(n):
            L.append('v %r %r %r' % (rnd.uniform(-1.6, 1.6), rnd.uniform(-1.6, 1.6), rnd.uniform(-1.5, 2.5)))
        for i in range(n):
            if rnd.random() < 0.5: L.append('c %d %d %d' % tuple(rnd.randrange(256) for _ in range(3)))
            else: L.append('cf %r %r %r' % tuple(rnd.random() for _ in range(3)))
        for i in range(rnd.randint(3, 9)):
            if rnd.random() < 0.75: L.append('l %d %d %d %d' % (rnd.randrange(n), rnd.randrange(n), rnd.randrange(n), rnd.randrange(n)))
            else: L.append('p %d %d %d' % (rnd.randrange(n), rnd.randrange(n), rnd.randint(0, 3)))
    open('rand-%02d.case' % k, 'w').write('\n'.join(L) + '\n')
