"""The result classes of stcontact.solve, stcontact.svd and stcontact.compare (docs/python.md).

Each holds the NumPy arrays the compiled core moved into Python (no copy was made on the way) and
the texts the command line writes, parsed: summary.json as a dict, summary.csv as rows. Each pickles
(a SolveResult's problem as the scene it was assembled from, assembled again on first use).
"""

import csv
import io
import json

import numpy as np


class SolveResult:
    """One solve: the interface histories, the tables of reactions.csv and history.csv, summary.json.

    history: history.csv's columns (iteration, relaxations, indicator, error, rank, wall_s,
    error_estimate) and sparse_solves, one array entry per iteration; error and error_estimate are
    NaN where the file's cell is empty (no reference; an estimate not yet known).

    Interface arrays (the library's layout, NumPy order 'F': column k is instant t_k; d = dimension,
    2 or 3):
      interface_forces         d n_C x m  rows d i: normal force of contact node i, d i + 1: tangential
                                          (along tau_1), d i + 2 (3D): along tau_2
      interface_displacements  d n_C x m  the same rows for the interface displacements v_n, v_t
      normal_forces, tangential_forces, normal_displacements, tangential_displacements
                               n_C x m    views of the rows above (no copy); tangential: along tau_1
      tangential_forces_2, tangential_displacements_2
                               n_C x m    3D only: along tau_2
    contact.csv's columns (n_C x m, the writer's own numbers; 3D adds shear_2, slip_2 along tau_2):
      pressure, shear          the forces over tributary (n_C,: the tributary length, or area in 3D)
      gap                      g0 + v_n
      slip                     v_t(t_k) - v_t(t_{k-1}) where the node is in contact, 0 where open
      state                    0 open, 1 stick, 2 slip
    Node i of the interface is mesh node contact_nodes[i] (a position, from 0), which the mesh file and
    contact.csv call contact_node_tags[i] (Gmsh's node tag; from 1 for a generated mesh); with two bodies (contact.master) it is paired
    with mesh node master_nodes[i] (empty for a rigid obstacle) and its rows are the relative
    displacement u_s - u_m and the force on the slave (its opposite acts on the master).
    A priori strategies (fas-apriori, latin-pgd; no columns for the others):
      spatial_modes            n_free x r  energy modes of the separated expansion, by energy
      interface_directions     d n_C x p   the separated global stage's directions (warm starts)
    """

    def __init__(self, data):
        self.solver = data["solver"]
        self.dimension = data["dimension"]
        self.summary = json.loads(data["summary_json"])
        self.history = data["history"]
        self.reactions = data["reactions"]
        self.times = data["times"]
        self.contact_nodes = data["contact_nodes"]
        self.master_nodes = data["master_nodes"]
        self.interface_forces = data["forces"]
        self.interface_displacements = data["displacements"]
        self.spatial_modes = data["spatial_modes"]
        self.interface_directions = data["interface_directions"]
        self.problem = data["problem"]
        self.contact_node_tags = data["contact"]["node_tags"]
        self.tributary = data["contact"]["tributary"]
        self.gap = data["contact"]["gap"]
        self.state = data["contact"]["state"]
        self._slip = data["contact"]["slip"]

    @property
    def pressure(self):
        """lambda_n over the tributary length or area, n_C x m (contact.csv's pressure)."""
        return self.normal_forces / self.tributary[:, None]

    @property
    def shear(self):
        """lambda_t (along tau_1) over the tributary length or area, n_C x m."""
        return self.tangential_forces / self.tributary[:, None]

    @property
    def shear_2(self):
        """3D: lambda_t along tau_2 over the tributary area, n_C x m."""
        return self.tangential_forces_2 / self.tributary[:, None]

    @property
    def slip(self):
        """The slip along tau_1 (0 where open), n_C x m."""
        return self._slip[0::self.dimension - 1]

    @property
    def slip_2(self):
        """3D: the slip along tau_2, n_C x m."""
        if self.dimension != 3:
            raise ValueError("the second tangential component exists in 3D scenes only")
        return self._slip[1::2]

    @property
    def normal_forces(self):
        """lambda_n, n_C x m (a view of interface_forces)."""
        return self.interface_forces[0::self.dimension]

    @property
    def tangential_forces(self):
        """lambda_t, n_C x m (a view of interface_forces)."""
        return self.interface_forces[1::self.dimension]

    @property
    def normal_displacements(self):
        """v_n, n_C x m (a view of interface_displacements)."""
        return self.interface_displacements[0::self.dimension]

    @property
    def tangential_displacements(self):
        """v_t, n_C x m (a view of interface_displacements)."""
        return self.interface_displacements[1::self.dimension]

    @property
    def tangential_forces_2(self):
        """3D: lambda_t along tau_2, n_C x m (a view of interface_forces)."""
        return self._second_tangent(self.interface_forces)

    @property
    def tangential_displacements_2(self):
        """3D: v_t along tau_2, n_C x m (a view of interface_displacements)."""
        return self._second_tangent(self.interface_displacements)

    def _second_tangent(self, rows):
        if self.dimension != 3:
            raise ValueError("the second tangential component exists in 3D scenes only")
        return rows[2::3]

    @property
    def termination(self):
        """"converged", "max_iterations", "stagnated", "numerical_issue" or "stopped_by_callback"."""
        return self.summary["termination"]

    @property
    def converged(self):
        return self.summary["termination"] == "converged"

    @property
    def iterations(self):
        return self.summary["iterations"]

    @property
    def error(self):
        """The last true error (None without the incremental reference)."""
        return self.summary["error"]

    def stress_fields(self, displacements=None):
        """The stress of every element at every instant, as the frames hold it: stress (m, n_e, 6) in
        VTK's order xx, yy, zz, xy, yz, xz and von_mises (m, n_e), from displacement_fields() (one
        factorisation of K_ff) or the given n_dofs x m displacements."""
        u = self.displacement_fields() if displacements is None else displacements
        pairs = [self.problem.stresses(u[:, k]) for k in range(u.shape[1])]
        return np.stack([p[0] for p in pairs]), np.stack([p[1] for p in pairs])

    def displacement_fields(self):
        """The full displacements n_dofs x m, rebuilt from the interface forces with one factorisation
        of K_ff: row d j is u_x of mesh node j, row d j + 1 its u_y (d j + 2: u_z in 3D); column k is
        instant t_k."""
        return self.problem.displacements(self.interface_forces)

    def __repr__(self):
        return "<SolveResult %s: %s after %d iterations, %d contact nodes x %d instants>" % (
            self.solver, self.termination, self.iterations, self.interface_forces.shape[0] // self.dimension,
            self.interface_forces.shape[1])


