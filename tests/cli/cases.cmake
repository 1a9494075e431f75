# Each case: stc_cli_test(NAME EXIT_CODE PATTERN ARGS...). Small settings keep them fast.
set(seed ${scenes}/hemicylinder.toml)
set(small --set mesh.arc_nodes=21 --set time.steps=21)
list(JOIN small " " small_text)  # the same, inside a bash -c command

stc_cli_test(help 0 "Usage" --help)
# Every command's --help works and states the defaults a user would otherwise guess.
foreach(command check solve compare svd sweep scaling true-error)
  stc_cli_test(help_${command} 0 "Usage" ${command} --help)
endforeach()
stc_cli_test(help_solve_defaults 0 "--tol FLOAT +tolerance on the error estimate \\(default: the scene's solver.tolerance, else 1e-06\\)" solve --help)
foreach(program compare_bases fas_aposteriori_study ex1 ex2 ex3 ex4 ex5)  # examples/ is added after tests/
  add_test(NAME cli.help_program_${program} COMMAND bash ${expect} 0 "Usage" $<TARGET_FILE:${program}> --help)
  set_tests_properties(cli.help_program_${program} PROPERTIES LABELS cli)
endforeach()
stc_cli_test(version 0 "stcontact 0\\.3\\.0" --version)
stc_cli_test(no_command 1 "subcommand" )
stc_cli_test(check_seed_sizes 0 "dofs +1142 \\(1088 free, 54 prescribed\\)" check ${seed})
stc_cli_test(check_seed_contact_nodes 0 "contact nodes +101 on boundary 'arc'" check ${seed})
stc_cli_test(check_punch 0 "contact nodes" check ${scenes}/punch.toml)
# check names the search law it printed k for (docs/method.md §2): the local one by default.
stc_cli_test(check_search_law_local 0 "search direction k = kappa E l_i hbar / \\(L h_i\\) \\(law local" check ${seed})
stc_cli_test(check_search_law_tributary 0 "search direction k = kappa E l_i / L \\(law tributary\\)" check ${seed}
             --set solver.search_law=tributary)
# Two bodies (examples/scenes/two_cylinders.toml): node-to-node pairs, every body's contact forces.
stc_cli_test(check_pair 0 "contact nodes +101 on boundary 'arc', node to node with 'mirror_arc' \\(two bodies\\)"
             check ${scenes}/two_cylinders.toml)

# Solves: exit 0 when converged, 2 when not (results still written).
set(out ${CMAKE_CURRENT_BINARY_DIR}/out)
stc_cli_test(solve_latin_small 0 "latin: converged" solve ${seed} ${small} --solver latin --out ${out}/latin)
stc_cli_test(solve_incremental_small 0 "incremental: converged" solve ${seed} ${small} --solver incremental
             --out ${out}/incremental)
stc_cli_test(solve_not_converged_exits_2 2 "max_iterations" solve ${seed} ${small} --solver latin
             --max-iterations 3 --out ${out}/latin3)
# summary.json's "parameters" say what was solved: --solver and --max-iterations appear in it.
add_test(NAME cli.parameters_record_the_solver_used
         COMMAND bash -c "grep -Eq '\"name\" *: *\"latin-pgd\"' ${out}/latin-pgd_limit/summary.json && grep -Eq '\"max_iterations\" *: *3' ${out}/latin-pgd_limit/summary.json")
set_tests_properties(cli.parameters_record_the_solver_used PROPERTIES DEPENDS cli.solve_latin-pgd_limit_exits_2 LABELS cli)
# Every iterative strategy stops at the iteration limit with exit 2, its summary saying why.
foreach(solver latin-pgd fas-aposteriori fas-apriori)
  stc_cli_test(solve_${solver}_limit_exits_2 2 "${solver}: max_iterations" solve ${seed} ${small} --solver ${solver}
               --max-iterations 3 --out ${out}/${solver}_limit)
endforeach()
# The default solver (the scene's [solver] name, fas-apriori) converges without --solver.
stc_cli_test(solve_default_is_fas_apriori 0 "fas-apriori: converged" solve ${seed} ${small} --out ${out}/default)
# ... run.log keeps its progress and its final report, and summary.json its times: the run's reference,
# solve and writing are parts of the whole run.
add_test(NAME cli.solve_writes_every_output
         COMMAND bash -c "for f in reactions.csv contact.csv history.csv summary.json solution.h5 solution.xdmf run.log; do test -s ${out}/latin3/$f || { echo missing $f; exit 1; }; done; grep -q 'solution.h5:/frames/step_00020/stress' ${out}/latin3/solution.xdmf && grep -q '\"termination\": \"max_iterations\"' ${out}/latin3/summary.json && grep -q '^progress: latin: iteration 3 ' ${out}/latin3/run.log && grep -q '^  the whole run .* s (reference .* s, writing .* s)$' ${out}/latin3/run.log && python3 -c \"import json, sys; s = json.load(open(sys.argv[1])); sys.exit(0 if s['run_s'] >= s['reference_s'] + s['wall_s'] + s['write_s'] > 0 else 1)\" ${out}/latin3/summary.json")
set_tests_properties(cli.solve_writes_every_output PROPERTIES DEPENDS cli.solve_not_converged_exits_2 LABELS cli)

