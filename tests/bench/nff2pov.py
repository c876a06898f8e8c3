#!/usr/bin/env python3
"""nff2pov.py: an NFF file (Eric Haines's Neutral File Format, as the SPD
writes it) as a POV-Ray 3.7 scene with the NFF's own primitives, for
bench_spd_pov.sh.  Written for the bench; it does not go through links1's
scene (links1 export-pov gives POV-Ray links1's own triangles).

    nff2pov.py IN.nff -o OUT.pov [--depth D] [--bailout B]

What becomes what:
  v (from, at, up, angle, resolution)  camera: location, look_at, sky, a
      right-handed right vector (NFF is right-handed, POV-Ray left-handed),
      and angle = the horizontal field of view edge to edge: NFF's angle
      spans the centres of the first and last pixels across the narrower
      side, as links1's NFF reader reads it.  hither: no near plane (neither
      has one); resolution: given to povray as +W +H by the caller.
  b                      background
  l x y z [r g b]        point light, colour r g b, or 1/sqrt(lights) each
                         (links1's reader's intensity)
  f r g b Kd Ks Shine T ior
      pigment rgbf <r, g, b, T> (filtered: the light through takes the
      colour, as links1's transmission does); finish ambient 0, diffuse
      Kd, reflection Ks (NFF's Ks is the mirror share), phong Ks with
      phong_size Shine (the highlight of a reflecting surface); ior into
      interior when T > 0.  As links1's reader: Ks + T capped at 1.
  s                      sphere
  c                      cylinder (equal radii) or cone, open at both ends
                         as NFF's are
  p                      triangle (3 vertices) or polygon (more)
  pp                     smooth_triangle, a fan of them past 3 vertices
global_settings: max_trace_level D (default 5: Haines's depth counting the
eye ray), adc_bailout B (default 0: no adaptive depth), ambient_light 0,
assumed_gamma 1.
"""
import math
import sys


class Nff:
    """The file as one stream of words (NFF is free-form: an entity may
    share a line with the next), comments (# to the line's end) left out."""

    def __init__(self, path):
        with open(path) as f:
            self.words = [w for ln in f for w in ln.split('#', 1)[0].split()]
        self.i = 0

    def word(self):
        if self.i >= len(self.words):
            raise ValueError('the file ends inside an entity')
        self.i += 1
        return self.words[self.i - 1]

    def nums(self, n):
        return [float(self.word()) for _ in range(n)]

    def number_next(self):
        try:
            float(self.words[self.i])
            return True
        except (IndexError, ValueError):
            return False


def vec(p):
    return '<%.9g, %.9g, %.9g>' % (p[0], p[1], p[2])


def view(nff, out, depth, bailout):
    sizes = {'from': 3, 'at': 3, 'up': 3, 'angle': 1, 'hither': 1, 'resolution': 2}
    v = {}
    for _ in range(6):
        key = nff.word()
        if key not in sizes:
            raise ValueError('view: unknown word %r' % key)
        v[key] = nff.nums(sizes[key])
    width, height = int(v['resolution'][0]), int(v['resolution'][1])
    m = min(width, height)
    t = math.tan(math.radians(v['angle'][0]) / 2) * width / (m - 1 if m > 1 else 1)
    fov = math.degrees(2 * math.atan(t))
    out.append('global_settings { max_trace_level %d adc_bailout %.9g ambient_light 0 '
               'assumed_gamma 1 }' % (depth, bailout))
    out.append('camera { perspective location %s sky %s up y right -x * %d / %d '
               'angle %.9g look_at %s }' % (vec(v['from']), vec(v['up']), width, height,
                                            fov, vec(v['at'])))


def surface(f, k):
    r, g, b, kd, ks, shine, tr, ior = f
    tr = min(tr, 1.0)
    ks = min(ks, 1.0)
    if ks + tr > 1:
        ks = 1 - tr
    fin = 'ambient 0 diffuse %.9g' % kd
    if ks > 0:
        fin += ' reflection { %.9g } phong %.9g phong_size %.9g' % (ks, ks, min(shine, 1e5))
    text = ('#declare F%d = texture { pigment { rgbf <%.9g, %.9g, %.9g, %.9g> } '
            'finish { %s } }' % (k, r, g, b, tr, fin))
    inside = ' interior { ior %.9g }' % max(ior, 1.0) if tr > 0 else ''
    return text, inside


def polygon(nff, n, smooth):
    if n < 3:
        raise ValueError('a polygon of %d vertices' % n)
    pts = [nff.nums(6 if smooth else 3) for _ in range(n)]
    if smooth:
        return ['smooth_triangle { %s, %s, %s, %s, %s, %s' %
                (vec(pts[0][:3]), vec(pts[0][3:]), vec(pts[i][:3]), vec(pts[i][3:]),
                 vec(pts[i + 1][:3]), vec(pts[i + 1][3:])) for i in range(1, n - 1)]
    if n == 3:
        return ['triangle { %s, %s, %s' % tuple(vec(p) for p in pts)]
    return ['polygon { %d, %s' % (n + 1, ', '.join(vec(p) for p in pts + [pts[0]]))]


def translate(path, depth, bailout):
    nff = Nff(path)
    head, body, lights = [], [], []
    look = ''
    k = 0
    while nff.i < len(nff.words):
        kind = nff.word()
        if kind == 'v':
            view(nff, head, depth, bailout)
        elif kind == 'b':
            head.append('background { rgb %s }' % vec(nff.nums(3)))
        elif kind == 'l':
            lights.append(nff.nums(3) + (nff.nums(3) if nff.number_next() else []))
        elif kind == 'f':
            k += 1
            text, inside = surface(nff.nums(8), k)
            head.append(text)
            look = ' texture { F%d }%s }' % (k, inside)
        elif kind == 's':
            c = nff.nums(4)
            body.append('sphere { %s, %.9g%s' % (vec(c), c[3], look))
        elif kind == 'c':
            a, b = nff.nums(4), nff.nums(4)
            if a[3] == b[3]:
                body.append('cylinder { %s, %s, %.9g open%s' % (vec(a), vec(b), a[3], look))
            else:
                body.append('cone { %s, %.9g, %s, %.9g open%s' % (vec(a), a[3], vec(b), b[3], look))
        elif kind in ('p', 'pp'):
            body += [o + look for o in polygon(nff, int(nff.word()), kind == 'pp')]
        else:
            raise ValueError('word %d: unknown entity %r' % (nff.i, kind))
    plain = 1 / math.sqrt(len(lights)) if lights else 1
    for l in lights:
        colour = l[3:6] if len(l) >= 6 else [plain] * 3
        head.append('light_source { %s color rgb %s }' % (vec(l[:3]), vec(colour)))
    return head + body


def main(argv):
    args, out, depth, bailout = [], None, 5, 0.0
    it = iter(argv)
    for a in it:
        if a == '-o':
            out = next(it, None)
        elif a == '--depth':
            depth = int(next(it, '5'))
        elif a == '--bailout':
            bailout = float(next(it, '0'))
        else:
            args.append(a)
    if len(args) != 1 or not out:
        sys.stderr.write('usage: nff2pov.py IN.nff -o OUT.pov [--depth D] [--bailout B]\n')
        return 2
    try:
        lines = translate(args[0], depth, bailout)
    except (OSError, ValueError, IndexError) as e:
        sys.stderr.write('nff2pov.py: %s: %s\n' % (args[0], e))
        return 1
    with open(out, 'w') as f:
        f.write('// %s, translated by tests/bench/nff2pov.py\n' % args[0])
        f.write('\n'.join(lines) + '\n')
    return 0


if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
