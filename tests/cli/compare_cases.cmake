# `stcontact compare` bad input: exit 1, one "error:" line naming the option or solver.
# (The successful run is checked end to end, file by file, by tests/cli/test_compare_command.cpp.)
stc_cli_test(compare_unknown_solver 1 "unknown solver 'fast'" compare ${seed} ${small} --solvers latin,fast
             --out ${out}/compare_bad)
stc_cli_test(compare_solver_listed_twice 1 "'latin' is listed twice" compare ${seed} ${small}
             --solvers latin,latin --out ${out}/compare_bad)
stc_cli_test(compare_empty_solver_name 1 "--solvers: empty name" compare ${seed} ${small} --solvers "latin,,incremental"
             --out ${out}/compare_bad)
stc_cli_test(compare_zero_repeats 1 "--repeats must be >= 1" compare ${seed} ${small} --repeats 0 --out ${out}/compare_bad)
stc_cli_test(compare_negative_tol 1 "--tol must be > 0" compare ${seed} ${small} --tol -1 --out ${out}/compare_bad)
stc_cli_test(compare_unwritable_out 1 "/dev/null/out" compare ${seed} ${small} --out /dev/null/out)
stc_cli_test(compare_one_solver_small 0 "report: .*summary\\.md" compare ${seed} ${small} --solvers incremental
             --repeats 1 --out ${out}/compare_incremental)
