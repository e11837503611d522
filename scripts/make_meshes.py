#!/usr/bin/env python3
"""Make the small triangle meshes and 2-D vertex files of sluice's cases and tests.

    python3 scripts/make_meshes.py [--out DIR]      every shipped file (default cases/meshes)
    python3 scripts/make_meshes.py --check [DIR]    check the meshes and vertex files in DIR
    python3 scripts/make_meshes.py SHAPE ... --out FILE [--format F]

Shapes: box, tilted-box, cylinder, sphere (icosphere or UV sphere), ramp (a closed wedge),
plane (an open rectangle) and polyline (a 2-D vertex file). Formats: stl-ascii, stl-binary,
obj, ply-ascii, off (chosen from the file's extension unless --format says; binary STL only
by --format). Run a shape with --help for its parameters.

Conventions: metres; closed meshes are watertight, share their vertices and have outward
normals (counter-clockwise seen from outside, right-hand rule) unless asked for inward ones;
an STL facet normal is the normalised (b - a) x (c - a). ASCII coordinates are written with
Python's repr (the shortest text that reads back to the same double), so reruns are
byte-identical and shared vertices are bit-identical in every facet. A 2-D vertex file holds
"x,y" rows after "#" comment lines; each segment's normal is its direction turned clockwise,
(dy, -dx), as sluice reads it.

Standard library only (math, struct, argparse): any Python 3.8 or later.
"""

import argparse
import math
import re
import shlex
import struct
import sys
from pathlib import Path

REPO = Path(__file__).resolve().parent.parent
DEFAULT_OUT = REPO / "cases" / "meshes"
PROG = "python3 scripts/make_meshes.py"
FORMATS = ("stl-ascii", "stl-binary", "obj", "ply-ascii", "off")
EXT_FORMAT = {".stl": "stl-ascii", ".obj": "obj", ".ply": "ply-ascii", ".off": "off"}
MESH_EXTS = (".stl", ".obj", ".ply", ".off")
VERTEX_EXTS = (".csv", ".txt", ".xy")
# Words an STL reader takes as keywords (CGAL's reads the file word by word): none may appear
# in the text of a "solid" line.
STL_WORDS = {"solid", "endsolid", "facet", "endfacet", "outer", "loop", "endloop", "vertex",
             "normal"}


class MeshError(Exception):
    pass


# --------------------------------------------------------------------------------------------
# Numbers and small vector helpers


def num(x):
    """A float as the shortest text that reads back to the same double (no -0)."""
    x = float(x) + 0.0
    if not math.isfinite(x):
        raise MeshError("a coordinate or parameter is not a finite number")
    return repr(x)


def vtext(v):
    return "(" + ", ".join(num(c) for c in v) + ")"


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1], a[2] - b[2])


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def norm(a):
    return math.sqrt(dot(a, a))


def unit_normal(a, b, c):
    n = cross(sub(b, a), sub(c, a))
    length = norm(n)
    if length == 0:
        raise MeshError("a degenerate triangle (zero area)")
    return (n[0] / length, n[1] / length, n[2] / length)


# --------------------------------------------------------------------------------------------
# Shapes


class Mesh:
    """Shared vertices and triangles (index triples), or 2-D vertices of a polyline."""

    def __init__(self, vertices, triangles=None, closed=True, description="", facing="",
                 short=""):
        self.vertices = [tuple(float(c) + 0.0 for c in v) for v in vertices]
        self.triangles = [tuple(t) for t in (triangles or [])]
        self.closed = closed
        self.description = description
        self.facing = facing  # the side the normals point to, in words
        self.short = short or description  # for the 80 bytes of a binary STL header


def box_vertices(lo, hi):
    return [((hi[0] if k & 1 else lo[0]), (hi[1] if k & 2 else lo[1]), (hi[2] if k & 4 else lo[2]))
            for k in range(8)]


# Each face of a box as two triangles, counter-clockwise seen from outside (vertex k has x from
# bit 0, y from bit 1, z from bit 2): z-, z+, y-, y+, x-, x+.
BOX_QUADS = ((0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5))


def box_triangles():
    tris = []
    for q in BOX_QUADS:
        tris.append((q[0], q[1], q[2]))
        tris.append((q[0], q[2], q[3]))
    return tris


def flipped(tris):
    return [(t[0], t[2], t[1]) for t in tris]


def check_box(lo, hi):
    for a in range(3):
        if not hi[a] > lo[a]:
            raise MeshError("--hi must exceed --lo along every axis")


def make_box(lo, hi, inward):
    check_box(lo, hi)
    tris = box_triangles()
    if inward:
        tris = flipped(tris)
    facing = "inward (into the box)" if inward else "outward"
    desc = "axis-aligned box from %s to %s m, 12 triangles, normals %s" % (vtext(lo), vtext(hi),
                                                                          facing)
    short = "box %s to %s m, normals %s" % (vtext(lo), vtext(hi), "in" if inward else "out")
    return Mesh(box_vertices(lo, hi), tris, True, desc, facing, short)


def rotate_xyz(p, deg):
    """R p with R = Rz Ry Rx (degrees; x first), as sluice's shape placement rotates."""
    ax, ay, az = (math.radians(d) for d in deg)
    x, y, z = p
    y, z = math.cos(ax) * y - math.sin(ax) * z, math.sin(ax) * y + math.cos(ax) * z
    x, z = math.cos(ay) * x + math.sin(ay) * z, -math.sin(ay) * x + math.cos(ay) * z
    x, y = math.cos(az) * x - math.sin(az) * y, math.sin(az) * x + math.cos(az) * y
    return (x, y, z)


def make_tilted_box(lo, hi, rot, inward):
    check_box(lo, hi)
    c = tuple(0.5 * (lo[a] + hi[a]) for a in range(3))
    verts = []
    for v in box_vertices(lo, hi):
        r = rotate_xyz(sub(v, c), rot)
        verts.append((c[0] + r[0], c[1] + r[1], c[2] + r[2]))
    tris = box_triangles()
    if inward:
        tris = flipped(tris)
    facing = "inward (into the box)" if inward else "outward"
    desc = ("box from %s to %s m rotated by %s degrees about its centre %s "
            "(about x, then y, then z: p' = c + Rz Ry Rx (p - c)), 12 triangles, normals %s"
            % (vtext(lo), vtext(hi), vtext(rot), vtext(c), facing))
    short = "box %s to %s m turned %s deg" % (vtext(lo), vtext(hi), vtext(rot))
    return Mesh(verts, tris, True, desc, facing, short)


AXES = {"x": (1, 2, 0), "y": (2, 0, 1), "z": (0, 1, 2)}  # (u, v, w): a right-handed frame


