#!/usr/bin/env python3
"""Writes rotating_waves_disc.msh: the unit disc in quadrilaterals (Gmsh MSH 2.2
ASCII), an O-grid: a square core of half-width 0.45 with N x N cells and four
blocks of N x M cells between its sides and the circle, graded so that the
wall's cells are RATIO times thinner than the innermost ring's. Vertex 1 is on
the wall (the stream function is zero there). Physical groups: the curve
"wall" and the surface "disc". Usage: python3 rotating_waves_disc.py [N M RATIO]."""
import math, sys

N = int(sys.argv[1]) if len(sys.argv) > 1 else 32
M = int(sys.argv[2]) if len(sys.argv) > 2 else 16
RATIO = float(sys.argv[3]) if len(sys.argv) > 3 else 6.0
S = 0.45

nodes = {}
coords = []
def node(key, x, y):
    if key not in nodes:
        nodes[key] = len(coords) + 1
        coords.append((x, y))
    return nodes[key]

# radial stations 0 (square side) .. M (circle), geometric with the last cell RATIO times thinner than the first
g = RATIO ** (-1.0 / (M - 1)) if M > 1 else 1.0
w = [g ** k for k in range(M)]
eta = [0.0]
for k in range(M):
    eta.append(eta[-1] + w[k])
eta = [e / eta[-1] for e in eta]

def side_point(side, t):
    """square side point and circle point for t in [-1, 1], counter-clockwise sides 0..3 (right, top, left, bottom)"""
    ang = side * math.pi / 2
    c, s = math.cos(ang), math.sin(ang)
    px, py = S, S * t                   # right side before rotation
    th = t * math.pi / 4
    cx, cy = math.cos(th), math.sin(th)
    return (c * px - s * py, s * px + c * py), (c * cx - s * cy, s * cx + c * cy)

# wall vertices first: the key is the angle index around the circle (0 .. 4N-1)
def wall_key(side, i):
    return ("w", (side * N + i) % (4 * N))
for side in range(4):
    for i in range(N):
        t = -1.0 + 2.0 * i / N
        _, cp = side_point(side, t)
        node(wall_key(side, i), cp[0], cp[1])

def sq_key(i, j):  # core square vertex (i, j), 0..N
    return ("s", i, j)
def square_xy(i, j):
    return (-S + 2 * S * i / N, -S + 2 * S * j / N)

def ring_key(side, i, k):
    """vertex i (0..N) along the side, k (0..M) out from the square"""
    if k == M:
        return wall_key(side, i) if i < N else wall_key(side + 1, 0)
    if k == 0:  # on the square's boundary
        return [sq_key(N, i), sq_key(N - i, N), sq_key(0, N - i), sq_key(i, 0)][side]
    # shared block edges: the corner diagonals
    if i == N:
        return ring_key(side + 1, 0, k) if side < 3 else ("r", 0, 0, k)
    if i == 0 and side == 0:
        return ("r", 0, 0, k)
    return ("r", side, i, k)

quads = []
for j in range(N + 1):
    for i in range(N + 1):
        node(sq_key(i, j), *square_xy(i, j))
for j in range(N):
    for i in range(N):
        quads.append([nodes[sq_key(i, j)], nodes[sq_key(i + 1, j)], nodes[sq_key(i + 1, j + 1)], nodes[sq_key(i, j + 1)]])
for side in range(4):
    for i in range(N + 1):
        t = -1.0 + 2.0 * i / N
        sp, cp = side_point(side, t)
        for k in range(M + 1):
            e = eta[k]
            node(ring_key(side, i, k), (1 - e) * sp[0] + e * cp[0], (1 - e) * sp[1] + e * cp[1])
    for i in range(N):
        for k in range(M):
            a, b = nodes[ring_key(side, i, k)], nodes[ring_key(side, i, k + 1)]
            c, d = nodes[ring_key(side, i + 1, k + 1)], nodes[ring_key(side, i + 1, k)]
            quads.append([a, b, c, d])  # counter-clockwise: outwards, then along the side
walls = []
for m in range(4 * N):
    walls.append([nodes[("w", m)], nodes[("w", (m + 1) % (4 * N))]])

# orientation check (counter-clockwise)
for q in quads:
    x = [coords[n - 1] for n in q]
    area = sum(x[i][0] * x[(i + 1) % 4][1] - x[(i + 1) % 4][0] * x[i][1] for i in range(4))
    assert area > 0, q

with open("rotating_waves_disc.msh", "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n")
    f.write('$PhysicalNames\n2\n1 1 "wall"\n2 2 "disc"\n$EndPhysicalNames\n')
    f.write("$Nodes\n%d\n" % len(coords))
    for n, (x, y) in enumerate(coords):
        f.write("%d %.17g %.17g 0\n" % (n + 1, x, y))
    f.write("$EndNodes\n$Elements\n%d\n" % (len(walls) + len(quads)))
    e = 0
    for w2 in walls:
        e += 1
        f.write("%d 1 2 1 1 %d %d\n" % (e, w2[0], w2[1]))
    for q in quads:
        e += 1
        f.write("%d 3 2 2 2 %d %d %d %d\n" % (e, *q))
    f.write("$EndElements\n")
print("%d nodes, %d quadrilaterals, %d wall edges" % (len(coords), len(quads), len(walls)))
