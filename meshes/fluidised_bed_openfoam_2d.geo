// The OpenFOAM tutorial multiphase/twoPhaseEulerFoam/RAS/fluidisedBed as a 2D domain:
// 0.15 m wide x 1 m tall, all quads (OpenFOAM: 30 x 200 cells, 5 mm).
// Physical groups: inlet (bottom, id 1), outlet (top, id 2), wall (sides, id 3), fluid.
// Base cells: 3 x 20 (5 cm); `set initial refinement = 2` gives 12 x 80 (1.25 cm, Q2
// velocity nodes every 6.25 mm), 3 gives 24 x 160.
DefineConstant[ width = {0.15, Name "width"}, height = {1.0, Name "height"},
                nx = {3, Name "nx"}, ny = {20, Name "ny"} ];
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
