#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""The wall layer of configs/rotating_waves.ini at the two stagnation points (Nigam 1999, section 4.4.1):

  rotating_waves_layer.py OUT.h5 [--sluice PATH] [--band B]

The m = n = 1 wave has two stagnation points on the wall, on the rays at
+-pi/2 from the phase of its first azimuthal mode (`stream_function_phase`):
at one the flow runs toward the wall, at the other away from it, where
Nigam, by analogy with Hiemenz's problem, expects the viscous layer to grow
("Already at time t = 5 the viscous region ... is observed to be thicker in
the lower half-plane", section 4.4.2). Which ray is which is read from the
sign of u_r at r = 1 - B. The measure is the displacement thickness of the
swirl across the band 1 - B <= r <= 1 (default B = 0.1),

    delta* = int_{1-B}^{1} (1 - u_theta(r) / u_theta(1 - B)) dr,

which is B/3 for a linear fall to the no-slip value and grows by
2 (nu t / pi)^(1/2) in Rayleigh's impulsive layer while that is thinner
than the band. The profiles come from `sluice sample --line` along each
ray (each cell's own basis); points between the circle and a wall cell's
quadratic edge lie outside the mesh and are left out (a sliver of 1e-4 or
less of the band). Prints per output: t, the phase, delta* on the
inflow ray (toward the wall) and the outflow ray (away from it), and their
ratio; the first output from which the outflow ray's layer stays thicker."""
import csv
import io
import math
import subprocess
import sys

import h5py

args = sys.argv[1:]
SLUICE, BAND, N = "sluice", 0.1, 2001
if "--sluice" in args:
    i = args.index("--sluice")
    SLUICE = args[i + 1]
    del args[i:i + 2]
if "--band" in args:
    i = args.index("--band")
    BAND = float(args[i + 1])
    del args[i:i + 2]
path = args[0]


def profile(t, th):
    """u_r, u_theta on the ray at angle th from r = 1 - BAND to the wall, at output time t."""
    r0, r1 = 1 - BAND, 1 - 1e-9
    line = f"{r0*math.cos(th)},{r0*math.sin(th)}:{r1*math.cos(th)},{r1*math.sin(th)}"
    out = subprocess.run([SLUICE, "sample", path, "--field", "velocity", "--time", repr(t), "--line", line,
                          "--n", str(N)], check=True, capture_output=True, text=True).stdout
    rows = list(csv.DictReader(io.StringIO(out)))
    rs, ur, ut = [], [], []
    for w in rows:
        x, y = float(w["x"]), float(w["y"])
        u, v = float(w["velocity_0"]), float(w["velocity_1"])
        if math.isnan(u) or math.isnan(v):
            continue  # between the circle and the wall cell's quadratic edge: outside the mesh
        r = math.hypot(x, y)
        rs.append(r)
        ur.append((u * x + v * y) / r)
        ut.append((-u * y + v * x) / r)
    if rs[-1] < 1 - 2e-2 * BAND:  # a straight wall edge sags by up to (dtheta/2)^2/2 from the circle
        sys.exit(f"{path}: the ray at {th:.4f} ends at r = {rs[-1]:.6f}, not at the wall")
    return rs, ur, ut


def displacement(rs, ut):
    """int (1 - u_theta/u_theta(r0)) dr by the trapezoidal rule on the sampled points."""
    f = [1 - u / ut[0] for u in ut]
    return sum(0.5 * (f[k] + f[k + 1]) * (rs[k + 1] - rs[k]) for k in range(len(rs) - 1))


f = h5py.File(path, "r")
times = sorted((float(f[k].attrs["time"]), float(f[k].attrs["stream_function_phase"]))
               for k in f if k.startswith("step_") and "stream_function_phase" in f[k].attrs)
print(f"{path}: displacement thickness of u_theta over {1 - BAND:g} <= r <= 1 at the stagnation points")
print("     t    phase   toward the wall   away from it   away/toward   (ray angles)")
since = None
for t, ph in times:
    res = []
    for th in (ph + math.pi / 2, ph - math.pi / 2):
        rs, ur, ut = profile(t, th)
        res.append((ur[0], displacement(rs, ut), th))
    res.sort(key=lambda q: -q[0])  # u_r > 0 first: the flow toward the wall
    (_, d_in, th_in), (_, d_out, th_out) = res
    if d_out > d_in:
        since = since if since is not None else t
    else:
        since = None
    print(f"  {t:6.2f}  {ph:+6.3f}   {d_in:.5f}          {d_out:.5f}        {d_out/d_in:.4f}"
          f"   ({math.degrees(th_in) % 360:5.1f}, {math.degrees(th_out) % 360:5.1f} deg)")
print(f"  the layer away from the wall is thicker from t = {since:g} on" if since is not None
      else "  the layer away from the wall is not thicker at the end")
