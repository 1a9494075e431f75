"""The .vtu frames of `stcontact solve` read back by readers that share no code with the writer.

Usage: vtu_read_back.py STCONTACT SCENES_DIR WORK_DIR   (ctest: cli.vtu_frames_read_back; exit 77, a
skip, when python3-meshio is missing).

Small 2D (plane strain and plane stress) and 3D solves are written in Float64 and Float32. Each
frame is read with meshio (arrays, types, values) and its XML header with xml.etree (component
names, active tensors), and python3-vtk9's vtkXMLUnstructuredGridReader when it is installed. The
stress of every element is recomputed here from the frame's own points and displacement with
Hooke's law (E, nu and the plane model from summary.json's parameters) and compared, in VTK's order
XX, YY, ZZ, XY, YZ, XZ, with the frame's `stress`; the components are checked distinct, so that a
swapped pair cannot pass. The Float32 frames must hold the Float64 values rounded to float.
"""

import json
import subprocess
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import numpy as np

try:
    import meshio
except ImportError:
    print("python3-meshio is not installed (apt-get install -y python3-meshio): skipped")
    sys.exit(77)

VECTOR_NAMES = ["X", "Y", "Z"]
TENSOR_NAMES = ["XX", "YY", "ZZ", "XY", "YZ", "XZ"]  # vtkMath::TensorFromSymmetricTensor's order
STATE_CODES = {-1, 0, 1, 2}  # not a contact node, open, stick, slip


def solve(cli, scene, out, *sets):
    args = [cli, "solve", str(scene), "--solver", "incremental", "--quiet", "--out", str(out),
            "--set", 'output.format="vtu"']
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True)
    return json.loads((out / "summary.json").read_text())["parameters"]


def frames(out):
    """The frame files the collection lists, in order."""
    root = ElementTree.parse(out / "solution.pvd").getroot()
    files = [out / d.get("file") for d in root.iter("DataSet")]
    assert files and all(f.is_file() for f in files), files
    return files


def xml_header(path):
    """The document without its appended bytes: the XML up to <AppendedData ...> and from its end."""
    raw = path.read_bytes()
    start = raw.index(b"<AppendedData")
    opening_end = raw.index(b">", start) + 1
    closing = raw.rindex(b"</AppendedData>")
    return ElementTree.fromstring(raw[:opening_end] + raw[closing:])


def block_counts(path):
    """The number of zlib blocks of each array: the first UInt64 word of its data."""
    raw = path.read_bytes()
    data = raw.index(b"_", raw.index(b"<AppendedData")) + 1
    arrays = xml_header(path).iter("DataArray")
    return {a.get("Name"): int.from_bytes(raw[data + int(a.get("offset")):][:8], "little") for a in arrays}


def data_array(header, section, name):
    for array in header.find("UnstructuredGrid/Piece/" + section).iter("DataArray"):
        if array.get("Name") == name:
            return array
    raise AssertionError("no DataArray %s in %s" % (name, section))


def check_header(path, precision):
    header = xml_header(path)
    assert header.get("header_type") == "UInt64" and header.get("compressor") == "vtkZLibDataCompressor"
    piece = header.find("UnstructuredGrid/Piece")
    assert piece.find("PointData").get("Vectors") == "displacement"
    assert piece.find("CellData").get("Tensors") == "stress"
    for name in ("displacement", "contact_force"):
        array = data_array(header, "PointData", name)
        assert array.get("NumberOfComponents") == "3", name
        assert [array.get("ComponentName%d" % i) for i in range(3)] == VECTOR_NAMES, name
        assert array.get("type") == precision, name
    stress = data_array(header, "CellData", "stress")
    assert stress.get("NumberOfComponents") == "6"
    assert [stress.get("ComponentName%d" % i) for i in range(6)] == TENSOR_NAMES
    assert data_array(header, "PointData", "contact_state").get("type") == "Int8"
    assert data_array(header, "Points", "Points").get("type") == precision
    types = {a.get("Name"): a.get("type") for a in piece.find("Cells").iter("DataArray")}
    assert types == {"connectivity": "Int32", "offsets": "Int32", "types": "UInt8"}, types


