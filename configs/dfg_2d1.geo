// The DFG benchmark 2D-1 (Schafer & Turek 1996): a channel of 2.2 x 0.41 m
// with a cylinder of diameter 0.1 m centred at (0.2, 0.2). The cylinder is
// two half circles through (0.15, 0.2) and (0.25, 0.2), so that the points
// of the pressure difference are mesh vertices.
//   gmsh -2 -order 2 -format msh41 dfg_2d1.geo -o dfg_2d1.msh
// (-order 2: 6-node triangles, so the cylinder is curved; sluice reads the
// face nodes as the cells' second-order geometry.)
h = 0.03;   // element size in the channel
hc = 0.005; // on the cylinder (64 faces)
Point(1) = {0, 0, 0, h}; Point(2) = {2.2, 0, 0, h}; Point(3) = {2.2, 0.41, 0, h}; Point(4) = {0, 0.41, 0, h};
Point(5) = {0.2, 0.2, 0, hc}; Point(6) = {0.15, 0.2, 0, hc}; Point(7) = {0.25, 0.2, 0, hc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 6};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6};
Plane Surface(1) = {1, 2};
Physical Curve("inlet") = {4};
Physical Curve("outlet") = {2};
Physical Curve("channel walls") = {1, 3};
Physical Curve("cylinder") = {5, 6};
Physical Surface("fluid") = {1};
