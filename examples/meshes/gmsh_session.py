"""What the mesh scripts of this folder share: a Gmsh session that writes MSH 4.1 ASCII with a fixed
seed, and a background size field as the only source of element sizes."""
import gmsh


def use_only_size_field(field: int) -> None:
    """Element sizes from `field` alone (not from the points, the boundary or the curvature)."""
    gmsh.model.mesh.field.setAsBackgroundMesh(field)
    gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
    gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)


def write_mesh(build, dimension: int, out: str) -> None:
    """Runs build() in a fresh Gmsh session, meshes in `dimension` and writes `out` (MSH 4.1 ASCII,
    the physical groups only, Delaunay with seed 1: the same mesh on the same Gmsh version)."""
    gmsh.initialize(["-noenv"])
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setNumber("Mesh.RandomSeed", 1)
        gmsh.option.setNumber("Mesh.MshFileVersion", 4.1)
        gmsh.option.setNumber("Mesh.Binary", 0)
        gmsh.option.setNumber("Mesh.SaveAll", 0)
        build()
        gmsh.model.mesh.generate(dimension)
        gmsh.write(out)
        nodes = len(gmsh.model.mesh.getNodes()[0])
        print(f"{out}: {nodes} nodes")
    finally:
        gmsh.finalize()