# A moving obstacle: check says so.
stc_cli_test(check_moving_pad 0 "obstacle motion +a rigid translation up to \\|d\\| = 0\\.0632" check ${scenes}/moving_pad.toml)
# Two bodies at small settings: converged; as VTU, one block per body in every frame (parts 0 and 1
# of the collection, each carrying its body code), one grid without it for one body; in
# solution.xdmf, the body of each element as a field.
stc_cli_test(solve_pair_small 0 "fas-apriori: converged" solve ${scenes}/two_cylinders.toml ${small} --out ${out}/pair)
stc_cli_test(solve_pair_small_vtu 0 "fas-apriori: converged" solve ${scenes}/two_cylinders.toml ${small}
             --set "output.format=\"vtu\"" --out ${out}/pair_vtu)
stc_cli_test(solve_default_vtu 0 "fas-apriori: converged" solve ${seed} ${small} --set "output.format=\"vtu\"" --out ${out}/default_vtu)
add_test(NAME cli.solve_pair_writes_the_body_of_each_node
         COMMAND bash -c "grep -aq 'Name=\"body\"' ${out}/pair_vtu/vtu/step_00020_body1.vtu && grep -q 'part=\"1\" file=\"vtu/step_00020_body1.vtu\" name=\"body 1\"' ${out}/pair_vtu/solution.pvd && ! test -e ${out}/pair_vtu/vtu/step_00020.vtu && ! grep -aq 'Name=\"body\"' ${out}/default_vtu/vtu/step_00020.vtu && grep -q 'Attribute Name=\"body\"' ${out}/pair/solution.xdmf && ! grep -q 'Name=\"body\"' ${out}/default/solution.xdmf")
set_tests_properties(cli.solve_pair_writes_the_body_of_each_node PROPERTIES
                     DEPENDS "cli.solve_pair_small;cli.solve_pair_small_vtu;cli.solve_default_vtu;cli.solve_default_is_fas_apriori" LABELS cli)

# The 3D seed scene (examples/scenes/hemisphere.toml) at small settings: sizes, a solve with its
# 3D tables and tetrahedron VTU, the svd tables.
set(hemisphere ${scenes}/hemisphere.toml)
set(small3d --set mesh.divisions=3 --set time.steps=11)
# check says what solve will write: the frames the automatic stride keeps, contact.csv or not.
stc_cli_test(check_says_what_solve_writes 0 "outputs +solution.h5 \\+ solution.xdmf, 12 frames \\(one in 182 instants, output.frame_stride auto\\), no contact.csv"
             check ${scenes}/hemisphere_fretting.toml)
stc_cli_test(check_hemisphere_model 0 "model +3D, P1 tetrahedra" check ${hemisphere})
stc_cli_test(check_hemisphere_interface 0 "contact nodes +737 on boundary 'contact' \\(2211 interface unknowns" check ${hemisphere})
stc_cli_test(solve_hemisphere_small 0 "fas-apriori: converged" solve ${hemisphere} ${small3d} --out ${out}/hemisphere)
add_test(NAME cli.solve_hemisphere_writes_3d_tables
         COMMAND bash -c "head -1 ${out}/hemisphere/reactions.csv | grep -qx 'step,t,normal_force,tangential_force,tangential_force_2,contact_xmin,contact_xmax,n_contact,n_slip,force_x,force_y,force_z' && head -1 ${out}/hemisphere/contact.csv | grep -qx 'step,t,node,x,y,z,normal_force,tangential_force,tangential_force_2,pressure,shear,shear_2,gap,slip,slip_2,state' && grep -q 'TopologyType=\"Tetrahedron\"' ${out}/hemisphere/solution.xdmf && grep -q 'Attribute Name=\"stress\" AttributeType=\"Tensor6\" Center=\"Cell\"' ${out}/hemisphere/solution.xdmf")
set_tests_properties(cli.solve_hemisphere_writes_3d_tables PROPERTIES DEPENDS cli.solve_hemisphere_small LABELS cli)
# The 3D fretting history (examples/scenes/hemisphere_fretting.toml) at divisions 6 and 401 instants,
# its ten cycles kept: fas-apriori converged with its true error against the incremental solution
# within tau (1.3e-7 measured), and the cycles do what the scene says: a partial slip (some nodes of
# the contact disc slip, not all) and a gross slip (every contact node slips at some instant).
stc_cli_test(solve_hemisphere_fretting_small 0 "fas-apriori: converged" solve ${scenes}/hemisphere_fretting.toml
             --set mesh.divisions=6 --set time.steps=401 --set output.frames=false --out ${out}/hemisphere_fretting)
add_test(NAME cli.hemisphere_fretting_within_tolerance_partial_then_gross_slip
         COMMAND python3 -c "import csv, json, sys; d = sys.argv[1]; s = json.load(open(d + '/summary.json')); rows = [(int(r['n_contact']), int(r['n_slip'])) for r in csv.DictReader(open(d + '/reactions.csv'))]; ok = s['termination'] == 'converged' and s['error'] <= 1e-6 and any(0 < k < n for n, k in rows) and any(n > 0 and k == n for n, k in rows); print(s['error'], max(k / n for n, k in rows if n)); sys.exit(0 if ok else 1)" ${out}/hemisphere_fretting)
set_tests_properties(cli.hemisphere_fretting_within_tolerance_partial_then_gross_slip PROPERTIES
                     DEPENDS cli.solve_hemisphere_fretting_small LABELS cli)
