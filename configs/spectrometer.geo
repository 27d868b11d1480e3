// Greenspan's centrifugal spectrometer (Nigam 1999, section 4.3, Fig. 4-15),
// the part where the separation takes place: two conical channels joined by
// a slot at centre height, in the (r, z) half-plane of an axisymmetric
// scene (x = r, y = z). The thesis's dimensions are only in its figure,
// which is lost; this geometry is built from what the text states and is
// stated in configs/spectrometer.ini:
//  - both channels are cones about the rotation axis: along a generator
//    xi (from the cone's apex at the origin), across it n, the point is
//    xi (sin g, -cos g) + n (cos g, sin g), g the inclination from the
//    vertical (assumed 45 degrees); the channels slope outward as they go
//    down, so the centrifugal force pushes particles across them, outward;
//  - lengths in L* = the radius of the inner channel's inlet (its centre
//    line starts at r = 1, xi0 = 1/sin g); half-width delta = H*/L* =
//    Q/(4 pi) = 0.015518 with the design flux Q = 0.195 (the thesis's
//    velocity scale U* = Q*/(4 pi L* H*) makes Q = 4 pi delta);
//  - inner channel n in [-delta, delta], a wall delta/2 thick, the outer
//    channel n in [1.5 delta, 3.5 delta] (assumed);
//  - the channels are 24 delta long (Fig. 4-18 shows the channel flow over
//    about 20 half-widths; assumed), the slot 2 delta wide at mid-length,
//    xi in [xi0 + 11 delta, xi0 + 13 delta] (assumed).
// Structured: nn cells across a channel (a multiple of 3, so that the
// inflow profile's edge zeta = -1/3 of eq 4.148 is a mesh line), the cells
// about delta/nl along. Regenerate with
//   gmsh -2 -format msh41 configs/spectrometer.geo -o configs/spectrometer.msh
// (-setnumber nn 6 -setnumber nl 2 for the coarse mesh of the test:
//   -o tests/scenes/spectrometer_coarse.msh).
If (!Exists(nn))
  nn = 12;
EndIf
If (!Exists(nl))
  nl = 3;
EndIf
// the slot's width along the channel and the separating wall's thickness, in delta (-setnumber sw, wt: the
// geometry's sensitivity, docs/rotating.md; the scene's outer channel then needs [parameters] off = (2 + wt) delta)
If (!Exists(sw))
  sw = 2;
EndIf
If (!Exists(wt))
  wt = 0.5;
EndIf
g = Pi / 4;
delta = 0.195 / (4 * Pi);
w = wt * delta;
xi0 = 1 / Sin(g);
L = 24 * delta;
xa = xi0 + (12 - sw / 2) * delta;
xb = xi0 + (12 + sw / 2) * delta;
xe = xi0 + L;
xs[] = {xi0, xa, xb, xe};
ns[] = {-delta, delta, delta + w, 3 * delta + w};
For i In {0 : 3}
  For j In {0 : 3}
    Point(1 + 4 * i + j) = {xs[i] * Sin(g) + ns[j] * Cos(g), -xs[i] * Cos(g) + ns[j] * Sin(g), 0};
  EndFor
EndFor
// point(i, j) = 1 + 4 i + j: i along (inlet, slot start, slot end, outlet), j across
// lines along xi: 100 + 10 i + j from point(i, j) to point(i + 1, j)
For i In {0 : 2}
  For j In {0 : 3}
    Line(100 + 10 * i + j) = {1 + 4 * i + j, 1 + 4 * (i + 1) + j};
  EndFor
EndFor
// lines across: 200 + 10 i + j from point(i, j) to point(i, j + 1)
For i In {0 : 3}
  For j In {0 : 2}
    Line(200 + 10 * i + j) = {1 + 4 * i + j, 1 + 4 * i + j + 1};
  EndFor
EndFor
// blocks: inner (j = 0), slot (j = 1, i = 1 only), outer (j = 2)
For i In {0 : 2}
  For j In {0 : 2}
    If (j != 1 || i == 1)
      Curve Loop(10 * i + j + 1) = {100 + 10 * i + j, 200 + 10 * (i + 1) + j, -(100 + 10 * i + j + 1), -(200 + 10 * i + j)};
      Plane Surface(10 * i + j + 1) = {10 * i + j + 1};
    EndIf
  EndFor
EndFor
na = Round((12 - sw / 2) * nl) + 1; // cells along the parts before and after the slot
nb = Round(sw * nl) + 1;             // along the slot
For j In {0 : 3}
  Transfinite Curve{100 + j} = na; Transfinite Curve{110 + j} = nb; Transfinite Curve{120 + j} = na;
EndFor
For i In {0 : 3}
  Transfinite Curve{200 + 10 * i} = nn + 1; Transfinite Curve{200 + 10 * i + 2} = nn + 1;
  Transfinite Curve{200 + 10 * i + 1} = Round(nn * wt / 2) + 1; // the wall wt delta thick
EndFor
For i In {0 : 2}
  For j In {0 : 2}
    If (j != 1 || i == 1)
      Transfinite Surface{10 * i + j + 1};
      Recombine Surface{10 * i + j + 1};
    EndIf
  EndFor
EndFor
Physical Curve("inner_inlet") = {200};
Physical Curve("outer_inlet") = {202};
Physical Curve("inner_outlet") = {230};
Physical Curve("outer_outlet") = {232};
Physical Curve("walls") = {100, 110, 120, 101, 121, 102, 122, 103, 113, 123, 211, 221};
Physical Surface("inner_up") = {1};
Physical Surface("inner_slot") = {11};
Physical Surface("inner_down") = {21};
Physical Surface("slot") = {12};
Physical Surface("outer_up") = {3};
Physical Surface("outer_slot") = {13};
Physical Surface("outer_down") = {23};
