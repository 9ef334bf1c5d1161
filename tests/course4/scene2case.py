#!/usr/bin/env python3
# tests/course4/scene2case.py -- a pipetrace scene as a case of the course's harness (Kraft4)
# See LICENSE for copyright and license.
#
# Usage: python3 tests/course4/scene2case.py SCENE > CASE
# Writes the case file the course's renderer-4 harness (Kraft4.java, its case
# format: docs/renderer4.md) reads for the scene: the same framebuffer,
# viewport, camera, switches and models, with 0-based indices.  Only the
# directives renderer 4 has are read (framebuffer, background, viewport,
# viewport-background, camera perspective|orthographic, scene, antialias,
# gamma, model, translate, v, l, segment, point, color, vcolor, vcolor-float,
# hidden-position, hidden-model); a `color` line becomes one colour a vertex.
# The debug switches are given to the harness on its command line.
import sys


def main(path):
    fb = [800, 600]
    bg = None
    vp = None
    vpbg = None
    head = []
    models = []
    cur = None
    for raw in open(path):
        f = raw.split('#', 1)[0].split()
        if not f:
            continue
        d, a = f[0], f[1:]
        if d == 'framebuffer':
            fb = a[:2]
        elif d == 'background':
            bg = a[:3]
        elif d == 'viewport':
            vp = a[:4]
        elif d == 'viewport-background':
            vpbg = a[:3]
        elif d == 'camera':
            head.append('camera ' + {'perspective': 'persp', 'orthographic': 'ortho'}[a[0]])
        elif d == 'scene':
            head.append('scene ' + a[0])
        elif d in ('antialias', 'gamma'):
            head.append(('aa ' if d == 'antialias' else 'gamma ') + ('1' if a[0] == 'on' else '0'))
        elif d == 'model':
            cur = {'head': ['model ' + ' '.join(a[:2])], 'body': [], 'nv': 0, 'color': None}
            models.append(cur)
        elif d == 'translate':
            cur['head'].append('t ' + ' '.join(a[:3]))
        elif d == 'v':
            cur['head'].append('v ' + ' '.join(a[:3]))
            cur['nv'] += 1
        elif d == 'l':
            ix = [int(x) - 1 for x in a]
            for i, j in zip(ix, ix[1:]):
                cur['body'].append('l %d %d' % (i, j))
        elif d == 'segment':
            cur['body'].append('l ' + ' '.join(str(int(x) - 1) for x in a))
        elif d == 'point':
            p = [str(int(x) - 1) for x in a[:2]] + a[2:3]
            cur['body'].append('p ' + ' '.join(p))
        elif d == 'color':
            cur['color'] = a[:3]
        elif d == 'vcolor':
            cur['body'].append('c ' + ' '.join(a[:3]))
        elif d == 'vcolor-float':
            cur['body'].append('cf ' + ' '.join(a[:3]))
        elif d == 'hidden-position':
            cur['body'].append('hidepos')
        elif d == 'hidden-model':
            cur['body'].append('hidemodel')
        else:
            sys.exit('%s: %s: not a directive of renderer 4' % (path, d))
    out = ['fb %s %s' % tuple(fb) + (' %s %s %s' % tuple(bg) if bg else '')]
    if vp or vpbg:
        v = vp or ['0', '0'] + list(fb)
        out.append('vp ' + ' '.join(v) + (' ' + ' '.join(vpbg) if vpbg else ''))
    out += head
    for m in models:
        out += m['head']
        if m['color']:
            out += ['c ' + ' '.join(m['color'])] * m['nv']
        out += m['body']
    print('\n'.join(out))


if __name__ == '__main__':
    main(sys.argv[1])