# The shallow press (examples/scenes/hemisphere_shallow.toml) at divisions 6 and 51 instants:
# fas-apriori converged with its true error against the incremental solution within tau (2.5e-8
# measured) and the disc slides as a whole at the end (every contact node slips at the last instant).
stc_cli_test(solve_hemisphere_shallow_small 0 "fas-apriori: converged" solve ${scenes}/hemisphere_shallow.toml
             --set mesh.divisions=6 --set time.steps=51 --set output.frames=false --out ${out}/hemisphere_shallow)
add_test(NAME cli.hemisphere_shallow_within_tolerance_sliding
         COMMAND python3 -c "import csv, json, sys; d = sys.argv[1]; s = json.load(open(d + '/summary.json')); n, k = [(int(r['n_contact']), int(r['n_slip'])) for r in csv.DictReader(open(d + '/reactions.csv'))][-1]; ok = s['termination'] == 'converged' and s['error'] <= 1e-6 and 0 < n == k; print(s['error'], n, k); sys.exit(0 if ok else 1)" ${out}/hemisphere_shallow)
set_tests_properties(cli.hemisphere_shallow_within_tolerance_sliding PROPERTIES
                     DEPENDS cli.solve_hemisphere_shallow_small LABELS cli)
# The frames read back by readers that share no code with the writer (meshio, xml.etree, VTK's own
# when python3-vtk9 is installed): array names, types, component names, the stress tensor in VTK's
# order against Hooke's law, Float32 = Float64 rounded (tests/io/vtu_read_back.py; exit 77 = skipped
# without python3-meshio).
if(Python3_EXECUTABLE)
  add_test(NAME cli.vtu_frames_read_back
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/io/vtu_read_back.py ${cli} ${scenes} ${out}/vtu_read_back)
  set_tests_properties(cli.vtu_frames_read_back PROPERTIES LABELS cli SKIP_RETURN_CODE 77 TIMEOUT 600)
  # solution.xdmf through meshio's XDMF time-series reader (every frame, stress against Hooke's law)
  # and solution.h5's interface histories through h5py, equal to contact.csv (tests/io/solution_read_back.py).
  add_test(NAME cli.solution_read_back
           COMMAND ${Python3_EXECUTABLE} ${PROJECT_SOURCE_DIR}/tests/io/solution_read_back.py ${cli} ${scenes} ${out}/solution_read_back)
  set_tests_properties(cli.solution_read_back PROPERTIES LABELS cli SKIP_RETURN_CODE 77 TIMEOUT 600)
endif()
stc_cli_test(svd_hemisphere_small 0 "99.9" svd ${hemisphere} ${small3d} --out ${out}/svd3d)
# The scaling study on the 3D scene: its mesh series varies mesh.divisions (the folder and the CSV
# column say so); --arc-nodes does not apply to it.
stc_cli_test(scaling_hemisphere_small 0 "divisions 3, steps 11" scaling ${hemisphere} --divisions 2,3 --steps none
             --set time.steps=11 --solvers latin-pgd,incremental --repeats 1 --out ${out}/scaling3d)
add_test(NAME cli.scaling_hemisphere_names_the_divisions
         COMMAND bash -c "head -1 ${out}/scaling3d/scaling.csv | grep -q '^series,divisions,dofs,' && test -s ${out}/scaling3d/sizes/divisions_3_steps_11/summary.md && grep -q '| divisions | dofs |' ${out}/scaling3d/summary.md")
set_tests_properties(cli.scaling_hemisphere_names_the_divisions PROPERTIES DEPENDS cli.scaling_hemisphere_small LABELS cli)
# What a user gets comes first: the solve at the target as tolerance, in the CSV and the summary,
# every strategy of the run with a termination and a true error.
add_test(NAME cli.scaling_reports_the_solve_at_tolerance
         COMMAND bash -c "head -1 ${out}/scaling3d/scaling.csv | grep -q ',time_at_tolerance_s,termination_at_tolerance,relaxations_at_tolerance,sparse_solves_at_tolerance,error_estimate_at_tolerance,error_at_tolerance,time_ratio_at_tolerance,krylov_iterations_at_tolerance,peak_rss_mb_at_tolerance,incremental_form_at_tolerance$' && test $(grep -c ',converged,[0-9]*,[0-9]*,[^,]*,[0-9.e+-]*,[0-9.e+-]*,[0-9]*,[0-9.e+-]*,[a-z-]*$' ${out}/scaling3d/scaling.csv) -eq 4 && test $(grep -c '^mesh,.*,incremental,.*,converged,.*,interface$' ${out}/scaling3d/scaling.csv) -eq 2 && grep -q '^A solve at tolerance 0.0001' ${out}/scaling3d/summary.md")
set_tests_properties(cli.scaling_reports_the_solve_at_tolerance PROPERTIES DEPENDS cli.scaling_hemisphere_small LABELS cli)
stc_cli_test(bad_scaling_arc_nodes_on_half_ball 1 "--arc-nodes does not apply to a scene with the half_ball generator"
             scaling ${hemisphere} --arc-nodes 21 --steps none --out ${out}/scaling3d_bad)

# A posteriori space-time SVD (docs/method.md §3): prints the modes for 99%, 99.9%, 99.99% of the energy.
stc_cli_test(svd_small 0 "99.9" svd ${seed} ${small} --out ${out}/svd)

