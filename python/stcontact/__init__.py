"""stcontact: quasi-static frictional contact of elastic bodies over the whole space-time grid.

The command line's work from Python (docs/python.md):

    import stcontact
    scene = stcontact.load_scene("examples/scenes/hemicylinder.toml", sets=["mesh.arc_nodes=31"])
    print(stcontact.check(scene))                       # the sizes `stcontact check` prints
    result = stcontact.solve(scene, solver="latin")     # every strategy, the CLI's options
    result.reactions["normal_force"], result.history["error"], result.summary["termination"]
    warm = stcontact.solve(scene.with_sets("contact.friction=0.2"), start=result)
    stcontact.svd(scene), stcontact.compare(scene, ["latin", "fas-apriori"], repeats=1)
    run = stcontact.load_run("results/first")           # a run folder: run.pressure, run.frame(k), ...

A scene is a TOML file, a TOML text or a dict with the file's keys; either way the command line's
reader checks it, and bad input raises InputError (a ValueError) with the command line's message
(FileNotFoundError for a scene or mesh file that does not exist). Solves release the interpreter's
lock and stop on Ctrl-C (KeyboardInterrupt); threads= applies to that call alone. Scenes and
results pickle. Started by `mpirun -np N python3 script.py` (a build with PETSc), solve() runs on the
N ranks together, as `mpirun -np N stcontact solve` does: every rank makes the same calls and
receives the whole result, rank 0 alone writes `out` (ranks() says which one a process is).
"""

from __future__ import annotations  # the annotations below as text: X | None on Python 3.8 too

import json
import os
from collections.abc import Mapping
from typing import Any, Callable, Sequence, Union

from . import _core
from ._results import CompareResult, SolveResult, Strategy, SvdResult
from ._run_files import Run, load_run
from ._scene_toml import SceneValueError, override_text, scene_toml

__version__ = _core.__version__
blas_kernels = _core.blas_kernels  # OpenBLAS's kernel set in use (docs/threads.md, "BLAS kernels")
InputError = _core.InputError
IterationRecord = _core.IterationRecord

# What a scene argument or --set overrides may be (docs/python.md, "Scenes"); typing's generics, which
# Python 3.8 can subscript.
_PathLike = Union[str, "os.PathLike[str]"]
_SceneLike = Union["Scene", _PathLike, "Mapping[str, Any]"]
_Sets = Union[str, Sequence[str], "Mapping[str, Any]", None]

__all__ = ["Scene", "load_scene", "check", "solve", "svd", "compare", "true_error", "available_solvers", "ranks", "load_run", "Run",
           "InputError", "IterationRecord", "SolveResult", "SvdResult", "CompareResult", "Strategy", "__version__",
           "blas_kernels"]


def _overrides(sets):
    """--set texts from a list of "KEY=VALUE" strings or a dict {KEY: Python value}."""
    if sets is None:
        return []
    if isinstance(sets, str):
        return [sets]
    if isinstance(sets, Mapping):
        try:
            return [override_text(key, value) for key, value in sets.items()]
        except SceneValueError as error:
            raise InputError("--set: %s" % error) from None
    return [str(s) for s in sets]


