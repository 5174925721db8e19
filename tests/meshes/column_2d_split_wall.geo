// meshes/column_2d.geo (5 cm x 30 cm, 5 x 30 quads) with its side walls as two
// physical groups: wall_left (x = 0, id 3) and wall_right (x = 5 cm, id 4); inlet
// (bottom, id 1), outlet (top, id 2). The same cells and nodes as column_2d.geo:
// case_checks.py wall_groups compares the two.
width = 0.05; height = 0.30; nx = 5; ny = 30;
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
Physical Curve("wall_left", 3) = {4};
Physical Curve("wall_right", 4) = {2};
Physical Surface("fluid", 10) = {1};
