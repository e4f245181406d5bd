// A concrete foundation, 200 mm wide and 100 mm high (0 <= x <= 200,
// 0 <= y <= 100 mm), under the punch of punch.geo. A 10 mm layer of grout
// (60 <= x <= 140, 90 <= y <= 100) lies right under the punch: zone
// "grout"; the rest is zone "concrete". Lengths in mm (scale = 1e-3).
// Quadrilaterals, graded from about 0.75 mm along the punch to 10 mm at
// the base (after Gmsh's subdivision of every cell).
W = 200;  H = 100;  xg0 = 60;  xg1 = 140;  t = 10;
h_contact = 1.5;
h_far     = 20;
Point(1) = {0, 0, 0, h_far};
Point(2) = {W, 0, 0, h_far};
Point(3) = {W, H, 0, h_far / 2};
Point(4) = {xg1, H, 0, h_contact};
Point(5) = {xg0, H, 0, h_contact};
Point(6) = {0, H, 0, h_far / 2};
Point(7) = {xg0, H - t, 0, h_contact * 2};
Point(8) = {xg1, H - t, 0, h_contact * 2};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {5, 7};
Line(8) = {7, 8};
Line(9) = {8, 4};
Curve Loop(1) = {1, 2, 3, -9, -8, -7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {4, 7, 8, 9};
Plane Surface(2) = {2};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3, 4, 5};
Physical Curve("left") = {6};
Physical Surface("concrete") = {1};
Physical Surface("grout") = {2};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