class Scene:
    """A validated scene: its TOML text, its source and its --set overrides.

    Build it with Scene.from_file, Scene.from_dict or Scene.from_toml (or load_scene); every check
    of the scene file applies, a bad value raises InputError with the command line's message, a
    scene or mesh file that does not exist FileNotFoundError. Checks that need the mesh (boundary
    names, initial penetration) run at the first check(), mesh() or solve.

    Scenes with the same text, source and overrides are equal. A scene pickles as those three: it is
    read again, every check included, when unpickled (a mesh file it names must then exist).
    """

    def __init__(self, handle):
        self._handle = handle

    @classmethod
    def from_file(cls, path: _PathLike, sets: _Sets = None) -> Scene:
        """The scene file at `path` (messages name it as given; a relative mesh file is found beside it)."""
        return cls(_core.Scene.from_file(os.fspath(path), _overrides(sets)))

    @classmethod
    def from_toml(cls, text: str, source: _PathLike = "<text>", sets: _Sets = None) -> Scene:
        """A scene file's text; `source` names it in messages and locates a relative mesh file."""
        return cls(_core.Scene.from_toml(text, os.fspath(source), _overrides(sets)))

    @classmethod
    def from_dict(cls, scene: Mapping[str, Any], sets: _Sets = None, source: _PathLike = "<dict>") -> Scene:
        """A dict with the scene file's keys ({"name": ..., "mesh": {...}, "dirichlet": [{...}], ...})."""
        try:
            text = scene_toml(scene)
        except SceneValueError as error:
            raise InputError("%s: %s" % (os.fspath(source), error)) from None
        return cls.from_toml(text, source, sets)

    def with_sets(self, *sets: _Sets) -> Scene:
        """This scene with more overrides: with_sets("contact.friction=0.3") or with_sets({"time.steps": 41})."""
        extra = [text for s in sets for text in _overrides(s)]
        return Scene(self._handle.with_sets(extra))

    name = property(lambda self: self._handle.name, doc="The scene's name.")
    source = property(lambda self: self._handle.source, doc="The file (or source name) it was read from.")
    text = property(lambda self: self._handle.text, doc="The TOML text, before the overrides.")
    sets = property(lambda self: list(self._handle.sets), doc="The --set overrides applied.")
    solver = property(lambda self: self._handle.solver, doc="The scene's [solver] name.")

    @property
    def parameters(self) -> dict[str, Any]:
        """The scene as read, overrides applied (summary.json's "parameters")."""
        return json.loads(self._handle.parameters_json)

    def check(self) -> dict[str, Any]:
        """The sizes `stcontact check` prints, as a dict."""
        return self._handle.check()

    def mesh(self) -> dict[str, Any]:
        """nodes (N x 2), triangles (E x 3 node ids), contact_nodes (n_C node ids), master_nodes (two bodies:
        the master node paired with each contact node, else empty), master_facets and master_weights (two
        bodies: n_C x k, the master nodes each contact node is compared with, -1 padded, and their
        weights summing to 1; k = 1 node to node, d with contact.pairing = "segment"), initial_gap (n_C),
        times (m)."""
        return self._handle.mesh()

    def _key(self):
        return self.text, self.source, tuple(self.sets)

    def __eq__(self, other):
        """Equal scenes have the same text, source and overrides (so the same problem)."""
        if not isinstance(other, Scene):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self):
        return hash(self._key())

    def __repr__(self):
        return "<Scene %s from %s%s>" % (self.name, self.source, "".join(" --set " + s for s in self.sets))


def load_scene(scene: _SceneLike, sets: _Sets = None) -> Scene:
    """A Scene from a Scene (more overrides applied), a file path or a dict."""
    if isinstance(scene, Scene):
        return scene.with_sets(sets) if sets else scene
    if isinstance(scene, Mapping):
        return Scene.from_dict(scene, sets)
    if isinstance(scene, (str, bytes, os.PathLike)):
        return Scene.from_file(scene, sets)
    raise TypeError("a scene is a Scene, a file path or a dict, not %s" % type(scene).__name__)


def available_solvers() -> list[str]:
    """The strategies solve() and compare() accept."""
    return list(_core.available_solvers())


def ranks() -> tuple[int, int]:
    """(rank, size): this process's MPI rank and how many there are. Under `mpirun -np N` (a build
    with PETSc) the first call starts them, and solve() runs on all N together: every rank must make
    the same calls in the same order (each solve is collective), each receives the whole result, and
    rank 0 alone writes `out`; each rank runs one thread, and svd() and compare() are refused there.
    (0, 1) without a launcher."""
    rank, size = _core.ranks()
    return rank, size


def check(scene: _SceneLike, sets: _Sets = None) -> dict[str, Any]:
    """The model's sizes, as `stcontact check SCENE` prints them (nodes, elements, dofs, free_dofs,
    prescribed_dofs, contact_nodes, instants, kappa, ...)."""
    return load_scene(scene, sets).check()