# Bad input (the scene, its mesh, the options): exit 1 and one "error:" line naming the key, file or
# entity and the rule broken. One row a case, fields separated by '|':
#   bad_NAME|PATTERN|ARGS...      the program run with ARGS;
#   refuse_NAME|PATTERN|SCENE|ARGS...  `solve SCENE --solver latin --out DIR ARGS...`,
#                                  and DIR not created: the refusal comes before anything is written.
set(refused ${CMAKE_CURRENT_BINARY_DIR}/refused)
set(pair ${scenes}/two_cylinders.toml)
set(hemisphere_scene ${scenes}/hemisphere.toml)
set(trunc ${bad}/truncated.toml)
string(REPLACE ";" "|" small_fields "${small}")
set(stc_refusals
  "bad_unknown_key|unknown key 'material.youngs'|check|${seed}|--set|material.youngs=1.0"
  "bad_poisson_half|material.poisson.*\\[-0\\.999999, 0\\.4999995\\]|check|${seed}|--set|material.poisson=0.5"
  "bad_missing_boundary|boundary 'rim' is not in the mesh|check|${seed}|--set|contact.boundary=rim"
  "bad_penetrating_node|starts inside the obstacle|check|${seed}|--set|obstacle.point=[0.0, -0.99]"
  "bad_truncated_msh|truncated\\.msh|check|${bad}/truncated.toml"
  "bad_malformed_toml|malformed\\.toml:2|check|${bad}/malformed.toml"
  "bad_missing_scene|no_such_scene\\.toml|check|${bad}/no_such_scene.toml"
  "bad_unknown_solver|unknown solver 'fast'|solve|${seed}|--solver|fast"
  "bad_unwritable_out|/dev/null/out|solve|${seed}|${small_fields}|--solver|latin|--out|/dev/null/out"
  "bad_negative_tol|--tol|solve|${seed}|${small_fields}|--solver|latin|--tol|-1"
  "refuse_malformed_toml|malformed\\.toml:2:[0-9]+: TOML syntax error|${bad}/malformed.toml"
  "refuse_missing_scene|no_such_scene\\.toml: cannot open|${bad}/no_such_scene.toml"
  "refuse_bad_table_header|bad_table_header\\.toml:3:2: TOML syntax error: a table name cannot start with '\\.'|${bad}/bad_table_header.toml"
  "refuse_unknown_search_law|key 'solver\\.search_law' = .foo. is not one of .tributary., .local.|${seed}|--set|solver.search_law=foo"
  "refuse_set_index_overflow|--set dirichlet\\[9+\\]\\.values=\\[1\\]: malformed key|${seed}|--set|dirichlet[99999999999999999999999].values=[1]"
  "refuse_unknown_key|unknown key 'contact\\.frction'|${seed}|${small_fields}|--set|contact.frction=0.3"
  "refuse_unknown_table|unknown key 'solvers'|${seed}|${small_fields}|--set|solvers.name=latin"
  "refuse_wrong_type_float_for_int|key 'time\\.steps' must be an integer, got a float|${seed}|--set|time.steps=2.5"
  "refuse_wrong_type_string_for_number|key 'material\\.young' must be a number, got a string|${seed}|--set|material.young=abc"
  "refuse_wrong_type_number_for_array|key 'obstacle\\.normal' must be an array|${seed}|--set|obstacle.normal=1.0"
  "refuse_nan_young|key 'material\\.young' = nan is not a finite number|${seed}|--set|material.young=nan"
  "refuse_inf_friction|key 'contact\\.friction' = inf is not a finite number|${seed}|--set|contact.friction=inf"
  "refuse_nan_in_history|key 'dirichlet\\[0\\]\\.values\\[1\\]' = nan is not a finite number|${seed}|--set|dirichlet[0].values=[0.0, nan, 0.05]"
  "refuse_young_zero|key 'material\\.young' = 0 is out of range: must be > 0|${seed}|--set|material.young=0"
  "refuse_young_negative|key 'material\\.young' = -3000 is out of range: must be > 0|${seed}|--set|material.young=-3000"
  "refuse_poisson_half|key 'material\\.poisson' = 0\\.5 is out of range: must be in \\[-0\\.999999, 0\\.4999995\\]|${seed}|--set|material.poisson=0.5"
  "refuse_poisson_above_half|key 'material\\.poisson' = 0\\.6 is out of range|${seed}|--set|material.poisson=0.6"
  "refuse_friction_negative|key 'contact\\.friction' = -0\\.1 is out of range: must be >= 0|${seed}|--set|contact.friction=-0.1"
  "refuse_one_step|key 'time\\.steps' = 1 is out of range: must be >= 2|${seed}|--set|time.steps=1"
  "refuse_times_repeated|key 'dirichlet\\[0\\]\\.times' must be strictly increasing, but entry 2 = 0\\.2 follows 0\\.2|${seed}|--set|dirichlet[0].times=[0.0, 0.2, 0.2]"
  "refuse_times_decreasing|key 'dirichlet\\[1\\]\\.times' must be strictly increasing, but entry 2 = 0\\.1 follows 0\\.2|${seed}|--set|dirichlet[1].times=[0.0, 0.2, 0.1]"
  "refuse_empty_boundary|key 'contact\\.boundary' must not be empty|${seed}|--set|contact.boundary=\"\""
  "refuse_unknown_contact_boundary|key 'contact\\.boundary': boundary 'rim' is not in the mesh \\(it has: 'arc' 'top'\\)|${seed}|--set|contact.boundary=rim"
  "refuse_unknown_dirichlet_boundary|key 'dirichlet\\[1\\]\\.boundary': boundary 'rim' is not in the mesh|${seed}|--set|dirichlet[1].boundary=rim"
  "refuse_inverted_element|inverted\\.msh: line 36: triangle 4 is inverted|${bad}/inverted.toml"
  "refuse_initial_penetration|contact node [0-9]+ at \\(.*\\) starts inside the obstacle \\(initial gap -[0-9.e-]+ < 0|${seed}|--set|obstacle.point=[0.0, -0.99]"
  "refuse_missing_mesh|cannot open mesh file '.*no_such\\.msh'|${trunc}|--set|mesh.file=no_such.msh"
  "refuse_empty_mesh|empty\\.msh: empty file|${trunc}|--set|mesh.file=empty.msh"
  "refuse_truncated_mesh|truncated\\.msh: line 1123: expected 3 numbers \\(x y z\\) for node 455|${trunc}"
  "refuse_tol_nan|--tol must be > 0|${seed}|${small_fields}|--tol|nan"
  "refuse_max_iterations_zero|--max-iterations must be >= 1|${seed}|${small_fields}|--max-iterations|0"
  "refuse_free_translation|key 'dirichlet': the conditions leave the body free to move rigidly \\(translation along x\\)|${bad}/free_translation.toml"
  "refuse_period_off_grid|key 'dirichlet\\[0\\]\\.period' = 0\\.2012 is not a whole number of time steps|${seed}|--set|dirichlet[0].period=0.2012|--set|dirichlet[0].cycles=2"
  "refuse_negative_obstacle_radius|key 'obstacle\\.radius' = -1 is out of range: must be > 0|${scenes}/hemicylinder_seat.toml|--set|obstacle.radius=-1"
  "refuse_obstacles_overlapping_the_body|starts inside the obstacle|${scenes}/hemicylinder_seat.toml|--set|obstacle.radius=1.5"
  "refuse_pair_negative_mirror_gap|key 'mesh\\.mirror_gap' = -0\\.1 is out of range: must be >= 0|${pair}|--set|mesh.mirror_gap=-0.1"
  "refuse_pair_with_obstacle|table \\[obstacle\\] and key 'contact\\.master' exclude each other|${pair}|--set|obstacle.point=[0.0, -1.01]"
  "refuse_pair_same_boundary|key 'contact\\.master' must name another boundary than 'contact\\.boundary'|${pair}|--set|contact.master=arc"
  "refuse_pair_not_facing|slave node 0 at \\(-1, 0\\) does not face the master boundary|${pair}|--set|contact.master=mirror_top"
  "refuse_pair_overlapping|has no master node on its line along contact\\.normal \\(no master node lies on the master's side|${pair}|--set|contact.normal=[0.0, -1.0]"
  "refuse_pair_normal_zero|key 'contact\\.normal' = \\[0, 0\\] must be a nonzero finite vector|${pair}|--set|contact.normal=[0.0, 0.0]"
  "refuse_master_material_without_master|table \\[master_material\\] applies to two bodies only|${seed}|--set|master_material.young=9000|--set|master_material.poisson=0.3"
  "refuse_normal_without_master|key 'contact\\.normal' applies to two bodies only|${seed}|--set|contact.normal=[0.0, 1.0]"
  "refuse_pairing_without_master|key 'contact\\.pairing' applies to two bodies only|${seed}|--set|contact.pairing=segment"
  "refuse_pairing_unknown|key 'contact\\.pairing'.*node.*segment|${pair}|--set|contact.pairing=surface"
  "refuse_segment_without_normal|key 'contact\\.pairing' = \"segment\" needs 'contact\\.normal'|${bad}/pair_segment_without_normal.toml"
  "refuse_nonmatching_node_to_node|interface meshes do not match \\(node-to-node contact needs matching meshes. contact\\.pairing = \"segment\" pairs non-matching ones\\)|${scenes}/fretting_pad.toml|--set|mesh.file=../meshes/fretting_pad_nonmatching_small.msh"
  "refuse_pair_free_body|free to move rigidly \\(body 2 of 2, around \\(0, -1\\.55\\): translation along x, translation along y, rotation about z\\)|${bad}/pair_free_body.toml"
  "refuse_obstacle_motion_boundary|key 'obstacle\\.motion\\[0\\]\\.boundary' does not apply to the obstacle's motion|${scenes}/moving_pad.toml|--set|obstacle.motion[0].boundary=arc"
  "refuse_obstacle_motion_period_off_grid|key 'obstacle\\.motion\\[1\\]\\.period' = 0\\.201 is not a whole number of time steps|${scenes}/moving_pad.toml|--set|obstacle.motion[1].period=0.201"
  "refuse_surface_in_2d|key 'obstacle\\.type' = \"surface\" needs a 3D scene|${seed}|--set|obstacle.type=surface|--set|obstacle.file=x.msh"
  "refuse_surface_missing_file|cannot open mesh file '.*no_such\\.msh'|${scenes}/on_sphere_surface.toml|--set|obstacle.file=no_such.msh"
  "refuse_surface_volume_mesh|tetrahedron 251: a rigid surface is given by its triangles alone|${scenes}/on_sphere_surface.toml|--set|obstacle.file=../meshes/half_ball_graded_small.msh"
  "refuse_surface_foreign_key|key 'obstacle\\.point' does not apply to obstacle\\.type = \"surface\"|${scenes}/hemisphere.toml|--set|obstacle.type=surface"
  "refuse_polyline_odd|key 'obstacle\\.points' must list x, y pairs of at least two points|${scenes}/groove.toml|--set|obstacle.points=[-2.0, -0.2, 0.0]"
  "refuse_polyline_coincident|key 'obstacle\\.points': points 0 and 1 coincide|${scenes}/groove.toml|--set|obstacle.points=[0.0, -1.2, 0.0, -1.2, 2.0, -0.2]"
  "refuse_polyline_point_key|key 'obstacle\\.point' does not apply to obstacle\\.type = \"polyline\" \\(its keys: 'points'\\)|${scenes}/groove.toml|--set|obstacle.point=[0.0, 0.0]"
  "refuse_polyline_in_3d|key 'obstacle\\.type' = \"polyline\" needs a 2D scene|${hemisphere_scene}|--set|obstacle.type=polyline"
  "refuse_polyline_through_the_body|starts inside the obstacle|${scenes}/groove.toml|--set|obstacle.points=[-2.0, -0.2, 0.0, -0.9, 2.0, -0.2]"
  "refuse_loads_only|free to move rigidly \\(translation along x. translation along y. rotation about z\\)|${bad}/loads_only.toml"
  "bad_check_free_translation|free to move rigidly \\(translation along x\\).*prescribe it on a boundary|check|${bad}/free_translation.toml"
  "bad_check_loads_only|free to move rigidly \\(translation along x. translation along y. rotation about z\\)|check|${bad}/loads_only.toml"
  "refuse_search_scale_tiny|the search direction's scale κ R / L = 1e-08 .* must be in \\[0\\.01, 100\\]|${seed}|--set|solver.search_scale=1e-8"
  "refuse_arc_nodes_overflow|the problem does not fit in memory: mesh\\.arc_nodes = 2147483647|${seed}|--set|mesh.arc_nodes=2147483647"
  "refuse_steps_huge|does not fit in memory: .*time\\.steps = 100000000|${seed}|--set|time.steps=100000000"
  "bad_threads_huge|--threads: thread count 2147483647: must be in \\[1, [0-9]+\\]|solve|${seed}|${small_fields}|--threads|2147483647"
  "refuse_young_overflow|key 'material\\.young': the stiffness matrix's largest entry .* is not finite|${seed}|--set|material.young=1e308"
  "refuse_young_underflow|key 'material\\.young': .* outside \\[1e-150, 1e150\\]|${seed}|--set|material.young=1e-308"
  "refuse_time_end_overflow|key 'time\\.end': instant t_2 = inf is not finite|${seed}|--set|time.end=1e308"
  "refuse_radius_overflow|the elements' mean area is not finite: not computed reliably|${seed}|--set|mesh.radius=1e308"
  "refuse_length_scale_tiny|κ R / L = 40000 \\(κ = solver\\.search_scale = 4, L = contact\\.length_scale = 0\\.0001|${seed}|--set|contact.length_scale=1e-4")
