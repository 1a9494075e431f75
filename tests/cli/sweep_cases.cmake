# `stcontact sweep` bad input: exit 1, one "error:" line naming the option, key or value and the
# rule, and no report folder created: every value is checked before anything is written.
# (The successful runs are checked end to end by tests/cli/test_sweep_command.cpp.)
function(stc_sweep_refused name pattern)
  add_test(NAME cli.sweep_refuse_${name}
           COMMAND bash ${expect} --absent ${refused}/sweep_${name} 1 "${pattern}"
                   ${cli} sweep ${seed} ${small} --out ${refused}/sweep_${name} ${ARGN})
  set_tests_properties(cli.sweep_refuse_${name} PROPERTIES LABELS cli)
endfunction()
set(mu contact.friction=0.05:0.5:3)
stc_sweep_refused(no_range "--set-range is required")
stc_sweep_refused(range_syntax "--set-range 'contact\\.friction=0\\.05:0\\.5': expected KEY=FROM:TO:COUNT"
                  --set-range contact.friction=0.05:0.5)
stc_sweep_refused(range_not_a_number "FROM 'low' is not a finite number" --set-range contact.friction=low:0.5:3)
stc_sweep_refused(count_zero "COUNT '0' must be an integer from 1" --set-range contact.friction=0.05:0.5:0)
stc_sweep_refused(count_fraction "COUNT '2\\.5' must be an integer" --set-range contact.friction=0.05:0.5:2.5)
stc_sweep_refused(unknown_key "unknown key 'contact\\.frction'" --set-range contact.frction=0.05:0.5:3)
stc_sweep_refused(value_out_of_range "key 'contact\\.friction' = -0\\.1 is out of range: must be >= 0"
                  --set-range contact.friction=-0.1:0.2:4)
stc_sweep_refused(integer_key_fraction "key 'solver\\.pre_relaxations' must be an integer, got a float"
                  --set-range solver.pre_relaxations=1:2:3)
stc_sweep_refused(last_value_penetrates "starts inside the obstacle" --set-range "obstacle.point[1]=-1.02:-0.99:4")
stc_sweep_refused(set_same_key "--set contact\\.friction=0\\.3 conflicts with --set-range contact\\.friction"
                  --set contact.friction=0.3 --set-range ${mu})
stc_sweep_refused(tol_and_tolerance_range "--tol conflicts with --set-range solver\\.tolerance"
                  --tol 1e-6 --set-range solver.tolerance=1e-6:1e-4:3)
stc_sweep_refused(incremental "--solver incremental: a sweep compares warm and cold starts" --solver incremental
                  --set-range ${mu})
stc_sweep_refused(unknown_solver "unknown solver 'fast'" --solver fast --set-range ${mu})
stc_sweep_refused(negative_tol "--tol must be > 0" --tol -1 --set-range ${mu})
stc_cli_test(sweep_unwritable_out 1 "/dev/null/out" sweep ${seed} ${small} --set-range ${mu} --out /dev/null/out)
