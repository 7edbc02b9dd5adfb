#!/usr/bin/python3
"""Inputs that used to pass silently with a wrong meaning (issue 23, item 4): each one now ends
in one clear error line, or runs with exactly the warning lines that say what happens.

    silent_cases.py --case NAME      one case (one ctest each, label "input")
    silent_cases.py --list           the case names

The cases run through tests/input/bad_input.py's driver (the same checks: exit status, the
expected text without PETSc's option echo, no crash signature, one "poroseam: error:" line,
no hang within its timeout). On top of those, a case with `warnings=N` must print exactly N
lines "poroseam: warning: ..." (once, not once per rank), each with the `warn` texts, and a
case may write a file into its output directory first (`write`), make a FIFO (`fifo`) or a
sparse file of a given size (`sparse`) next to it.

The classes (docs/input_errors.md, "Conditions, time tables, stabilisation, derived defaults"):
  - two conditions on one unknown of one boundary: a displacement component and a non-zero
    traction component (the traction was dropped), a pressure and a flux, the free water's
    load and a prescribed displacement along its normal;
  - two boundaries prescribing different values of one unknown at a shared vertex: the later
    one in -boundaries holds, with one warning line (before: silently);
  - time tables: a third column, a first time after the start of the run, NaN/inf, times not
    increasing, no rows, a FIFO or device (hung), a file larger than a table can be;
  - -stabilization_factor far outside its range (0, 1e12): one warning line, the run goes on;
  - a derived default refused or used (K0 = nu/(1-nu)): the message names the option given.
"""

import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import bad_input  # noqa: E402  (its helpers and driver; the cases below replace its list)

SOURCE = bad_input.SOURCE
TERZAGHI_3D = os.path.join(SOURCE, "tests", "verification", "terzaghi_3d.opts")
SHORT = ["-ts_max_time", "0.4"]  # two steps of the base scene: a run that must succeed
TABLE = ["-bc_top_traction_table", "{out}/table.csv"]
# a geostatic start of the base column (top at y = 1), valid with a given K0
GEOSTATIC = ["-initial_state", "geostatic", "-gravity", "9.81", "-surface_elevation", "1",
             "-region_soil_rho_s", "2650", "-region_soil_porosity", "0.4"]

GEOSTATIC_2D = os.path.join(SOURCE, "tests", "physics", "geostatic_2d.opts")
WATER = ["-water_level", "3", "-water_load_boundaries", "top", "-bc_top_p", "19620",
         "-ts_max_time", "2"]

