"""Helpers shared by the interface-hydraulics drivers of tests/hydraulics/.

Imports tests/verification/common.py (run poroseam, read timeseries.csv, Checks) and
tests/support/interface_reader.py (per-integration-point interface output).
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
TESTS = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(TESTS, "verification"))
sys.path.insert(0, os.path.join(TESTS, "support"))
import common  # noqa: E402,F401
from common import analytic  # noqa: E402,F401

MU_W = 1e-3  # water viscosity (poroseam default)


def scene(name):
    return os.path.join(HERE, name)


def interface_points(out_dir):
    """interface_reader.read_interfaces(out_dir), or a failure of the driver."""
    from interface_reader import read_interfaces, InterfaceOutputError
    try:
        return read_interfaces(out_dir)
    except (InterfaceOutputError, OSError) as e:
        common.fail(f"cannot read the interface output of {out_dir}: {e}")


def point_field(out, name, index=-1):
    """An integration-point field of the interface output at output time `index`."""
    fields = out.point_fields[index]
    if name not in fields:
        common.fail(f"interface output has no point field '{name}' (fields: {', '.join(sorted(fields))})")
    return np.asarray(fields[name])


def rel(a, b, ref):
    return abs(a - b) / abs(ref)
