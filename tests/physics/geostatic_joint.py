"""Drained geostatic column with a joint: the water in an interface without flow.

In a drained scene the pore pressure stays hydrostatic, and so does the water in a gap that
has no flow model: it pushes both faces, the total normal pressure on the joint being
p'_N + p_w (Terzaghi). The geostatic state is then an exact equilibrium: no displacement
(|u| < 1e-12 m), p'_N = gamma' depth at every joint integration point (relative 1e-9), and the
force on the lower layer from the upper one is -(gamma' + gamma_w) depth W (1e-9).
Without the gap water the soil would press into the joint by p_w / K_N.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "verification"))
sys.path.insert(0, os.path.join(os.path.dirname(HERE), "support"))
import common  # noqa: E402
from interface_reader import read_interfaces  # noqa: E402

g, rho_w, rho_s, n, W, depth = 9.81, 1000.0, 2650.0, 0.36, 0.1, 0.5
gamma_b = ((1 - n) * rho_s + n * rho_w - rho_w) * g  # buoyant unit weight
out = common.output_dir("geostatic_joint")
common.run(os.path.join(HERE, "geostatic_joint.opts"), out, ["-probe_top", "0.05,1", "-probe_mid", "0.05,0.75"])
ts = common.read_timeseries(out)
chk = common.Checks("drained geostatic column with a joint")
umax = max(np.max(np.abs(ts[c])) for c in ("top.ux", "top.uy", "mid.ux", "mid.uy"))
chk.check("max |u| at probes [m]", umax, 1e-12)
pts = read_interfaces(out).point_fields[-1]
pn = pts["contact_pressure_effective"]
chk.check("max |p'_N - gamma' depth| / (gamma' depth)", np.max(np.abs(pn - gamma_b * depth)) / (gamma_b * depth), 1e-9)
total = (gamma_b + rho_w * g) * depth * W
chk.check("|joint.Fy + (gamma' + gamma_w) depth W| / that", abs(ts["joint.Fy"][-1] + total) / total, 1e-9)
chk.finish()
