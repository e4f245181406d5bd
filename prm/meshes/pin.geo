// A steel pin of radius 10 mm in the bore of lug.geo, its centre 0.05 mm
// below the bore's: it rests on the bottom of the bore. Lengths in mm
// (scale = 1e-3). Quadrilaterals, about 0.5 mm along its lower half (the
// slave face "lower", after Gmsh's subdivision of every cell); the load
// acts on its upper half ("upper").
R = 10;  cx = 40;  cy = 29.95;
h_contact = 1;
h_core    = 4;
Point(5) = {cx, cy, 0, h_core};
Point(6) = {cx + R, cy, 0, h_contact};
Point(7) = {cx, cy - R, 0, h_contact};
Point(8) = {cx - R, cy, 0, h_contact};
Point(9) = {cx, cy + R, 0, 2 * h_contact};
Circle(5) = {8, 5, 7};
Circle(6) = {7, 5, 6};
Circle(7) = {6, 5, 9};
Circle(8) = {9, 5, 8};
Curve Loop(1) = {5, 6, 7, 8};
Plane Surface(1) = {1};
Physical Curve("lower") = {5, 6};
Physical Curve("upper") = {7, 8};
Physical Surface("steel") = {1};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
