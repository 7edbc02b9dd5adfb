#!/usr/bin/python3
"""Bad-input tests: poroseam run on a broken scene must fail cleanly.

    bad_input.py --case NAME [--ranks N]     one case (one ctest each, label "input")
    bad_input.py --list                      the case names

A failure case passes when
  (a) the exit status is non-zero,
  (b) the error text names the offending item (option, file or value): every expected
      substring must occur in the output *without* PETSc's echo of the options
      (the "Option left: ..." lines and the "PETSc Option Table entries" block are removed
      first, since they contain every option and would make any name match),
  (c) there is no crash signature ("Segmentation", "Caught signal", "core dumped", ...),
  (d) it ends within a few seconds (the driver kills it after 60 s and fails: a hang).
Two cases instead check a good run: an unused option is reported as "never used", and
`poroseam -help` exits 0 and prints the scene options of docs/scenes.md.

The base scene is tests/verification/terzaghi_2d.opts (a valid scene); each case adds
command-line options (which override the file) or drops options from a copy of the scene.
"""

import argparse
import os
import random
import re
import shutil
import struct
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")
BASE_SCENE = os.path.join(SOURCE, "tests", "verification", "terzaghi_2d.opts")
# a joint with flow across a 2-layer column (meshes/joint_column_2d.geo): interface cases
JOINT_SCENE = os.path.join(SOURCE, "options", "joint_column_2d.opts")
TIMEOUT = 60.0        # a run still going after this is a hang
MAX_SECONDS = 15.0    # "finishes in seconds" (the mesh is meshed by gmsh first)
# signals as crashes report them (PETSc's "Caught signal number 11", Open MPI's "exited on
# signal", "Signal: Segmentation fault"), not the word itself: -help prints the documentation,
# which names the signals that stop a run cleanly (docs/checkpoints.md)
CRASH = [r"Segmentation", r"(?i)caught signal|exited on signal|signal:\s|signal code",
         r"core dumped", r"Floating point exception",
         r"std::bad_alloc", r"terminate called", r"SIGSEGV|SIGBUS|SIGFPE|SIGABRT"]

# a valid Mohr-Coulomb soil for the base scene (c = 10 kPa, phi = 30, psi = 5 degrees)
MOHR_COULOMB = ["-region_soil_material", "mohr_coulomb", "-region_soil_cohesion", "1e4",
                "-region_soil_friction_angle", "30", "-region_soil_dilation_angle", "5"]

