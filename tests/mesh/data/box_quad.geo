// 2 x 1 box of two transfinite quad surfaces (regions "lower_left" and
// "right_part"), the bottom made of two curves in one physical group.
// gmsh -2 -format msh22 -o box_quad_22.msh box_quad.geo (and msh41)
Point(1) = {0, 0, 0};
Point(2) = {0.8, 0, 0};
Point(3) = {2, 0, 0};
Point(4) = {2, 1, 0};
Point(5) = {0.8, 1, 0};
Point(6) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Transfinite Curve {1, 5} = 3;
Transfinite Curve {2, 4} = 4;
Transfinite Curve {3, 6, 7} = 3;
Transfinite Surface {1};
Transfinite Surface {2};
Recombine Surface {1, 2};
Physical Curve("bottom") = {1, 2};
Physical Curve("outlet") = {3};
Physical Curve("top") = {4, 5};
Physical Curve("inlet") = {6};
Physical Surface("lower_left") = {1};
Physical Surface("right_part") = {2};