def make_cylinder(centre, radius, height, axis, segments):
    if not radius > 0 or not height > 0:
        raise MeshError("--radius and --height must be positive")
    if segments < 3:
        raise MeshError("--segments must be at least 3")
    iu, iv, iw = AXES[axis]

    def point(cu, cv, cw):
        p = [0.0, 0.0, 0.0]
        p[iu], p[iv], p[iw] = cu, cv, cw
        return tuple(p)

    cu, cv, cw = centre[iu], centre[iv], centre[iw]
    top = cw + height
    verts = []
    for k in range(segments):  # bottom ring 0..n-1, top ring n..2n-1
        th = 2.0 * math.pi * k / segments
        verts.append(point(cu + radius * math.cos(th), cv + radius * math.sin(th), cw))
    for k in range(segments):
        verts.append(point(verts[k][iu], verts[k][iv], top))
    bottom_c = len(verts)
    verts.append(point(cu, cv, cw))
    top_c = len(verts)
    verts.append(point(cu, cv, top))
    n = segments
    tris = []
    for k in range(n):
        k1 = (k + 1) % n
        tris.append((k, k1, n + k1))  # side quad, outward
        tris.append((k, n + k1, n + k))
    for k in range(n):
        k1 = (k + 1) % n
        tris.append((bottom_c, k1, k))  # bottom cap, facing -axis
    for k in range(n):
        k1 = (k + 1) % n
        tris.append((top_c, n + k, n + k1))  # top cap, facing +axis
    desc = ("closed cylinder, axis %s, base centre %s, radius %s m, height %s m, %d segments, "
            "caps as fans from a centre point, %d triangles, normals outward"
            % (axis, vtext(centre), num(radius), num(height), n, len(tris)))
    short = "cylinder %s base %s r %s h %s n %d" % (axis, vtext(centre), num(radius),
                                                      num(height), n)
    return Mesh(verts, tris, True, desc, "outward", short)


ICO_FACES = ((0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11),
             (1, 5, 9), (5, 11, 4), (11, 10, 2), (10, 7, 6), (7, 1, 8),
             (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9),
             (4, 9, 5), (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1))


def unit(p):
    length = norm(p)
    return (p[0] / length, p[1] / length, p[2] / length)