# name: dict(args=[...], drop=[options removed from the scene], expect=[substrings],
#            ranks=1, ok=False (expect success instead of failure))
CASES = {
    "missing_mesh": dict(args=["-mesh", "meshes/does_not_exist.msh"],
                         expect=["meshes/does_not_exist.msh", "does not exist"]),
    # a real Gmsh geometry, copied under a name that is neither .msh nor .geo
    "mesh_extension": dict(args=["-mesh", "{out}/column.txt"], copy=("meshes/terzaghi_column_2d.geo", "column.txt"),
                           expect=["column.txt", ".msh"]),
    "unknown_region": dict(args=["-regions", "soil,rock"], expect=["'rock'", "-regions"]),
    "unknown_boundary": dict(args=["-boundaries", "top,bottom,left,right,roof"],
                             expect=["'roof'", "-boundaries"]),
    # 'right' is a boundary of the mesh, but not listed in -boundaries, and has -bc_right_ux 0
    "bc_unlisted_boundary": dict(args=["-boundaries", "top,bottom,left"], expect=["-bc_right_ux"]),
    "missing_E": dict(drop=["-region_soil_E"], expect=["-region_soil_E", "missing"]),
    "E_zero": dict(args=["-region_soil_E", "0"], expect=["-region_soil_E", "> 0"]),
    "E_negative": dict(args=["-region_soil_E", "-1e6"], expect=["-region_soil_E", "> 0"]),
    "nu_half": dict(args=["-region_soil_nu", "0.5"], expect=["-region_soil_nu", "0.5"]),
    "nu_below_minus_one": dict(args=["-region_soil_nu", "-1.2"], expect=["-region_soil_nu", "-1.2"]),
    "negative_permeability": dict(args=["-region_soil_permeability", "-1e-12"],
                                  expect=["-region_soil_permeability"]),
    "missing_material": dict(drop=["-region_soil_material"], expect=["-region_soil_material"]),
    "unknown_material": dict(args=["-region_soil_material", "clay"],
                             expect=["-region_soil_material", "clay"]),
    # PETSc's own parser rejects the value; the message must still say which option it was
    "non_numeric": dict(args=["-region_soil_E", "abc"], expect=["abc", "-region_soil_E"]),
    "probe_wrong_coords": dict(args=["-probe_bad", "0.05"], expect=["-probe_bad", "expected 2"]),
    "probe_outside": dict(args=["-probe_far", "5,5"], expect=["-probe_far", "outside the mesh"]),
    # meshes/bad_inverted.msh: 2 triangles in the unit square, element 6 is clockwise
    "inverted_element": dict(args=["-mesh", "meshes/bad_inverted.msh"], expect=["inverted element"]),
    # the same failures on 2 ranks: must exit (every rank), not hang
    "probe_outside_np2": dict(args=["-probe_far", "5,5"], expect=["-probe_far", "outside the mesh"],
                              ranks=2),
    "inverted_element_np2": dict(args=["-mesh", "meshes/bad_inverted.msh"],
                                 expect=["inverted element"], ranks=2),
    "missing_E_np2": dict(drop=["-region_soil_E"], expect=["-region_soil_E"], ranks=2),
    # --- malformed .msh files (written by msh_fixture below, into the case's directory): PETSc's
    # reader trusts the file (a missing node crashed it with SIGSEGV); poroseam checks it first
    # and names the file
    "msh22_missing_node": dict(msh=("22", "missing_node"), expect=["bad.msh", "refers to node 9"]),
    "msh41_missing_node": dict(msh=("41", "missing_node"), expect=["bad.msh", "refers to node 9"]),
    "msh41_binary_missing_node": dict(msh=("41b", "missing_node"),
                                      expect=["bad.msh", "refers to node 9"]),
    "msh22_binary_missing_node": dict(msh=("22b", "missing_node"),
                                      expect=["bad.msh", "refers to node 9"]),
    "msh22_truncated_elements": dict(msh=("22", "truncate_elements"), expect=["bad.msh", "truncated"]),
    "msh22_truncated_nodes": dict(msh=("22", "truncate_nodes"), expect=["bad.msh", "truncated"]),
    "msh41_binary_truncated": dict(msh=("41b", "truncate_nodes"), expect=["bad.msh", "truncated"]),
    "msh22_node_count_high": dict(msh=("22", "node_count_high"),
                                  expect=["bad.msh", "'$EndNodes' where a node tag was expected"]),
    "msh22_element_count_low": dict(msh=("22", "element_count_low"),
                                    expect=["bad.msh", "expected $EndElements"]),
    "msh41_node_count_mismatch": dict(msh=("41", "node_count_high"),
                                      expect=["bad.msh", "hold 4 nodes, 6 declared"]),
    "msh_garbage": dict(msh=("22", "garbage"), expect=["bad.msh", "does not start with $MeshFormat"]),
    "msh_empty": dict(msh=("22", "empty"), expect=["bad.msh", "the file is empty"]),
    "msh_geo_text": dict(msh=("22", "geo_text"), expect=["bad.msh", "does not start with $MeshFormat"]),
    "msh_version_3": dict(msh=("22", "version_3"), expect=["bad.msh", "MSH format 3", "msh22"]),
    # one 6-node triangle among linear elements (second-order files are read for
    # -mesh_geometry_order 2, tests/input/curved_input.py; a mixed one is refused)
    "msh_second_order": dict(msh=("22", "second_order"),
                             expect=["bad.msh", "element 5 is of order 2", "gmsh -order 1 or 2"]),
    "msh_no_physical_names": dict(msh=("22", "no_physical_names"),
                                  expect=["bad.msh", "no $PhysicalNames"]),
    "msh_nan_coordinate": dict(msh=("22", "nan"), expect=["bad.msh", "not a finite number"]),
    "msh_duplicate_node": dict(msh=("22", "duplicate_node"), expect=["bad.msh", "node 3 is defined twice"]),
    "msh41_unknown_entity": dict(msh=("41", "unknown_entity"),
                                 expect=["bad.msh", "entity 7", "not in $Entities"]),
    "mesh_directory": dict(args=["-mesh", "{out}/dir.msh"], mkdir="dir.msh",
                           expect=["dir.msh", "is a directory"]),
    "geo_syntax_error": dict(args=["-mesh", "{out}/broken.geo"], write=("broken.geo", "Point(1) = {0, 0;\n"),
                             expect=["gmsh failed to mesh", "broken.geo", "gmsh.log"]),
    # --- scene lists and conditions
    "duplicate_regions": dict(args=["-regions", "soil,soil"], expect=["-regions", "'soil' twice"]),
    "duplicate_boundaries": dict(args=["-boundaries", "top,bottom,left,right,top"],
                                 expect=["-boundaries", "'top' twice"]),
    "duplicate_interfaces": dict(scene=JOINT_SCENE, args=["-interfaces", "joint,joint"],
                                 expect=["-interfaces", "'joint' twice"]),
    "duplicate_surfaces": dict(scene=JOINT_SCENE, args=["-interface_joint_surfaces", "joint,joint"],
                               expect=["-interface_joint_surfaces", "'joint' twice"]),
    "surface_in_two_interfaces": dict(
        scene=JOINT_SCENE, args=["-interfaces", "joint,other", "-interface_other_surfaces", "joint",
                                 "-interface_other_side1", "lower", "-interface_other_KN", "1e12",
                                 "-interface_other_KT", "1e12", "-interface_other_friction", "0.5"],
        expect=["'joint' and 'other'", "face group 'joint'"]),
    "interface_on_outer_boundary": dict(scene=JOINT_SCENE, args=["-interface_joint_surfaces", "top", "-interface_joint_side1", "upper"],
                                        expect=["interface 'joint'", "'top'", "outer boundary"]),
    "p3_boundary_not_met": dict(scene=JOINT_SCENE, args=["-bc_top_p3", "0"],
                                expect=["-bc_top_p3", "no interface with flow", "'top'"]),
    "flux_and_pressure": dict(args=["-bc_top_flux", "1e-6"], expect=["-bc_top_flux", "-bc_top_p"]),
    # --- numeric options: the message names the option, not only the value
    "ts_max_steps_abc": dict(args=["-ts_max_steps", "abc"], expect=["-ts_max_steps abc", "integer"]),
    "ts_dt_abc": dict(args=["-ts_dt", "abc"], expect=["-ts_dt abc", "number"]),
    "ts_max_time_abc": dict(args=["-ts_max_time", "1x"], expect=["-ts_max_time 1x", "number"]),
    "snes_max_it_real": dict(args=["-snes_max_it", "2.5"], expect=["-snes_max_it 2.5", "integer"]),
    "prefixed_ksp_rtol_abc": dict(args=["-fieldsplit_pressure_ksp_rtol", "tight"],
                                  expect=["-fieldsplit_pressure_ksp_rtol tight", "number"]),
    # not in poroseam's table: PETSc's parser meets it inside the solve (inside log stages and
    # events); the error handler finds the option by its value
    "mumps_icntl_abc": dict(args=["-mat_mumps_icntl_14", "lots"],
                            expect=["-mat_mumps_icntl_14 lots", "integer"]),
    "output_fields_every_x": dict(args=["-output_fields_every", "x"],
                                  expect=["-output_fields_every x"]),
    "solver_auto_threshold_abc": dict(args=["-solver_auto_threshold", "many"],
                                      expect=["-solver_auto_threshold many", "integer"]),
    "mesh_size_factor_abc": dict(args=["-mesh_size_factor", "half"], expect=["-mesh_size_factor half"]),
    "ts_max_time_zero": dict(args=["-ts_max_time", "0"], expect=["-ts_max_time 0", "> 0"]),
    "ts_max_time_negative": dict(args=["-ts_max_time", "-5"], expect=["-ts_max_time -5", "> 0"]),
    "ts_max_steps_zero": dict(args=["-ts_max_steps", "0"], expect=["-ts_max_steps 0", "> 0"]),
    # run endings and restarts (docs/checkpoints.md): a run that stops before its final time
    # fails and says where; restart options that cannot be honoured are refused
    "step_limit_before_final_time": dict(args=["-ts_max_steps", "2"],
                                         expect=["stopped at step 2", "-ts_max_steps 2", "final time 25"]),
    "checkpoint_every_negative": dict(args=["-checkpoint_every", "-1"], expect=["-checkpoint_every -1"]),
    "checkpoint_every_abc": dict(args=["-checkpoint_every", "abc"], expect=["-checkpoint_every abc", "integer"]),
    "checkpoint_with_bdf2": dict(args=["-ts_type", "bdf", "-ts_bdf_order", "2", "-checkpoint_every", "2"],
                                 expect=["-checkpoint_every", "backward Euler"]),
    "restart_missing_dir": dict(args=["-restart", "{out}/no_such_run"], expect=["-restart", "no_such_run", "no such directory"]),
    "restart_no_checkpoint": dict(args=["-restart", "{out}"], expect=["-restart", "no checkpoint"]),
    "restart_step_without_restart": dict(args=["-restart_step", "3"], expect=["-restart_step 3", "-restart"]),
    "ts_max_reject_negative": dict(args=["-ts_max_reject", "-1"], expect=["-ts_max_reject -1", ">= 0"]),
    "ts_dt_zero": dict(args=["-ts_dt", "0"], expect=["-ts_dt 0", "> 0"]),
    # --- mesh size: estimated before gmsh runs, limit -mesh_max_elements
    "mesh_size_factor_absurd": dict(args=["-mesh_size_factor", "0.0005"],
                                    expect=["-mesh_size_factor 0.0005", "-mesh_max_elements"]),
    "mesh_max_elements_exceeded": dict(msh=("22", "good"), args=["-mesh_max_elements", "1"],
                                       expect=["bad.msh", "has 2 elements", "-mesh_max_elements 1"]),
    "mesh_max_elements_abc": dict(args=["-mesh_max_elements", "lots"],
                                  expect=["-mesh_max_elements lots", "whole number"]),
    # --- files and directories
    "missing_options_file": dict(raw=["-options_file", "{out}/nope.opts"],
                                 expect=["nope.opts", "-options_file", "does not exist"]),
    "options_file_directory": dict(raw=["-options_file", "{out}"],
                                   expect=["-options_file", "is a directory"]),
    "output_dir_under_file": dict(args=["-output_dir", "{out}/afile/results"], write=("afile", "x"),
                                  expect=["afile/results", "-output_dir", "Not a directory"]),
    "output_dir_is_file": dict(args=["-output_dir", "{out}/afile"], write=("afile", "x"),
                               expect=["afile", "-output_dir"]),
    # an error inside a log stage with a nested -log_view format: only the real error
    "error_in_log_stage": dict(args=["-regions", "soil,rock", "-log_view", ":{out}/log.xml:ascii_xml"],
                               expect=["'rock'"], absent_text=["parents", "Entry"]),
    "error_in_solve_log_events": dict(
        args=["-mat_mumps_icntl_14", "lots", "-log_view", ":{out}/log.txt:ascii_flamegraph"],
        expect=["-mat_mumps_icntl_14 lots"], absent_text=["parents", "Entry", "unbalanced"]),
    # the same on 2 ranks: one line, every rank exits
    "msh22_missing_node_np2": dict(msh=("22", "missing_node"), expect=["bad.msh", "refers to node 9"],
                                   ranks=2),
    "msh_garbage_np2": dict(msh=("22", "garbage"), expect=["bad.msh", "$MeshFormat"], ranks=2),
    "mesh_directory_np2": dict(args=["-mesh", "{out}/dir.msh"], mkdir="dir.msh",
                               expect=["dir.msh", "is a directory"], ranks=2),
    "interface_on_outer_boundary_np2": dict(scene=JOINT_SCENE, args=["-interface_joint_surfaces", "top", "-interface_joint_side1", "upper"],
                                            expect=["interface 'joint'", "outer boundary"], ranks=2),
    "p3_boundary_not_met_np2": dict(scene=JOINT_SCENE, args=["-bc_top_p3", "0"],
                                    expect=["-bc_top_p3", "no interface with flow"], ranks=2),
    "duplicate_regions_np2": dict(args=["-regions", "soil,soil"], expect=["'soil' twice"], ranks=2),
    "ts_max_steps_abc_np2": dict(args=["-ts_max_steps", "abc"], expect=["-ts_max_steps abc"], ranks=2),
    "mumps_icntl_abc_np2": dict(args=["-mat_mumps_icntl_14", "lots"],
                                expect=["-mat_mumps_icntl_14 lots"], ranks=2),
    "ts_max_reject_negative_np2": dict(args=["-ts_max_reject", "-1"], expect=["-ts_max_reject -1"],
                                       ranks=2),
    "missing_options_file_np2": dict(raw=["-options_file", "{out}/nope.opts"],
                                     expect=["nope.opts", "does not exist"], ranks=2),
    "output_dir_under_file_np2": dict(args=["-output_dir", "{out}/afile/results"], write=("afile", "x"),
                                      expect=["afile/results", "Not a directory"], ranks=2),
    "error_in_log_stage_np2": dict(args=["-regions", "soil,rock", "-log_view", ":{out}/log.xml:ascii_xml"],
                                   expect=["'rock'"], absent_text=["parents", "Entry"], ranks=2),
    # --- misspelt scene options: refused right after the scene is read, with the option meant
    "misspelt_region_option": dict(args=["-region_soil_permeabilty", "1e-12"],
                                   expect=["-region_soil_permeabilty",
                                           "did you mean -region_soil_permeability?"]),
    "misspelt_bc_option": dict(args=["-bc_top_trction", "0,-1e4"],
                               expect=["-bc_top_trction", "did you mean -bc_top_traction?"]),
    "misspelt_interface_option": dict(scene=JOINT_SCENE, args=["-interface_joint_frction", "0.5"],
                                      expect=["-interface_joint_frction",
                                              "did you mean -interface_joint_friction?"]),
    # --- shear dilation of an interface (docs/scenes.md): angle in degrees in [0, 90), limit >= 0
    "dilation_angle_negative": dict(scene=JOINT_SCENE, args=["-interface_joint_dilation_angle", "-5"],
                                    expect=["-interface_joint_dilation_angle", "-5", "0 <= psi < 90"]),
    "dilation_angle_90": dict(scene=JOINT_SCENE, args=["-interface_joint_dilation_angle", "90"],
                              expect=["-interface_joint_dilation_angle", "90", "0 <= psi < 90"]),
    "dilation_angle_abc": dict(scene=JOINT_SCENE, args=["-interface_joint_dilation_angle", "steep"],
                               expect=["-interface_joint_dilation_angle", "steep", "expected a number"]),
    "dilation_limit_negative": dict(scene=JOINT_SCENE,
                                    args=["-interface_joint_dilation_angle", "10",
                                          "-interface_joint_dilation_limit", "-1e-3"],
                                    expect=["-interface_joint_dilation_limit", "-0.001", ">= 0"]),
    "misspelt_dilation_option": dict(scene=JOINT_SCENE, args=["-interface_joint_dilation_angel", "10"],
                                     expect=["-interface_joint_dilation_angel",
                                             "did you mean -interface_joint_dilation_angle?"]),
    "misspelt_probe_option": dict(args=["-prbe_top", "0.05,1"],
                                  expect=["-prbe_top", "did you mean -probe_top?"]),
    "misspelt_region_name": dict(args=["-region_sand_E", "1e7"],
                                 expect=["-region_sand_E", "not in -regions",
                                         "did you mean -region_soil_E?"]),
    "misspelt_boundary_name": dict(args=["-bc_rigth_ux", "0"],
                                   expect=["-bc_rigth_ux", "not in -boundaries",
                                           "did you mean -bc_right_ux?"]),
    "misspelt_split_name": dict(args=["-fieldsplit_displacment_ksp_type", "gmres"],
                                expect=["-fieldsplit_displacment_ksp_type",
                                        "did you mean -fieldsplit_displacement_ksp_type?"]),
    # the displacement-block dump (vertex_blocks): a file rank 0 cannot write is refused on
    # every rank (it hung 2 ranks before), a set-up number below 1 too
    "dump_unwritable_np2": dict(args=["-options_file", "options/solvers/fieldsplit.opts",
                                      "-fieldsplit_displacement_vertex_blocks_dump_operator",
                                      "/nonexistent-dir/block.bin"],
                                expect=["-fieldsplit_displacement_vertex_blocks_dump_operator",
                                        "/nonexistent-dir/block.bin", "cannot write"], ranks=2),
    "dump_setup_zero": dict(args=["-options_file", "options/solvers/fieldsplit.opts",
                                  "-fieldsplit_displacement_vertex_blocks_dump_operator",
                                  "{out}/block.bin",
                                  "-fieldsplit_displacement_vertex_blocks_dump_operator_setup", "0"],
                            expect=["-fieldsplit_displacement_vertex_blocks_dump_operator_setup 0",
                                    "expected a set-up number >= 1"]),
    # the coarse lag of vertex_blocks: a number of set-ups below 1, a value that is no integer
    "coarse_lag_zero": dict(args=["-options_file", "options/solvers/fieldsplit.opts",
                                  "-fieldsplit_displacement_vertex_blocks_coarse_lag", "0"],
                            expect=["-fieldsplit_displacement_vertex_blocks_coarse_lag 0",
                                    "expected a number of set-ups >= 1"]),
    "coarse_lag_not_integer_np2": dict(args=["-options_file", "options/solvers/fieldsplit.opts",
                                             "-fieldsplit_displacement_vertex_blocks_coarse_lag",
                                             "ten"],
                                       expect=["-fieldsplit_displacement_vertex_blocks_coarse_lag",
                                               "ten", "expected an integer"], ranks=2),
    # the Krylov test's switch (mass_balance_test.hpp): a value that is no boolean, a misspelling
    "mass_balance_test_maybe": dict(args=["-mass_balance_krylov_test", "maybe"],
                                    expect=["-mass_balance_krylov_test", "maybe",
                                            "expected true or false"]),
    "misspelt_mass_balance_test": dict(args=["-mass_balance_krylov_tset", "0"],
                                       expect=["-mass_balance_krylov_tset",
                                               "did you mean -mass_balance_krylov_test?"]),
    "misspelt_scene_name": dict(args=["-gravty", "9.81"],
                                expect=["-gravty", "did you mean -gravity?"]),
    "ramp_without_value": dict(args=["-bc_top_flux_ramp", "3"],
                               expect=["-bc_top_flux_ramp", "-bc_top_flux", "not given"]),
    "misspelt_bc_option_np2": dict(args=["-bc_top_trction", "0,-1e4"],
                                   expect=["-bc_top_trction", "did you mean -bc_top_traction?"],
                                   ranks=2),
    # good runs
    # a split of a field the scene does not have (Terzaghi has no interface pressure): its
    # options are spelt right; typed, they stop the run unless -options_unused_ok (the
    # preset's own are never refused: tests/input/petsc_options.py), then reported at the end
    "absent_split_unused": dict(args=["-fieldsplit_pressures_fieldsplit_interface_pressure_ksp_type",
                                      "cg", "-ts_max_time", "0.4", "-options_unused_ok"], ok=True,
                                expect=["-fieldsplit_pressures_fieldsplit_interface_pressure_ksp_type",
                                        "never used"]),
    # the preset's coarse lag with an inner PC that is no multigrid: rebuilt at each set-up,
    # not an error (vertex_blocks.cpp)
    "coarse_lag_non_multigrid": dict(args=["-options_file", "options/solvers/fieldsplit.opts",
                                           "-fieldsplit_displacement_vertex_blocks_pc_type", "jacobi",
                                           "-ts_max_time", "0.4"], ok=True, expect=["2 steps"]),
    # -options_left is read by PETSc as it finishes: not reported as unused by poroseam
    "options_left_not_unused": dict(args=["-options_left", "-ts_max_time", "0.4"], ok=True,
                                    expect=["2 steps"], absent_text=["-options_left was given"]),
    # an option nothing reads stops the run (tests/input/petsc_options.py); with
    # -options_unused_ok the run goes on and it is reported at the end
    "unused_option": dict(args=["-not_an_option", "3", "-ts_max_time", "0.4", "-options_unused_ok"], ok=True,
                          expect=["-not_an_option", "never used"]),
    # paths with shell characters are only ever file names: gmsh is run without a shell, so
    # the quote and the $(...) in the mesh path and output directory do nothing but name them
    "shell_characters_in_paths": dict(
        args=["-mesh", "{out}/it's $(touch pwned)/column.geo",
              "-output_dir", "{out}/it's $(touch pwned)/results", "-ts_max_time", "0.2"],
        copy=("meshes/terzaghi_column_2d.geo", "it's $(touch pwned)/column.geo"), ok=True,
        expect=["1 steps"], absent=["pwned", "{out}/pwned", "{out}/it's $(touch pwned)/pwned"],
        present=["{out}/it's $(touch pwned)/results/timeseries.csv"]),
    # an output directory whose name is a shell command: created as a literal name, nothing run
    "shell_output_dir": dict(args=["-output_dir", "{out}/o'; touch X; echo '", "-ts_max_time", "0.2"],
                             ok=True, expect=["1 steps"], absent=["X", "{out}/X", "{out}/o'; touch X; echo '/X"],
                             present=["{out}/o'; touch X; echo '/timeseries.csv"]),
    "shell_output_dir_backticks": dict(
        args=["-output_dir", "{out}/a`touch Y`|b&c;$(touch Z) >w", "-ts_max_time", "0.2"], ok=True,
        expect=["1 steps"], absent=["Y", "Z", "w", "{out}/Y", "{out}/Z", "{out}/w"],
        present=["{out}/a`touch Y`|b&c;$(touch Z) >w/timeseries.csv"]),
    # valid meshes in every format the checker reads: it must not refuse them
    "msh22_good": dict(msh=("22", "good"), args=["-ts_max_time", "0.2"], ok=True, expect=["1 steps"]),
    "msh41_good": dict(msh=("41", "good"), args=["-ts_max_time", "0.2"], ok=True, expect=["1 steps"]),
    "msh41_binary_good": dict(msh=("41b", "good"), args=["-ts_max_time", "0.2"], ok=True,
                              expect=["1 steps"]),
    "msh22_binary_good": dict(msh=("22b", "good"), args=["-ts_max_time", "0.2"], ok=True,
                              expect=["1 steps"]),
    "gmsh_msh41_files": dict(gmsh_formats=True, ok=True, expect=["1 steps"]),
    # a mesh size factor below 0.5 that is fine: estimated, then meshed
    "mesh_size_factor_fine": dict(args=["-mesh_size_factor", "0.25", "-ts_max_time", "0.2"], ok=True,
                                  expect=["1 steps"]),
    # a killed run takes gmsh with it (the child dies with its parent: PR_SET_PDEATHSIG)
    "gmsh_dies_with_run": dict(gmsh_kill=True, ok=True, expect=[]),
    # nothing leaks (PETSc's -malloc_dump lists what was not freed at PetscFinalize)
    "malloc_dump_clean": dict(args=["-ts_max_time", "0.4", "-malloc_dump"], ok=True, expect=["2 steps"],
                              absent_text=["PetscMalloc", "bytes "]),
    "malloc_dump_clean_interface_np2": dict(
        scene=JOINT_SCENE, args=["-ts_max_time", "0.4", "-malloc_dump", "-bc_left_p3", "0"], ok=True,
        expect=["2 steps"], absent_text=["PetscMalloc", "bytes "], ranks=2),
    # Mohr-Coulomb soil (-region_<r>_material mohr_coulomb): strength parameters and the
    # initial stress inside the yield surface.
    "mc_missing_cohesion": dict(args=MOHR_COULOMB[0:2] + MOHR_COULOMB[4:],
                                expect=["-region_soil_cohesion", "missing"]),
    "mc_negative_cohesion": dict(args=MOHR_COULOMB + ["-region_soil_cohesion", "-1"],
                                 expect=["-region_soil_cohesion", ">= 0"]),
    "mc_friction_90": dict(args=MOHR_COULOMB + ["-region_soil_friction_angle", "90"],
                           expect=["-region_soil_friction_angle", "[0, 90)"]),
    "mc_dilation_above_friction": dict(args=MOHR_COULOMB + ["-region_soil_dilation_angle", "35"],
                                       expect=["-region_soil_dilation_angle = 35", "[0, phi] = [0, 30"]),
    "mc_no_strength": dict(args=MOHR_COULOMB + ["-region_soil_cohesion", "0",
                                                "-region_soil_friction_angle", "0",
                                                "-region_soil_dilation_angle", "0"],
                           expect=["-region_soil_cohesion = 0", "no strength"]),
    "mc_tension_cutoff_negative": dict(args=MOHR_COULOMB + ["-region_soil_tension_cutoff", "-5"],
                                       expect=["-region_soil_tension_cutoff", ">= 0"]),
    "mc_tension_cutoff_beyond_apex": dict(args=MOHR_COULOMB + ["-region_soil_tension_cutoff", "1e5"],
                                          expect=["-region_soil_tension_cutoff", "apex"]),
    # K0 = 0.1 below the active coefficient of phi = 30 degrees (1/3): the geostatic state lies
    # outside the cone (c = 1 kPa is small beside sigma'_v ~ 10 kPa at the base).
    "mc_initial_stress_outside": dict(
        args=MOHR_COULOMB + ["-region_soil_cohesion", "1e3", "-region_soil_K0", "0.1",
                             "-region_soil_rho_s", "2650", "-region_soil_porosity", "0.4",
                             "-gravity", "9.81", "-initial_state", "geostatic",
                             "-surface_elevation", "1"],
        expect=["region 'soil'", "outside the yield surface", "-region_soil_K0"]),
    # interface penalties far from K h / E in [1, 1e4] (docs/interface_parameters.md): one
    # warning line per interface and stiffness at set-up, naming both and the advised range;
    # the run goes on. The scene's own penalties (K h / E about 2e3) give none.
    "penalty_soft_warning_np2": dict(
        scene=JOINT_SCENE, args=["-interface_joint_KN", "1e5", "-bc_left_p3", "0", "-ts_max_time", "0.2"],
        ok=True, ranks=2, count=("poroseam: warning: interface joint: K_N", 1),
        expect=["interface joint: K_N = 100000 Pa/m is soft", "10 to 1000 E / h"],
        absent_text=["K_T = "]),
    "penalty_stiff_warning": dict(
        scene=JOINT_SCENE, args=["-interface_joint_KT", "1e18", "-bc_left_p3", "0", "-ts_max_time", "0.2"],
        ok=True, count=("poroseam: warning: interface joint: K_T", 1),
        expect=["interface joint: K_T = 1e+18 Pa/m is stiff"], absent_text=["K_N = "]),
    "penalty_fine_no_warning": dict(
        scene=JOINT_SCENE, args=["-bc_left_p3", "0", "-ts_max_time", "0.2"], ok=True,
        expect=["1 steps"], absent_text=["poroseam: warning: interface"]),
    "help": dict(help=True, ok=True,
                 expect=["-region_<r>_E", "-region_<r>_permeability", "-bc_<b>_traction",
                         "-initial_state", "-probe_<name>", "timeseries.csv"]),
}


