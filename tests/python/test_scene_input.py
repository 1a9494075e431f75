"""Scenes from files and from dicts go through the same checks: bad input raises InputError, a
ValueError whose message is the program's "error:" line without its prefix; a scene or mesh file
that does not exist raises FileNotFoundError with that message, ENOENT and the path."""

import errno
import tomllib

import pytest

import stcontact
from conftest import BAD_DIR, SEED_SCENE, SMALL, cli_error


def seed_dict():
    with open(SEED_SCENE, "rb") as f:
        return tomllib.load(f)


@pytest.mark.parametrize("name", ["malformed.toml", "bad_table_header.toml", "truncated.toml", "inverted.toml"])
def test_bad_files_give_the_programs_message(cli, name):
    path = BAD_DIR / name
    expected = cli_error(cli, "check", path)
    with pytest.raises(ValueError) as raised:
        stcontact.check(str(path))
    assert str(raised.value) == expected
    assert isinstance(raised.value, stcontact.InputError)


def test_a_missing_scene_file_raises_file_not_found(cli):
    path = BAD_DIR / "no_such_scene.toml"
    expected = cli_error(cli, "check", path)
    with pytest.raises(FileNotFoundError) as raised:
        stcontact.check(str(path))
    error = raised.value
    assert error.errno == errno.ENOENT and error.filename == str(path)
    assert error.strerror == expected  # the program's message, unchanged
    assert not isinstance(error, ValueError)


def test_a_missing_mesh_file_raises_file_not_found(cli):
    path = BAD_DIR / "truncated.toml"
    expected = cli_error(cli, "check", path, "--set", "mesh.file=no_such.msh")
    scene = stcontact.load_scene(path, sets=["mesh.file=no_such.msh"])  # the mesh is read at the first use
    with pytest.raises(FileNotFoundError) as raised:
        scene.check()
    error = raised.value
    assert error.errno == errno.ENOENT and error.filename == str(BAD_DIR / "no_such.msh")
    assert error.strerror == expected


def test_a_folder_given_as_scene_stays_an_input_error(cli):
    expected = cli_error(cli, "check", BAD_DIR)
    with pytest.raises(stcontact.InputError) as raised:
        stcontact.check(BAD_DIR)
    assert str(raised.value) == expected


@pytest.mark.parametrize("override", ["material.poisson=0.5", "material.youngs=1.0", "contact.boundary=rim",
                                      "obstacle.point=[0.0, -0.99]", "time.steps=1", "solver.name=fast",
                                      "dirichlet[2].values=[0.0]", "time.end=1e308", "material.young=1e308",
                                      "mesh.arc_nodes=2147483647", "time.steps=100000000"])
def test_bad_overrides_give_the_programs_message(cli, override):
    expected = cli_error(cli, "check", SEED_SCENE, "--set", override)
    with pytest.raises(ValueError) as raised:
        stcontact.check(str(SEED_SCENE), sets=[override])
    assert str(raised.value) == expected


def test_bad_solve_options_give_the_programs_message(cli, small_scene):
    small = [arg for s in SMALL for arg in ("--set", s)]
    cases = [(["--solver", "fast"], dict(solver="fast")),
             (["--solver", "latin", "--tol", "-1"], dict(solver="latin", tol=-1.0)),
             (["--solver", "latin", "--max-iterations", "0"], dict(solver="latin", max_iterations=0))]
    for cli_args, options in cases:
        expected = cli_error(cli, "solve", SEED_SCENE, *small, *cli_args, "--out", "/dev/null/out")
        with pytest.raises(ValueError) as raised:
            stcontact.solve(small_scene, **options)
        assert str(raised.value) == expected


def test_dict_scene_equals_the_file():
    from_file = stcontact.Scene.from_file(SEED_SCENE, sets=SMALL)
    from_dict = stcontact.Scene.from_dict(seed_dict(), sets=SMALL, source=SEED_SCENE)
    assert from_dict.check() == from_file.check()
    assert from_dict.parameters == from_file.parameters
    assert from_dict.name == "hemicylinder"


@pytest.mark.parametrize("section, key, value", [("material", "poisson", 0.5), ("time", "steps", 20.5),
                                                 ("contact", "friction", -0.1), ("material", "youngs", 1.0),
                                                 ("mesh", "arc_nodes", "many"), ("contact", "boundary", "rim")])
def test_bad_dict_values_give_the_programs_message(cli, tmp_path, section, key, value):
    scene = seed_dict()
    scene[section][key] = value
    path = tmp_path / "scene.toml"
    path.write_text(stcontact._scene_toml.scene_toml(scene))
    expected = cli_error(cli, "check", path)
    with pytest.raises(ValueError) as raised:
        stcontact.Scene.from_dict(scene, source=path).check()
    assert str(raised.value) == expected
    assert key in expected


def test_a_missing_section_in_a_dict_is_named():
    scene = seed_dict()
    del scene["material"]
    with pytest.raises(ValueError, match="missing required key 'material'"):
        stcontact.Scene.from_dict(scene)


def test_values_without_toml_counterpart_are_refused():
    scene = seed_dict()
    scene["contact"]["friction"] = None
    with pytest.raises(ValueError, match=r"^<dict>: key 'contact.friction' = None has no TOML value"):
        stcontact.Scene.from_dict(scene)


def test_sets_as_dict_and_strings_agree():
    by_text = stcontact.check(SEED_SCENE, sets=["mesh.arc_nodes=21", "model.plane=stress"])
    by_dict = stcontact.check(SEED_SCENE, sets={"mesh.arc_nodes": 21, "model.plane": "stress"})
    assert by_text == by_dict and by_dict["plane"] == "stress" and by_dict["contact_nodes"] == 21


def test_non_ascii_strings_reach_the_reader_as_text():
    scene = seed_dict()
    scene["name"] = "hémicylindre"
    assert stcontact.Scene.from_dict(scene).name == "hémicylindre"
