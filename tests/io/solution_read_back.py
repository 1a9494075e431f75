"""solution.h5 and solution.xdmf of `stcontact solve` read back by readers that share no code with
the writer.

Usage: solution_read_back.py STCONTACT SCENES_DIR WORK_DIR   (ctest: cli.solution_read_back; exit
77, a skip, when python3-meshio or python3-h5py is missing).

Small 2D and 3D solves (fas-apriori, whose frames come from its own displacement, and incremental)
write solution.h5 with contact.csv beside it. meshio's XDMF time-series reader (the reader of
ParaView's format in Debian's python3-meshio) reads every frame the XDMF file lists: the mesh, the
displacement, the contact force and state, the stress in VTK's order XX, YY, ZZ, XY, YZ, XZ, checked
against Hooke's law from the frame's own displacement (tests/io/vtu_read_back.py's formulas) and
von Mises. h5py reads the interface histories, which must equal contact.csv's columns (written with
12 significant digits), and the reactions, equal to reactions.csv's.
"""

import csv
import json
import subprocess
import sys
from pathlib import Path

import numpy as np

try:
    import h5py
    import meshio
    from meshio.xdmf import TimeSeriesReader
except ImportError:
    print("python3-meshio or python3-h5py is not installed (apt-get install -y python3-meshio python3-h5py): skipped")
    sys.exit(77)

sys.path.insert(0, str(Path(__file__).resolve().parent))
from vtu_read_back import check_stress  # noqa: E402  (Hooke's law, the components told apart)

CSV_DIGITS = 1e-11  # contact.csv's 12 significant digits, relative to each column's largest value


def solve(cli, scene, out, solver, *sets):
    args = [cli, "solve", str(scene), "--solver", solver, "--quiet", "--no-reference", "--out", str(out),
            "--set", 'output.contact_csv="always"']
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True)
    return json.loads((out / "summary.json").read_text())


def check_frames(out, parameters, dimension, label):
    """Every frame of solution.xdmf through meshio's time-series reader."""
    with TimeSeriesReader(out / "solution.xdmf") as reader:
        points, cells = reader.read_points_cells()
        cell_type = "triangle" if dimension == 2 else "tetra"
        assert [block.type for block in cells] == [cell_type], cells
        assert points.shape[1] == 3
        times = []
        for k in range(reader.num_steps):
            t, point_data, cell_data = reader.read_data(k)
            times.append(t)
            assert {"displacement", "contact_force", "contact_state"} <= set(point_data), point_data.keys()
            assert {"stress", "von_mises"} <= set(cell_data), cell_data.keys()
            assert point_data["displacement"].shape == (len(points), 3)
            state = point_data["contact_state"].reshape(-1)
            assert set(np.unique(state)) <= {-1, 0, 1, 2} and -1 in state, np.unique(state)
            if k == 0:
                continue  # nothing touches yet
            mesh = meshio.Mesh(points, cells, point_data=point_data, cell_data=cell_data)
            check_stress(mesh, parameters, dimension, "%s frame %d" % (label, k))
    with h5py.File(out / "solution.h5", "r") as f:
        steps = f["frames/steps"][()]
        assert np.array_equal(f["frames/time"][()], f["time"][()][steps])
        assert np.allclose(times, f["frames/time"][()], rtol=1e-15), (times, f["frames/time"][()])
    print("%s: %d frames read by meshio's XDMF time-series reader" % (label, len(times)))


def columns(path):
    with open(path, newline="") as handle:
        rows = list(csv.DictReader(handle))
    return {name: [row[name] for row in rows] for name in rows[0]}


def close(written, expected, label):
    written, expected = np.asarray(written, float), np.asarray(expected, float)
    scale = max(np.abs(expected).max(), 1e-300)
    error = np.abs(written - expected).max() / scale
    assert error <= CSV_DIGITS, "%s differs from the CSV by %.3g (relative)" % (label, error)


def check_histories(out, dimension, label):
    """The interface histories of solution.h5 against contact.csv, the reactions against reactions.csv."""
    table = columns(out / "contact.csv")
    with h5py.File(out / "solution.h5", "r") as f:
        force, gap, slip, state = (f["interface/" + name][()] for name in ("force", "gap", "slip", "state"))
        tributary, nodes, time = f["contact/tributary"][()], f["contact/node_tags"][()], f["time"][()]
        assert np.array_equal(f["mesh/node_tags"][()][f["contact/nodes"][()]], nodes), label
        m, n = gap.shape
        assert force.shape == (m, n, dimension) and slip.shape == (m, n, dimension - 1), (force.shape, slip.shape)
        assert len(table["step"]) == m * n
        close(np.repeat(time, n), table["t"], label + " t")
        assert np.array_equal(np.tile(nodes, m), np.asarray(table["node"], int)), label
        tangential = ["tangential_force"] + (["tangential_force_2"] if dimension == 3 else [])
        for a, name in enumerate(["normal_force"] + tangential):
            close(force[:, :, a].reshape(-1), table[name], label + " " + name)
        close((force[:, :, 0] / tributary).reshape(-1), table["pressure"], label + " pressure")
        for a, name in enumerate(["shear", "shear_2"][: dimension - 1]):
            close((force[:, :, a + 1] / tributary).reshape(-1), table[name], label + " " + name)
            close(slip[:, :, a].reshape(-1), table[["slip", "slip_2"][a]], label + " slip")
        close(gap.reshape(-1), table["gap"], label + " gap")
        names = np.array(["open", "stick", "slip"])
        assert np.array_equal(names[state.reshape(-1)], np.array(table["state"])), label + " state"
        assert not slip[state == 0].any(), label + ": slip where open"
        reactions = columns(out / "reactions.csv")
        close(f["reactions/normal_force"][()], reactions["normal_force"], label + " reactions")
        close(f["reactions/force"][()][:, 0], reactions["force_x"], label + " reactions force_x")
        assert f.attrs["format"] == "stcontact solution" and f.attrs["n_steps"] == m
        assert len(f["history/iteration"][()]) == len(columns(out / "history.csv")["iteration"])
    print("%s: interface histories (%d instants x %d nodes) equal contact.csv" % (label, m, n))


def check_case(cli, scene, work, name, dimension, solver, sets):
    out = work / name
    summary = solve(cli, scene, out, solver, *sets)
    if solver != "incremental":
        assert summary["writer_sparse_solves"] == 0, summary["writer_sparse_solves"]
    check_frames(out, summary["parameters"], dimension, name)
    check_histories(out, dimension, name)


def main():
    cli, scenes, work = sys.argv[1], Path(sys.argv[2]), Path(sys.argv[3])
    work.mkdir(parents=True, exist_ok=True)
    small_2d = ["mesh.arc_nodes=21", "time.steps=21", "output.frame_stride=10", 'output.field_precision="float64"']
    check_case(cli, scenes / "hemicylinder.toml", work, "plane_fas_apriori", 2, "fas-apriori", small_2d)
    check_case(cli, scenes / "hemicylinder.toml", work, "plane_incremental", 2, "incremental", small_2d)
    small_3d = ["mesh.divisions=4", "time.steps=11", "output.frame_stride=5", 'output.field_precision="float64"']
    check_case(cli, scenes / "hemisphere.toml", work, "hemisphere", 3, "incremental", small_3d)
    print("solution.h5 and solution.xdmf read back")


if __name__ == "__main__":
    main()
