#!/usr/bin/env python3
"""diagrams.py - draws the slides' exact diagrams from their geometry (run from anywhere).

Writes into slides/figures/: sat-edge-normal.svg (two turned boxes whose AABBs overlap,
separated on an edge normal: the shadows are computed, not drawn by eye),
minkowski-rounded.svg (a circle cast against a box = its centre against the rounded box;
the first touch is solved from the quadratic), swept-false-positive.svg and
reflect-split.svg (v split into (v.n)n and the rest). Re-run after changing a number.
The SVG is built as an ElementTree and written by it, so every attribute and text is escaped
by the XML writer, never by hand.
"""
import math
import os
import xml.etree.ElementTree as ET

FIGURES = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'figures')
SVG_NS = 'http://www.w3.org/2000/svg'
FONT = 'DejaVu Sans, sans-serif'
FONT_SIZE = '28'
INK = '#222'


def num(v, digits=1):
    """A coordinate as the SVG attribute text: `digits` decimals, so reruns write the same file."""
    return f'{v:.{digits}f}'


class Svg:
    """One picture: a white page of w x h user units with the arrowhead marker `ar` defined."""

    def __init__(self, w, h, comment):
        self.root = ET.Element('svg', {'xmlns': SVG_NS, 'viewBox': f'0 0 {w} {h}',
                                       'font-family': FONT, 'font-size': FONT_SIZE})
        self.add('rect', width=w, height=h, fill='white')
        marker = ET.SubElement(ET.SubElement(self.root, 'defs'), 'marker', {
            'id': 'ar', 'viewBox': '0 0 10 10', 'refX': '9', 'refY': '5', 'markerWidth': '6',
            'markerHeight': '6', 'orient': 'auto-start-reverse'})
        # context-stroke: the arrowhead takes each line's own colour (SVG 2).
        ET.SubElement(marker, 'path', {'d': 'M0,0 L10,5 L0,10 z', 'fill': 'context-stroke'})
        # ElementTree writes a comment as given, and XML forbids '--' inside one.
        if '--' in comment or comment.endswith('-'):
            raise ValueError(f'diagrams.py: an SVG comment cannot hold "--": {comment}')
        self.root.append(ET.Comment(f' {comment} '))

    def add(self, tag, text=None, **attrs):
        """Appends <tag> with the attributes (a trailing _ is dropped, '_' in a name becomes '-')."""
        names = {k.rstrip('_').replace('_', '-'): str(v) for k, v in attrs.items() if v is not None}
        el = ET.SubElement(self.root, tag, names)
        el.text = text
        return el

    def line(self, a, b, c, w=4, dash=None, arrow=False):
        """A segment a->b in colour c; dash is an SVG dash array; arrow puts `ar` on the end."""
        self.add('line', x1=num(a[0]), y1=num(a[1]), x2=num(b[0]), y2=num(b[1]), stroke=c,
                 stroke_width=w, stroke_dasharray=dash, marker_end='url(#ar)' if arrow else None)

    def text(self, p, s, c=INK, size=None, bold=False):
        """A label with its baseline starting at p (whole units)."""
        self.add('text', s, x=num(p[0], 0), y=num(p[1], 0), fill=c, font_size=size,
                 font_weight='bold' if bold else None)

    def poly(self, pts, c, op=0.2, w=4, dash=None):
        """A closed polygon, filled with c at opacity op and outlined in c."""
        self.add('polygon', points=' '.join(f'{num(x)},{num(y)}' for x, y in pts), fill=c,
                 fill_opacity=op, stroke=c, stroke_width=w, stroke_dasharray=dash)

    def box(self, x, y, w, h, fill, digits=None, **style):
        """An axis-aligned rectangle; digits rounds the numbers (None writes them as given)."""
        f = (lambda v: v) if digits is None else (lambda v: num(v, digits))
        self.add('rect', x=f(x), y=f(y), width=f(w), height=f(h), fill=fill, **style)

    def circle(self, cx, cy, r, fill, digits=None, **style):
        """A circle; digits rounds the centre (None writes it as given)."""
        f = (lambda v: v) if digits is None else (lambda v: num(v, digits))
        self.add('circle', cx=f(cx), cy=f(cy), r=r, fill=fill, **style)

    def write(self, name):
        """Writes FIGURES/name whole or not at all (a temporary file renamed over it)."""
        ET.indent(self.root, space='')
        path = os.path.join(FIGURES, name)
        try:
            with open(path + '.tmp', 'w', encoding='utf-8') as out:
                ET.ElementTree(self.root).write(out, encoding='unicode')
                out.write('\n')
            os.replace(path + '.tmp', path)
        finally:
            if os.path.exists(path + '.tmp'):
                os.remove(path + '.tmp')


