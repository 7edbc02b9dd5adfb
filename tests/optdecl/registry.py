#!/usr/bin/python3
"""One declaration per option (include/poroseam/options.def, docs/options.md), label "input".

    registry.py --case docs      every declared option is described in the docs page its
                                 declaration names (docs/scenes.md, docs/checkpoints.md, ...):
                                 "-name" occurs there as a whole name; a choice's values too
    registry.py --case readers   every option a reader in src/ names by a string literal
                                 (PetscOptionsInt/Real/Bool/String/Get*/HasName, and the scene
                                 getters getReal/getString/... of scene_options.hpp) is PETSc's
                                 own; an option of poroseam's is read through its declaration
                                 (spec(Option::name)), never by a literal of its own; and every
                                 declared option is read somewhere (no dead declaration); the
                                 same for the keys of -region_<r>_*, -interface_<i>_*, -bc_<b>_*
                                 (declared in options.def too, described in docs/scenes.md)
    registry.py --case help      `poroseam -options_file <Terzaghi> -help`: each declared option
                                 -help lists is listed once, with the help text and docs page
                                 of its declaration, and the options read in every run are there

The sources are read from POROSEAM_SOURCE (default: this checkout), so that the check can be
shown to fail on a changed copy (a literal reader put back, an option taken out of the docs).
"""

import argparse
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")

# Names of PETSc's own options (and of its objects) start with one of these.
PETSC_PREFIXES = ("ts_", "snes_", "ksp_", "pc_", "mat_", "vec_", "dm_", "log", "malloc",
                  "options_", "help", "info", "version", "viewer", "draw", "is_", "sf_",
                  "fieldsplit_", "mg_", "sub_", "petsc", "mpi")
# Files the lead owns in this round, which still read a declared option by a literal
# (src/solve/solver_preset.cpp: -solver_preset). Each entry: (path, option).
KNOWN_LITERALS = set()
# Options of poroseam's preconditioner vertex_blocks, read through its PC object with a solver
# prefix (-fieldsplit_displacement_vertex_blocks_coarse_lag) in src/solve/vertex_blocks.cpp,
# the lead's file this round: not declared yet (docs/options.md, "Not declared yet").
KNOWN_UNDECLARED = {"vertex_blocks_dump_operator", "vertex_blocks_dump_operator_setup",
                    "vertex_blocks_coarse_lag", "vertex_blocks_order_coarsening",
                    "vertex_blocks_stiff_ratio"}
# Options read without a -help line (PetscOptionsGet*: where an error needs it, or only with
# -ts_type cn).
NOT_IN_HELP = {"io_agreement_timeout", "test_io_fail_rank", "test_allow_crank_nicolson"}


def split_args(text):
    """The macro's arguments: top-level commas, string literals kept whole and joined."""
    args, cur, quoted, i = [], "", False, 0
    while i < len(text):
        c = text[i]
        if quoted:
            cur += c
            if c == "\\":
                cur += text[i + 1]
                i += 1
            elif c == '"':
                quoted = False
        elif c == '"':
            quoted = True
            cur += c
        elif c == ",":
            args.append(cur)
            cur = ""
        else:
            cur += c
        i += 1
    args.append(cur)
    out = []
    for a in args:
        literals = re.findall(r'"((?:[^"\\]|\\.)*)"', a)
        out.append("".join(literals) if literals else a.strip())
    return out


def macro_calls(text, macro):
    """The argument texts of every `macro(...)` call in `text` (parentheses inside string
    literals skipped)."""
    calls = []
    for m in re.finditer(r"^%s\((?=[A-Za-z])" % macro, text, re.M):
        i, depth, quoted, start = m.end(), 1, False, m.end()
        while depth:
            c = text[i]
            if quoted:
                if c == "\\":
                    i += 1
                elif c == '"':
                    quoted = False
            elif c == '"':
                quoted = True
            elif c == "(":
                depth += 1
            elif c == ")":
                depth -= 1
            i += 1
        calls.append(text[start:i - 1])
    return calls


def options_def():
    text = open(os.path.join(SOURCE, "include", "poroseam", "options.def")).read()
    # Comments off (no "//" inside the declarations' strings).
    return "\n".join(line for line in text.splitlines() if not line.lstrip().startswith("//"))


