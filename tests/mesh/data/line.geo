// 1-D column [0, 3] of two curves meeting at x = 1.
// gmsh -1 -format msh22 -o line_22.msh line.geo (and msh41)
Point(1) = {0, 0, 0, 0.5};
Point(2) = {1, 0, 0, 0.25};
Point(3) = {3, 0, 0, 0.5};
Line(1) = {1, 2};
Line(2) = {2, 3};
Physical Point("left") = {1};
Physical Point("right") = {3};
Physical Curve("column") = {1, 2};