CASES = {
    # --- two conditions on one unknown of one boundary -------------------------------------
    # the example: Terzaghi's loaded top also fixed vertically
    "top_uy_and_traction": dict(args=["-bc_top_uy", "0"],
                                expect=["-bc_top_uy and -bc_top_traction", "'top'",
                                        "component 2 of -bc_top_traction is -10000"]),
    "top_ux_and_shear_traction": dict(args=["-bc_top_ux", "0", "-bc_top_traction", "2e3,-1e4"],
                                      expect=["-bc_top_ux and -bc_top_traction",
                                              "component 1 of -bc_top_traction is 2000"]),
    "top_uz_and_traction_3d": dict(scene=TERZAGHI_3D, args=["-bc_top_uz", "0"],
                                   expect=["-bc_top_uz and -bc_top_traction", "component 3"]),
    # a zero traction component on a prescribed component is its reaction: a rough, rigid
    # loading plate (options/block_shear_2d.opts does this)
    "zero_component_accepted": dict(args=["-bc_top_ux", "0"] + SHORT, ok=True, warnings=0,
                                    expect=[]),
    "flux_and_pressure_top": dict(args=["-bc_top_flux", "0"],
                                  expect=["-bc_top_flux and -bc_top_p", "'top'"]),
    # the free water's load on the sea bed (tests/physics/geostatic_2d.opts, water 2 m above
    # the surface) competes with a prescribed normal displacement there, not a tangential one
    "water_load_and_normal_displacement": dict(
        scene=GEOSTATIC_2D, args=WATER + ["-bc_top_uy", "0"],
        expect=["-water_load_boundaries names 'top', where -bc_top_uy is prescribed"]),
    "water_load_and_tangential_displacement_runs": dict(
        scene=GEOSTATIC_2D, args=WATER + ["-bc_top_ux", "0"], ok=True, warnings=0, expect=[]),
    # --- two boundaries, one shared vertex --------------------------------------------------
    # bottom fixes uy = 0 at (0, 0), left now prescribes 1 mm there: the later one holds
    "corner_differs_warned": dict(args=["-bc_left_uy", "0.001"] + SHORT, ok=True, warnings=1,
                                  warn=["-bc_bottom_uy 0 and -bc_left_uy 0.001", "(0, 0)",
                                        "-bc_left_uy holds", "listed later in -boundaries"],
                                  expect=[]),
    "corner_pressure_differs_warned_np2": dict(
        args=["-bc_left_p", "1e4", "-bc_left_p_ramp", "1"] + SHORT, ok=True, ranks=2, warnings=1,
        warn=["-bc_top_p 0 and -bc_left_p 10000 (ramp)", "(0, 1)", "-bc_left_p holds"],
        expect=[]),
    # the same value at the shared vertex: nothing to say
    "corner_same_value_silent": dict(args=["-bc_left_p", "0", "-bc_left_uy", "0"] + SHORT,
                                     ok=True, warnings=0, expect=[]),
    # --- time tables ------------------------------------------------------------------------
    "table_third_column": dict(args=TABLE, write=("table.csv", "time,factor\n0,0\n1,1,5\n"),
                               expect=["table.csv' line 3", "3 fields",
                                       "exactly two columns"]),
    "table_trailing_comma": dict(args=TABLE, write=("table.csv", "0,0\n1,1,\n"),
                                 expect=["table.csv' line 2", "3 fields"]),
    "table_starts_late": dict(args=TABLE, write=("table.csv", "5,1\n10,2\n"),
                              expect=["-bc_top_traction_table", "starts at t = 5 s",
                                      "add a first row '0,<factor>'"]),
    "table_nan": dict(args=TABLE, write=("table.csv", "0,0\n1,nan\n"),
                      expect=["table.csv' line 2", "'1,nan'", "finite"]),
    "table_inf": dict(args=TABLE, write=("table.csv", "0,0\n1e400,1\n"),
                      expect=["table.csv' line 2", "finite"]),
    # a first line that is not a header (a number first) is data, checked like any other
    "table_nan_first_line": dict(args=TABLE, write=("table.csv", "0,nan\n1,1\n"),
                                 expect=["table.csv' line 1", "finite"]),
    "table_not_increasing": dict(args=TABLE, write=("table.csv", "0,0\n2,1\n1,2\n"),
                                 expect=["table.csv' line 3", "increase strictly"]),
    "table_no_rows": dict(args=TABLE, write=("table.csv", "time,factor\n# none yet\n"),
                          expect=["table.csv' has no rows"]),
    "table_fifo": dict(args=["-bc_top_traction_table", "{out}-fifo"], fifo="{out}-fifo",
                       expect=["not a regular file", "FIFO"]),
    "table_fifo_np2": dict(args=["-bc_top_traction_table", "{out}-fifo"], fifo="{out}-fifo",
                           ranks=2, expect=["not a regular file", "FIFO"]),
    "table_device": dict(args=["-bc_top_traction_table", "/dev/zero"],
                         expect=["'/dev/zero' is not a regular file"]),
    "table_directory": dict(args=["-bc_top_traction_table", "{out}"],
                            expect=["is not a regular file (a directory)"]),
    "table_huge": dict(args=["-bc_top_traction_table", "{out}-huge.csv"],
                       sparse=("{out}-huge.csv", 65 << 20),
                       expect=["bytes, more than the 64 MiB"]),
    # a binary file (a PNG) as a table: one line naming the line, no raw bytes in it
    "table_binary": dict(args=TABLE, copy=("docs/fig9a_caisson_axisym.png", "table.csv"),
                         expect=["table.csv' line 1", "expected two numbers"]),
    "table_binary_field_quoted": dict(args=TABLE, write=("table.csv", "0,0\n1,\x01\x02\x03\n"),
                                      expect=["table.csv' line 2", "'1,???'"]),
    # a valid table with a header, blanks and CRLF line ends still runs
    "table_valid_runs": dict(args=TABLE + SHORT, ok=True, warnings=0,
                             write=("table.csv", "time, factor\r\n0, 0\r\n# ramp\r\n1, 1\r\n"),
                             expect=[]),
    # --- pressure stabilisation -------------------------------------------------------------
    "stabilization_zero_warned": dict(args=["-stabilization_factor", "0"] + SHORT, ok=True,
                                      warnings=1, warn=["-stabilization_factor 0 turns off",
                                                        "inf-sup", "oscillate"], expect=[]),
    "stabilization_huge_warned": dict(args=["-stabilization_factor", "1e12"] + SHORT, ok=True,
                                      warnings=1, warn=["-stabilization_factor 1e+12",
                                                        "over-smoothed", "drains too fast"],
                                      expect=[]),
    "stabilization_huge_warned_np2": dict(args=["-stabilization_factor", "1e12"] + SHORT,
                                          ok=True, ranks=2, warnings=1,
                                          warn=["-stabilization_factor 1e+12"], expect=[]),
    "stabilization_default_silent": dict(args=SHORT, ok=True, warnings=0, expect=[]),
    # a drained scene has no pressure to stabilise
    "stabilization_drained_silent": dict(args=["-drained", "-stabilization_factor", "0",
                                               "-ts_max_time", "0.4"],
                                         drop=["-bc_top_p"], ok=True, warnings=0, expect=[]),
    # --- derived defaults -------------------------------------------------------------------
    # the example: a valid nu, the derived K0 negative, K0 never given
    "nu_negative_geostatic": dict(args=["-region_soil_nu", "-0.1"] + GEOSTATIC,
                                  expect=["K0 = nu/(1-nu) = -0.0909091 from -region_soil_nu -0.1",
                                          "-region_soil_K0 not given",
                                          "set -region_soil_K0 explicitly"]),
    # K0 given: nu -0.1 is fine; without a geostatic state K0 is not used at all
    "nu_negative_K0_given_runs": dict(args=["-region_soil_nu", "-0.1", "-region_soil_K0", "0.5"]
                                      + GEOSTATIC + SHORT, ok=True, warnings=0, expect=[]),
    "nu_negative_no_geostatic_runs": dict(args=["-region_soil_nu", "-0.1"] + SHORT, ok=True,
                                          warnings=0, expect=[]),
    # other defaults that the messages now name: an interface's face group (its own name),
    # a porous region's place in the ground column
    "interface_default_surfaces_missing": dict(
        args=["-interfaces", "crack"],
        expect=["interface 'crack' (without -interface_crack_surfaces, the face group named "
                "'crack'; set -interface_crack_surfaces to its groups)", "the mesh has:"]),
    "ground_default_above_surface": dict(
        args=["-initial_state", "geostatic", "-gravity", "9.81", "-surface_elevation", "0.5",
              "-region_soil_K0", "0.5"],
        expect=["reaches z = 1 above the soil surface 0.5",
                "takes -region_soil_ground false; porous regions are ground by default"]),
    "K0_negative_given": dict(args=["-region_soil_K0", "-0.2"] + GEOSTATIC,
                              expect=["-region_soil_K0 = -0.2", ">= 0"]),
    # the derived K0 puts the initial state outside the Mohr-Coulomb cone: the message says it
    # came from nu
    "K0_derived_outside_yield": dict(
        args=GEOSTATIC + bad_input.MOHR_COULOMB + ["-region_soil_cohesion", "1",
                                                    "-region_soil_nu", "0.1"],
        expect=["choose -region_soil_K0", "K0 = nu/(1-nu) = 0.111111 from -region_soil_nu 0.1"]),
}