def declarations():
    decls = []
    for call in macro_calls(options_def(), "POROSEAM_OPTION"):
        a = split_args(call)
        if len(a) != 9:
            sys.exit("options.def: a declaration without its 9 fields: " + call[:80])
        decls.append(dict(name=a[0], kind=a[1], choices=a[2].split(), check=a[3], shown=a[4],
                          help=a[5], doc=a[6], restart=a[7], space=a[8]))
    if len(decls) < 10:
        sys.exit("options.def: only %d declarations read" % len(decls))
    return decls


# The families named after a scene's parts: their keys are declared in options.def and read in
# one file each, through the declaration (key(RegionKey::E)).
FAMILIES = [("region", "<r>", "REGION", "RegionKey", "src/scene/scene_region.cpp"),
            ("interface", "<i>", "INTERFACE", "InterfaceKey", "src/scene/scene_interface.cpp"),
            ("bc", "<b>", "BOUNDARY", "BoundaryKey", "src/scene/scene_boundary.cpp")]


def family_keys(macro):
    return [k.strip() for k in macro_calls(options_def(), "POROSEAM_%s_KEY" % macro)]


def case_families():
    failures = []
    for family, entity, macro, enum, reader in FAMILIES:
        declared = family_keys(macro)
        if len(declared) < 5:
            failures.append("options.def: only %d keys of -%s_%s_*" % (len(declared), family,
                                                                       entity))
            continue
        text = open(os.path.join(SOURCE, reader)).read()
        used = set(re.findall(r"\b%s::([A-Za-z0-9_]+)" % enum, text))
        literal = set(re.findall(r'\bp \+ "([A-Za-z0-9_]+)"', text))
        literal |= set(re.findall(r'\bcondition\("([A-Za-z0-9_]+)"', text))
        for k in sorted(literal):
            failures.append("%s: reads -%s_%s_%s by a literal: take it from its declaration, "
                            "key(%s::%s)" % (reader, family, entity, k, enum, k))
        for k in sorted(set(declared) - used):
            failures.append("-%s_%s_%s: declared in options.def but not read in %s" %
                            (family, entity, k, reader))
    return failures


def case_docs(decls):
    failures = []
    scenes = open(os.path.join(SOURCE, "docs", "scenes.md")).read()
    for family, entity, macro, _, _ in FAMILIES:
        for k in family_keys(macro):
            head = "-%s_%s_" % (family, entity)
            # "-bc_<b>_ux V`, `_uy`, `_uz`": a key named after the family on the same line
            if not re.search(r"%s%s\b|%s.*`_%s`" % (re.escape(head), re.escape(k),
                                                    re.escape(head), re.escape(k)), scenes):
                failures.append("-%s_%s_%s: not described in docs/scenes.md" % (family, entity, k))
    for d in decls:
        page = os.path.join(SOURCE, d["doc"])
        if not d["doc"].startswith("docs/") or not os.path.isfile(page):
            failures.append("-%s: its docs page %s does not exist" % (d["name"], d["doc"]))
            continue
        text = open(page).read()
        if not re.search(r"(?<![A-Za-z0-9_-])-%s(?![A-Za-z0-9_])" % re.escape(d["name"]), text):
            failures.append("-%s: not described in %s" % (d["name"], d["doc"]))
        for c in d["choices"]:
            if not re.search(r"-%s\W[^\n]*\b%s\b" % (re.escape(d["name"]), re.escape(c)), text):
                failures.append("-%s: its value %s is not in %s (on a line naming it)" %
                                (d["name"], c, d["doc"]))
    failures += restart_table(decls)
    return failures


def restart_table(decls):
    """docs/checkpoints.md's table of the options a restart may change ("Free, that is a
    restart may change them") names each option declared may_change, by name or by a family
    ("-test_*"), and no option declared fixed."""
    text = open(os.path.join(SOURCE, "docs", "checkpoints.md")).read()
    start = text.find("Free, that is a restart may change them")
    if start < 0:
        return ["docs/checkpoints.md: the table of options a restart may change is gone"]
    table = text[start:].split("\n\n")[1]
    names = set(re.findall(r"`-([A-Za-z][A-Za-z0-9_]*)`", table))
    families = set(re.findall(r"`-([A-Za-z][A-Za-z0-9_]*)\*`", table))
    failures = []
    for d in decls:
        covered = d["name"] in names or any(d["name"].startswith(f) for f in families)
        if d["restart"] == "may_change" and not covered:
            failures.append("-%s: a restart may change it (options.def), but the table of "
                            "docs/checkpoints.md does not say so" % d["name"])
        if d["restart"] == "fixed" and covered:
            failures.append("-%s: a restart must keep it (options.def), but the table of "
                            "docs/checkpoints.md lists it as free" % d["name"])
    return failures