# The unit square of meshes/bad_inverted.msh with both triangles counter-clockwise: physical
# curves bottom, right, top, left (tags 1-4) and surface soil (5), the names of the base scene.
SQUARE_NODES = [(1, 0.0, 0.0), (2, 1.0, 0.0), (3, 1.0, 1.0), (4, 0.0, 1.0)]
SQUARE_LINES = [(1, 1, (1, 2)), (2, 2, (2, 3)), (3, 3, (3, 4)), (4, 4, (4, 1))]  # id, tag, nodes
SQUARE_TRIANGLES = [(5, (1, 2, 3)), (6, (1, 3, 4))]
PHYSICAL_NAMES = '$PhysicalNames\n5\n1 1 "bottom"\n1 2 "right"\n1 3 "top"\n1 4 "left"\n' \
                 '2 5 "soil"\n$EndPhysicalNames\n'


def msh_fixture(version, defect):
    """The unit square as MSH 2.2 or 4.1, ASCII or binary ('22', '22b', '41', '41b'), with one
    defect: missing_node (element 6 names node 9), node_count_high (2 more nodes declared than
    given), element_count_low, truncate_nodes / truncate_elements (cut inside the section),
    garbage, empty, geo_text, version_3, second_order (a 6-node triangle), no_physical_names,
    nan (a coordinate), duplicate_node, unknown_entity (4.1: a block names entity 7), good."""
    if defect == "empty":
        return b""
    if defect == "garbage":
        rng = random.Random(11)
        return bytes(rng.randrange(256) for _ in range(2000))
    if defect == "geo_text":
        with open(os.path.join(SOURCE, "meshes", "terzaghi_column_2d.geo"), "rb") as f:
            return f.read()
    nodes = list(SQUARE_NODES)
    tris = [list(t) for t in SQUARE_TRIANGLES]
    tri_type, n_extra = 2, 0
    if defect == "missing_node":
        tris[1][1] = (1, 9, 4)
    if defect == "duplicate_node":
        nodes[3] = (3, 0.0, 1.0)
    if defect == "node_count_high":
        n_extra = 2
    binary = version.endswith("b")
    fmt = "2.2" if version.startswith("22") else "4.1"
    if defect == "version_3":
        fmt = "3.0"
    head = f"$MeshFormat\n{fmt} {1 if binary else 0} 8\n".encode()
    if binary:
        head += struct.pack("<i", 1) + b"\n"
    head += b"$EndMeshFormat\n"
    names = b"" if defect == "no_physical_names" else PHYSICAL_NAMES.encode()
    coord = (lambda v: "nan" if defect == "nan" and v == 1.0 else repr(v))
    if version == "22":
        body = f"$Nodes\n{len(nodes) + n_extra}\n"
        body += "".join(f"{i} {coord(x)} {coord(y)} 0\n" for i, x, y in nodes) + "$EndNodes\n"
        elements = [f"{i} 1 2 {t} {t} {a} {b}" for i, t, (a, b) in SQUARE_LINES]
        if defect == "second_order":
            elements += [f"{i} 9 2 5 1 {a} {b} {c} 1 2 3" for i, (a, b, c) in tris]
        else:
            elements += [f"{i} {tri_type} 2 5 1 {a} {b} {c}" for i, (a, b, c) in tris]
        count = len(elements) - (1 if defect == "element_count_low" else 0)
        body += f"$Elements\n{count}\n" + "\n".join(elements) + "\n$EndElements\n"
        data = head + names + body.encode()
    elif version == "22b":
        body = f"$Nodes\n{len(nodes) + n_extra}\n".encode()
        for i, x, y in nodes:
            body += struct.pack("<iddd", i, x, y, 0.0)
        body += b"\n$EndNodes\n" + f"$Elements\n{len(SQUARE_LINES) + len(tris)}\n".encode()
        body += struct.pack("<iii", 1, len(SQUARE_LINES), 2)
        for i, t, (a, b) in SQUARE_LINES:
            body += struct.pack("<iiiii", i, t, t, a, b)
        body += struct.pack("<iii", 2, len(tris), 2)
        for i, (a, b, c) in tris:
            body += struct.pack("<iiiiii", i, 5, 1, a, b, c)
        body += b"\n$EndElements\n"
        data = head + names + body
    else:
        entity7 = defect == "unknown_entity"
        if not binary:
            ent = "$Entities\n0 4 1 0\n"
            ent += "".join(f"{t} 0 0 0 1 1 0 1 {t} 0\n" for t in range(1, 5))
            ent += "1 0 0 0 1 1 0 1 5 4 1 2 3 4\n$EndEntities\n"
            nod = f"$Nodes\n1 {len(nodes) + n_extra} 1 4\n2 1 0 {len(nodes)}\n"
            nod += "".join(f"{i}\n" for i, _, _ in nodes)
            nod += "".join(f"{coord(x)} {coord(y)} 0\n" for _, x, y in nodes) + "$EndNodes\n"
            el = f"$Elements\n5 6 1 6\n"
            for i, t, (a, b) in SQUARE_LINES:
                el += f"1 {t} 1 1\n{i} {a} {b}\n"
            el += f"2 {7 if entity7 else 1} 2 {len(tris)}\n"
            el += "".join(f"{i} {a} {b} {c}\n" for i, (a, b, c) in tris) + "$EndElements\n"
            data = head + names + (ent + nod + el).encode()
        else:
            ent = b"$Entities\n" + struct.pack("<QQQQ", 0, 4, 1, 0)
            for t in range(1, 5):
                ent += struct.pack("<i6dQiQ", t, 0, 0, 0, 1, 1, 0, 1, t, 0)
            ent += struct.pack("<i6dQiQ4i", 1, 0, 0, 0, 1, 1, 0, 1, 5, 4, 1, 2, 3, 4)
            ent += b"\n$EndEntities\n"
            nod = b"$Nodes\n" + struct.pack("<QQQQ", 1, len(nodes) + n_extra, 1, 4)
            nod += struct.pack("<iiiQ", 2, 1, 0, len(nodes))
            nod += b"".join(struct.pack("<Q", i) for i, _, _ in nodes)
            nod += b"".join(struct.pack("<3d", x, y, 0.0) for _, x, y in nodes)
            nod += b"\n$EndNodes\n"
            el = b"$Elements\n" + struct.pack("<QQQQ", 5, 6, 1, 6)
            for i, t, (a, b) in SQUARE_LINES:
                el += struct.pack("<iiiQ", 1, t, 1, 1) + struct.pack("<3Q", i, a, b)
            el += struct.pack("<iiiQ", 2, 7 if entity7 else 1, 2, len(tris))
            el += b"".join(struct.pack("<4Q", i, a, b, c) for i, (a, b, c) in tris)
            el += b"\n$EndElements\n"
            data = head + names + ent + nod + el
    if defect == "truncate_nodes":
        data = data[:data.index(b"$Nodes") + 40]
    if defect == "truncate_elements":
        data = data[:data.index(b"$Elements") + 30]
    return data


