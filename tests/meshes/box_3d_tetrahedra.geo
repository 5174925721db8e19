// A 3D box meshed into tetrahedra (no `Recombine`): wetbed must refuse it with exit 2
// naming mesh/file (tests/prm_inputs.py), not crash inside deal.II.
SetFactory("OpenCASCADE");
Mesh.CharacteristicLengthMax = 0.02;
Box(1) = {0, 0, 0, 0.05, 0.3, 0.05};
Physical Surface("inlet", 1) = {3};
Physical Surface("outlet", 2) = {4};
Physical Surface("wall", 3) = {1, 2, 5, 6};
Physical Volume("fluid", 10) = {1};
