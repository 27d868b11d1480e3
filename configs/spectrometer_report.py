#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-2.0-or-later
"""What configs/spectrometer.ini's output says (Nigam 1999, section 4.3):

  spectrometer_report.py [--slot SW WT] OUT.h5 [OUT2.h5 ...]
  spectrometer_report.py [--slot SW WT] --series OUT.h5 RESTARTED.h5 ...   (one run, continued by --restart)

--slot: the mesh was made with gmsh -setnumber sw SW -setnumber wt WT (the slot's width and the separating
wall's thickness in delta; default 2 and 0.5, configs/spectrometer.geo).

per output time: the solids inventories downstream of the slot (inner_down,
outer_down) and the efficiency outer_down/(inner_down + outer_down); the
solids leaving through each outlet per unit time since the previous output
(from solids_through_*, the transport's own fluxes, per radian) and the
outer outlet's share; the share passing the slot, 1 - (inner outlet + the
inner channel's inventory growth)/inflow; the most retrograde swirl u_theta in the slot
(its nodes); the largest phi in the cells on the inclined walls (the
sediment); and at the last time the velocity across the inner channel half
way to the slot against the rotating-channel profile of the inflow, and the
slot's through-flow u_s (the mean outward velocity on its mid-line) with the
swirl it adds by the Coriolis force, -(5/4)(Omega cos(g) b^2/nu) u_s (b the
slot's half-width; docs/rotating.md, "The swirl in the slot").

Then the steadiness, window by window: over each window of WINDOW = 0.5
time units ending at an output time (at least the inner channel's
through-flow time T = V/(Q/2 pi) = 0.42, V its volume per radian), the
efficiency P, the share of the solids entering that pass to the outer
channel: 1 - (inner outlet + the inner channel's inventory growth)/(solids
entering); its change from the window before; the inner channel's growth
and the whole inventory's (of the solids entering); the share E = outer
outlet/(both outlets) of the solids leaving, and the cumulative share
(outer_down + outer outlet)/(inner_down + outer_down + both outlets) of
the particles that went downstream of the slot (the thesis's efficiency,
extrapolated from the inventories downstream of the slot). The run is
steady from the first window of the last span of windows where P's
change and the inner channel's growth are both below STEADY = 1e-3. The outer channel's sediment may
still fill and slide (E then moves with it); once it is steady too, E and
the cumulative share tend to P.

A sediment that slides in surges moves P by percents from window to window
long after the mean has settled. The statistical steady state is therefore
read over the last SPAN = 8 windows (4 time units, 9.5 through-flow
times): the mean of P over them (with equal windows and a steady inflow,
the P of the whole span), their range (min to max, the spread), and the
drift, the mean of the last 4 windows less that of the 4 before. The mean
is settled when |drift| < DRIFT = 2e-3, below the mesh differences it is
compared with (0.6 points between 18 and 24 cells across)."""
import math
import sys

import h5py
import numpy as np

Q = 0.195
G = math.pi / 4
DELTA = Q / (4 * math.pi)
S, C = math.sin(G), math.cos(G)
XI0 = 1 / S
SW, WT = 2.0, 0.5  # the slot's width and the wall's thickness, in delta (--slot)
XA, XB, XE = XI0 + (12 - SW / 2) * DELTA, XI0 + (12 + SW / 2) * DELTA, XI0 + 24 * DELTA
W = WT * DELTA
RO, RE = 4.22e-4, 1.06
# the inner channel's through-flow time: its volume per radian, 2 delta int r dxi with r = xi sin(g), over the flux
# per radian Q/(2 pi)
T_THROUGH = 2 * DELTA * S * (XE**2 - XI0**2) / 2 / (Q / (2 * math.pi))
WINDOW, STEADY = 0.5, 1e-3
SPAN, DRIFT = 8, 2e-3  # the statistical steady state: the last SPAN windows, settled when |drift| < DRIFT


def chan(x, y):
    """(xi, n): along the cone's generator and across it."""
    return x * S - y * C, x * C + y * S


