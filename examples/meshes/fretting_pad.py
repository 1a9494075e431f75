#!/usr/bin/env python3
"""A cylindrical pad on a flat specimen, two bodies of one 2D mesh (examples/scenes/fretting_pad.toml).

The pad is the half-disc x² + y² <= R², y <= 0 (R = 1); the specimen the rectangle [-L, L] × [-R - g0 - D,
-R - g0] below it, a gap g0 under the pad's lowest point. Node-to-node contact needs matching interface
meshes: the pad's arc carries nodes at equal angles θ_k = k h / R, |x_k| <= X (its face), and the
specimen's top carries nodes right below them, at x_k = R sin θ_k (its face). Gmsh meshes the rest
with triangles of size h at the faces growing linearly with the distance to them, up to `--far` (Delaunay, fixed seed).

Physical groups: surfaces `pad`, `specimen`; curves `pad_top` (y = 0), `pad_face` (the arc's nodes
|x| <= X), `specimen_face` (the nodes below them), `specimen_bottom`.

Regenerate the committed meshes (Debian 12 package python3-gmsh), from this folder:
    python3 fretting_pad.py --h 0.01 --out fretting_pad.msh
    python3 fretting_pad.py --h 0.02 --out fretting_pad_small.msh
With --specimen-h H the specimen's face has nodes at equal spacing H instead (non-matching meshes, for
contact.pairing = "segment"):
    python3 fretting_pad.py --h 0.02 --specimen-h 0.013 --out fretting_pad_nonmatching_small.msh
The refinement study of docs/two_bodies.md ("Mindlin's loop in 2D") adds --h 0.005 and 0.0025. The
committed meshes were written by Gmsh 4.8; its Delaunay mesher with a fixed seed gives the same mesh
on the same Gmsh version (the faces' nodes, which the pairing needs, on any).
"""
import argparse
import math
import sys

import gmsh

from gmsh_session import use_only_size_field, write_mesh


def face_points(geo, n: int, h: float, radius: float, y) -> list:
    """Points k = -n … n of a face: x_k = R sin(k h / R), at height y(x) (the arc or the flat)."""
    tags = []
    for k in range(-n, n + 1):
        x = radius * math.sin(k * h / radius)
        tags.append(geo.addPoint(x, y(k * h / radius), 0.0))
    return tags


def polyline(geo, points: list) -> list:
    """One straight line per pair of consecutive points, each to be meshed as a single element."""
    return [geo.addLine(a, b) for a, b in zip(points[:-1], points[1:])]


def build(h: float, far: float, grow: float, half_width: float, radius: float, gap: float, length: float, depth: float,
          specimen_h: float) -> None:
    gmsh.model.add("fretting_pad")
    geo = gmsh.model.geo
    n = math.ceil(math.asin(min(half_width / radius, 1.0)) * radius / h)
    if n * h / radius >= math.pi / 2 or radius * math.sin(n * h / radius) >= length:
        raise RuntimeError("the face must stay below the pad's equator and inside the specimen")
    # The pad, counter-clockwise: its face (left to right), the arc up to (R, 0), the top, the arc down.
    centre = geo.addPoint(0.0, 0.0, 0.0)
    pad_face = face_points(geo, n, h, radius, lambda t: -radius * math.cos(t))
    right, left = geo.addPoint(radius, 0.0, 0.0), geo.addPoint(-radius, 0.0, 0.0)
    pad_face_lines = polyline(geo, pad_face)
    pad_right = geo.addCircleArc(pad_face[-1], centre, right)
    pad_top = geo.addLine(right, left)
    pad_left = geo.addCircleArc(left, centre, pad_face[0])
    pad = geo.addPlaneSurface([geo.addCurveLoop(pad_face_lines + [pad_right, pad_top, pad_left])])
    # The specimen, counter-clockwise: bottom, right side, its top from the right (face reversed), left side.
    top = -radius - gap
    if specimen_h > 0:  # non-matching: equal spacing, one node beyond the pad's face on each side
        count = math.ceil(radius * math.sin(n * h / radius) / specimen_h) + 1
        specimen_face = [geo.addPoint(k * specimen_h, top, 0.0) for k in range(-count, count + 1)]
    else:
        specimen_face = face_points(geo, n, h, radius, lambda t: top)
    corners = [geo.addPoint(x, y, 0.0) for x, y in ((-length, top - depth), (length, top - depth), (length, top), (-length, top))]
    bottom = geo.addLine(corners[0], corners[1])
    right_side = geo.addLine(corners[1], corners[2])
    top_right = geo.addLine(corners[2], specimen_face[-1])
    specimen_face_lines = polyline(geo, specimen_face[::-1])
    top_left = geo.addLine(specimen_face[0], corners[3])
    left_side = geo.addLine(corners[3], corners[0])
    loop = [bottom, right_side, top_right] + specimen_face_lines + [top_left, left_side]
    specimen = geo.addPlaneSurface([geo.addCurveLoop(loop)])
    geo.synchronize()
    for line in pad_face_lines + specimen_face_lines:
        gmsh.model.mesh.setTransfiniteCurve(line, 2)  # the face's nodes are the points, nothing between
    for dim, tags, name in ((2, [pad], "pad"), (2, [specimen], "specimen"), (1, [pad_top], "pad_top"),
                            (1, pad_face_lines, "pad_face"), (1, specimen_face_lines, "specimen_face"),
                            (1, [bottom], "specimen_bottom")):
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    # Size h(d) = min(h + grow d, far), d the distance to the faces.
    distance = gmsh.model.mesh.field.add("Distance")
    gmsh.model.mesh.field.setNumbers(distance, "CurvesList", pad_face_lines + specimen_face_lines)
    size = gmsh.model.mesh.field.add("MathEval")
    gmsh.model.mesh.field.setString(size, "F", f"Min({h!r} + {grow!r} * F{distance}, {far!r})")
    use_only_size_field(size)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--h", type=float, default=0.01, help="node spacing on the faces")
    parser.add_argument("--far", type=float, default=0.25, help="element size far from the contact")
    parser.add_argument("--grow", type=float, default=0.3, help="growth of the element size with the distance")
    parser.add_argument("--face", type=float, default=0.3, help="half-width X of the faces")
    parser.add_argument("--radius", type=float, default=1.0, help="the pad's radius R")
    parser.add_argument("--gap", type=float, default=0.005, help="g0, between the pad and the specimen")
    parser.add_argument("--length", type=float, default=3.0, help="the specimen's half-width L")
    parser.add_argument("--depth", type=float, default=2.0, help="the specimen's depth D")
    parser.add_argument("--specimen-h", type=float, default=0.0,
                        help="node spacing on the specimen's face (0: the pad's nodes, matching)")
    parser.add_argument("--out", required=True, help="the .msh file to write (MSH 4.1 ASCII)")
    args = parser.parse_args()
    if not 0 < args.h <= args.far or args.grow <= 0 or args.specimen_h < 0 or min(args.face, args.radius, args.length, args.depth) <= 0 or args.gap < 0:
        parser.error("needs 0 < h <= far, positive face, radius, length and depth, gap >= 0")
    write_mesh(lambda: build(args.h, args.far, args.grow, args.face, args.radius, args.gap, args.length, args.depth,
                             args.specimen_h), 2, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
