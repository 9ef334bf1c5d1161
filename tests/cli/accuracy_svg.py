# tests/cli/accuracy_svg.py -- check a plot of `pipetrace accuracy --svg`: panels, axes, label boxes
# See LICENSE for copyright and license.
#
# Usage: python3 tests/cli/accuracy_svg.py PLOT.svg.  Prints one line per failed
# check ("FAIL ...") and exits 1 if any.  A text's box is its characters at 0.6
# of its font size wide, from 0.8 of the font size above the baseline to 0.25
# below, rotated with the text: the widths sans-serif fonts stay under for the
# plot's letters and digits.
import re
import sys
import xml.etree.ElementTree as ET

NS = "{http://www.w3.org/2000/svg}"
UNITS = ["coordinates", "pixels", "array places", "raster"]
fails = []


def check(descr, ok):
    if not ok:
        fails.append(descr)


def box(t, fs_default):
    fs = float(t.get("font-size", fs_default))
    x, y = float(t.get("x", 0)), float(t.get("y", 0))
    w = 0.6 * fs * len(t.text or "")
    anchor = t.get("text-anchor", "start")
    x0 = x if anchor == "start" else x - w / 2 if anchor == "middle" else x - w
    b = [x0, y - 0.8 * fs, x0 + w, y + 0.25 * fs]
    m = re.match(r"rotate\(-90 ([-0-9.]+) ([-0-9.]+)\)", t.get("transform", ""))
    if m:                                   # (cx + dx, cy + dy) -> (cx + dy, cy - dx)
        cx, cy = float(m.group(1)), float(m.group(2))
        b = [cx + (b[1] - cy), cy - (b[2] - cx), cx + (b[3] - cy), cy - (b[0] - cx)]
    return b


def overlap(a, b):
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


root = ET.parse(sys.argv[1]).getroot()
fs_root = root.get("font-size", "16")
panels = [g for g in root.iter(NS + "g") if g.get("class") == "panel"]
check("one panel per unit, in order: %s" % [g.get("data-unit") for g in panels],
      [g.get("data-unit") for g in panels] == UNITS)
for g in panels:
    unit = g.get("data-unit")
    for axis in ("axis x", "axis y"):
        names = [t.text for t in g.iter(NS + "text") if t.get("class") == axis]
        check("panel %s names its %s once" % (unit, axis), len(names) == 1 and names[0])
    rect = [r for r in g.iter(NS + "rect")][0]
    l, t = float(rect.get("x")), float(rect.get("y"))
    r, b = l + float(rect.get("width")), t + float(rect.get("height"))
    for lab in g.iter(NS + "text"):
        if lab.get("class") != "label":
            continue
        bx = box(lab, fs_root)
        check("panel %s: label %r inside the plot" % (unit, lab.text),
              bx[0] >= l and bx[2] <= r and bx[1] >= t and bx[3] <= b)
texts = [(t.text, box(t, fs_root)) for t in root.iter(NS + "text")]
for i in range(len(texts)):
    for j in range(i + 1, len(texts)):
        check("texts %r and %r do not overlap" % (texts[i][0], texts[j][0]),
              not overlap(texts[i][1], texts[j][1]))
for f in fails:
    print("FAIL " + f)
print("%d texts, %d panels, %d failed" % (len(texts), len(panels), len(fails)))
sys.exit(1 if fails else 0)
