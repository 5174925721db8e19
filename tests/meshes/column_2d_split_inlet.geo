// meshes/column_2d.geo (5 cm x 30 cm, 5 x 30 quads) with its inlet split into two
// physical groups at x = 2 cm: inlet_left (2 cells, id 1) and inlet_right (3 cells,
// id 4); outlet (top, id 2), wall (sides, id 3). The same cells and nodes as
// column_2d.geo: case_checks.py split_inlet compares the two.
width = 0.05; height = 0.30; nx = 5; ny = 30; split = 2;
Point(1) = {0, 0, 0};
Point(2) = {width, 0, 0};
Point(3) = {width, height, 0};
Point(4) = {0, height, 0};
Point(5) = {split * width / nx, 0, 0};
Line(1) = {1, 5};
Line(5) = {5, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 5, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1} = split + 1;
Transfinite Curve{5} = nx - split + 1;
Transfinite Curve{3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1} = {1, 2, 3, 4};
Recombine Surface{1};
Physical Curve("inlet_left", 1) = {1};
Physical Curve("inlet_right", 4) = {5};
Physical Curve("outlet", 2) = {3};
Physical Curve("wall", 3) = {2, 4};
Physical Surface("fluid", 10) = {1};
