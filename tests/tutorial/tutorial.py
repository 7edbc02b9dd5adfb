#!/usr/bin/python3
"""docs/tutorial.md, run exactly as it is written.

The tutorial's files are its code blocks whose info string names a file (```gmsh
file=sheet_pile.geo); its commands are the blocks marked ```sh run, in order. This test writes
the files into an empty folder, runs the commands there ($POROSEAM is the executable under
test), and passes when every command exits 0. The last command is the tutorial's own check
(check.py): equilibrium of the forces through the boundaries against the weight, and the water
balance of the whole run, both to 1e-6. It also checks that examples/sheet_pile/ holds the same
files as the page, byte for byte, so that the copies cannot drift apart.
"""
import os
import re
import shlex
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("POROSEAM_SOURCE", os.path.dirname(os.path.dirname(HERE)))
EXE = os.environ.get("POROSEAM_EXE", os.path.join(SOURCE, "build", "poroseam"))
OUTPUT_ROOT = os.environ.get("POROSEAM_TEST_OUTPUT", "/tmp/poroseam-test-output")
BLOCK = re.compile(r"^```([^\n]*)\n(.*?)^```$", re.S | re.M)


def blocks(text):
    """(files {name: content}, commands [argv]) of a Markdown page."""
    files, commands = {}, []
    for info, body in BLOCK.findall(text):
        m = re.search(r"\bfile=(\S+)", info)
        if m:
            files[m.group(1)] = body
        elif info.split()[1:2] == ["run"]:
            commands += [ln for ln in body.splitlines() if ln.strip() and not ln.startswith("#")]
    return files, commands


def main():
    with open(os.path.join(SOURCE, "docs", "tutorial.md")) as f:
        files, commands = blocks(f.read())
    failures = []
    if not files or not commands:
        failures.append(f"the page has {len(files)} files and {len(commands)} commands")
    example = os.path.join(SOURCE, "examples", "sheet_pile")
    for name, content in files.items():
        path = os.path.join(example, name)
        if not os.path.isfile(path) or open(path).read() != content:
            failures.append(f"examples/sheet_pile/{name} differs from the tutorial's block")
    work = os.path.join(OUTPUT_ROOT, "tutorial")
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    for name, content in files.items():
        with open(os.path.join(work, name), "w") as f:
            f.write(content)
    env = dict(os.environ, POROSEAM=EXE, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMPI_MCA_rmaps_base_oversubscribe="1")
    for line in commands:
        argv = [EXE if a == "$POROSEAM" else a for a in shlex.split(line)]
        print("run:", line, flush=True)
        p = subprocess.run(argv, cwd=work, env=env, stdout=subprocess.PIPE,
                           stderr=subprocess.STDOUT, timeout=600)
        text = p.stdout.decode(errors="replace")
        print("    " + "\n    ".join(text.strip().splitlines()[-8:]))
        if p.returncode != 0:
            failures.append(f"'{line}' exited with {p.returncode}")
            break
    if failures:
        print("FAIL:\n  " + "\n  ".join(failures))
        return 1
    print(f"PASS: {len(files)} files and {len(commands)} commands of docs/tutorial.md")
    return 0


if __name__ == "__main__":
    sys.exit(main())