def report(path):
    f = h5py.File(path, "r")
    xy = f["mesh/coordinates"][:, :2]
    cells = f["mesh/topology"][:]
    cc = f["mesh/cell_centres"][:, :2]
    xi_n, n_n = chan(xy[:, 0], xy[:, 1])
    xi_c, n_c = chan(cc[:, 0], cc[:, 1])
    slot_nodes = (n_n > DELTA - 1e-9) & (n_n < DELTA + W + 1e-9) & (xi_n > XA - 1e-9) & (xi_n < XB + 1e-9)
    # wall cells: within one cell of a channel wall, downstream of the slot
    wall_band = 0.2 * DELTA
    down = xi_c > XB
    walls = {
        "inner channel, outer wall (below the slot)": down & (n_c > DELTA - wall_band) & (n_c < DELTA),
        "outer channel, outer wall (below the slot)": down & (n_c > 3 * DELTA + W - wall_band),
        "outer channel, outer wall (above the slot's end)": (xi_c < XB) & (n_c > 3 * DELTA + W - wall_band),
    }
    steps = sorted(k for k in f if k.startswith("step_"))
    prev = None
    print(f"{path}:")
    print("   t      inner_down   outer_down   eff(inv)   solids out/time: inner  outer  eff(flux)  in        passing"
          "  min u_theta slot  max phi walls")
    for k in steps:
        g = f[k]
        a = g.attrs
        if "solids_inventory_inner_down" not in a:
            continue
        t = a["time"]
        i_d, o_d = a["solids_inventory_inner_down"], a["solids_inventory_outer_down"]
        eff = o_d / (i_d + o_d) if i_d + o_d > 0 else float("nan")
        phi = g["phi"][:].ravel()
        # the solids leaving through each outlet since the last output (the transport's own fluxes)
        inner = a["solids_inventory_inner_up"] + a["solids_inventory_inner_slot"] + a["solids_inventory_inner_down"]
        cum = (-a["solids_through_inner_outlet"], -a["solids_through_outer_outlet"], a["solids_through_inner_inlet"],
               inner)
        dt = t - prev[0] if prev else 0
        fl_in, fl_out, fl_src, grow = ((cum[i] - prev[1][i]) / dt for i in range(4)) if dt > 0 else (0.0,) * 4
        prev = (t, cum)
        efl = fl_out / (fl_in + fl_out) if fl_in + fl_out > 0 else float("nan")
        passing = 1 - (fl_in + grow) / fl_src if fl_src > 0 else float("nan")
        ut = g["u_theta"][:].ravel()
        sw = ut[slot_nodes].min()
        mw = [phi[m].max() if m.any() else 0 for m in walls.values()]
        print(f"  {t:5.2f}  {i_d:.4e}  {o_d:.4e}  {100*eff:6.1f} %  {fl_in:.3e} {fl_out:.3e}  {100*efl:6.1f} % {fl_src:.3e} {100*passing:6.1f} %"
              f"  {sw:8.3f}   " + "  ".join(f"{m:.3f}" for m in mw))
    print("  walls:", "; ".join(walls.keys()))
    # the velocity profile half way to the slot against the inflow's
    g = f[steps[-1]]
    u = g["velocity"][:]
    ut = g["u_theta"][:].ravel()
    xi_m = 0.5 * (XI0 + XA)
    sel = (np.abs(xi_n - xi_m) < 0.6 * DELTA / 3) & (n_n < DELTA + 1e-9)
    if sel.any():
        Ro, Re = RO, RE
        E1 = Ro / (Re * S * DELTA**2)
        aa = 1 / math.sqrt(E1)
        G1 = 2 * aa * (math.cosh(2 * aa) + math.cos(2 * aa)) / (math.sinh(2 * aa) - math.sin(2 * aa))
        D2 = (math.cosh(aa) * math.cos(aa)) ** 2 + (math.sinh(aa) * math.sin(aa)) ** 2
        k1 = G1 * math.cosh(aa) * math.cos(aa) / (2 * D2)
        k2 = -G1 * math.sinh(aa) * math.sin(aa) / (2 * D2)
        K = Q / (2 * math.pi * DELTA)
        z = n_n[sel] / DELTA
        r = xy[sel, 0]
        U = -k1 * np.sinh(aa * z) * np.sin(aa * z) - k2 * np.cosh(aa * z) * np.cos(aa * z)
        V = -G1 / 2 + k1 * np.cosh(aa * z) * np.cos(aa * z) - k2 * np.sinh(aa * z) * np.sin(aa * z)
        uxi = u[sel, 0] * S - u[sel, 1] * C
        print(f"  half way to the slot (xi - xi0 = {xi_m - XI0:.4f}), t = {g.attrs['time']:.2f}: u_xi against K U/r "
              f"{np.abs(uxi - K * U / r).max():.3e} of max {np.abs(K * U / r).max():.3f}; u_theta against K V/r "
              f"{np.abs(ut[sel] - K * V / r).max():.3e} of max {np.abs(K * V / r).max():.3f}")
    # the slot's through-flow: u_n = u . (cos g, sin g) on its mid-line, weighted by r (the flux per radian over
    # the area per radian); the swirl the Coriolis force on it adds at the slot's centre: the azimuthal component
    # of Nigam 1999 eq 4.151, (2/Ro) u_r = (1/Re) v'' across the slot (steady, advection neglected), with
    # u_r = cos(g) u_n, u_n = (3/2) u_s (1 - s^2/b^2) and v(+-b) = 0
    mid = (np.abs(n_n - (DELTA + W / 2)) < 1e-7) & (xi_n > XA - 1e-9) & (xi_n < XB + 1e-9)
    if mid.sum() > 1:
        o = np.argsort(xi_n[mid])
        x_m, u_m, r_m = xi_n[mid][o], (u[mid, 0] * C + u[mid, 1] * S)[o], xy[mid, 0][o]
        u_s = np.trapz(u_m * r_m, x_m) / np.trapz(r_m, x_m)
        b = SW * DELTA / 2
        print(f"  the slot's through-flow u_s = {u_s:.4f} (flux per radian {np.trapz(u_m * r_m, x_m):.5f}); the swirl"
              f" the Coriolis force on it adds, -(5/4)(Omega cos(g) b^2/nu) u_s = "
              f"{-1.25 * C * b * b * RE / RO * u_s:.4f}")