foreach(row IN LISTS stc_refusals)
  string(REPLACE "|" ";" fields "${row}")
  list(POP_FRONT fields name pattern)
  if(name MATCHES "^refuse_(.*)")
    list(POP_FRONT fields scene)
    add_test(NAME cli.${name}
             COMMAND bash ${expect} --absent ${refused}/${CMAKE_MATCH_1} 1 "${pattern}"
                     ${cli} solve ${scene} --solver latin --out ${refused}/${CMAKE_MATCH_1} ${fields})
    set_tests_properties(cli.${name} PROPERTIES LABELS cli)
  else()
    stc_cli_test(${name} 1 "${pattern}" ${fields})
  endif()
endforeach()

# svd checks --modes before it creates its folder.
add_test(NAME cli.bad_svd_modes_zero
         COMMAND bash ${expect} --absent ${refused}/svd_modes_zero 1 "--modes = 0 must be in \\[1, 20\\]"
                 ${cli} svd ${seed} ${small} --modes 0 --out ${refused}/svd_modes_zero)
set_tests_properties(cli.bad_svd_modes_zero PROPERTIES LABELS cli)

# An address-space limit below any run's need is refused at once (OpenBLAS 0.3.21 spun forever
# under ulimit -v 100-200 MB), and nothing is written.
add_test(NAME cli.refuse_low_address_space
         COMMAND bash -c "ulimit -v 300000 && bash ${expect} --absent ${refused}/low_address_space 1 \
           'address-space limit \\(ulimit -v\\) is 307 MB, below' ${cli} solve ${seed} --out ${refused}/low_address_space")
