// A planar Couette (shear) cell: the gap 0 <= x <= width between a moving wall (x = 0)
// and a fixed wall (x = width), periodic in y over `height` (one period of an infinitely
// long cell). All quads, nx across the gap, ny along it.
// Physical groups: bottom (id 1) and top (id 2), identified by periodicity; wall (the
// fixed wall, id 3); moving wall (id 4); fluid.
DefineConstant[ width = {0.005, Name "width"}, height = {0.000625, Name "height"},
                nx = {16, Name "nx"}, ny = {2, Name "ny"} ];
Point(1) = {0, 0, 0};
Point(2) = {width, 0, 0};
Point(3) = {width, height, 0};
Point(4) = {0, height, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {4, 3};
Line(4) = {1, 4};
Curve Loop(1) = {1, 2, -3, -4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = nx + 1;
Transfinite Curve{2, 4} = ny + 1;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("bottom", 1) = {1};
Physical Curve("top", 2) = {3};
Physical Curve("wall", 3) = {2};
Physical Curve("moving wall", 4) = {4};
Physical Surface("fluid", 10) = {1};