def rect(cx, cy, w, h, ang):
    """The corners of a w x h box centred on (cx, cy), turned by ang radians."""
    c, sn = math.cos(ang), math.sin(ang)
    return [(cx + c * x - sn * y, cy + sn * x + c * y)
            for x, y in [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2)]]


def bbox(p):
    """The AABB (left, top, right, bottom) of the points p."""
    xs = [x for x, _ in p]
    ys = [y for _, y in p]
    return min(xs), min(ys), max(xs), max(ys)


def sat_edge_normal():
    """Two turned boxes whose AABBs overlap, and their shadows on one box's edge normal."""
    svg = Svg(620, 560,
              'Two turned boxes whose AABBs overlap, separated on the normal of one of their edges.')
    a = rect(200, 170, 230, 60, math.radians(40))
    b = rect(330, 170, 230, 60, math.radians(40))
    ba, bb = bbox(a), bbox(b)
    ov = (max(ba[0], bb[0]), max(ba[1], bb[1]), min(ba[2], bb[2]), min(ba[3], bb[3]))
    svg.box(ov[0], ov[1], ov[2] - ov[0], ov[3] - ov[1], '#f1c40f', 1, fill_opacity=0.35)
    for bx, c in [(ba, '#2f6fd0'), (bb, '#d07a1f')]:
        svg.box(bx[0], bx[1], bx[2] - bx[0], bx[3] - bx[1], 'none', 1, stroke=c, stroke_width=2,
                stroke_dasharray='8 6')
    svg.poly(a, '#2f6fd0')
    svg.poly(b, '#d07a1f')
    e = (a[1][0] - a[0][0], a[1][1] - a[0][1])
    L = math.hypot(*e)
    n = (e[1] / L, -e[0] / L)
    if n[0] < 0:
        n = (-n[0], -n[1])
    O = (330, 420)

    def proj(p):
        return (p[0] - O[0]) * n[0] + (p[1] - O[1]) * n[1]

    def at(t):
        return (O[0] + n[0] * t, O[1] + n[1] * t)

    pa = [proj(p) for p in a]
    pb = [proj(p) for p in b]
    tmin = min(pa + pb) - 60
    tmax = max(pa + pb) + 60
    svg.line(at(tmin), at(tmax), '#555', 3, arrow=True)
    svg.text((at(tmax)[0] + 8, at(tmax)[1] + 8), 'axis', '#555')
    for vals, c, pts in [(pa, '#2f6fd0', a), (pb, '#d07a1f', b)]:
        svg.line(at(min(vals)), at(max(vals)), c, 12)
        for p, t in zip(pts, vals):
            if t in (min(vals), max(vals)):
                svg.line(p, at(t), c, 2, '6 6')
    gap = max(min(pb) - max(pa), min(pa) - max(pb))
    assert gap > 0, gap
    lo, hi = (max(pa), min(pb)) if min(pb) > max(pa) else (max(pb), min(pa))
    m = at((lo + hi) / 2)
    svg.text((m[0] + 14, m[1] + 30), 'gap', '#c0392b', bold=True)
    svg.text((20, 40), 'yellow: the AABBs overlap')
    svg.text((20, 520), 'on the normal of an edge the')
    svg.text((20, 552), 'shadows have a gap: no hit')
    svg.write('sat-edge-normal.svg')


def minkowski_rounded():
    """A circle cast at a box, drawn as its centre cast at the box grown by r."""
    svg = Svg(620, 520,
              'A moving circle against a box = its centre (a point) against the box grown by r: a rounded box.')
    bx, by, bw, bh, r = 260, 170, 220, 140, 60
    svg.box(bx - r, by - r, bw + 2 * r, bh + 2 * r, '#d07a1f', rx=r, ry=r, fill_opacity=0.12,
            stroke='#d07a1f', stroke_width=3, stroke_dasharray='10 6')
    svg.box(bx, by, bw, bh, '#d07a1f', fill_opacity=0.3, stroke='#d07a1f', stroke_width=4)
    svg.line((bx + bw, by + bh), (bx + bw + r * math.cos(0.7), by + bh + r * math.sin(0.7)), '#555', 3)
    svg.text((bx + bw + 30, by + bh + 40), 'r', '#555', bold=True)
    cx, cy = bx, by + bh
    target = (cx - r * math.cos(math.radians(50)), cy + r * math.sin(math.radians(50)))
    start = (70, 440)
    d = (target[0] - start[0], target[1] - start[1])
    Ld = math.hypot(*d)
    d = (d[0] / Ld, d[1] / Ld)
    # The first touch: |start + t d - corner| = r, the smaller root of t^2 + 2Bt + C = 0.
    fx, fy = start[0] - cx, start[1] - cy
    B_ = fx * d[0] + fy * d[1]
    C_ = fx * fx + fy * fy - r * r
    t = -B_ - math.sqrt(B_ * B_ - C_)
    hit = (start[0] + d[0] * t, start[1] + d[1] * t)
    svg.circle(start[0], start[1], r, '#2f6fd0', fill_opacity=0.15, stroke='#2f6fd0', stroke_width=3)
    svg.circle(start[0], start[1], 6, '#2f6fd0')
    svg.line(start, (start[0] + d[0] * (t + 90), start[1] + d[1] * (t + 90)), '#2f6fd0', 3, '10 6',
             arrow=True)
    svg.circle(hit[0], hit[1], r, 'none', 1, stroke='#2f6fd0', stroke_width=3)
    svg.circle(hit[0], hit[1], 8, '#c0392b', 1)
    svg.text((hit[0] - 40, hit[1] + 95), 'first touch: t', '#c0392b')
    svg.text((20, 40), 'the centre against the box grown by r:')
    svg.text((20, 75), 'two slabs and four corner circles')
    svg.write('minkowski-rounded.svg')


