// Cylinder (radius 0.5, height 1) for the 3D MMS test, all hexahedra (O-grid).
DefineConstant[ radius = {0.5, Name "radius"}, height = {1.0, Name "height"},
                n_core = {2, Name "n_core"}, n_ring = {1, Name "n_ring"},
                n_layers = {2, Name "n_layers"} ];
c = 0.45 * radius; // half-width of the core square
s = radius / Sqrt(2);
Point(1) = {0, 0, 0};
Point(2) = { c,  c, 0}; Point(3) = {-c,  c, 0}; Point(4) = {-c, -c, 0}; Point(5) = { c, -c, 0};
Point(6) = { s,  s, 0}; Point(7) = {-s,  s, 0}; Point(8) = {-s, -s, 0}; Point(9) = { s, -s, 0};
// core square
Line(1) = {2, 3}; Line(2) = {3, 4}; Line(3) = {4, 5}; Line(4) = {5, 2};
// outer arcs
Circle(5) = {6, 1, 7}; Circle(6) = {7, 1, 8}; Circle(7) = {8, 1, 9}; Circle(8) = {9, 1, 6};
// spokes
Line(9) = {2, 6}; Line(10) = {3, 7}; Line(11) = {4, 8}; Line(12) = {5, 9};
Curve Loop(1) = {1, 2, 3, 4};        Plane Surface(1) = {1};
Curve Loop(2) = {9, 5, -10, -1};     Plane Surface(2) = {2};
Curve Loop(3) = {10, 6, -11, -2};    Plane Surface(3) = {3};
Curve Loop(4) = {11, 7, -12, -3};    Plane Surface(4) = {4};
Curve Loop(5) = {12, 8, -9, -4};     Plane Surface(5) = {5};
Transfinite Curve{1, 2, 3, 4, 5, 6, 7, 8} = n_core + 1;
Transfinite Curve{9, 10, 11, 12} = n_ring + 1;
Transfinite Surface{1, 2, 3, 4, 5};
Recombine Surface{1, 2, 3, 4, 5};
out[] = Extrude {0, 0, height} { Surface{1, 2, 3, 4, 5}; Layers{n_layers}; Recombine; };
// out[] per surface: [0] top, [1] volume, [2..5] lateral faces in the order of the loop's curves
Physical Surface("inlet", 1) = {1, 2, 3, 4, 5};
Physical Surface("outlet", 2) = {out[0], out[6], out[12], out[18], out[24]};
// the curved faces: for ring patch k the second curve of its loop is the arc
Physical Surface("wall", 3) = {out[9], out[15], out[21], out[27]};
Physical Volume("fluid", 10) = {out[1], out[7], out[13], out[19], out[25]};