def read(path, dimension):
    mesh = meshio.read(path)
    assert set(mesh.point_data) == {"displacement", "contact_force", "contact_state"}, mesh.point_data.keys()
    assert set(mesh.cell_data) == {"stress", "von_mises"}, mesh.cell_data.keys()
    cell_type = "triangle" if dimension == 2 else "tetra"
    assert [block.type for block in mesh.cells] == [cell_type]
    n, e = len(mesh.points), len(mesh.cells[0].data)
    assert mesh.point_data["displacement"].shape == (n, 3)
    assert mesh.point_data["contact_force"].shape == (n, 3)
    state = mesh.point_data["contact_state"].reshape(-1)
    assert state.dtype == np.int8 and state.shape == (n,), state.dtype
    assert set(np.unique(state)) <= STATE_CODES and -1 in state and (state >= 0).any()
    assert mesh.cell_data["stress"][0].shape == (e, 6)
    assert mesh.cell_data["von_mises"][0].reshape(-1).shape == (e,)
    if dimension == 2:
        assert not mesh.points[:, 2].any() and not mesh.point_data["displacement"][:, 2].any()
    return mesh


def lame(parameters):
    young, nu = parameters["material"]["young"], parameters["material"]["poisson"]
    return young * nu / ((1 + nu) * (1 - 2 * nu)), young / (2 * (1 + nu)), young, nu


def stress_2d(mesh, parameters):
    """Constant-strain triangles: sigma in VTK's order, plane strain or plane stress."""
    lam, mu, young, nu = lame(parameters)
    x, u, tri = mesh.points[:, :2], mesh.point_data["displacement"][:, :2], mesh.cells[0].data
    edges = np.stack([x[tri[:, 1]] - x[tri[:, 0]], x[tri[:, 2]] - x[tri[:, 0]]], axis=1)  # e x 2 x 2
    du = np.stack([u[tri[:, 1]] - u[tri[:, 0]], u[tri[:, 2]] - u[tri[:, 0]]], axis=1)
    grad = np.linalg.solve(edges, du).transpose(0, 2, 1)  # grad[e, i, j] = du_i/dx_j
    exx, eyy, gxy = grad[:, 0, 0], grad[:, 1, 1], grad[:, 0, 1] + grad[:, 1, 0]
    if parameters.get("model", {}).get("plane", "strain") == "strain":
        sxx, syy, szz = (lam + 2 * mu) * exx + lam * eyy, lam * exx + (lam + 2 * mu) * eyy, lam * (exx + eyy)
    else:
        c = young / (1 - nu * nu)
        sxx, syy, szz = c * (exx + nu * eyy), c * (nu * exx + eyy), 0 * exx
    zero = 0 * exx
    return np.stack([sxx, syy, szz, mu * gxy, zero, zero], axis=1)


def stress_3d(mesh, parameters):
    """Constant-strain tetrahedra: sigma = lambda tr(eps) I + 2 mu eps in VTK's order."""
    lam, mu, _, _ = lame(parameters)
    x, u, tet = mesh.points, mesh.point_data["displacement"], mesh.cells[0].data
    edges = np.stack([x[tet[:, k]] - x[tet[:, 0]] for k in (1, 2, 3)], axis=1)  # e x 3 x 3
    du = np.stack([u[tet[:, k]] - u[tet[:, 0]] for k in (1, 2, 3)], axis=1)
    grad = np.linalg.solve(edges, du).transpose(0, 2, 1)
    eps = 0.5 * (grad + grad.transpose(0, 2, 1))
    trace = np.trace(eps, axis1=1, axis2=2)
    sigma = 2 * mu * eps + lam * trace[:, None, None] * np.eye(3)
    return np.stack([sigma[:, 0, 0], sigma[:, 1, 1], sigma[:, 2, 2], sigma[:, 0, 1], sigma[:, 1, 2],
                     sigma[:, 0, 2]], axis=1)


def von_mises(s):
    xx, yy, zz, xy, yz, xz = s.T
    return np.sqrt(0.5 * ((xx - yy) ** 2 + (yy - zz) ** 2 + (zz - xx) ** 2) + 3 * (xy ** 2 + yz ** 2 + xz ** 2))