set_tests_properties(cli.refuse_low_address_space PROPERTIES LABELS "cli;address_space")

# A solve interrupted by SIGINT or SIGTERM at any moment, from its first iterations to the middle of
# its VTU series, leaves its output folder whole (one complete run) with nothing beside it.
add_test(NAME cli.interrupted_runs_leave_whole_folders
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/interrupt_runs.sh ${cli} ${scenes}/hemisphere.toml
                 ${CMAKE_CURRENT_BINARY_DIR}/interrupted --set mesh.divisions=5 --set time.steps=101)
set_tests_properties(cli.interrupted_runs_leave_whole_folders PROPERTIES LABELS cli TIMEOUT 600
                     ENVIRONMENT "STC_PYTHON=${Python3_EXECUTABLE}")

# A re-run into a folder replaces it as a whole: no frame of a longer series stays behind; a folder
# that holds other files is refused, not replaced.
add_test(NAME cli.rerun_replaces_the_folder
         COMMAND bash -c "rm -rf ${refused}/rerun && ${cli} solve ${seed} ${small_text} --solver latin --out ${refused}/rerun --quiet --set output.format=\\\"vtu\\\" \
           && ${cli} solve ${seed} ${small_text} --solver latin --out ${refused}/rerun --quiet --set output.frame_stride=10 --set output.format=\\\"vtu\\\" \
           && [ \"$(ls ${refused}/rerun/vtu | wc -l)\" = 3 ] && touch ${refused}/rerun/notes.txt && rm ${refused}/rerun/.stcontact-run \
           ${refused}/rerun/summary.json && bash ${expect} 1 \"holds files that are not a run's\" ${cli} solve ${seed} ${small_text} \
           --solver latin --out ${refused}/rerun && [ -f ${refused}/rerun/notes.txt ]")