READER = re.compile(
    r"\b(PetscOptions(?:Int|Real|Bool|String|Enum|EList|IntArray|RealArray|StringArray|"
    r"GetInt|GetReal|GetBool|GetString|GetEnum|GetEList|GetIntArray|GetRealArray|"
    r"GetStringArray|HasName)|get(?:Real|String|StringList|RealList|RequiredReal|Flag))"
    r"\s*\(([^;]*?)\"-([A-Za-z][A-Za-z0-9_]*)\"", re.S)


def case_readers(decls):
    declared = {d["name"] for d in decls}
    failures, seen, used = [], 0, set()
    for root, _, files in os.walk(os.path.join(SOURCE, "src")):
        for f in sorted(files):
            if not f.endswith((".cpp", ".hpp")):
                continue
            path = os.path.join(root, f)
            rel = os.path.relpath(path, SOURCE)
            text = open(path).read()
            used.update(re.findall(r"\bOption::([A-Za-z0-9_]+)", text))
            for m in READER.finditer(text):
                # the literal must be the call's option argument, not in a later statement
                if m.group(2).count("(") != m.group(2).count(")") and ")" in m.group(2):
                    continue
                name = m.group(3)
                seen += 1
                line = text.count("\n", 0, m.start()) + 1
                if name in declared:
                    if (rel, name) not in KNOWN_LITERALS:
                        failures.append("%s:%d: %s reads -%s by a literal: take it from its "
                                        "declaration, spec(Option::%s).flag" %
                                        (rel, line, m.group(1), name, name))
                elif not name.startswith(PETSC_PREFIXES) and name not in KNOWN_UNDECLARED:
                    failures.append("%s:%d: %s reads -%s, which is not declared in "
                                    "include/poroseam/options.def" % (rel, line, m.group(1), name))
    if seen == 0:
        failures.append("no reader with a literal option found in src/: the pattern is broken")
    for d in decls:
        if d["name"] not in used:
            failures.append("-%s: declared, but no code in src/ reads it (spec(Option::%s))" %
                            (d["name"], d["name"]))
    print("readers with a literal option name: %d" % seen)
    return failures + case_families()


HELP_LINE = re.compile(r"^\s+-([A-Za-z][A-Za-z0-9_]*):? <[^>]*>:? (.*) \(([^()]*)\)\s*$")


def case_help(decls):
    scene = os.path.join(SOURCE, "tests", "verification", "terzaghi_2d.opts")
    out_dir = os.path.join(OUTPUT_ROOT, "optdecl_help")
    run = subprocess.run([EXE, "-options_file", scene, "-output_dir", out_dir, "-help"],
                         cwd=SOURCE, capture_output=True, text=True, timeout=60)
    if run.returncode != 0:
        return ["-help exited with %d: %s" % (run.returncode, run.stderr[-400:])]
    listed = {}
    for line in run.stdout.splitlines():
        m = HELP_LINE.match(line)
        if m:
            listed.setdefault(m.group(1), []).append((m.group(2), m.group(3)))
    failures = []
    for d in decls:
        lines = listed.get(d["name"], [])
        if not lines:
            if d["name"] not in NOT_IN_HELP:
                failures.append("-%s: not listed by -help" % d["name"])
            continue
        if len(lines) != 1:
            failures.append("-%s: listed %d times by -help" % (d["name"], len(lines)))
        help_text, doc = lines[0]
        if help_text != d["help"] and help_text != d["help"] + " (required)":
            failures.append("-%s: -help says '%s', its declaration '%s'" %
                            (d["name"], help_text, d["help"]))
        if doc != d["doc"]:
            failures.append("-%s: -help names %s, its declaration %s" % (d["name"], doc, d["doc"]))
    print("declared options listed by -help: %d of %d" %
          (sum(1 for d in decls if d["name"] in listed), len(decls)))
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--case", choices=["docs", "readers", "help"], required=True)
    args = parser.parse_args()
    decls = declarations()
    names = [d["name"] for d in decls]
    failures = ["-%s: declared twice" % n for n in sorted(set(names)) if names.count(n) > 1]
    failures += {"docs": case_docs, "readers": case_readers, "help": case_help}[args.case](decls)
    print("declared options: %d" % len(decls))
    for f in failures:
        print("FAIL " + f)
    print("%s: %s" % (args.case, "FAILED" if failures else "passed"))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
