#!/usr/bin/env python3
"""A block on its face: the smallest 3D mesh of one's own (docs/meshing.md; examples/scenes/block.toml).

The box [-a, a] × [-a, a] × [0, c] meshed by Gmsh with tetrahedra of size `--h`, its faces named as
a scene names boundaries: `bottom` (z = 0, the face that may touch), `top` (z = c, driven), `sides`.
The steps any mesh of one's own takes: build the solid, name the groups the scene uses (physical
surfaces in 3D, physical curves in 2D, and the volume or surface of the body), mesh, write MSH 4.1
ASCII (gmsh_session.write_mesh).

Regenerate the committed mesh (Debian 12 package python3-gmsh), from this folder:
    python3 block.py --h 0.1 --out block.msh
"""
import argparse
import sys

import gmsh

from gmsh_session import write_mesh


def build(h: float, half_width: float, height: float) -> None:
    gmsh.model.add("block")
    occ = gmsh.model.occ
    box = occ.addBox(-half_width, -half_width, 0.0, 2 * half_width, 2 * half_width, height)
    occ.synchronize()
    gmsh.model.setPhysicalName(3, gmsh.model.addPhysicalGroup(3, [box]), "block")
    faces = {"bottom": [], "top": [], "sides": []}
    for dim, tag in gmsh.model.getBoundary([(3, box)], oriented=False):
        zmin, zmax = gmsh.model.getBoundingBox(dim, tag)[2::3]  # widened by Gmsh's tolerance, 1e-7
        tolerance = 1e-6 * height
        name = "bottom" if zmax < tolerance else "top" if zmin > height - tolerance else "sides"
        faces[name].append(tag)
    for name, tags in faces.items():
        gmsh.model.setPhysicalName(2, gmsh.model.addPhysicalGroup(2, tags), name)
    gmsh.option.setNumber("Mesh.MeshSizeMin", h)
    gmsh.option.setNumber("Mesh.MeshSizeMax", h)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--h", type=float, default=0.1, help="element size")
    parser.add_argument("--half-width", type=float, default=0.5, help="a: the block spans [-a, a] in x and y")
    parser.add_argument("--height", type=float, default=0.5, help="c: the block spans [0, c] in z")
    parser.add_argument("--out", required=True, help="the .msh file to write (MSH 4.1 ASCII)")
    args = parser.parse_args()
    if min(args.h, args.half_width, args.height) <= 0:
        parser.error("needs h, half-width and height > 0")
    write_mesh(lambda: build(args.h, args.half_width, args.height), 3, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