def steadiness(paths):
    """The window table (module docstring) of one run, in one file or in several continued by --restart;
    returns (the steady time or None, P there, the last window's P)."""
    seen = {}
    for path in paths:
        f = h5py.File(path, "r")
        for k in sorted(k for k in f if k.startswith("step_")):
            a = f[k].attrs
            if "solids_inventory_inner_down" not in a:
                continue
            inner = a["solids_inventory_inner_up"] + a["solids_inventory_inner_slot"] + a["solids_inventory_inner_down"]
            seen[round(float(a["time"]), 9)] = (a["time"], a["solids_through_inner_inlet"],
                                                -a["solids_through_inner_outlet"], -a["solids_through_outer_outlet"],
                                                a["solids_inventory"], a["solids_inventory_inner_down"],
                                                a["solids_inventory_outer_down"], inner)
    rows = [seen[k] for k in sorted(seen)]
    t = np.array([r[0] for r in rows])
    print(f"  windows of {WINDOW} (through-flow time {T_THROUGH:.3f}); steady when P changes by < {STEADY:g} a window"
          f" and the inner channel's inventory grows by < {STEADY:g} of the solids entering:")
    print("   t      P(passing)  change    lost     growth: inner   all    E(outlets)  cumulative share downstream")
    prev_p, t_steady, p_steady, p = None, None, None, float("nan")
    ps = []
    for r in rows:
        j = np.where(np.abs(t - (r[0] - WINDOW)) < 1e-6)[0]
        if not len(j) or abs(r[0] / WINDOW - round(r[0] / WINDOW)) > 1e-6:
            continue
        q = rows[j[0]]
        d_in, d_io, d_oo, d_inv, d_inner = r[1] - q[1], r[2] - q[2], r[3] - q[3], r[4] - q[4], r[7] - q[7]
        p = 1 - (d_io + d_inner) / d_in
        e = d_oo / (d_io + d_oo)
        cum = (r[6] + r[3]) / (r[5] + r[6] + r[2] + r[3])
        ch = p - prev_p if prev_p is not None else float("nan")
        if prev_p is not None and abs(ch) < STEADY and abs(d_inner / d_in) < STEADY:
            if t_steady is None:
                t_steady, p_steady = r[0], p
        else:
            t_steady = None  # not steady (again): a later window starts the steady span
        print(f"  {r[0]:5.2f}  {100*p:8.2f} %  {100*ch:+7.2f} %  {100*d_io/d_in:6.2f} %  {100*d_inner/d_in:+7.2f} %"
              f" {100*d_inv/d_in:+7.2f} %  {100*e:7.2f} %   {100*cum:6.2f} %")
        prev_p = p
        ps.append((r[0], p))
    if len(ps) >= SPAN:
        last = np.array([q[1] for q in ps[-SPAN:]])
        drift = last[SPAN // 2:].mean() - last[:SPAN // 2].mean()
        print(f"  statistically: over the last {SPAN} windows (t = {ps[-SPAN][0] - WINDOW:.2f} to {ps[-1][0]:.2f}) P = "
              f"{100*last.mean():.2f} %, range {100*last.min():.2f} to {100*last.max():.2f} % (spread "
              f"{100*(last.max() - last.min()):.2f} points), drift {100*drift:+.2f} points: "
              + ("settled" if abs(drift) < DRIFT else "not settled"))
    if t_steady is not None:
        print(f"  steady from t = {t_steady:.2f}: P = {100*p_steady:.2f} %; at the last window {100*p:.2f} %")
    else:
        print(f"  not steady by t = {t[-1]:.2f}: P = {100*p:.2f} % at the last window")
    return t_steady, p_steady, p


args = sys.argv[1:]
if args[:1] == ["--slot"]:
    SW, WT = float(args[1]), float(args[2])
    XA, XB, W = XI0 + (12 - SW / 2) * DELTA, XI0 + (12 + SW / 2) * DELTA, WT * DELTA
    args = args[3:]
if args[:1] == ["--series"]:
    report(args[-1])
    steadiness(args[1:])
else:
    for p in args:
        report(p)
        steadiness([p])