def make_icosphere(centre, radius, subdivisions):
    if not radius > 0:
        raise MeshError("--radius must be positive")
    if not 0 <= subdivisions <= 8:
        raise MeshError("--subdivisions must be 0 to 8")
    t = (1.0 + math.sqrt(5.0)) / 2.0
    base = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t),
            (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    pts = [unit(tuple(float(c) for c in p)) for p in base]
    faces = list(ICO_FACES)
    for f in faces:  # the table is counter-clockwise seen from outside
        if dot(cross(sub(pts[f[1]], pts[f[0]]), sub(pts[f[2]], pts[f[0]])), pts[f[0]]) <= 0:
            raise MeshError("internal: icosahedron face not outward")
    for _ in range(subdivisions):
        cache = {}

        def middle(i, j):
            key = (i, j) if i < j else (j, i)
            m = cache.get(key)
            if m is None:
                a, b = pts[i], pts[j]
                pts.append(unit(((a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2)))
                m = cache[key] = len(pts) - 1
            return m

        finer = []
        for a, b, c in faces:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            finer += [(a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca)]
        faces = finer
    verts = [(centre[0] + radius * p[0], centre[1] + radius * p[1], centre[2] + radius * p[2])
             for p in pts]
    desc = ("icosphere, centre %s, radius %s m, subdivision %d, %d triangles, normals outward"
            % (vtext(centre), num(radius), subdivisions, len(faces)))
    short = "icosphere %s r %s, subdivision %d" % (vtext(centre), num(radius), subdivisions)
    return Mesh(verts, faces, True, desc, "outward", short)


def make_uvsphere(centre, radius, stacks, slices):
    if not radius > 0:
        raise MeshError("--radius must be positive")
    if stacks < 2 or slices < 3:
        raise MeshError("a UV sphere needs --stacks >= 2 and --slices >= 3")
    c = centre
    verts = [(c[0], c[1], c[2] - radius)]
    for i in range(1, stacks):
        th = math.pi * i / stacks
        for j in range(slices):
            ph = 2.0 * math.pi * j / slices
            verts.append((c[0] + radius * math.sin(th) * math.cos(ph),
                          c[1] + radius * math.sin(th) * math.sin(ph),
                          c[2] - radius * math.cos(th)))
    verts.append((c[0], c[1], c[2] + radius))
    top = len(verts) - 1

    def ring(i, j):
        return 1 + (i - 1) * slices + (j % slices)

    tris = []
    for j in range(slices):
        tris.append((0, ring(1, j + 1), ring(1, j)))
        for i in range(1, stacks - 1):
            tris.append((ring(i, j), ring(i, j + 1), ring(i + 1, j + 1)))
            tris.append((ring(i, j), ring(i + 1, j + 1), ring(i + 1, j)))
        tris.append((ring(stacks - 1, j), ring(stacks - 1, j + 1), top))
    desc = ("UV sphere, centre %s, radius %s m, %d stacks x %d slices (poles single points), "
            "%d triangles, normals outward" % (vtext(c), num(radius), stacks, slices, len(tris)))
    short = "UV sphere %s r %s, %d x %d" % (vtext(c), num(radius), stacks, slices)
    return Mesh(verts, tris, True, desc, "outward", short)


def ramp_height(length, height, angle):
    if height is not None:
        return height
    return length * math.tan(math.radians(angle))


def make_ramp(lo, length, width, height):
    if not length > 0 or not width > 0 or not height > 0:
        raise MeshError("--length, --width and the height (or --angle) must be positive")
    x0, y0, z0 = lo
    x1, y1, z1 = x0 + length, y0 + width, z0 + height
    # 0 1 2 on y = y0: foot, far bottom edge, top of the back face; 3 4 5 the same on y = y1.
    verts = [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y1, z0), (x1, y1, z0), (x1, y1, z1)]
    tris = [(0, 3, 4), (0, 4, 1),  # bottom (z0), facing -z
            (1, 4, 5), (1, 5, 2),  # back face (x = x1), facing +x
            (0, 2, 5), (0, 5, 3),  # slope, facing up and towards -x
            (0, 1, 2),             # side y = y0, facing -y
            (3, 5, 4)]             # side y = y1, facing +y
    desc = ("closed wedge (sloped bed): base %s to %s m at z = %s, rising along +x to height %s m "
            "at x = %s (slope %s degrees), 8 triangles, normals outward"
            % (vtext((x0, y0)), vtext((x1, y1)), num(z0), num(height), num(x1),
               num(math.degrees(math.atan2(height, length)))))
    short = "wedge from %s, %s x %s m, rise %s m along +x" % (vtext(lo), num(length), num(width),
                                                             num(height))
    return Mesh(verts, tris, True, desc, "outward", short)


def make_plane(corner, e1, e2, n1, n2):
    if n1 < 1 or n2 < 1:
        raise MeshError("--divisions must be at least 1")
    nrm = cross(e1, e2)
    if norm(nrm) == 0:
        raise MeshError("--edge1 and --edge2 must not be parallel")
    verts = []
    for j in range(n2 + 1):
        for i in range(n1 + 1):
            verts.append(tuple(corner[a] + e1[a] * i / n1 + e2[a] * j / n2 for a in range(3)))

    def idx(i, j):
        return j * (n1 + 1) + i

    tris = []
    for j in range(n2):
        for i in range(n1):
            tris.append((idx(i, j), idx(i + 1, j), idx(i + 1, j + 1)))
            tris.append((idx(i, j), idx(i + 1, j + 1), idx(i, j + 1)))
    facing = "along edge1 x edge2 = %s" % vtext(unit(nrm))
    desc = ("open rectangle, corner %s, edge1 %s, edge2 %s m, %d x %d cells, %d triangles, "
            "normals %s" % (vtext(corner), vtext(e1), vtext(e2), n1, n2, len(tris), facing))
    short = "open rectangle at %s, %d x %d cells" % (vtext(corner), n1, n2)
    return Mesh(verts, tris, False, desc, facing, short)


def polyline_points(ns):
    """The 2-D vertices a polyline command asks for, and what they are in words."""
    kinds = [k for k in ("points", "ramp", "sill") if getattr(ns, k) is not None]
    if len(kinds) != 1:
        raise MeshError("polyline takes exactly one of --points, --ramp, --sill")
    y0 = ns.y0
    if ns.points is not None:
        if len(ns.points) % 2 or len(ns.points) < 4:
            raise MeshError("--points takes x y pairs, at least two")
        pts = [(ns.points[k], ns.points[k + 1]) for k in range(0, len(ns.points), 2)]
        desc = "2-D polyline of %d vertices, in the order given" % len(pts)
    elif ns.ramp is not None:
        xl, xr, xt, angle = ns.ramp
        if not xl < xt < xr or not 0 < angle < 90:
            raise MeshError("--ramp needs X_LEFT < X_TOE < X_RIGHT and 0 < ANGLE < 90")
        rise = (xr - xt) * math.tan(math.radians(angle))
        pts = [(xr, y0 + rise), (xt, y0), (xl, y0)]
        desc = ("2-D sloped bed: flat at y = %s from x = %s to the toe at x = %s, then rising at "
                "%s degrees to y = %s at x = %s" % (num(y0), num(xl), num(xt), num(angle),
                                                    num(y0 + rise), num(xr)))
    else:
        xl, xr, xc, h, half = ns.sill
        if not (xl <= xc - half and xc + half <= xr and h > 0 and half > 0):
            raise MeshError("--sill needs X_LEFT <= X_CREST - HALF_BASE, "
                            "X_CREST + HALF_BASE <= X_RIGHT, HEIGHT > 0, HALF_BASE > 0")
        pts = [(xr, y0), (xc + half, y0), (xc, y0 + h), (xc - half, y0), (xl, y0)]
        if xc + half == xr:
            pts.pop(0)
        if xc - half == xl:
            pts.pop()
        desc = ("2-D bed with a symmetric triangular sill: bed y = %s from x = %s to %s, sill "
                "%s m high with its crest at x = %s and its foot %s m either side "
                "(slopes %s)" % (num(y0), num(xl), num(xr), num(h), num(xc), num(half),
                                 num(h / half)))
    if ns.closed:
        pts.append(pts[0])
    return pts, desc


def make_polyline(ns):
    pts, desc = polyline_points(ns)
    mesh = Mesh([(x, y, 0.0) for x, y in pts], None, bool(ns.closed), desc, "")
    return mesh


# --------------------------------------------------------------------------------------------
# Writers: each returns the file's bytes.


def header_lines(name, mesh, notes, command):
    lines = ["sluice mesh %s: %s" % (name, mesh.description)]
    for note in notes:
        lines.append("note: " + note)
    lines.append("units: metres; orientation: right-hand rule, normals %s" % mesh.facing)
    lines.append("made by: " + command)
    return lines


def check_stl_text(text):
    for word in text.split():
        if word.strip("()[],;:.'\"").lower() in STL_WORDS:
            raise MeshError("the STL header text may not hold the word \"%s\" (an STL keyword)"
                            % word)


def write_stl_ascii(name, mesh, notes, command):
    solid_name = "".join(ch if ch.isalnum() or ch in "_-." else "_" for ch in name) or "mesh"
    text = "; ".join([mesh.description] + ["note: " + n for n in notes] +
                     ["made by: " + command])
    text = " ".join(text.split())
    check_stl_text(solid_name + " " + text)
    out = ["solid %s %s" % (solid_name, text)]
    v = mesh.vertices
    for t in mesh.triangles:
        n = unit_normal(v[t[0]], v[t[1]], v[t[2]])
        out.append("  facet normal %s %s %s" % tuple(num(c) for c in n))
        out.append("    outer loop")
        for k in t:
            out.append("      vertex %s %s %s" % tuple(num(c) for c in v[k]))
        out.append("    endloop")
        out.append("  endfacet")
    out.append("endsolid %s" % solid_name)
    return ("\n".join(out) + "\n").encode("ascii")


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def write_stl_binary(name, mesh, notes, command):
    head = ("sluice mesh %s: %s" % (name, mesh.short)).encode("ascii")
    if len(head) > 80:
        head = head[:77] + b"..."
    tail = b"; make_meshes.py"
    if len(head) + len(tail) <= 80:
        head += tail
    head = head.ljust(80, b" ")
    if head[:5].lower() == b"solid":
        raise MeshError("a binary STL header may not start with \"solid\"")
    v = [tuple(f32(c) for c in p) for p in mesh.vertices]
    parts = [head, struct.pack("<I", len(mesh.triangles))]
    for t in mesh.triangles:
        n = unit_normal(v[t[0]], v[t[1]], v[t[2]])
        parts.append(struct.pack("<12fH", *n, *v[t[0]], *v[t[1]], *v[t[2]], 0))
    return b"".join(parts)


def write_obj(name, mesh, notes, command):
    out = ["# " + line for line in header_lines(name, mesh, notes, command)]
    for p in mesh.vertices:
        out.append("v %s %s %s" % tuple(num(c) for c in p))
    for t in mesh.triangles:
        out.append("f %d %d %d" % (t[0] + 1, t[1] + 1, t[2] + 1))
    return ("\n".join(out) + "\n").encode("ascii")


def write_ply(name, mesh, notes, command):
    out = ["ply", "format ascii 1.0"]
    out += ["comment " + line for line in header_lines(name, mesh, notes, command)]
    out += ["element vertex %d" % len(mesh.vertices), "property double x", "property double y",
            "property double z", "element face %d" % len(mesh.triangles),
            "property list uchar int vertex_indices", "end_header"]
    for p in mesh.vertices:
        out.append("%s %s %s" % tuple(num(c) for c in p))
    for t in mesh.triangles:
        out.append("3 %d %d %d" % t)
    return ("\n".join(out) + "\n").encode("ascii")


def write_off(name, mesh, notes, command):
    out = ["OFF"] + ["# " + line for line in header_lines(name, mesh, notes, command)]
    out.append("%d %d 0" % (len(mesh.vertices), len(mesh.triangles)))
    for p in mesh.vertices:
        out.append("%s %s %s" % tuple(num(c) for c in p))
    for t in mesh.triangles:
        out.append("3 %d %d %d" % t)
    return ("\n".join(out) + "\n").encode("ascii")


WRITERS = {"stl-ascii": write_stl_ascii, "stl-binary": write_stl_binary, "obj": write_obj,
           "ply-ascii": write_ply, "off": write_off}


def write_vertex_csv(name, mesh, notes, command):
    out = ["# sluice 2-D vertex file %s: %s" % (name, mesh.description)]
    for note in notes:
        out.append("# note: " + note)
    out.append("# units: metres. Each segment's normal is its direction (from one row to the "
               "next) turned clockwise, (dy, -dx);")
    out.append("# a bed listed from right (high x) to left (low x) has normals pointing up, "
               "into the fluid above it." + (" The last row repeats the first: a closed polygon."
                                              if mesh.closed else ""))
    out.append("# made by: " + command)
    out.append("# x,y")
    for p in mesh.vertices:
        out.append("%s,%s" % (num(p[0]), num(p[1])))
    return ("\n".join(out) + "\n").encode("ascii")


# --------------------------------------------------------------------------------------------
# Command line


def add_common(p, mesh=True):
    p.add_argument("--out", dest="out_file", required=True, metavar="FILE",
                   help="the file to write")
    if mesh:
        p.add_argument("--format", choices=FORMATS,
                       help="default: from the extension (.stl ASCII, .obj, .ply ASCII, .off)")
    p.add_argument("--name", help="the shape's name in the header (default: the file's stem)")
    p.add_argument("--note", action="append", default=[],
                   help="a line of provenance for the header (repeatable)")


def build_parser():
    top = argparse.ArgumentParser(
        prog=PROG, description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter,
        epilog="With no shape: write every shipped file into DIR (default cases/meshes) with "
               "its README.md.")
    top.add_argument("--out", dest="out_dir", metavar="DIR",
                     help="where the shipped files go (default: cases/meshes of the repository)")
    top.add_argument("--check", nargs="?", const=str(DEFAULT_OUT), metavar="DIR",
                     help="check every mesh and vertex file in DIR (default cases/meshes)")
    sp = top.add_subparsers(dest="shape", metavar="SHAPE")

    p = sp.add_parser("box", help="axis-aligned box, 12 triangles")
    p.add_argument("--lo", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    p.add_argument("--hi", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    p.add_argument("--inward", action="store_true",
                   help="normals into the box (a container holding fluid)")
    add_common(p)

    p = sp.add_parser("tilted-box", help="box rotated about its centre")
    p.add_argument("--lo", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    p.add_argument("--hi", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    p.add_argument("--rotate", type=float, nargs=3, required=True, metavar=("AX", "AY", "AZ"),
                   help="degrees about x, then y, then z, through the box's centre")
    p.add_argument("--inward", action="store_true")
    add_common(p)

    p = sp.add_parser("cylinder", help="closed cylinder with fan caps")
    p.add_argument("--centre", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"),
                   help="centre of the lower cap; the cylinder reaches --height along +axis")
    p.add_argument("--radius", type=float, required=True)
    p.add_argument("--height", type=float, required=True)
    p.add_argument("--axis", choices=("x", "y", "z"), default="z")
    p.add_argument("--segments", type=int, default=48)
    add_common(p)

    p = sp.add_parser("sphere", help="icosphere (default) or UV sphere")
    p.add_argument("--centre", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    p.add_argument("--radius", type=float, required=True)
    p.add_argument("--kind", choices=("ico", "uv"), default="ico")
    p.add_argument("--subdivisions", type=int, help="icosphere: 20 * 4^k triangles (default 3)")
    p.add_argument("--stacks", type=int, help="UV sphere: bands from pole to pole")
    p.add_argument("--slices", type=int, help="UV sphere: sectors around the axis")
    p.add_argument("--triangles", type=int, metavar="N",
                   help="about N triangles: the nearest icosphere subdivision, or a UV sphere "
                        "with slices = 2 stacks (4 stacks (stacks - 1) triangles)")
    add_common(p)

    p = sp.add_parser("ramp", help="closed wedge: a sloped bed rising along +x")
    p.add_argument("--lo", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"),
                   help="the wedge's lowest corner (its foot at y = Y)")
    p.add_argument("--length", type=float, required=True, help="along x")
    p.add_argument("--width", type=float, required=True, help="along y")
    g = p.add_mutually_exclusive_group(required=True)
    g.add_argument("--height", type=float, help="rise at the far end")
    g.add_argument("--angle", type=float, help="slope in degrees")
    add_common(p)

    p = sp.add_parser("plane", help="open rectangle, two triangles a cell")
    p.add_argument("--corner", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    p.add_argument("--edge1", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    p.add_argument("--edge2", type=float, nargs=3, required=True, metavar=("X", "Y", "Z"))
    p.add_argument("--divisions", type=int, nargs="+", default=[1], metavar="N",
                   help="cells along edge1 (and edge2; one number: both)")
    add_common(p)

    p = sp.add_parser("polyline", help="2-D vertex file (x,y rows)")
    p.add_argument("--points", type=float, nargs="+", metavar="X_Y",
                   help="x y pairs, in order")
    p.add_argument("--ramp", type=float, nargs=4,
                   metavar=("X_LEFT", "X_RIGHT", "X_TOE", "ANGLE"),
                   help="flat bed from X_LEFT to X_TOE, rising at ANGLE degrees to X_RIGHT "
                        "(listed right to left)")
    p.add_argument("--sill", type=float, nargs=5,
                   metavar=("X_LEFT", "X_RIGHT", "X_CREST", "HEIGHT", "HALF_BASE"),
                   help="flat bed with a symmetric triangular sill (listed right to left)")
    p.add_argument("--y0", type=float, default=0.0, help="bed level (default 0)")
    p.add_argument("--closed", action="store_true", help="repeat the first vertex at the end")
    add_common(p, mesh=False)
    return top


def recorded_path(path):
    """The output path as the header records it: relative to the repository when inside it."""
    p = Path(path).resolve()
    try:
        return p.relative_to(REPO).as_posix()
    except ValueError:
        return p.as_posix()


def sphere_choice(ns):
    """(kind, subdivisions, stacks, slices) of a sphere command."""
    if ns.kind == "ico":
        if ns.stacks is not None or ns.slices is not None:
            raise MeshError("--stacks/--slices are for --kind uv")
        if ns.triangles is not None:
            if ns.subdivisions is not None:
                raise MeshError("give --subdivisions or --triangles, not both")
            if ns.triangles < 1:
                raise MeshError("--triangles must be positive")
            k = min(range(9), key=lambda k: (abs(math.log(20 * 4 ** k / ns.triangles)), -k))
            return "ico", k, None, None
        return "ico", 3 if ns.subdivisions is None else ns.subdivisions, None, None
    if ns.subdivisions is not None:
        raise MeshError("--subdivisions is for --kind ico")
    if ns.triangles is not None:
        if ns.stacks is not None or ns.slices is not None:
            raise MeshError("give --stacks/--slices or --triangles, not both")
        s0 = max(2, int((1 + math.sqrt(1 + ns.triangles)) / 2))
        s = min((s0, s0 + 1), key=lambda s: (abs(4 * s * (s - 1) - ns.triangles), s))
        return "uv", None, s, 2 * s
    if ns.stacks is None or ns.slices is None:
        raise MeshError("a UV sphere needs --stacks and --slices (or --triangles)")
    return "uv", None, ns.stacks, ns.slices


def shape_of(ns):
    """(mesh, the canonical arguments that make it, without --out)."""
    s = ns.shape
    if s == "box":
        args = ["box", "--lo", *map(num, ns.lo), "--hi", *map(num, ns.hi)]
        if ns.inward:
            args.append("--inward")
        return make_box(ns.lo, ns.hi, ns.inward), args
    if s == "tilted-box":
        args = ["tilted-box", "--lo", *map(num, ns.lo), "--hi", *map(num, ns.hi), "--rotate",
                *map(num, ns.rotate)]
        if ns.inward:
            args.append("--inward")
        return make_tilted_box(ns.lo, ns.hi, ns.rotate, ns.inward), args
    if s == "cylinder":
        args = ["cylinder", "--centre", *map(num, ns.centre), "--radius", num(ns.radius),
                "--height", num(ns.height), "--axis", ns.axis, "--segments", str(ns.segments)]
        return make_cylinder(ns.centre, ns.radius, ns.height, ns.axis, ns.segments), args
    if s == "sphere":
        kind, k, st, sl = sphere_choice(ns)
        args = ["sphere", "--centre", *map(num, ns.centre), "--radius", num(ns.radius)]
        if kind == "ico":
            args += ["--subdivisions", str(k)]
            return make_icosphere(ns.centre, ns.radius, k), args
        args += ["--kind", "uv", "--stacks", str(st), "--slices", str(sl)]
        return make_uvsphere(ns.centre, ns.radius, st, sl), args
    if s == "ramp":
        h = ramp_height(ns.length, ns.height, ns.angle)
        args = ["ramp", "--lo", *map(num, ns.lo), "--length", num(ns.length), "--width",
                num(ns.width)]
        args += ["--height", num(ns.height)] if ns.height is not None else ["--angle",
                                                                            num(ns.angle)]
        return make_ramp(ns.lo, ns.length, ns.width, h), args
    if s == "plane":
        d = ns.divisions
        if len(d) > 2:
            raise MeshError("--divisions takes one or two numbers")
        n1, n2 = d[0], d[-1]
        args = ["plane", "--corner", *map(num, ns.corner), "--edge1", *map(num, ns.edge1),
                "--edge2", *map(num, ns.edge2), "--divisions", str(n1)]
        if n2 != n1:
            args.append(str(n2))
        return make_plane(ns.corner, ns.edge1, ns.edge2, n1, n2), args
    if s == "polyline":
        mesh = make_polyline(ns)
        args = ["polyline"]
        if ns.points is not None:
            args += ["--points", *map(num, ns.points)]
        elif ns.ramp is not None:
            args += ["--ramp", *map(num, ns.ramp)]
        else:
            args += ["--sill", *map(num, ns.sill)]
        if ns.y0 != 0:
            args += ["--y0", num(ns.y0)]
        if ns.closed:
            args.append("--closed")
        return mesh, args
    raise MeshError("unknown shape " + str(s))


def file_format(ns):
    if ns.shape == "polyline":
        return "csv"
    if ns.format:
        return ns.format
    ext = Path(ns.out_file).suffix.lower()
    if ext not in EXT_FORMAT:
        raise MeshError("cannot tell the format from \"%s\": give --format" % ns.out_file)
    return EXT_FORMAT[ext]


def generate(ns, record=None):
    """(the file's bytes, the command recorded in it); record: the --out the command names
    (default: the output path, relative to the repository when inside it)."""
    mesh, args = shape_of(ns)
    fmt = file_format(ns)
    if fmt != "csv":
        args += ["--format", fmt]
    name = ns.name or Path(ns.out_file).stem
    if ns.name:
        args += ["--name", ns.name]
    for note in ns.note:
        args += ["--note", note]
    args += ["--out", record or recorded_path(ns.out_file)]
    command = PROG + " " + " ".join(shlex.quote(a) for a in args)
    if fmt == "csv":
        return write_vertex_csv(name, mesh, ns.note, command), command
    return WRITERS[fmt](name, mesh, ns.note, command), command


# --------------------------------------------------------------------------------------------
# The shipped files


SHIPPED = [
    dict(file="obstacle_box_3d.stl",
         what="Square column obstacle, a closed box (outward normals)",
         params="lo (0.9, 0.24, 0), hi (1.02, 0.36, 0.45) m: the `[[walls.boxes]]` column of "
                "`perf/cases/dam_break_3d_obstacle.toml`; 12 triangles",
         args=["box", "--lo", "0.9", "0.24", "0", "--hi", "1.02", "0.36", "0.45", "--note",
               "the square column [[walls.boxes]] of perf/cases/dam_break_3d_obstacle.toml"]),
    dict(file="cylinder_3d.stl",
         what="Vertical cylinder, closed with fan caps (outward normals)",
         params="axis z, base centre (1.0, 0.25, 0), radius 0.05 m, height 0.3 m (z = 0 to "
                "0.3), 48 segments; 192 triangles",
         args=["cylinder", "--centre", "1", "0.25", "0", "--radius", "0.05", "--height", "0.3",
               "--axis", "z", "--segments", "48"]),
    dict(file="debris_tank_3d.stl",
         what="Cubic tank as a container: a closed box with normals pointing in, into the "
              "fluid; binary STL",
         params="lo (0, 0, 0), hi (1, 1, 1) m: `[walls] tank_lo / tank_hi` of "
                "`cases/debris_box_3d.toml`; 12 triangles",
         args=["box", "--lo", "0", "0", "0", "--hi", "1", "1", "1", "--inward", "--format",
               "stl-binary", "--note", "tank_lo / tank_hi of cases/debris_box_3d.toml, "
               "a container: normals into the fluid"]),
    dict(file="ramp_2d.csv",
         what="2-D sloped bed: flat, then rising at 10 degrees",
         params="the 1.6 m tank of `cases/dam_break_2d.toml`: y = 0 from x = 0 to the toe at "
                "x = 0.6 (under the 0.4 m reservoir and 0.2 m beyond), then 10 degrees up to "
                "x = 1.6 (y = 0.1763...); 3 vertices, right to left (normals up)",
         args=["polyline", "--ramp", "0", "1.6", "0.6", "10", "--note",
               "for a 2-D dam break over a slope in the 1.6 m tank of cases/dam_break_2d.toml "
               "(tank_lo.x = 0, tank_hi.x = 1.6)"]),
    dict(file="cadam_sill_2d.csv",
         what="2-D flume bed with a triangular sill: the dam break over a triangular bottom "
              "sill (EU CADAM benchmark, as in Zhou et al. 2004)",
         params="bed y = 0 from x = 0 to 38 m, sill 0.4 m high with its crest at x = 28.5 m "
                "and feet 3 m either side (x = 25.5 and 31.5 m); 5 vertices, right to left "
                "(normals up); `cases/dam_break_sill_2d.toml`",
         args=["polyline", "--sill", "0", "38", "28.5", "0.4", "3", "--note",
               "the flume of the CADAM dam break over a triangular bottom sill (Zhou, Causon, "
               "Mingham & Ingram 2004, J. Hydraul. Eng. 130(4)): 38 m long, sill 0.4 m high "
               "from x = 25.5 to 31.5 m"]),
    dict(file="tilted_box_3d.stl",
         what="Box 0.2 x 0.1 x 0.15 m rotated about its centre (outward normals)",
         params="lo (0.4, 0.45, 0.425), hi (0.6, 0.55, 0.575) m (centre (0.5, 0.5, 0.5)), "
                "rotated 20, 30, 10 degrees about x, then y, then z; 12 triangles",
         args=["tilted-box", "--lo", "0.4", "0.45", "0.425", "--hi", "0.6", "0.55", "0.575",
               "--rotate", "20", "30", "10"]),
    dict(file="sphere_3d.stl",
         what="Icosphere (outward normals)",
         params="centre (0.5, 0.5, 0.5), radius 0.1 m, subdivision 3; 1,280 triangles, "
                "642 vertices",
         args=["sphere", "--centre", "0.5", "0.5", "0.5", "--radius", "0.1", "--subdivisions",
               "3"]),
]


def shipped_namespace(entry, out_file):
    return build_parser().parse_args(entry["args"] + ["--out", str(out_file)])


def shipped_record(entry):
    """A shipped file names its command as the README does, wherever it is written, so that
    it is the same file byte for byte in any folder."""
    return "cases/meshes/" + entry["file"]


def readme_text():
    out = [
        "# Meshes and 2-D vertex files",
        "",
        "Small shapes for sluice's cases and tests, made by `scripts/make_meshes.py` (Python 3, "
        "standard library only). `python3 scripts/make_meshes.py` rewrites every file below and "
        "this README byte for byte; `python3 scripts/make_meshes.py --check cases/meshes` checks "
        "them (closed meshes: every edge used exactly twice, in opposite directions; signed "
        "volume against the analytic or polyhedral volume; facet normals; vertex files: every "
        "segment's normal points up).",
        "",
        "Conventions: metres. Closed meshes are watertight with outward normals "
        "(counter-clockwise seen from outside, right-hand rule) unless the table says otherwise; "
        "an STL facet normal is the normalised (b - a) x (c - a). ASCII files write each "
        "coordinate as the shortest decimal that reads back to the same double, so a vertex "
        "shared by several facets is bit-identical in each; binary STL stores 32-bit floats. "
        "A 2-D vertex file holds `x,y` rows after `#` comment lines; each segment's normal is "
        "its direction turned clockwise, (dy, -dx), so a bed listed from right (high x) to "
        "left (low x) has normals pointing up, into the fluid. Each file's header names what "
        "it is and the command that made it.",
        "",
        "| File | What it is | Parameters | Command |",
        "|---|---|---|---|",
    ]
    for e in SHIPPED:
        cmd = PROG + " " + " ".join(shlex.quote(a) for a in e["args"]) + \
            " --out " + shipped_record(e)
        out.append("| `%s` | %s | %s | `%s` |" % (e["file"], e["what"], e["params"], cmd))
    out += [
        "",
        "Other shapes and formats (`--format stl-ascii | stl-binary | obj | ply-ascii | off`, "
        "otherwise from the extension): `box`, `tilted-box`, `cylinder`, `sphere`, `ramp` "
        "(a closed wedge), `plane` (an open rectangle) and `polyline`; "
        "`python3 scripts/make_meshes.py SHAPE --help` lists the parameters. A sphere of about "
        "100,000 triangles for a set-up benchmark: `python3 scripts/make_meshes.py sphere "
        "--centre 0.5 0.5 0.5 --radius 0.1 --kind uv --triangles 100000 --format stl-binary "
        "--out sphere_100k.stl` (159 stacks x 318 slices, 100,488 triangles), or "
        "`--subdivisions 6` for an icosphere of 81,920.",
        "",
    ]
    return "\n".join(out)


def write_all(out_dir):
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    for e in SHIPPED:
        path = out_dir / e["file"]
        data, _ = generate(shipped_namespace(e, path), shipped_record(e))
        path.write_bytes(data)
        print("wrote %s (%d bytes)" % (path, len(data)))
    readme = out_dir / "README.md"
    readme.write_bytes(readme_text().encode("utf-8"))
    print("wrote %s" % readme)


# --------------------------------------------------------------------------------------------
# Check: read the files back with readers of their own and test them.


def read_stl(data):
    """(vertices, triangles, stored normals, kind, header text) with vertices merged exactly."""
    binary = False
    if len(data) >= 84:
        count = struct.unpack("<I", data[80:84])[0]
        binary = len(data) == 84 + 50 * count and not data[:5].lower() == b"solid"
    if not binary and data[:6] != b"solid ":
        raise MeshError("neither ASCII STL (\"solid \") nor binary STL of a consistent size")
    soup, normals = [], []
    if binary:
        header = data[:80].decode("ascii", "replace").rstrip()
        for k in range(count):
            vals = struct.unpack("<12fH", data[84 + 50 * k:84 + 50 * (k + 1)])
            normals.append(tuple(vals[0:3]))
            soup.append((tuple(vals[3:6]), tuple(vals[6:9]), tuple(vals[9:12])))
        kind = "stl-binary"
    else:
        text = data.decode("ascii")
        first, _, rest = text.partition("\n")
        header = first
        for word in first.split()[1:]:
            if word.lower() in STL_WORDS:
                raise MeshError("the solid line holds the STL keyword \"%s\"" % word)
        tok = rest.split()
        i = 0
        while i < len(tok):
            if tok[i] == "endsolid":
                break
            if tok[i:i + 2] != ["facet", "normal"] or tok[i + 5:i + 7] != ["outer", "loop"]:
                raise MeshError("malformed ASCII STL near word %d" % i)
            normals.append(tuple(float(x) for x in tok[i + 2:i + 5]))
            i += 7
            tri = []
            for _ in range(3):
                if tok[i] != "vertex":
                    raise MeshError("malformed ASCII STL: expected vertex")
                tri.append(tuple(float(x) for x in tok[i + 1:i + 4]))
                i += 4
            if tok[i:i + 2] != ["endloop", "endfacet"]:
                raise MeshError("malformed ASCII STL: expected endloop endfacet")
            i += 2
            soup.append(tuple(tri))
        else:
            raise MeshError("ASCII STL without endsolid")
        kind = "stl-ascii"
    index, verts, tris = {}, [], []
    for tri in soup:
        ids = []
        for p in tri:
            if p not in index:
                index[p] = len(verts)
                verts.append(p)
            ids.append(index[p])
        tris.append(tuple(ids))
    return verts, tris, normals, kind, header


def read_indexed(data, kind):
    text = data.decode("ascii")
    lines = text.split("\n")
    verts, tris, header = [], [], []
    if kind == "obj":
        for line in lines:
            w = line.split()
            if not w:
                continue
            if w[0] == "#":
                header.append(line[2:])
            elif w[0] == "v":
                verts.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == "f":
                tris.append(tuple(int(x.split("/")[0]) - 1 for x in w[1:]))
    elif kind == "ply-ascii":
        if lines[0] != "ply" or lines[1] != "format ascii 1.0":
            raise MeshError("not an ASCII PLY file")
        nv = nf = None
        k = 2
        while lines[k] != "end_header":
            w = lines[k].split()
            if w[0] == "comment":
                header.append(lines[k][8:])
            elif w[:2] == ["element", "vertex"]:
                nv = int(w[2])
            elif w[:2] == ["element", "face"]:
                nf = int(w[2])
            k += 1
        body = lines[k + 1:]
        verts = [tuple(float(x) for x in body[i].split()[:3]) for i in range(nv)]
        for i in range(nv, nv + nf):
            w = body[i].split()
            tris.append(tuple(int(x) for x in w[1:1 + int(w[0])]))
    else:
        if lines[0] != "OFF":
            raise MeshError("not an OFF file")
        body = []
        for line in lines[1:]:
            if line.startswith("#"):
                header.append(line[2:])
            elif line.strip():
                body.append(line)
        nv, nf = (int(x) for x in body[0].split()[:2])
        verts = [tuple(float(x) for x in body[1 + i].split()) for i in range(nv)]
        for i in range(nf):
            w = body[1 + nv + i].split()
            tris.append(tuple(int(x) for x in w[1:1 + int(w[0])]))
    for t in tris:
        if len(t) != 3:
            raise MeshError("a face that is not a triangle")
        if any(not 0 <= v < len(verts) for v in t):
            raise MeshError("a face index out of range")
    if len(set(verts)) != len(verts):
        raise MeshError("duplicated vertices (shared corners must be one vertex)")
    return verts, tris, None, kind, "\n".join(header)


def read_mesh(path):
    data = Path(path).read_bytes()
    ext = Path(path).suffix.lower()
    if ext == ".stl":
        return read_stl(data)
    return read_indexed(data, {".obj": "obj", ".ply": "ply-ascii", ".off": "off"}[ext])


def edge_report(tris):
    """(closed, oriented, edges, boundary edges, problems)."""
    directed = {}
    problems = []
    for t in tris:
        if len(set(t)) != 3:
            problems.append("a triangle with a repeated vertex")
        for a, b in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0])):
            directed[(a, b)] = directed.get((a, b), 0) + 1
    repeated = sum(1 for c in directed.values() if c > 1)
    if repeated:
        problems.append("%d directed edges used more than once (inconsistent orientation or "
                        "non-manifold)" % repeated)
    undirected = {}
    for (a, b), c in directed.items():
        key = (a, b) if a < b else (b, a)
        undirected[key] = undirected.get(key, 0) + c
    boundary = sum(1 for (a, b) in directed if (b, a) not in directed)
    over = sum(1 for c in undirected.values() if c > 2)
    if over:
        problems.append("%d edges shared by more than two triangles" % over)
    return boundary == 0 and not problems, not problems, len(undirected), boundary, problems


def volumes(verts, tris, ref):
    """Signed volume by tetrahedra from ref, and by the divergence theorem with the fields
    (x, 0, 0), (0, y, 0), (0, 0, z) (each exact for a closed polyhedron)."""
    det_terms, comp = [], ([], [], [])
    for t in tris:
        a, b, c = (sub(verts[k], ref) for k in t)
        det_terms.append(dot(a, cross(b, c)) / 6.0)
        n = cross(sub(b, a), sub(c, a))  # twice the area times the unit normal
        for d in range(3):
            comp[d].append(n[d] * (a[d] + b[d] + c[d]) / 6.0)
    return math.fsum(det_terms), tuple(math.fsum(x) for x in comp)


def rel(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def expectations(ns):
    """What a shipped shape must be, from its parameters alone."""
    s = ns.shape
    e = {}
    if s in ("box", "tilted-box"):
        v = (ns.hi[0] - ns.lo[0]) * (ns.hi[1] - ns.lo[1]) * (ns.hi[2] - ns.lo[2])
        e.update(closed=True, triangles=12, volume=-v if ns.inward else v, vtol=1e-12,
                 what="analytic")
    elif s == "cylinder":
        n = ns.segments
        v = 0.5 * n * ns.radius ** 2 * math.sin(2 * math.pi / n) * ns.height
        e.update(closed=True, triangles=4 * n, volume=v, vtol=1e-12, what="polyhedral",
                 smooth=math.pi * ns.radius ** 2 * ns.height)
    elif s == "sphere":
        kind, k, st, sl = sphere_choice(ns)
        e.update(closed=True, triangles=20 * 4 ** k if kind == "ico" else 2 * sl * (st - 1),
                 sphere=(tuple(ns.centre), ns.radius), smooth=4 / 3 * math.pi * ns.radius ** 3,
                 euler=2)
    elif s == "ramp":
        h = ramp_height(ns.length, ns.height, ns.angle)
        e.update(closed=True, triangles=8, volume=0.5 * ns.length * ns.width * h, vtol=1e-12,
                 what="analytic")
    elif s == "plane":
        n1, n2 = ns.divisions[0], ns.divisions[-1]
        nrm = cross(ns.edge1, ns.edge2)
        e.update(closed=False, triangles=2 * n1 * n2, area=norm(nrm), normal=unit(nrm),
                 boundary=2 * (n1 + n2))
    if s in ("box", "tilted-box", "cylinder", "ramp"):
        e["euler"] = 2
    return e


def check_mesh(path, expect, fresh):
    msgs, ok = [], True
    verts, tris, normals, kind, header = read_mesh(path)
    closed, oriented, nedges, boundary, problems = edge_report(tris)
    msgs.append("%s, %d triangles, %d vertices" % (kind, len(tris), len(verts)))
    if not header.strip():
        ok = False
        msgs.append("FAIL no header text")
    if problems:
        ok = False
        msgs.append("FAIL " + "; ".join(problems))
    if expect.get("triangles") is not None and expect["triangles"] != len(tris):
        ok = False
        msgs.append("FAIL expected %d triangles" % expect["triangles"])
    want_closed = expect.get("closed", closed)
    if want_closed and not closed:
        ok = False
        msgs.append("FAIL not closed: %d boundary edges" % boundary)
    elif closed:
        msgs.append("closed: each of %d edges used exactly twice, in opposite directions"
                    % nedges)
        chi = len(verts) - nedges + len(tris)
        if "euler" in expect and chi != expect["euler"]:
            ok = False
            msgs.append("FAIL Euler characteristic %d" % chi)
        lo = [min(v[d] for v in verts) for d in range(3)]
        hi = [max(v[d] for v in verts) for d in range(3)]
        ref = tuple(0.5 * (lo[d] + hi[d]) for d in range(3))
        vol, by_axis = volumes(verts, tris, ref)
        spread = max(rel(x, vol) for x in by_axis)
        msgs.append("signed volume %s (three divergence forms agree to %.1e)" % (num(vol),
                                                                                spread))
        if spread > 1e-12:
            ok = False
            msgs.append("FAIL volume forms disagree")
        if "volume" in expect:
            err = rel(vol, expect["volume"])
            tol = expect["vtol"] if kind != "stl-binary" else 1e-6
            msgs.append("%s volume %s, relative error %.1e" % (expect["what"],
                                                               num(expect["volume"]), err))
            if err > tol:
                ok = False
                msgs.append("FAIL volume off by more than %g" % tol)
        elif re.search(r"normals in\b|inward", header):
            msgs.append("the header says normals inward: volume %s" %
                        ("negative, as it should be" if vol < 0 else "NOT negative"))
            ok = ok and vol < 0
        elif vol <= 0:
            ok = False
            msgs.append("FAIL signed volume not positive (normals not outward)")
        if "sphere" in expect:
            c, r = expect["sphere"]
            dev = max(abs(norm(sub(v, c)) - r) / r for v in verts)
            msgs.append("vertices on the sphere to %.1e" % dev)
            if dev > 1e-12 or not 0 < vol < expect["smooth"]:
                ok = False
                msgs.append("FAIL vertices off the sphere or volume out of (0, sphere)")
        if "smooth" in expect:
            msgs.append("%.6f of the smooth shape's volume" % (vol / expect["smooth"]))
    else:
        msgs.append("open: %d boundary edges, %d edges, orientation %s"
                    % (boundary, nedges, "consistent" if oriented else "INCONSISTENT"))
        if "boundary" in expect and boundary != expect["boundary"]:
            ok = False
            msgs.append("FAIL expected %d boundary edges" % expect["boundary"])
        if "area" in expect:
            area = math.fsum(norm(cross(sub(verts[t[1]], verts[t[0]]),
                                        sub(verts[t[2]], verts[t[0]]))) / 2 for t in tris)
            dev = max(norm(sub(unit_normal(*(verts[k] for k in t)), expect["normal"]))
                      for t in tris)
            msgs.append("area %s (expected %s), normals along edge1 x edge2 to %.1e"
                        % (num(area), num(expect["area"]), dev))
            if rel(area, expect["area"]) > 1e-12 or dev > 1e-12:
                ok = False
                msgs.append("FAIL area or normals")
    if normals is not None:
        dev = 0.0
        for t, n in zip(tris, normals):
            dev = max(dev, norm(sub(n, unit_normal(*(verts[k] for k in t)))))
        tol = 1e-6 if kind == "stl-binary" else 1e-14
        msgs.append("stored facet normals = normalised right-hand normals to %.1e" % dev)
        if dev > tol:
            ok = False
            msgs.append("FAIL facet normals")
    same = matches_fresh(path, fresh, msgs)
    return ok and same, msgs


def matches_fresh(path, fresh, msgs):
    """True unless `fresh` (bytes of a new generation) is given and the file differs."""
    if fresh is None:
        return True
    same = Path(path).read_bytes() == fresh
    msgs.append("bytes match a fresh generation" if same else
                "FAIL bytes differ from a fresh generation")
    return same


def read_vertex_rows(path):
    """Rows as sluice reads them: '#' lines and blank lines skipped, two numbers a line."""
    text = Path(path).read_text("ascii")
    first = text.split("\n", 1)[0]
    pts = []
    for number, line in enumerate(text.split("\n"), 1):
        w = line.replace(",", " ").split()
        if not w or w[0].startswith("#"):
            continue
        if len(w) != 2:
            raise MeshError("line %d: expected two numbers \"x, y\"" % number)
        x, y = float(w[0]), float(w[1])
        if not (math.isfinite(x) and math.isfinite(y)):
            raise MeshError("line %d: not a finite number" % number)
        pts.append((x, y))
    return first, pts


def check_vertex_file(path, ns, fresh):
    msgs, ok = [], True
    first, pts = read_vertex_rows(path)
    msgs.append("2-D vertex file, %d vertices, %d segments" % (len(pts), len(pts) - 1))
    if not first.startswith("#"):
        ok = False
        msgs.append("FAIL no '#' header line")
    segs = list(zip(pts[:-1], pts[1:]))
    if any(a == b for a, b in segs):
        ok = False
        msgs.append("FAIL a zero-length segment")
    up = all((a[0] - b[0]) > 0 for a, b in segs)  # normal (dy, -dx): up when dx < 0
    msgs.append("every segment's normal (dy, -dx) points up" if up else
                "segment normals do not all point up")
    if len(pts) > 3 and pts[0] == pts[-1]:
        area = 0.5 * math.fsum(a[0] * b[1] - b[0] * a[1] for a, b in segs)
        msgs.append("closed polygon, signed area %s: %s" % (
            num(area), "counter-clockwise, normals outward" if area > 0 else
            "clockwise, normals inward"))
    if ns is not None:
        want = [(x, y) for x, y, _ in make_polyline(ns).vertices]
        if want != pts:
            ok = False
            msgs.append("FAIL vertices differ from the parameters")
        else:
            msgs.append("vertices equal the parameters' exactly")
        if (ns.ramp is not None or ns.sill is not None) and not up:
            ok = False
            msgs.append("FAIL a bed's normals must point up")
    same = matches_fresh(path, fresh, msgs)
    return ok and same, msgs


def check_dir(directory):
    directory = Path(directory)
    if not directory.is_dir():
        raise MeshError("no folder " + str(directory))
    shipped = {e["file"]: e for e in SHIPPED}
    files = sorted(p for p in directory.iterdir()
                   if p.is_file() and p.suffix.lower() in MESH_EXTS + VERTEX_EXTS)
    if not files:
        raise MeshError("no mesh or vertex file in " + str(directory))
    failures = 0
    for p in files:
        entry = shipped.get(p.name)
        ns = shipped_namespace(entry, p) if entry else None
        fresh = generate(ns, shipped_record(entry))[0] if ns else None
        try:
            if p.suffix.lower() in MESH_EXTS:
                ok, msgs = check_mesh(p, expectations(ns) if ns else {}, fresh)
            else:
                ok, msgs = check_vertex_file(p, ns, fresh)
        except (MeshError, ValueError, IndexError, UnicodeDecodeError, struct.error) as err:
            ok, msgs = False, ["FAIL cannot read: %s" % err]
        failures += not ok
        print("%s %s%s" % ("ok  " if ok else "FAIL", p.name, "" if entry else " (not shipped)"))
        for m in msgs:
            print("       " + m)
    # A folder holding any shipped file must hold them all.
    present = [f for f in shipped if (directory / f).exists()]
    missing = [f for f in shipped if present and f not in present]
    for f in missing:
        print("FAIL %s missing" % f)
    failures += len(missing)
    print("%d files checked, %d failed" % (len(files), failures))
    return failures == 0


def main(argv=None):
    parser = build_parser()
    ns = parser.parse_args(argv)
    try:
        if ns.check is not None:
            if ns.shape or ns.out_dir:
                parser.error("--check takes no shape and no --out")
            return 0 if check_dir(ns.check) else 1
        if ns.shape is None:
            write_all(ns.out_dir or DEFAULT_OUT)
            return 0
        if ns.out_dir:
            parser.error("give --out after the shape (the file to write)")
        data, _ = generate(ns)
        Path(ns.out_file).parent.mkdir(parents=True, exist_ok=True)
        Path(ns.out_file).write_bytes(data)
        print("wrote %s (%d bytes)" % (ns.out_file, len(data)))
        return 0
    except MeshError as err:
        print("make_meshes.py: error: %s" % err, file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
