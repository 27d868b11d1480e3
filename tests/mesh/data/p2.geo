// A second-order triangle mesh (6-node triangles, type 9) of a polygon: the
// face nodes sit at the edge midpoints, so it reads as the straight mesh.
// gmsh -2 -order 2 -format msh22 -o p2_straight_22.msh p2.geo
Point(1) = {0, 0, 0, 1};
Point(2) = {1, 0, 0, 1};
Point(3) = {0, 1, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve("wall") = {1, 2, 3};
Physical Surface("fluid") = {1};