def check_stress(mesh, parameters, dimension, label):
    written = mesh.cell_data["stress"][0]
    computed = stress_2d(mesh, parameters) if dimension == 2 else stress_3d(mesh, parameters)
    scale = np.abs(computed).max()
    assert scale > 0, label
    error = np.abs(written - computed).max() / scale
    assert error < 1e-9, "%s: stress differs from Hooke's law by %.3g (relative)" % (label, error)
    vm = mesh.cell_data["von_mises"][0].reshape(-1)
    assert np.abs(vm - von_mises(computed)).max() < 1e-9 * scale, label
    # Distinct components: a permutation of the written columns would not match.
    pairs = [(0, 1), (0, 2), (1, 2), (2, 3)] + ([(3, 4), (3, 5), (4, 5)] if dimension == 3 else [])
    for i, j in pairs:
        gap = np.abs(computed[:, i] - computed[:, j]).max()
        assert gap > 1e-3 * scale, "%s: %s and %s too close to tell apart" % (label, TENSOR_NAMES[i], TENSOR_NAMES[j])
    if dimension == 2:
        assert not written[:, 4:].any(), label  # yz = xz = 0
    print("%s: stress of %d elements in VTK order, largest relative difference %.2g" % (label, len(written), error))


def check_rounding(exact, rounded, label):
    """The Float32 frame holds the Float64 frame's values rounded to float."""
    assert rounded.points.dtype == np.float32
    assert np.array_equal(rounded.points, exact.points.astype(np.float32)), label
    assert np.array_equal(rounded.cells[0].data, exact.cells[0].data), label
    for name, values in exact.point_data.items():
        expected = values if values.dtype == np.int8 else values.astype(np.float32)
        assert rounded.point_data[name].dtype == expected.dtype, (label, name)
        assert np.array_equal(rounded.point_data[name], expected), (label, name)
    for name, values in exact.cell_data.items():
        assert np.array_equal(rounded.cell_data[name][0], values[0].astype(np.float32)), (label, name)
    print("%s: Float32 frame = Float64 frame rounded to float" % label)


def check_with_vtk(path, mesh, dimension, label):
    try:
        from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader
        from vtkmodules.util.numpy_support import vtk_to_numpy
    except ImportError:
        print("%s: python3-vtk9 not installed, VTK's own reader not tried" % label)
        return
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    assert grid.GetNumberOfCells() == len(mesh.cells[0].data), label
    cells = grid.GetCellData()
    assert cells.GetTensors() is not None and cells.GetTensors().GetName() == "stress", label
    stress = cells.GetArray("stress")
    assert [stress.GetComponentName(i) for i in range(6)] == TENSOR_NAMES, label
    assert np.array_equal(vtk_to_numpy(stress), mesh.cell_data["stress"][0]), label
    points = grid.GetPointData()
    assert [points.GetArray("displacement").GetComponentName(i) for i in range(3)] == VECTOR_NAMES, label
    state = points.GetArray("contact_state")
    assert state.GetDataTypeAsString() == "signed char", state.GetDataTypeAsString()
    assert np.array_equal(vtk_to_numpy(state), mesh.point_data["contact_state"].reshape(-1)), label
    print("%s: VTK's reader agrees (component names, tensors, Int8 states)" % label)


def check_case(cli, scene, work, name, dimension, sets):
    exact_dir, rounded_dir = work / (name + "_float64"), work / (name + "_float32")
    parameters = solve(cli, scene, exact_dir, *sets, "output.field_precision=float64")
    solve(cli, scene, rounded_dir, *sets)
    exact_files, rounded_files = frames(exact_dir), frames(rounded_dir)
    assert [f.name for f in exact_files] == [f.name for f in rounded_files]
    for exact_file, rounded_file in zip(exact_files[1:], rounded_files[1:]):  # frame 0: nothing touches yet
        label = "%s %s" % (name, exact_file.name)
        check_header(exact_file, "Float64")
        check_header(rounded_file, "Float32")
        exact, rounded = read(exact_file, dimension), read(rounded_file, dimension)
        check_stress(exact, parameters, dimension, label)
        check_rounding(exact, rounded, label)
        check_with_vtk(rounded_file, rounded, dimension, label)
    blocks = block_counts(exact_files[-1])
    if dimension == 3:  # the stress spans several 32 KiB blocks, the last one partial
        assert blocks["stress"] >= 2, blocks


def main():
    cli, scenes, work = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    work.mkdir(parents=True, exist_ok=True)
    small_2d = ["mesh.arc_nodes=21", "time.steps=21", "output.frame_stride=10"]
    check_case(cli, scenes / "hemicylinder.toml", work, "plane_strain", 2, small_2d)
    check_case(cli, scenes / "hemicylinder.toml", work, "plane_stress", 2, small_2d + ["model.plane=stress"])
    small_3d = ["mesh.divisions=4", "time.steps=11", "output.frame_stride=5"]
    check_case(cli, scenes / "hemisphere.toml", work, "hemisphere", 3, small_3d)
    print("every frame read back")


if __name__ == "__main__":
    main()