def swept_false_positive():
    """The bounds of a diagonal move's start and end cover a target the path misses."""
    svg = Svg(620, 520,
              'The box around the start and end of a diagonal move covers a target the path never touches.')
    s0, e0, w = (60, 330), (420, 90), 70
    svg.box(s0[0], e0[1], e0[0] - s0[0] + w, s0[1] - e0[1] + w, '#c0392b', fill_opacity=0.08,
            stroke='#c0392b', stroke_width=3, stroke_dasharray='10 6')
    svg.poly([(s0[0], s0[1]), (e0[0], e0[1]), (e0[0] + w, e0[1]), (e0[0] + w, e0[1] + w),
              (s0[0] + w, s0[1] + w), (s0[0], s0[1] + w)], '#2f6fd0', 0.12, 2)
    svg.box(s0[0], s0[1], w, w, '#2f6fd0', fill_opacity=0.4, stroke='#2f6fd0', stroke_width=4)
    svg.box(e0[0], e0[1], w, w, 'none', stroke='#2f6fd0', stroke_width=4, stroke_dasharray='8 6')
    svg.line((s0[0] + w / 2, s0[1] + w / 2), (e0[0] + w / 2 - 6, e0[1] + w / 2 + 4), '#2f6fd0', 3,
             arrow=True)
    svg.box(385, 290, 90, 90, '#d07a1f', fill_opacity=0.4, stroke='#d07a1f', stroke_width=4)
    svg.text((385, 430), 'target', '#b35900')
    svg.text((20, 45), 'dashed red: the swept bounds', '#c0392b')
    svg.text((20, 475), 'the bounds overlap the target, the path')
    svg.text((20, 508), 'does not: a false positive. Sweep next.')
    svg.write('swept-false-positive.svg')


def reflect_split():
    """A bounce: v split into (v.n)n, which turns round, and the rest, which is kept."""
    svg = Svg(600, 480, 'Reflection: v splits into (v·n)n along the normal and the rest along the surface.')
    P = (300, 380)
    v = (170, 200)
    A = (P[0] - v[0], P[1] - v[1])
    svg.box(30, 380, 540, 50, '#888', fill_opacity=0.3)
    svg.line((30, 380), (570, 380), '#555')
    svg.line(A, (P[0] - 4, P[1] - 4), '#2f6fd0', 6, arrow=True)
    svg.text((150, 320), 'v', '#2f6fd0', size=36, bold=True)
    svg.line(A, (A[0] + v[0], A[1]), '#1e8449', 4, '10 6', arrow=True)
    svg.text((A[0] - 20, A[1] - 16), 'v − (v·n)n: kept', '#1e8449')
    svg.line((A[0] + v[0], A[1]), (P[0], P[1] - 6), '#c0392b', 4, '10 6', arrow=True)
    svg.text((P[0] + 10, A[1] + 40), '(v·n)n', '#c0392b')
    R = (P[0] + v[0], P[1] - v[1])
    svg.line(P, R, '#8e44ad', 6, arrow=True)
    svg.text((430, 320), 'v′', '#8e44ad', size=36, bold=True)
    svg.line((530, 380), (530, 300), '#555', 3, arrow=True)
    svg.text((545, 320), 'n', '#555', bold=True)
    svg.text((20, 465), 'v′ = v − (1+e)(v·n)n')
    svg.write('reflect-split.svg')


if __name__ == '__main__':
    sat_edge_normal()
    minkowski_rounded()
    swept_false_positive()
    reflect_split()