set_tests_properties(cli.rerun_replaces_the_folder PROPERTIES LABELS cli)

# Progress in batch logs (docs/interface.md, "Progress and messages"): with standard error a file,
# plain "progress:" lines (no carriage return), none with --progress-interval 0 or --quiet.
add_test(NAME cli.progress_lines_in_a_log
         COMMAND bash -c "set -e; d=${out}/progress_log; rm -rf $d; mkdir -p $d \
           && ${cli} solve ${seed} ${small_text} --solver latin --out $d/run --progress-interval 0.001 2>$d/log >/dev/null \
           && grep -Eq '^progress: latin: iteration [0-9]+  indicator [0-9.e+-]+  estimate [0-9.e+-]+' $d/log \
           && ! grep -q $'\\r' $d/log \
           && ${cli} solve ${seed} ${small_text} --solver latin --out $d/run --progress-interval 0 2>$d/off >/dev/null \
           && ${cli} solve ${seed} ${small_text} --solver latin --out $d/run --quiet --progress-interval 0.001 2>$d/quiet \
           && ! grep -q progress: $d/off $d/quiet")
set_tests_properties(cli.progress_lines_in_a_log PROPERTIES LABELS cli)
# The incremental reference (the true error column of history.csv) is skipped beyond 1000 contact nodes
# unless --reference asks for it (1161 nodes here); --reference and --no-reference exclude each other.
add_test(NAME cli.reference_whatever_the_size
         COMMAND bash -c "set -e; d=${out}/reference_size; rm -rf $d; mkdir -p $d; \
           S='--set mesh.divisions=10 --set output.frames=false --quiet'; \
           ${cli} solve ${scenes}/hemisphere_shallow.toml $S --out $d/default \
           && ${cli} solve ${scenes}/hemisphere_shallow.toml $S --reference --out $d/asked \
           && tail -1 $d/default/history.csv | grep -Eq '^[0-9]+,[0-9]+,[0-9.e+-]+,,' \
           && tail -1 $d/asked/history.csv | grep -Eq '^[0-9]+,[0-9]+,[0-9.e+-]+,[0-9]\\.[0-9]+e-0[7-9],' \
           && bash ${expect} 1 'excludes' ${cli} solve ${scenes}/hemisphere_shallow.toml --reference --no-reference")
set_tests_properties(cli.reference_whatever_the_size PROPERTIES LABELS cli)
# The phase after the last iteration (the far nodes' lift of a zone solve, SolveInputs::phase_note),
# which no iteration line covers, is told at once in the log and kept in run.log.
add_test(NAME cli.progress_phase_after_the_iteration
         COMMAND bash -c "set -e; d=${out}/progress_phase; rm -rf $d; mkdir -p $d \
           && ${cli} solve ${scenes}/hemisphere_shallow.toml --no-reference --set output.frames=false --out $d/run 2>$d/log >/dev/null \
           && grep -Eq '^progress: fas-apriori: after the last iteration: the displacement from the converged history, at most [0-9]+ sparse solves$' $d/log \
           && grep -Eq '^progress: fas-apriori: after the last iteration: [1-9][0-9]* sparse solves, [0-9.]+ s$' $d/run/run.log")
set_tests_properties(cli.progress_phase_after_the_iteration PROPERTIES LABELS cli)
# On a backend without a trailing block the incremental solver (and a solve's reference) solves for
# the Delassus columns of the nodes within reach before its first record: told at once, in the log.
if(STC_HAVE_PETSC)
  add_test(NAME cli.progress_phase_before_the_march
           COMMAND bash -c "set -e; d=${out}/progress_march; rm -rf $d; mkdir -p $d \
             && ${cli} solve ${scenes}/hemisphere_shallow.toml --solver incremental --set 'solver.linear=\"cg-gamg\"' \
                --set output.frames=false --out $d/run 2>$d/log >/dev/null \
             && grep -Eq '^progress: incremental: before the march: the Delassus columns of the [1-9][0-9]* nodes within reach, [1-9][0-9]* sparse solves$' $d/log \
             && grep -Eq '^progress: incremental: before the march: [1-9][0-9]* sparse solves, [0-9.]+ s$' $d/run/run.log")
  set_tests_properties(cli.progress_phase_before_the_march PROPERTIES LABELS cli)
