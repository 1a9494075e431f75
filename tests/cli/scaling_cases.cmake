# `stcontact scaling` bad input: exit 1, one "error:" line naming the option. A time cap too short for
# any iteration: every iterative strategy "not reached (time cap)", the report still written (exit 0).
# (The successful run is checked file by file by tests/cli/test_scaling_command.cpp.)
set(tiny --set mesh.arc_nodes=11 --set time.steps=11 --repeats 1)
stc_cli_test(scaling_zero_repeats 1 "--repeats must be >= 1" scaling ${seed} --repeats 0 --out ${out}/scaling_bad)
stc_cli_test(scaling_bad_size 1 "--arc-nodes: 'x' is not an integer" scaling ${seed} --arc-nodes 11,x
             --out ${out}/scaling_bad)
stc_cli_test(scaling_size_too_small 1 "--steps: 1 must be >= 2" scaling ${seed} --steps 1 --out ${out}/scaling_bad)
stc_cli_test(scaling_size_twice 1 "--steps: 11 is listed twice" scaling ${seed} --steps 11,11 --out ${out}/scaling_bad)
stc_cli_test(scaling_no_sizes 1 "both empty" scaling ${seed} --arc-nodes none --steps none --out ${out}/scaling_bad)
stc_cli_test(scaling_target_above_one 1 "--target-error must be in \\(0, 1\\)" scaling ${seed} --target-error 2
             --out ${out}/scaling_bad)
stc_cli_test(scaling_zero_time_cap 1 "--time-cap must be > 0" scaling ${seed} --time-cap 0 --out ${out}/scaling_bad)
stc_cli_test(scaling_mesh_series_of_a_file_mesh 1 "--arc-nodes needs a scene with the half_disc" scaling
             ${scenes}/punch.toml --out ${out}/scaling_bad)
stc_cli_test(scaling_unknown_solver 1 "unknown solver 'fast'" scaling ${seed} --solvers latin,fast
             --out ${out}/scaling_bad)
stc_cli_test(scaling_time_cap_not_reached 0 "latin: not reached \\(time cap, best error [0-9.e+-]+\\)" scaling ${seed} ${tiny}
             --solvers latin,incremental --arc-nodes 11 --steps 11,21 --time-cap 1e-9 --out ${out}/scaling_cap)
stc_cli_test(scaling_time_series_only 0 "report: .*summary\\.md" scaling ${scenes}/punch.toml --repeats 1
             --solvers incremental --arc-nodes none --steps 11,21 --out ${out}/scaling_punch)
stc_cli_test(scaling_time_cap_at_tolerance_only 1 "--time-cap stops the first-reach error runs" scaling ${seed}
             --only-at-tolerance --time-cap 5 --out ${out}/scaling_bad)
