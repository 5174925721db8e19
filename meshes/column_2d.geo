// 2D slice of the seed-000 small column: 5 cm wide x 30 cm tall, all quads.
// Physical groups: inlet (bottom, id 1), outlet (top, id 2), wall (sides, id 3), fluid.
// Base cells: 5 x 30 (1 cm); refine further with `set initial refinement` in the .prm.
DefineConstant[ width = {0.05, Name "width"}, height = {0.30, Name "height"},
                nx = {5, Name "nx"}, ny = {30, Name "ny"} ];
Point(1) = {0, 0, 0};
Point(2) = {width, 0, 0};
Point(3) = {width, height, 0};
Point(4) = {0, height, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("inlet", 1) = {1};
Physical Curve("outlet", 2) = {3};
Physical Curve("wall", 3) = {2, 4};
Physical Surface("fluid", 10) = {1};