class SvdResult:
    """The energy SVD of the incremental solution, as `stcontact svd` computes it.

    sigma, energy_fraction, cumulative_energy   r pairs (singular_values.csv's columns)
    time_functions   m x modes        nu_i(t_k) sqrt(sigma_i) (time_functions.csv's columns)
    spatial_modes    n_dofs x modes   Upsilon_i sqrt(sigma_i), dofs interleaved as displacement fields
    modes_for_energy {"99%": count, "99.9%": ..., "99.99%": ...} (None: more than r pairs)
    """

    def __init__(self, data):
        for key, value in data.items():
            setattr(self, key, value)

    def __repr__(self):
        return "<SvdResult: %d pairs, %d resolved, modes for 99.9%% of the energy: %s>" % (
            len(self.sigma), self.resolved, self.modes_for_energy["99.9%"])


def _cell(text):
    """A summary.csv cell as a Python value: '' -> None, true/false -> bool, numbers -> int or float."""
    if text == "":
        return None
    if text in ("true", "false"):
        return text == "true"
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


class Strategy:
    """What compare measured for one strategy: its termination and its timed runs. Each run is a
    dict {"repeat", "total_s", "points"}, points holding work_precision.csv's columns as arrays
    (iteration, relaxations, sparse_solves, indicator, error, wall_s), error copied from the run
    that measured it."""

    def __init__(self, data):
        for key, value in data.items():
            setattr(self, key, value)

    def __repr__(self):
        return "<Strategy %s: %s, %d runs>" % (self.solver, self.termination, len(self.runs))


class CompareResult:
    """A work-precision comparison, as `stcontact compare` measures and reports it.

    strategies   {name: Strategy}, in the order compared
    summary      summary.csv's rows as dicts (medians of the work to reach 1e-2, 1e-4, 1e-6, ...)
    summary_csv, work_precision_csv, summary_markdown   the report's texts
    """

    def __init__(self, data):
        self.strategies = {s["solver"]: Strategy(s) for s in data.pop("strategies")}
        for key, value in data.items():
            setattr(self, key, value)
        rows = csv.DictReader(io.StringIO(self.summary_csv))
        self.summary = [{key: _cell(value) for key, value in row.items()} for row in rows]

    def __repr__(self):
        return "<CompareResult %s: %s>" % (self.scene, ", ".join(self.strategies))