def solve(scene: _SceneLike, solver: str | None = None, *, tol: float | None = None, max_iterations: int | None = None,
          sets: _Sets = None, reference: bool = True, threads: int | None = None, start: SolveResult | None = None,
          seed_basis: bool = True, callback: Callable[[IterationRecord], Any] | None = None,
          out: _PathLike | None = None, spatial_modes: bool = True) -> SolveResult:
    """Solves the scene, as `stcontact solve` does, and returns a SolveResult.

    solver           latin | latin-pgd | fas-aposteriori | fas-apriori | incremental (default: the
                     scene's [solver] name)                                   (--solver)
    tol              tolerance on the error estimate                         (--tol)
    max_iterations   iteration limit                                         (--max-iterations)
    sets             overrides, ["KEY=VALUE", ...] or {KEY: value}           (--set)
    reference        False: no incremental reference, no true error          (--no-reference)
    threads          threads for this call only (other Python threads keep theirs) (--threads)
    out              also write the command line's output files there        (--out)
    start            warm start: a previous SolveResult of the same sizes (its interface histories
                     and, with seed_basis, its interface directions seed fas-apriori's and
                     latin-pgd's separated global stage)
    spatial_modes    False: fas-apriori and latin-pgd return no spatial_modes (an empty array), and
                     spend no sparse solves on them after the last iteration (as the command line)
    callback         callback(record: IterationRecord) -> bool, after every iteration; False stops
                     the solve (termination "stopped_by_callback"); an exception it raises stops the
                     solve and is raised again here.
    Ctrl-C stops the solve and raises KeyboardInterrupt.
    """
    forces = displacements = seed = None
    if start is not None:
        forces, displacements = start.interface_forces, start.interface_displacements
        if seed_basis:
            seed = start.interface_directions
    data = _core.solve(load_scene(scene)._handle, solver, tol, max_iterations, _overrides(sets), reference,
                       threads, None if out is None else os.fspath(out), forces, displacements, seed, callback,
                       spatial_modes)
    return SolveResult(data)


def svd(scene: _SceneLike, modes: int = 10, *, sets: _Sets = None, threads: int | None = None) -> SvdResult:
    """The energy SVD of the incremental solution (`stcontact svd`): an SvdResult with `modes` time
    functions and spatial modes (at least 50 singular values, or m - 1)."""
    return SvdResult(_core.svd(load_scene(scene)._handle, modes, _overrides(sets), threads))


def true_error(scene: _SceneLike, solution: _PathLike, *, sets: _Sets = None, threads: int | None = None) -> dict[str, Any]:
    """The true error of a run's solution.h5 (`stcontact true-error`), measured here against the
    incremental reference of `scene` with `sets` (the run's; [solver] ones set the reference's solve):
    {"error", "error_estimate" (the run's, None without one), "run_error" (the run's own true error,
    None when it measured none), "solver", "seconds"}. Raises InputError when the file was solved on
    another model; Ctrl-C stops the reference and raises KeyboardInterrupt."""
    return _core.true_error(load_scene(scene)._handle, os.fspath(solution), _overrides(sets), threads)


def compare(scene: _SceneLike, solvers: str | Sequence[str] | None = None, *, repeats: int = 3, tol: float | None = None,
            sets: _Sets = None, threads: int | None = None, out: _PathLike | None = None) -> CompareResult:
    """Work against precision of strategies (`stcontact compare`): each solver (default: every
    available one) gets an error run and `repeats` timed runs, against the incremental reference.
    With `out`, the report files (and gnuplot's plots, when available) are written there too.
    Ctrl-C stops it (KeyboardInterrupt; the reference solve is finished first)."""
    if isinstance(solvers, str):
        solvers = [solvers]
    data = _core.compare(load_scene(scene)._handle, list(solvers or []), repeats, tol, _overrides(sets), threads,
                         None if out is None else os.fspath(out))
    return CompareResult(data)
