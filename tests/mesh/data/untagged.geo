// The left side is in no physical group; saved with -save_all its line
// elements carry no physical tag: refused.
// gmsh -2 -save_all -format msh41 -o bad_untagged_41.msh untagged.geo
Point(1) = {0, 0, 0, 1};
Point(2) = {1, 0, 0, 1};
Point(3) = {1, 1, 0, 1};
Point(4) = {0, 1, 0, 1};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("wall") = {1, 2, 3};
Physical Surface("fluid") = {1};
