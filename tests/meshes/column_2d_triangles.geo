// The 2D column of meshes/column_2d.geo without `Recombine`: gmsh makes triangles,
// which wetbed must refuse (exit 2 naming mesh/file, telling the user to Recombine)
// rather than hand to deal.II's p4est triangulation (a crash). tests/prm_inputs.py.
width = 0.05; height = 0.30;
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
Transfinite Curve{1, 3} = 6;
Transfinite Curve{2, 4} = 31;
Transfinite Surface{1};
Physical Curve("inlet", 1) = {1};
Physical Curve("outlet", 2) = {3};
Physical Curve("wall", 3) = {2, 4};
Physical Surface("fluid", 10) = {1};