def main():
    case_name = None
    if "--case" in sys.argv:
        case_name = sys.argv[sys.argv.index("--case") + 1]
    if case_name is None or "--list" in sys.argv:
        print("\n".join(CASES))
        return 0
    case = CASES[case_name]
    out = os.path.join(bad_input.OUTPUT_ROOT, "input", case_name)
    # files next to the output directory (the driver empties the directory itself)
    if "fifo" in case:
        path = case["fifo"].format(out=out)
        if os.path.lexists(path):
            os.remove(path)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        os.mkfifo(path)
    if "sparse" in case:
        path = case["sparse"][0].format(out=out)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "wb") as f:
            f.truncate(case["sparse"][1])  # no disk blocks: a hole
    bad_input.CASES = CASES
    status = bad_input.main()
    for key in ("fifo", "sparse"):
        if key in case:
            path = case[key] if key == "fifo" else case[key][0]
            os.remove(path.format(out=out))
    if "warnings" in case:
        with open(os.path.join(out, "log.txt")) as f:
            text = f.read()
        warnings = [l for l in text.splitlines() if l.startswith("poroseam: warning:")]
        failures = []
        if len(warnings) != case["warnings"]:
            failures.append(f"{len(warnings)} 'poroseam: warning:' lines, expected "
                            f"{case['warnings']}: {warnings}")
        for s in case.get("warn", []):
            if not any(s in w for w in warnings):
                failures.append(f"no warning line contains '{s}'")
        print("warnings:\n    " + "\n    ".join(warnings or ["(none)"]))
        if failures:
            print(f"FAIL {case_name}:\n  " + "\n  ".join(failures))
            return 1
    return status


if __name__ == "__main__":
    sys.exit(main())
