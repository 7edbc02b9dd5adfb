"""Storage of a gap opened at a known rate (docs/verification.md, interface flow).

    gap_storage.py [--ranks N] [--order 2] [--axisymmetric]

Scene tests/hydraulics/gap_storage_2d.opts: a near-rigid (E = 1e15 Pa) porous base
[0,1] x [0,0.5] drained at its bottom (p = 0), a near-rigid elastic block on it pulled up at
v = 1e-6 m/s (ramp of the top displacement from t = 0), interface side 1 = base with
T1 = 1e-9 m/(Pa s), T2 = 0 (impervious block), closed ends. Per unit area, steady from the first
step on (rigid, incompressible base: div u = 0, Darcy with a linear p):

    dh/dt = v,  f1 = v,  p1 = -v H1 / k'  (top of the base),  p3 = p1 - v / T1,
    bottom inflow = v A,  contact force on the base -p3 A  (open gap, p'_N = 0).

Checks:
  * every step: interface water balance with closed ends, storage_rate = flux1 (T2 = 0: the
    gap is fed from side 1 only); discrete identity (sum of the p3 test functions), 1e-10 of vA;
  * every step: storage_rate = (storage_n - storage_{n-1}) / dt (backward Euler), 1e-8 of vA
    (the CSV carries 11 digits of a storage that grows to 2e-5 m3: 1e-16 / dt = 1e-10 of vA);
  * from step 2: dh/dt = storage_rate / A = v and flux1 = v A, to 1e-8. At step 1 the suction
    jumps from 0 to p3 and the near-rigid bodies give back p3 H / E = 1.4e-12 m of the 1e-6 m
    opening (1.4e-6 relative): that step is checked against v to 1e-5 only;
  * from step 2: bottom inflow = v A, p1 (probe 1e-9 m below the interface) and p3 (interface
    output) against the closed forms, contact force = -p3 A: 1e-8.

--axisymmetric: the same mesh as a solid cylinder of radius 1 m (x = r; nu = 0 and ux = 0 at
top and bottom keep u_r = 0, no hoop strain): the same state, every flow and force for the full
circle, A = pi (the ring weights 2 pi r of the interface's storage, exchange and p3 force).
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from hydraulics_common import common, scene, interface_points, point_field  # noqa: E402

V = 1e-6          # opening rate: 1e-5 m over the 10 s ramp
AREA = 1.0        # interface length x 1 m
H1 = 0.5          # base height
KP = 1e-12 / 1e-3  # k / mu_w of the base
T1 = 1e-9


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--order", type=int, choices=(1, 2), default=1)
    ap.add_argument("--axisymmetric", action="store_true",
                    help="the mesh as a solid cylinder (x = r): full-circle flows, A = pi")
    args = ap.parse_args()
    order = f"_order{args.order}" if args.order > 1 else ""
    axi = "_axi" if args.axisymmetric else ""
    out = common.output_dir(f"hydraulics_gap_storage{axi}{order}_np{args.ranks}")
    probe = ["-probe_below", f"0.5,{H1 - 1e-9}"] if args.order == 1 else []
    extra = probe + (["-displacement_order", args.order] if args.order > 1 else [])
    extra += ["-axisymmetric"] if args.axisymmetric else []
    common.run(scene("gap_storage_2d.opts"), out, extra, ranks=args.ranks)
    ts = common.read_timeseries(out)
    chk = common.Checks(f"storage of a gap opened at v = {V:g} m/s{order}"
                        f"{', axisymmetric' if args.axisymmetric else ''}, {args.ranks} rank(s)")
    area = AREA * (np.pi if args.axisymmetric else 1.0)
    vA = V * area
    rate, f1, dt = ts["contact.storage_rate"], ts["contact.flux1"], ts["dt"]
    storage = np.r_[ts["contact.storage"][0] - dt[0] * rate[0], ts["contact.storage"]]
    p1 = -V * H1 / KP
    p3 = p1 - V / T1
    print(f"  closed forms: dh/dt = {V:g} m/s, p1 = {p1:g} Pa, p3 = {p3:g} Pa; steps {len(dt)}, "
          f"storage {storage[0]:.6e} -> {storage[-1]:.6e} m3{'' if args.axisymmetric else ' per m'}")
    for k in range(len(dt)):
        below = f", below.p {ts['below.p'][k]:.6f}" if probe else ""
        print(f"  t {ts['time'][k]:5.1f}: storage_rate {rate[k]:.10e}, flux1 {f1[k]:.10e}, "
              f"bottom.flux {ts['bottom.flux'][k]:.10e}{below}")
    chk.check("cut-backs", ts["rejected"].sum(), 0)
    chk.check("every step: max |storage_rate - flux1| / (vA)", np.max(np.abs(rate - f1)) / vA, 1e-10)
    chk.check("every step: max |storage_rate - d(storage)/dt| / (vA)",
              np.max(np.abs(rate - np.diff(storage) / dt)) / vA, 1e-8)
    chk.check("step 1: |dh/dt - v| / v (bodies take p3 H/E)", abs(rate[0] / area - V) / V, 1e-5)
    later = slice(1, None)
    chk.check("steps >= 2: max |dh/dt - v| / v", np.max(np.abs(rate[later] / area - V)) / V, 1e-8)
    chk.check("steps >= 2: max |flux1 - vA| / (vA)", np.max(np.abs(f1[later] - vA)) / vA, 1e-8)
    chk.check("steps >= 2: max |-bottom.flux - vA| / (vA)",
              np.max(np.abs(-ts["bottom.flux"][later] - vA)) / vA, 1e-8)
    if probe:
        chk.check("steps >= 2: max |p1 - (-v H1/k')| / |p3|",
                  np.max(np.abs(ts["below.p"][later] - p1)) / abs(p3), 1e-8)
    chk.check("steps >= 2: max |contact.Fy - (-p3 A)| / |p3 A|",
              np.max(np.abs(ts["contact.Fy"][later] + p3 * area)) / abs(p3 * area), 1e-8)
    ifc = interface_points(out)
    worst = max(np.max(np.abs(f["interface_pressure"] - p3)) for f in ifc.point_fields[2:])
    chk.check("steps >= 2: max |p3 - (p1 - v/T1)| / |p3| (interface output)", worst / abs(p3), 1e-8)
    ar = max(np.max(np.abs(f["aperture_rate"] - V)) for f in ifc.point_fields[2:])
    chk.check("steps >= 2: max |aperture_rate - v| / v (interface output)", ar / V, 1e-8)
    chk.finish()


if __name__ == "__main__":
    main()
