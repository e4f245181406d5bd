// A steel lug plate, 80 mm x 60 mm, with a bore of radius 10.05 mm centred
// at (40, 30), for the pin of pin.geo (0.05 mm radial clearance). Lengths in
// mm (scale = 1e-3). Quadrilaterals, about 0.5 mm along the bore (after
// Gmsh's subdivision of every cell); the bore's lower half is the face
// "bore_lower", its upper half "bore_upper".
R = 10.05;  cx = 40;  cy = 30;
h_bore = 1;
h_far  = 12;
Point(1) = {0, 0, 0, h_far};
Point(2) = {80, 0, 0, h_far};
Point(3) = {80, 60, 0, h_far};
Point(4) = {0, 60, 0, h_far};
Point(5) = {cx, cy, 0, h_bore};
Point(6) = {cx + R, cy, 0, h_bore};
Point(7) = {cx, cy - R, 0, h_bore};
Point(8) = {cx - R, cy, 0, h_bore};
Point(9) = {cx, cy + R, 0, 2 * h_bore};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Circle(5) = {8, 5, 7};
Circle(6) = {7, 5, 6};
Circle(7) = {6, 5, 9};
Circle(8) = {9, 5, 8};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("bore_lower") = {5, 6};
Physical Curve("bore_upper") = {7, 8};
Physical Surface("steel") = {1};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
