"""stcontact.load_run: a run folder written by `stcontact solve` (or solve(..., out=...)) read back
as NumPy arrays (docs/interface.md, "solution.h5 and solution.xdmf"; docs/python.md)."""

import json
from pathlib import Path

import numpy as np

STATES = ("open", "stick", "slip")  # the codes of `state`: 0, 1, 2


class Run:
    """A run folder read back. Arrays per instant and contact node are (m, n_C[, components]):

    time (m,); points (n, 3), cells (n_e, d + 1) 0-based, node_body, cell_body, node_tags (the mesh
    file's node numbers, Gmsh's tags; from 1 for a generated mesh); contact_nodes (n_C,) the rows of
    points of the interface's nodes, contact_node_tags their tags, tributary (n_C,); force (m, n_C, d): normal, then tangential
    along tau_1 (and tau_2); pressure (m, n_C) and shear (m, n_C, d - 1): force over tributary;
    gap (m, n_C); slip (m, n_C, d - 1), 0 where open; state (m, n_C): 0 open, 1 stick, 2 slip.
    reactions and history: dicts of columns (reactions.csv's and history.csv's); summary: summary.json.
    frame_steps, frame_times: the instants with fields; frame(k) the fields of instant k as a dict
    (displacement, contact_force, contact_state, stress in VTK's order xx yy zz xy yz xz, von_mises).
    """

    def __init__(self, folder):
        try:
            import h5py
        except ImportError:  # pragma: no cover - the tests install it
            raise ImportError("stcontact.load_run reads solution.h5 with h5py (apt-get install -y python3-h5py)") from None
        self.folder = Path(folder)
        path = self.folder / "solution.h5"
        if not path.is_file():
            raise FileNotFoundError("%s: no solution.h5 (not a run folder, or one of a version before 0.4)" % self.folder)
        self.summary = json.loads((self.folder / "summary.json").read_text())
        self._file = h5py.File(path, "r")
        f = self._file
        self.attributes = dict(f.attrs)
        self.time = f["time"][()]
        self.points, self.cells = f["mesh/points"][()], f["mesh/cells"][()]
        self.node_body, self.cell_body = f["mesh/node_body"][()], f["mesh/cell_body"][()]
        self.contact_nodes, self.tributary = f["contact/nodes"][()], f["contact/tributary"][()]
        self.node_tags, self.contact_node_tags = f["mesh/node_tags"][()], f["contact/node_tags"][()]
        self.force, self.gap = f["interface/force"][()], f["interface/gap"][()]
        self.slip, self.state = f["interface/slip"][()], f["interface/state"][()]
        self.pressure = self.force[:, :, 0] / self.tributary
        self.shear = self.force[:, :, 1:] / self.tributary[None, :, None]
        self.reactions = {name: f["reactions/" + name][()] for name in f["reactions"]}
        self.reactions["t"] = self.time
        self.history = {name: f["history/" + name][()] for name in f["history"]}
        frames = f.get("frames")
        self.frame_steps = frames["steps"][()] if frames is not None else np.zeros(0, int)
        self.frame_times = frames["time"][()] if frames is not None else np.zeros(0)

    def frame(self, k):
        """The fields of instant k (one of frame_steps) as a dict of arrays."""
        name = "frames/step_%05d" % k
        if name not in self._file:
            raise KeyError("instant %d has no frame (frames at %s; output.frame_stride)" % (k, list(self.frame_steps)))
        group = self._file[name]
        return {key: group[key][()] for key in group}

    def close(self):
        self._file.close()

    def __enter__(self):
        return self

    def __exit__(self, *_):
        self.close()


def load_run(folder):
    """The run folder `folder` (solution.h5, summary.json) as a Run of NumPy arrays."""
    return Run(folder)
