// A quarter ring, 0.5 < r < 1, in second-order triangles: curved inner and
// outer walls (ring_p2_41.msh ASCII, ring_p2_41_bin.msh binary):
//   gmsh -2 -order 2 -format msh41 ring_p2.geo -o ring_p2_41.msh
//   gmsh -2 -order 2 -format msh41 -bin ring_p2.geo -o ring_p2_41_bin.msh
h = 0.25;
Point(1) = {0, 0, 0, h}; Point(2) = {0.5, 0, 0, h}; Point(3) = {1, 0, 0, h};
Point(4) = {0, 1, 0, h}; Point(5) = {0, 0.5, 0, h};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Curve("bottom") = {1}; Physical Curve("outer wall") = {2};
Physical Curve("left") = {3}; Physical Curve("inner wall") = {4};
Physical Surface("fluid") = {1};
