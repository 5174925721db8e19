// Seed 004's quasi-2D spouted bed as a 2D slice: 0.15 m wide x 1.0 m tall, a central
// gas jet slot in the bottom whose width times the bed depth (0.02 m) equals the area
// of the nine 2 mm holes (9 pi (1 mm)^2 = 2.83e-5 m^2: slot = 1.414 mm). All quads:
// three columns of cells (left, slot, right) with matching layers; across the sides the
// cells grow geometrically from the slot's width to the walls.
// Physical groups: jet (the slot, id 1), outlet (top, id 2), wall (sides and the bottom
// beside the slot, id 3), fluid.
DefineConstant[ width = {0.15, Name "width"}, height = {1.0, Name "height"},
                slot = {1.4142e-3, Name "slot"}, n_slot = {1, Name "n_slot"},
                n_side = {16, Name "n_side"}, growth = {1.18, Name "growth"},
                ny = {200, Name "ny"} ];
x0 = width / 2 - slot / 2;
x1 = width / 2 + slot / 2;
Point(1) = {0, 0, 0};
Point(2) = {x0, 0, 0};
Point(3) = {x1, 0, 0};
Point(4) = {width, 0, 0};
Point(5) = {width, height, 0};
Point(6) = {x1, height, 0};
Point(7) = {x0, height, 0};
Point(8) = {0, height, 0};
Line(1) = {1, 2};  // bottom, left of the slot
Line(2) = {2, 3};  // the slot
Line(3) = {3, 4};  // bottom, right of the slot
Line(4) = {4, 5};  // right wall
Line(5) = {5, 6};  // top, right
Line(6) = {6, 7};  // top, above the slot
Line(7) = {7, 8};  // top, left
Line(8) = {8, 1};  // left wall
Line(9) = {2, 7};  // left edge of the slot column
Line(10) = {3, 6}; // right edge of the slot column
Curve Loop(1) = {1, 9, 7, 8};
Curve Loop(2) = {2, 10, 6, -9};
Curve Loop(3) = {3, 4, 5, -10};
Plane Surface(1) = {1};
Plane Surface(2) = {2};
Plane Surface(3) = {3};
// the side cells shrink toward the slot
Transfinite Curve{1} = n_side + 1 Using Progression 1 / growth;
Transfinite Curve{7} = n_side + 1 Using Progression growth;
Transfinite Curve{3} = n_side + 1 Using Progression growth;
Transfinite Curve{5} = n_side + 1 Using Progression 1 / growth;
Transfinite Curve{2, 6} = n_slot + 1;
Transfinite Curve{4, 8, 9, 10} = ny + 1;
Transfinite Surface{1} = {1, 2, 7, 8};
Transfinite Surface{2} = {2, 3, 6, 7};
Transfinite Surface{3} = {3, 4, 5, 6};
Recombine Surface{1, 2, 3};
Physical Curve("jet", 1) = {2};
Physical Curve("outlet", 2) = {5, 6, 7};
Physical Curve("wall", 3) = {1, 3, 4, 8};
Physical Surface("fluid", 10) = {1, 2, 3};
