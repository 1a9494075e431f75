# Each case: stc_cli_test(NAME EXIT_CODE PATTERN ARGS...). Small settings keep them fast.
set(seed ${scenes}/hemicylinder.toml)
set(small --set mesh.arc_nodes=21 --set time.steps=21)

stc_cli_test(help 0 "Usage" --help)
stc_cli_test(version 0 "stcontact 0\\.1\\.0" --version)
stc_cli_test(no_command 1 "subcommand" )
stc_cli_test(check_seed_sizes 0 "dofs +1142 \\(1088 free, 54 prescribed\\)" check ${seed})
stc_cli_test(check_seed_contact_nodes 0 "contact nodes +101 on boundary 'arc'" check ${seed})
stc_cli_test(check_punch 0 "contact nodes" check ${scenes}/punch.toml)

# Bad input: exit 1, one "error:" line naming the key, file or entity.
stc_cli_test(bad_unknown_key 1 "unknown key 'material.youngs'" check ${seed} --set material.youngs=1.0)
stc_cli_test(bad_poisson_half 1 "material.poisson.*\\(-1, 0\\.5\\)" check ${seed} --set material.poisson=0.5)
stc_cli_test(bad_missing_boundary 1 "boundary 'rim' is not in the mesh" check ${seed} --set contact.boundary=rim)
stc_cli_test(bad_penetrating_node 1 "starts inside the obstacle" check ${seed} --set "obstacle.point=[0.0, -0.99]")
stc_cli_test(bad_truncated_msh 1 "truncated\\.msh" check ${bad}/truncated.toml)
stc_cli_test(bad_malformed_toml 1 "malformed\\.toml:2" check ${bad}/malformed.toml)
stc_cli_test(bad_missing_scene 1 "no_such_scene\\.toml" check ${bad}/no_such_scene.toml)
stc_cli_test(bad_unknown_solver 1 "unknown solver 'fast'" solve ${seed} --solver fast)
stc_cli_test(bad_unwritable_out 1 "/dev/null/out" solve ${seed} ${small} --solver latin --out /dev/null/out)
stc_cli_test(bad_negative_tol 1 "--tol" solve ${seed} ${small} --solver latin --tol -1)

# Solves: exit 0 when converged, 2 when not (results still written).
set(out ${CMAKE_CURRENT_BINARY_DIR}/out)
stc_cli_test(solve_latin_small 0 "latin: converged" solve ${seed} ${small} --solver latin --out ${out}/latin)
stc_cli_test(solve_incremental_small 0 "incremental: converged" solve ${seed} ${small} --solver incremental
             --out ${out}/incremental)
stc_cli_test(solve_not_converged_exits_2 2 "max_iterations" solve ${seed} ${small} --solver latin
             --max-iterations 3 --out ${out}/latin3)
add_test(NAME cli.solve_writes_every_output
         COMMAND bash -c "for f in reactions.csv contact.csv history.csv summary.json solution.pvd vtu/step_00020.vtu; do test -s ${out}/latin3/$f || { echo missing $f; exit 1; }; done; grep -q '\"termination\": \"max_iterations\"' ${out}/latin3/summary.json")
set_tests_properties(cli.solve_writes_every_output PROPERTIES DEPENDS cli.solve_not_converged_exits_2 LABELS cli)

# A posteriori space-time SVD (METHOD.md §3): prints the modes for 99%, 99.9%, 99.99% of the energy.
stc_cli_test(svd_small 0 "99.9" svd ${seed} ${small} --out ${out}/svd)
