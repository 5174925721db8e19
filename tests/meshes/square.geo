// Unit square for the MMS tests: inlet (bottom), outlet (top), wall (sides); 4 x 4 quads.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 5;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("inlet", 1) = {1};
Physical Curve("outlet", 2) = {3};
Physical Curve("wall", 3) = {2, 4};
Physical Surface("fluid", 10) = {1};
