#!/usr/bin/env python3
"""A spherical cap as a rigid surface (3D, obstacle.type = "surface"; examples/scenes/on_sphere_surface.toml).

The sphere of radius R centred at (0, 0, -R - 1 - g0) (its top g0 below the pole (0, 0, -1) of the
hemisphere scenes) cut at `--depth` below its top, meshed by Gmsh with triangles of size `--h`: the
rigid sphere of examples/scenes/hard/on_sphere.toml given as a triangulated surface. Its physical
surface `cap` carries the triangles; Gmsh orients them outward (the normals point away from the
sphere's centre, toward the body: obstacle.side = "outside").

Regenerate the committed mesh (Debian 12 package python3-gmsh), from this folder:
    python3 sphere_cap.py --h 0.08 --out sphere_cap.msh
"""
import argparse
import sys

import gmsh

from gmsh_session import write_mesh


def build(h: float, radius: float, gap: float, depth: float) -> None:
    gmsh.model.add("sphere_cap")
    occ = gmsh.model.occ
    top = -1.0 - gap
    centre = top - radius
    ball = occ.addSphere(0.0, 0.0, centre, radius)
    below = occ.addBox(-2 * radius, -2 * radius, centre - 2 * radius, 4 * radius, 4 * radius, 2 * radius + radius - depth)
    occ.cut([(3, ball)], [(3, below)])
    occ.synchronize()
    caps = [tag for dim, tag in gmsh.model.getEntities(2) if gmsh.model.getBoundingBox(dim, tag)[5] > top - 1e-6]
    caps = [tag for tag in caps if gmsh.model.getBoundingBox(2, tag)[2] < top - 1e-6]  # the curved face, not the flat cut
    if len(caps) != 1:
        raise RuntimeError(f"expected one curved face, got {caps}")
    gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, caps), "cap")
    gmsh.option.setNumber("Mesh.MeshSizeMin", h)
    gmsh.option.setNumber("Mesh.MeshSizeMax", h)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--h", type=float, default=0.08, help="element size")
    parser.add_argument("--radius", type=float, default=2.0, help="the sphere's radius R")
    parser.add_argument("--gap", type=float, default=0.01, help="g0, below the pole (0, 0, -1)")
    parser.add_argument("--depth", type=float, default=0.25, help="the cap's depth below its top")
    parser.add_argument("--out", required=True, help="the .msh file to write (MSH 4.1 ASCII)")
    args = parser.parse_args()
    if min(args.h, args.radius, args.depth) <= 0 or args.gap < 0 or args.depth >= args.radius:
        parser.error("needs h, radius, depth > 0, gap >= 0, depth < radius")
    write_mesh(lambda: build(args.h, args.radius, args.gap, args.depth), 2, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
