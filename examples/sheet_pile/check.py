"""Checks a sheet-pile run against two conservation laws (docs/tutorial.md, step 6).

    /usr/bin/python3 check.py results

1. Equilibrium at the end: the forces through all boundaries balance the weight of soil and
   pile (sum of Fy = W, sum of Fx = 0).
2. Water balance over the whole run: the water that left through the boundaries and along the
   interface equals the volume the soil lost plus the water the gap lost (the grains and the
   water are incompressible here, so every cubic metre of soil that shrinks is a cubic metre
   of water gone).
Prints both and exits 1 when either is off by more than 1e-6 (relative).
"""
import sys

import h5py
import numpy as np

out = sys.argv[1] if len(sys.argv) > 1 else "results"
g, rho_w = 9.81, 1000.0
soil_density = (1 - 0.4) * 2650 + 0.4 * rho_w       # saturated silt [kg/m3]
pile_density = 7850.0

# --- the time series: one row per step
with open(f"{out}/timeseries.csv") as f:
    header = f.readline().strip().split(",")
data = np.loadtxt(f"{out}/timeseries.csv", delimiter=",", skiprows=1, ndmin=2)
col = {name: data[:, i] for i, name in enumerate(header)}
boundaries = sorted({c.split(".")[0] for c in header if c.endswith(".Fx") and c.count(".") == 1}
                    - {"wall"})

# --- areas of soil and pile, and the soil's volume change, from fields.h5
with h5py.File(f"{out}/fields.h5", "r") as f:
    xy = f["geometry/vertices"][:, :2]
    cells = f["topology/cells"][:]
    region = f["cell_fields/region"][:].ravel()
    names = f["cell_fields/region"].attrs["names"]
    names = (names.decode() if isinstance(names, bytes) else str(names)).split(",")
    last = str(max(int(k) for k in f["cell_fields/strain"].keys()))
    strain = f["cell_fields/strain/" + last][:].reshape(-1, 3, 3)
    t_fields = f["cell_fields/strain/" + last].attrs["time"]
a, b, c = (xy[cells[:, k]] for k in range(3))               # triangles
area = 0.5 * np.abs((b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (c[:, 0] - a[:, 0]) * (b[:, 1] - a[:, 1]))
soil = region == names.index("soil")
pile = region == names.index("pile")

# 1. equilibrium (per metre of wall: plane strain)
weight = g * (soil_density * area[soil].sum() + pile_density * area[pile].sum())
fy = sum(col[f"{b}.Fy"][-1] for b in boundaries)
fx = sum(col[f"{b}.Fx"][-1] for b in boundaries)
largest_fx = max(abs(col[f"{b}.Fx"][-1]) for b in boundaries)
print(f"weight {weight / 1e3:.2f} kN/m, sum of boundary Fy {fy / 1e3:.2f} kN/m: "
      f"off by {abs(fy - weight) / weight:.1e}")
print(f"sum of boundary Fx {fx:.3g} N/m against the largest {largest_fx / 1e3:.2f} kN/m: "
      f"off by {abs(fx) / largest_fx:.1e}")

# 2. water balance: what left (boundaries, and along the interface) = what the soil and the
# gap lost. Backward Euler: a step's flux is its mean rate over the step.
assert abs(t_fields - col["time"][-1]) < 1e-9 * col["time"][-1], "fields.h5 lacks the last step"
outflow = [c for c in header if c.endswith(".flux") or c.endswith(".interface_outflow")]
left = sum(np.sum(col["dt"] * col[c]) for c in outflow)
inflow = -sum(np.sum(col["dt"] * np.minimum(col[c], 0.0)) for c in outflow)
soil_lost = -np.sum(area[soil] * (strain[soil, 0, 0] + strain[soil, 1, 1]))
gap_lost = col["wall.storage"][0] - col["wall.storage"][-1]
print(f"water out {left:.4e} m3/m = soil volume lost {soil_lost:.4e} + gap water lost "
      f"{gap_lost:.4e}: off by {abs(left - soil_lost - gap_lost) / inflow:.1e} of the "
      f"{inflow:.4e} m3/m that came in")

ok = (abs(fy - weight) / weight < 1e-6 and abs(fx) / largest_fx < 1e-6
      and abs(left - soil_lost - gap_lost) / inflow < 1e-6)
print("balanced" if ok else "NOT balanced")
sys.exit(0 if ok else 1)
