"""The scenes of the issue's speed and rank goals, as (label, scene file, --set overrides): one list
for the study scripts that report on them (shared_floor.py, rank_against_sparse_solves.py), so their
tables name the same scenes the same way. Run from the repository's root."""

SEED = "examples/scenes/hemicylinder.toml"
HALF_BALL = "examples/scenes/hemisphere.toml"

SEED_SCENE = ("seed", SEED, [])
ARC_NODES_801 = ("arc_nodes 801", SEED, ["mesh.arc_nodes=801"])
ARC_NODES_1601 = ("arc_nodes 1601", SEED, ["mesh.arc_nodes=1601"])
LONG_GRID = ("401 x 2001", SEED, ["mesh.arc_nodes=401", "time.steps=2001"])
FRETTING = ("fretting, 10 cycles x 2001", "examples/scenes/fretting.toml", [])
HEMISPHERE_8 = ("hemisphere, divisions 8", HALF_BALL, [])
HEMISPHERE_12 = ("hemisphere, divisions 12", HALF_BALL, ["mesh.divisions=12"])
HEMISPHERE_16 = ("hemisphere, divisions 16", HALF_BALL, ["mesh.divisions=16"])
