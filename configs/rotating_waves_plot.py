#!/usr/bin/env python3
"""Reads the output of configs/rotating_waves.ini (with [output]
stream_function_stats = true) and writes an SVG plot of max|psi| / max|psi|_0
against t beside the geostrophic decay reference exp(-t (E/sqrt|eps|)^(1/2))
= exp(-0.0316 t) of Nigam (1999, eqs 4.194-4.196), and prints the table.
Usage: python3 rotating_waves_plot.py OUT.h5 PLOT.svg   (needs h5py)"""
import math, sys
import h5py

out, svg = sys.argv[1], sys.argv[2]
rows = []
with h5py.File(out, "r") as f:
    for k in sorted(k for k in f if k.startswith("step_")):
        a = f[k].attrs
        if "stream_function_min" in a and a.get("complete", 1):
            rows.append((float(a["time"]), -float(a["stream_function_min"]), float(a["stream_function_phase"])))
rows.sort()
t0, a0, p0 = rows[0]
W, H, L, B = 640, 400, 60, 40
tmax = max(150.0, rows[-1][0])
def X(t): return L + (W - L - 20) * t / tmax
def Y(v): return H - B - (H - B - 20) * v / 1.1
pts = " ".join("%.1f,%.1f" % (X(t), Y(a / a0)) for t, a, _ in rows)
ref = " ".join("%.1f,%.1f" % (X(t), Y(math.exp(-0.0316 * t))) for t in [tmax * i / 100 for i in range(101)])
ticks = "".join('<text x="%.1f" y="%d" font-size="12" text-anchor="middle">%g</text>' % (X(t), H - B + 16, t)
                for t in range(0, int(tmax) + 1, 25))
ticks += "".join('<text x="%d" y="%.1f" font-size="12" text-anchor="end">%.1f</text>' % (L - 6, Y(v) + 4, v)
                 for v in [0, 0.2, 0.4, 0.6, 0.8, 1.0])
with open(svg, "w") as g:
    g.write('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif">\n' % (W, H))
    g.write('<rect width="100%" height="100%" fill="white"/>\n')
    g.write('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>' % (L, H - B, W - 20, H - B))
    g.write('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="black"/>\n' % (L, H - B, L, 20))
    g.write(ticks + "\n")
    g.write('<polyline fill="none" stroke="#1f77b4" stroke-width="2" points="%s"/>\n' % pts)
    g.write('<polyline fill="none" stroke="#d62728" stroke-dasharray="6,4" points="%s"/>\n' % ref)
    g.write('<text x="%d" y="%d" font-size="13" text-anchor="middle">t (units of 1/(|eps|^1/2 Omega))</text>\n'
            % ((W + L) // 2, H - 6))
    g.write('<text x="%d" y="40" font-size="13">max|psi| / max|psi|_0: sluice (blue), exp(-0.0316 t) (red, dashed)</text>\n' % (L + 10))
    g.write("</svg>\n")
print("t, max|psi|/max|psi|_0, exp(-0.0316 t), pattern turned (rad), c t")
for t, a, p in rows:
    if abs(t - round(t / 10) * 10) < 1e-6:
        print("%6.1f  %.4f  %.4f  %+.4f  %.4f" % (t, a / a0, math.exp(-0.0316 * t), math.remainder(p - p0, 2 * math.pi),
                                                0.0324 * t))
