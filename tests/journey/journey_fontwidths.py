#!/usr/bin/env python3
# tests/journey/journey_fontwidths.py -- jplace.c's font widths against the font files
# See LICENSE for copyright and license.
#
# Usage: python3 tests/journey/journey_fontwidths.py [FONTDIR].  src/tools/journey/
# jplace.c estimates a label's width from the advance widths of DejaVu Sans
# (regular, bold) and DejaVu Sans Mono, written there as tables; this reads
# the same widths from the TrueType files (hmtx through the cmap, standard
# library only) and checks every entry.  Without the fonts (Debian package
# fonts-dejavu-core) it skips: "0 passed, 0 failed".
import os
import re
import struct
import sys

FONTDIR = sys.argv[1] if len(sys.argv) > 1 else '/usr/share/fonts/truetype/dejavu'


def advances(path, chars):
    """Advance width of each character, in thousandths of an em, rounded up."""
    d = open(path, 'rb').read()
    tab = {}
    for i in range(struct.unpack('>H', d[4:6])[0]):
        tag, _, off, _ = struct.unpack('>4sIII', d[12 + 16 * i:28 + 16 * i])
        tab[tag.decode('latin-1')] = off
    upem = struct.unpack('>H', d[tab['head'] + 18:tab['head'] + 20])[0]
    nh = struct.unpack('>H', d[tab['hhea'] + 34:tab['hhea'] + 36])[0]
    adv = [struct.unpack('>H', d[tab['hmtx'] + 4 * i:tab['hmtx'] + 4 * i + 2])[0]
           for i in range(nh)]
    co, sub = tab['cmap'], None
    for i in range(struct.unpack('>H', d[co + 2:co + 4])[0]):
        pid, eid, off = struct.unpack('>HHI', d[co + 4 + 8 * i:co + 12 + 8 * i])
        if (pid, eid) == (3, 1):
            sub = co + off
    assert sub is not None and struct.unpack('>H', d[sub:sub + 2])[0] == 4
    segx2 = struct.unpack('>H', d[sub + 6:sub + 8])[0]
    ends = sub + 14
    starts = ends + segx2 + 2
    deltas = starts + segx2
    ranges = deltas + segx2

    def u16(a):
        return struct.unpack('>H', d[a:a + 2])[0]

    def glyph(c):
        for s in range(segx2 // 2):
            if c <= u16(ends + 2 * s):
                st = u16(starts + 2 * s)
                if c < st:
                    return 0
                dl = struct.unpack('>h', d[deltas + 2 * s:deltas + 2 * s + 2])[0]
                ro = u16(ranges + 2 * s)
                if ro == 0:
                    return (c + dl) & 0xffff
                g = u16(ranges + 2 * s + ro + 2 * (c - st))
                return (g + dl) & 0xffff if g else 0
        return 0

    out = {}
    for c in chars:
        a = adv[min(glyph(c), nh - 1)] * 1000
        out[c] = a // upem + (1 if a % upem else 0)
    return out


def table(src, name):
    m = re.search(r'%s\[95\] = \{([^}]*)\}' % name, src)
    return [int(x) for x in m.group(1).replace('\n', ' ').split(',') if x.strip()]


def main():
    passed = failed = 0
    faces = {'sans_regular': 'DejaVuSans.ttf', 'sans_bold': 'DejaVuSans-Bold.ttf'}
    if not all(os.path.exists(os.path.join(FONTDIR, f))
               for f in list(faces.values()) + ['DejaVuSansMono.ttf']):
        print('  skipped: the DejaVu fonts are not in ' + FONTDIR)
        print('0 passed, 0 failed')
        return 0
    src = open('src/tools/journey/jplace.c').read()
    chars = list(range(32, 127))
    for name, f in faces.items():
        want = advances(os.path.join(FONTDIR, f), chars)
        got = table(src, name)
        bad = [chr(c) for c, g in zip(chars, got) if g != want[c]]
        if len(got) == 95 and not bad:
            passed += 1
        else:
            failed += 1
            print('FAIL fw-1 %s: %d entries, differ at %r' % (name, len(got), bad[:10]))
    mono = advances(os.path.join(FONTDIR, 'DejaVuSansMono.ttf'), chars)
    m = re.search(r'#define MONO_WIDTH\s+(\d+)', src)
    if m and set(mono.values()) == {int(m.group(1))}:
        passed += 1
    else:
        failed += 1
        print('FAIL fw-2 MONO_WIDTH %s, the font: %s' % (m and m.group(1), sorted(set(mono.values()))))
    for c in (0x2192, 0x2191, 0x2193):             # the axes' arrows: within OTHER_WIDTH
        w = max(advances(os.path.join(FONTDIR, f), [c])[c] for f in faces.values())
        m = re.search(r'#define OTHER_WIDTH\s+(\d+)', src)
        if m and w <= int(m.group(1)):
            passed += 1
        else:
            failed += 1
            print('FAIL fw-3 U+%04X is %d wide, OTHER_WIDTH %s' % (c, w, m and m.group(1)))
    print('%d passed, %d failed' % (passed, failed))
    return 1 if failed else 0


sys.exit(main())
