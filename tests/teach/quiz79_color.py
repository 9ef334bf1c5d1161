#!/usr/bin/env python3
# tests/teach/quiz79_color.py -- the colour question's worked numbers, evaluated again
# See LICENSE for copyright and license.
#
# Usage: python3 tests/teach/quiz79_color.py QUIZ_OUTPUT KEY [TRACE.jsonl]
# QUIZ_OUTPUT is what pipetrace quiz printed for a sheet whose colour answer
# is wrong; KEY the colour's right answer ("r g b" or "none").  Every
# "EXPR = VALUE" of the colour's worked lines whose EXPR is numbers alone is
# evaluated here (Java's float casts by struct, Math.pow by the C library's
# pow, as pipetrace's stages use it) and must give VALUE; the bytes line's
# Java conversion (int)((double)(c*255f) + 0.5) of each component must give
# its bytes, those the key, its colour the results of the lines above it.
# With TRACE, the write it names (pixel, model, primitive, coverage, how many
# writes) must be the trace's last pixel record there.  Prints what fails;
# exits 1 then.
import json
import re
import struct
import sys


def f32(x):
    return struct.unpack('f', struct.pack('f', x))[0]


def fpow(a, b):
    return f32(a ** b)


def fabs32(x):
    return f32(abs(x))


NUMERIC = re.compile(r'^[-+0-9.eE*/(), ]+$')


def to_python(expr):
    """expr in the worked lines' notation as Python, or None when it is
    not numbers alone."""
    e = expr.replace('(float)Math.pow(', 'fpow(')
    if '(float)|' in e:
        a, rest = e.split('(float)|', 1)
        if '|' not in rest:
            return None
        inner, tail = rest.split('|', 1)
        e = a + 'fabs32(' + inner + ')' + tail
    e = e.replace('(float)(', 'f32(')
    bare = e.replace('fpow(', '(').replace('fabs32(', '(').replace('f32(', '(')
    if not NUMERIC.match(bare) or not re.search(r'[0-9]', bare):
        return None
    return e


def lead_number(s):
    m = re.match(r'^\(?(-?[0-9][0-9.eE+-]*)', s)
    return float(m.group(1)) if m else None


def close(a, b):
    return a == b or abs(a - b) <= 1e-6 * max(abs(a), abs(b)) or abs(a - b) <= 1e-9


def main():
    out, key = sys.argv[1], sys.argv[2].split()
    lines = open(out).read().split('\n')
    try:
        i = next(k for k, l in enumerate(lines) if l.startswith('color: '))
    except StopIteration:
        print('no colour question')
        return 1
    block = []
    for l in lines[i + 1:]:
        if l.startswith('  go on with'):
            break
        block.append(l)
    worked = [l[4:] for l in block if l.startswith('    ')]
    fails, n, results = [], 0, []
    if key == ['none']:
        ok = len(worked) == 1 and worked[0].startswith('none: dropped (Bad pixel coordinate)')
        if not ok:
            fails.append('a dropped pixel: no "none: dropped" line')
    for l in worked:
        parts = l.split(' = ')
        for k in range(1, len(parts) - 1):
            e = to_python(parts[k])
            v = lead_number(parts[k + 1])
            if e is None or v is None:
                continue
            got = eval(e, {'f32': f32, 'fpow': fpow, 'fabs32': fabs32})
            n += 1
            results.append(parts[k + 1].split(' ')[0].rstrip(';,'))
            if not close(got, v):
                fails.append('%s: %r gives %r, the line says %r' % (l[:40], parts[k], got, v))
    m = [re.search(r'^bytes = .* of \(([^)]*)\) = \((\d+), (\d+), (\d+)\)(.*)$', l) for l in worked]
    m = [x for x in m if x]
    if key != ['none']:
        if len(m) != 1:
            fails.append('no bytes line')
        else:
            cs = [float(x) for x in m[0].group(1).split(', ')]
            bs = [int(m[0].group(k)) for k in (2, 3, 4)]
            want = [min(255, int(f32(c * 255.0) + 0.5)) for c in cs]
            if bs != want:
                fails.append('bytes %s, Java\'s conversion of %s gives %s' % (bs, cs, want))
            if [str(b) for b in bs] != key:
                fails.append('bytes %s, the key %s' % (bs, key))
            if m[0].group(5):
                fails.append('the rasterizer wrote other bytes: %s' % m[0].group(5))
            text = '\n'.join(worked[:-1])
            for c in m[0].group(1).split(', '):
                if c not in results and ('(' + c) not in text and (' ' + c + ',') not in text \
                        and (' ' + c + ')') not in text:
                    fails.append('the colour %s is no result above the bytes' % c)
    if len(sys.argv) > 3 and key != ['none'] and worked:
        h = re.search(r'^the (?:last of (\d+) writes|only write) at \(x_fb, y_fb\) = '
                      r'\((-?\d+), (-?\d+)\), .*?: model (\S+?)(?: \(position (\S+)\))?, '
                      r'primitive (\d+) of the rasterizer', worked[0])
        if not h:
            fails.append('no write named: %s' % worked[0][:80])
        else:
            nw = int(h.group(1) or 1)
            x, y, model, prim = int(h.group(2)), int(h.group(3)), h.group(4), int(h.group(6))
            cov = re.search(r'coverage (?:1 - f|f) = ([0-9.e-]+)', '\n'.join(worked))
            cov = float(cov.group(1)) if cov else 1.0
            recs = []
            for line in open(sys.argv[3]):
                r = json.loads(line)
                if r.get('type') == 'pixel' and r['x'] == x and r['y'] == y:
                    recs.append(r)
            if not recs:
                fails.append('the trace has no pixel record at (%d, %d)' % (x, y))
            else:
                last = recs[-1]
                got = (len(recs), last['model'], last['primitive'], last['rgb'], last['coverage'])
                want = (nw, model, prim, [int(k) for k in key], cov)
                if got[:4] != want[:4] or not close(got[4], want[4]):
                    fails.append('the trace\'s last write %s, the quiz\'s %s' % (got, want))
    for f in fails:
        print('  ' + f)
    print('%d equations evaluated' % n)
    return 1 if fails else 0


if __name__ == '__main__':
    sys.exit(main())