endif()
stc_cli_test(bad_progress_interval 1 "--progress-interval: -1 seconds: must be >= 0" solve ${seed}
             --progress-interval -1)

# An empty --solvers list is an error (leaving the option out runs every strategy), before any folder.
add_test(NAME cli.bad_compare_solvers_empty
         COMMAND bash -c "bash ${expect} --absent ${refused}/solvers_empty 1 '--solvers: the list is empty' \
           ${cli} compare ${seed} --solvers '' --out ${refused}/solvers_empty")
set_tests_properties(cli.bad_compare_solvers_empty PROPERTIES LABELS cli)

# Unwritable output folders: refused before the solve, and nothing created or changed.
stc_cli_test(refuse_out_in_proc 1 "cannot create output folder '/proc/stcontact-out'" solve ${seed} ${small}
             --solver latin --out /proc/stcontact-out)
# --out names an existing file: refused, and the file keeps its content (no temporary left beside it).
set(out_file ${refused}/out_is_a_file/file)
add_test(NAME cli.refuse_out_is_a_file
         COMMAND bash -c "rm -rf ${refused}/out_is_a_file && mkdir -p ${refused}/out_is_a_file && echo keep >${out_file} \
           && bash ${expect} 1 \"output folder '${out_file}' exists and is not a folder\" ${cli} solve ${seed} \
                --solver latin --out ${out_file} \
           && [ \"$(cat ${out_file})\" = keep ] && [ \"$(ls -A ${refused}/out_is_a_file)\" = file ]")
set_tests_properties(cli.refuse_out_is_a_file PROPERTIES LABELS cli)

# Threads (docs/threads.md): --threads and STC_THREADS set the count; summary.json records it; a
# bad count is refused before the output folder is created.
stc_cli_test(solve_latin_two_threads 0 "latin: converged" solve ${seed} ${small} --solver latin --threads 2
             --out ${out}/latin_t2)
add_test(NAME cli.solve_records_threads
         COMMAND bash -c "grep -q '\"threads\": 2' ${out}/latin_t2/summary.json")
set_tests_properties(cli.solve_records_threads PROPERTIES DEPENDS cli.solve_latin_two_threads LABELS cli)
stc_cli_test(bad_threads_zero 1 "--threads" solve ${seed} ${small} --threads 0)
add_test(NAME cli.bad_stc_threads
         COMMAND bash ${expect} --absent ${refused}/bad_stc_threads 1 "STC_THREADS = 'two'"
                 env STC_THREADS=two ${cli} solve ${seed} ${small} --out ${refused}/bad_stc_threads)
set_tests_properties(cli.bad_stc_threads PROPERTIES LABELS cli)

# Trust where users abuse the program (tests/cli/trust_checks.sh): a run folder replaces only what a
# run wrote, every run stops on a signal also in its set-up, devices and pipes are refused, and the
# messages name what is wrong.
add_test(NAME cli.trust_checks
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/trust_checks.sh ${cli} ${PROJECT_SOURCE_DIR}
                 ${CMAKE_CURRENT_BINARY_DIR}/trust)
set_tests_properties(cli.trust_checks PROPERTIES LABELS cli TIMEOUT 300)

# Two MPI ranks give one process's answer (tests/cli/mpi_ranks.sh, docs/linear_solvers.md "Ranks"):
# in a build with PETSc, where mpirun is found.
find_program(STC_MPIRUN mpirun)
if(STC_HAVE_PETSC AND STC_MPIRUN)
  add_test(NAME cli.mpi_ranks
           COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/mpi_ranks.sh ${cli} ${PROJECT_SOURCE_DIR}
                   ${CMAKE_CURRENT_BINARY_DIR}/mpi_ranks)
  set_tests_properties(cli.mpi_ranks PROPERTIES LABELS "cli;mpi" TIMEOUT 600 ENVIRONMENT "STC_PYTHON=${Python3_EXECUTABLE}")
endif()

# stcontact true-error: the true error of a written solution, read back (tests/cli/true_error_checks.sh:
# it agrees with the run's own), and refused on a file of another scene or no solution at all.
add_test(NAME cli.true_error_agrees_with_the_run
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/true_error_checks.sh ${cli} ${PROJECT_SOURCE_DIR}
                 ${CMAKE_CURRENT_BINARY_DIR}/true_error)
set_tests_properties(cli.true_error_agrees_with_the_run PROPERTIES LABELS cli)
set(true_error_run ${CMAKE_CURRENT_BINARY_DIR}/true_error/fas/solution.h5)
stc_cli_test(true_error_other_sizes 1 "was not solved on this scene: it holds 2D, .* 21 contact nodes, 21 instants"
             true-error ${seed} --set mesh.arc_nodes=31 --set time.steps=21 --solution ${true_error_run})
stc_cli_test(true_error_other_model 1 "was not solved on this scene: the model differs"
             true-error ${seed} ${small} --set contact.friction=0.3 --solution ${true_error_run})
stc_cli_test(true_error_not_hdf5 1 "cannot read '.*hemicylinder.toml': not an HDF5 file"
             true-error ${seed} ${small} --solution ${seed})
stc_cli_test(true_error_missing 1 "cannot read '.*none.h5': no such file" true-error ${seed} ${small} --solution none.h5)
set_tests_properties(cli.true_error_other_sizes cli.true_error_other_model PROPERTIES DEPENDS cli.true_error_agrees_with_the_run)
