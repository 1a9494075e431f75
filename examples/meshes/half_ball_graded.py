#!/usr/bin/env python3
"""An unstructured, graded half-ball for the hemisphere's loading (examples/scenes/half_ball_graded.toml).

The ball x² + y² + z² <= R², z <= 0 (R = 1), meshed by Gmsh with tetrahedra of size `--pole` at the
pole (0, 0, -R), growing linearly with the distance from it to `--far` at `--reach` and beyond: a mesh
nobody tuned for the solvers, whose contact nodes' tributary areas vary by about (far / pole)². Its
physical surfaces are named as the `half_ball` generator's groups: `top` (the flat face z = 0) and
`contact` (the curved surface).

Regenerate the committed meshes (Debian 12 package python3-gmsh), from this folder:
    python3 half_ball_graded.py --pole 0.03 --far 0.15 --out half_ball_graded.msh
    python3 half_ball_graded.py --pole 0.08 --far 0.3 --out half_ball_graded_small.msh
The committed files hold 1637 and 157 nodes (599 and 89 contact nodes); Debian 12's Gmsh 4.8
makes 1023 and 197 (425 and 108) from the same commands. Gmsh's Delaunay mesher with a fixed seed
gives the same mesh on the same Gmsh version.
"""
import argparse
import sys

import gmsh

from gmsh_session import use_only_size_field, write_mesh


def build(pole: float, far: float, reach: float, radius: float) -> None:
    """The half-ball as an OpenCASCADE solid, its two physical surfaces, and the size field."""
    gmsh.model.add("half_ball_graded")
    occ = gmsh.model.occ
    ball = occ.addSphere(0.0, 0.0, 0.0, radius)
    upper = occ.addBox(-2 * radius, -2 * radius, 0.0, 4 * radius, 4 * radius, 2 * radius)
    occ.cut([(3, ball)], [(3, upper)])
    occ.synchronize()
    volumes = gmsh.model.getEntities(3)
    if len(volumes) != 1:
        raise RuntimeError(f"expected one volume after the cut, got {len(volumes)}")
    top, curved = [], []
    for dim, tag in gmsh.model.getBoundary(volumes, oriented=False):
        _, _, zmin, _, _, zmax = gmsh.model.getBoundingBox(dim, tag)
        (top if abs(zmin) < 1e-5 and abs(zmax) < 1e-5 else curved).append(tag)  # OCC boxes carry a tolerance
    if not top or not curved:
        raise RuntimeError("could not tell the flat face from the curved surface")
    for dim, tags, name in ((3, [volumes[0][1]], "body"), (2, top, "top"), (2, curved, "contact")):
        gmsh.model.setPhysicalName(dim, gmsh.model.addPhysicalGroup(dim, tags), name)
    # Size h(d) = pole + (far - pole) min(d / reach, 1), d the distance to the pole (0, 0, -R).
    size = gmsh.model.mesh.field.add("MathEval")
    d = f"Sqrt(x^2 + y^2 + (z + {radius!r})^2)"
    gmsh.model.mesh.field.setString(size, "F", f"{pole!r} + {far - pole!r} * Min({d} / {reach!r}, 1)")
    use_only_size_field(size)


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pole", type=float, default=0.03, help="element size at the pole")
    parser.add_argument("--far", type=float, default=0.15, help="element size far from it")
    parser.add_argument("--reach", type=float, default=0.6, help="distance over which the size grows")
    parser.add_argument("--radius", type=float, default=1.0)
    parser.add_argument("--out", required=True, help="the .msh file to write (MSH 4.1 ASCII)")
    args = parser.parse_args()
    if not 0 < args.pole <= args.far or args.reach <= 0 or args.radius <= 0:
        parser.error("needs 0 < pole <= far, reach > 0, radius > 0")
    write_mesh(lambda: build(args.pole, args.far, args.reach, args.radius), 3, args.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
