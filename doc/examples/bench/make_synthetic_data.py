#!/usr/bin/env python3
"""Write the SYNTHETIC example bench data of this directory (seeded).

Nothing here is measured: the "simulation" and the "true" actuator curves are
made-up smooth functions of plausible size, and the bench runs are produced
from them with the forward model that scripts/compare_experiment inverts,
    V_syringe = Delta V^p(p) + p/(p + p0) V^p + Delta V_compliance(p),
plus a little seeded noise on the pressure transducer.  Then a made-up
tracked_points.csv (the displacement of two surface nodes along the same
"simulation") and markers.csv (the same two points "tracked on video" on a
slightly softer cast, with noise), for scripts/compare_experiment --markers.

Run from anywhere: python3 doc/examples/bench/make_synthetic_data.py
"""

import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
COMMENT = ("# SYNTHETIC data for illustration only (made up by "
           "make_synthetic_data.py, not measured)")
P0 = 101.325                                    # kPa
CAVITY = 14612.3                                # V^p [mm^3]
rng = np.random.default_rng(20240607)


def write(name, header, rows, formats):
    with open(os.path.join(HERE, name), "w") as f:
        f.write(COMMENT + "\n" + ",".join(header) + "\n")
        for row in rows:
            f.write(",".join(fmt % x for fmt, x in zip(formats, row)) + "\n")


def compliance(p):
    """"True" syringe + tubing compliance [mm^3]."""
    return 27.5 * p - 0.22 * p**2


def pressure_for(volume, actuator):
    """Invert the (monotone) forward model V_syringe(p) for p."""
    grid = np.linspace(0.0, 25.0, 25001)
    v = compliance(grid)
    if actuator is not None:
        v = v + actuator(grid) + grid / (grid + P0) * CAVITY
    return np.interp(volume, v, grid)


# Simulation: 20 load steps up to 15 kPa, nearly linear Delta V.
steps = np.arange(21)
p_sim = 15.0 * steps / 20
dv_sim = 182.0 * p_sim + 1.25 * p_sim**2
rows = [(k, k / 20, p, CAVITY + dv, dv, 0.0021 * dv, 0.0009 * dv,
         3 + (k > 0) + (k > 12), 2e-9 * (1 + k), int(k == 20))
        for k, p, dv in zip(steps, p_sim, dv_sim)]
write("load_path.csv",
      ["step", "load_factor", "pressure_kPa", "cavity_volume_mm3",
       "delta_volume_mm3", "design_mean_ux_mm",
       "design_mean_inward_radial_mm", "newton_iterations",
       "residual_norm_N", "at_target"], rows,
      ["%d", "%.3f", "%.4f", "%.3f", "%.3f", "%.5f", "%.5f", "%d", "%.3e",
       "%d"])

# Compliance run (actuator replaced by a plug): 3 ml/min, 10 samples/s.
t = np.arange(0.0, 9.6, 0.1)
v = 3.0 * 1000 / 60 * t
p = pressure_for(v, None) + rng.normal(0.0, 0.02, t.size)
write("compliance.csv", ["time_s", "syringe_volume_ml", "pressure_kPa"],
      zip(t, v / 1000, p), ["%.1f", "%.4f", "%.3f"])

# Three actuator runs at 5 ml/min, 2 samples/s, with a few % spread between
# casts; stopped just below 15 kPa.
for run, stiffness in enumerate([0.97, 1.0, 1.04], start=1):
    def actuator(p, s=stiffness):
        return (176.0 * p + 1.45 * p**2) / s
    t = np.arange(0.0, 120.0, 0.5)
    v = 5.0 * 1000 / 60 * t
    p = pressure_for(v, actuator)
    keep = p < 14.7
    p = p[keep] + rng.normal(0.0, 0.02, keep.sum())
    write(f"run{run}.csv", ["time_s", "syringe_volume_ml", "pressure_kPa"],
          zip(t[keep], v[keep] / 1000, p), ["%.1f", "%.4f", "%.3f"])


# Tracked points of the "simulation" (as softopt writes them for
# "Tracked points = tip: 60, 0, 11.5; side: 30, 0, 11.5"): the surface node
# chosen for each and its displacement, made up in proportion to Delta V.
nodes = {"tip": (60.0, 0.0, 11.5), "side": (30.12, 0.0, 11.5)}


def marker_displacements(dv):
    """Made-up displacements (ux, uy, uz) [mm] of the two nodes."""
    return {"tip": (0.0021 * dv, 0.0 * dv, 0.0002 * dv),
            "side": (0.0010 * dv, 0.0 * dv, 0.0012 * dv)}


u = marker_displacements(dv_sim)
rows = [(k, k / 20, p) + tuple(x for name in nodes
                               for x in nodes[name] + tuple(
                                   c[k] for c in u[name]))
        for k, p in enumerate(p_sim)]
write("tracked_points.csv",
      ["step", "load_factor", "pressure_kPa"]
      + [f"{name}_{q}_mm" for name in nodes
         for q in ("X", "Y", "Z", "ux", "uy", "uz")], rows,
      ["%d", "%.3f", "%.4f"] + ["%.3f"] * 3 * len(nodes) * 2)

# Markers on video: one camera facing the x-z plane (so u_x and u_z only),
# 1 frame/s over a 5 ml/min run of a cast 4 % softer than the simulation,
# marker positions picked to +-0.03 mm.
t = np.arange(0.0, 120.0, 1.0)
v = 5.0 * 1000 / 60 * t


def cast(p):
    return (182.0 * p + 1.25 * p**2) * 1.04


p = pressure_for(v, cast)
keep = p < 14.7
p = p[keep]
u = marker_displacements(cast(p))
columns = [t[keep], p + rng.normal(0.0, 0.02, p.size)]
for name in nodes:
    for c in (0, 2):
        columns.append(u[name][c] + rng.normal(0.0, 0.03, p.size))
write("markers.csv",
      ["time_s", "pressure_kPa", "tip_ux_mm", "tip_uz_mm", "side_ux_mm",
       "side_uz_mm"], zip(*columns), ["%.1f", "%.3f"] + ["%.3f"] * 4)