def gmsh_formats(out):
    """Meshes the Terzaghi column with gmsh in MSH 4.1 ASCII and binary and MSH 2.2 binary;
    each must run. Returns (exit status, output) of the last run that failed or the last."""
    text, rc = "", 0
    for fmt, extra in (("msh41", []), ("msh41", ["-bin"]), ("msh22", ["-bin"])):
        msh = os.path.join(out, f"column_{fmt}{''.join(extra)}.msh")
        subprocess.run(["gmsh", "-3", "-v", "1", "-format", fmt] + extra +
                       ["-o", msh, os.path.join(SOURCE, "meshes", "terzaghi_column_2d.geo")],
                       check=True, stdout=subprocess.DEVNULL)
        p = subprocess.run([EXE, "-options_file", BASE_SCENE, "-output_dir", out, "-mesh", msh,
                            "-ts_max_time", "0.2"], cwd=SOURCE, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=TIMEOUT)
        text += f"[{os.path.basename(msh)}]\n" + p.stdout.decode(errors="replace")
        rc = rc or p.returncode
    return rc, text


def children_of(pid):
    """Process ids whose parent is pid (from /proc)."""
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            with open(f"/proc/{entry}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            if int(fields[1]) == pid:
                found.append(int(entry))
        except (OSError, IndexError, ValueError):
            pass
    return found


def command_name(pid):
    try:
        with open(f"/proc/{pid}/comm") as f:
            return f.read().strip()
    except OSError:
        return ""


def gmsh_kill(out):
    """Starts a run whose gmsh takes a while (the 3D caisson quarter at factor 0.3), kills
    poroseam with SIGKILL once gmsh runs, and checks that gmsh is gone within 5 s."""
    cmd = [EXE, "-options_file", os.path.join(SOURCE, "options", "caisson_partially_drained.opts"),
           "-output_dir", out, "-mesh_size_factor", "0.3", "-mesh_max_elements", "100000000"]
    p = subprocess.Popen(cmd, cwd=SOURCE, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    gmsh, t0 = None, time.time()
    while time.time() - t0 < 20 and gmsh is None and p.poll() is None:
        for child in children_of(p.pid):
            # the factor-1 estimate mesh comes first; wait for the real one
            if command_name(child) == "gmsh" and os.path.exists(os.path.join(out, "mesh")) and \
                    time.time() - t0 > 1.0:
                gmsh = child
        time.sleep(0.05)
    if gmsh is None:
        p.kill()
        p.wait()
        return 1, "no gmsh child process seen within 20 s"
    time.sleep(0.3)
    p.kill()
    p.wait()
    t1 = time.time()
    while time.time() - t1 < 5:
        if not os.path.exists(f"/proc/{gmsh}") or command_name(gmsh) != "gmsh":
            return 0, f"gmsh (pid {gmsh}) ended {time.time() - t1:.2f} s after poroseam was killed"
        with open(f"/proc/{gmsh}/stat") as f:
            if f.read().rsplit(")", 1)[1].split()[0] == "Z":
                return 0, f"gmsh (pid {gmsh}) ended (zombie) after poroseam was killed"
        time.sleep(0.05)
    os.kill(gmsh, 9)
    return 1, f"gmsh (pid {gmsh}) still running 5 s after poroseam was killed (killed it now)"


def strip_option_echo(text):
    """The output without PETSc's listing of the options (which names every option)."""
    out, in_table = [], False
    for line in text.splitlines():
        body = re.sub(r"^\[\d+\]PETSC ERROR: ", "", line)
        if "PETSc Option Table entries" in body:
            in_table = True
            continue
        if in_table:
            if "End of Error Message" in body:
                in_table = False
            continue
        if body.startswith("Option left:") or body.startswith("Configure options"):
            continue
        out.append(line)
    return "\n".join(out)


def scene_without(options, out_dir):
    """A copy of the base scene with the given options removed; mesh paths stay relative to
    the source tree, where poroseam runs."""
    path = os.path.join(out_dir, "scene.opts")
    with open(BASE_SCENE) as f, open(path, "w") as g:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words and words[0] in options:
                continue
            g.write(line)
    return path


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case")
    ap.add_argument("--list", action="store_true")
    a = ap.parse_args()
    if a.list or not a.case:
        print("\n".join(CASES))
        return 0
    case = CASES[a.case]
    out = os.path.join(OUTPUT_ROOT, "input", a.case)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    if "msh" in case:
        with open(os.path.join(out, "bad.msh"), "wb") as f:
            f.write(msh_fixture(*case["msh"]))
        case = dict(case, args=["-mesh", "{out}/bad.msh"] + case.get("args", []))
    if "mkdir" in case:
        os.makedirs(os.path.join(out, case["mkdir"]))
    if "write" in case:
        with open(os.path.join(out, case["write"][0]), "w") as f:
            f.write(case["write"][1])
    if "copy" in case:
        target = os.path.join(out, case["copy"][1])
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copy(os.path.join(SOURCE, case["copy"][0]), target)
    for path in case.get("absent", []):  # e.g. left by an earlier, broken build
        path = os.path.join(SOURCE, path.format(out=out))
        if os.path.exists(path):
            os.remove(path)
    if case.get("help"):
        cmd = [EXE, "-help"]
    elif "raw" in case:
        cmd = [EXE] + [s.format(out=out) for s in case["raw"]]
    else:
        base = case.get("scene", BASE_SCENE)
        scene = scene_without(case["drop"], out) if "drop" in case else base
        cmd = [EXE, "-options_file", scene, "-output_dir", out] + \
              [s.format(out=out) for s in case.get("args", [])]
    ranks = case.get("ranks", 1)
    if ranks > 1:
        cmd = ["mpiexec", "-n", str(ranks)] + cmd
    env = dict(os.environ)
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT", "1")
    env.setdefault("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1")
    env.setdefault("OMPI_MCA_rmaps_base_oversubscribe", "1")
    print("run:", " ".join(cmd), flush=True)
    t0 = time.time()
    if case.get("gmsh_formats"):
        rc, text = gmsh_formats(out)
    elif case.get("gmsh_kill"):
        rc, text = gmsh_kill(out)
    else:
        try:
            p = subprocess.run(cmd, cwd=SOURCE, env=env, stdout=subprocess.PIPE,
                               stderr=subprocess.STDOUT, timeout=TIMEOUT)
            rc, text = p.returncode, p.stdout.decode(errors="replace")
        except subprocess.TimeoutExpired as e:
            rc, text = "timeout", (e.stdout or b"").decode(errors="replace")
    wall = time.time() - t0
    with open(os.path.join(out, "log.txt"), "w") as f:
        f.write(text)
    # the case's directory named as <out>: its name (the case's name) must not make a match
    message = strip_option_echo(text).replace(out, "<out>")
    failures = []
    if rc == "timeout":
        failures.append(f"no exit within {TIMEOUT:.0f} s (hang)")
    elif case.get("ok") and rc != 0:
        failures.append(f"exit status {rc}, expected 0")
    elif not case.get("ok") and rc == 0:
        failures.append("exit status 0, expected a failure")
    if wall > MAX_SECONDS:
        failures.append(f"took {wall:.1f} s (> {MAX_SECONDS:.0f} s)")
    for s in case["expect"]:
        if s not in message:
            failures.append(f"the output (options echo removed) does not contain '{s}'")
    for path in case.get("absent", []):
        if os.path.exists(os.path.join(SOURCE, path.format(out=out))):
            failures.append(f"'{path.format(out=out)}' exists: a path was run as a command")
    for path in case.get("present", []):
        if not os.path.exists(path.format(out=out)):
            failures.append(f"'{path.format(out=out)}' was not written")
    for s in CRASH:
        if re.search(s, text):
            failures.append(f"crash signature '{s}' in the output")
    for s in case.get("absent_text", []):
        if s in text:
            failures.append(f"the output contains '{s}'")
    if "count" in case:  # a line printed once, by rank 0 only
        lines = [l for l in text.splitlines() if l.startswith(case["count"][0])]
        if len(lines) != case["count"][1]:
            failures.append(f"{len(lines)} lines starting '{case['count'][0]}', expected {case['count'][1]}")
    if not case.get("ok"):
        # one line that says it, once (not once per rank), without PETSc's banner or an abort
        errors = [l for l in text.splitlines() if l.startswith("poroseam: error:")]
        if len(errors) != 1:
            failures.append(f"{len(errors)} 'poroseam: error:' lines, expected exactly 1")
        for s in ("PETSC ERROR", "MPI_ABORT", "Traceback"):
            if s in text:
                failures.append(f"the output contains '{s}'")
    # show the error text (the lines that matter) for the log
    shown = [l for l in message.splitlines()
             if "PETSC ERROR: #" not in l and l.strip()
             and not re.search(r"PETSC ERROR: (See https|Petsc Release|.*named .* by|-----|WARNING! There)", l)]
    print(f"exit {rc} after {wall:.2f} s; output (options echo removed):")
    print("    " + "\n    ".join(shown[:12 if not case.get("help") else 3]))
    if failures:
        print(f"FAIL {a.case}:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS {a.case}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
