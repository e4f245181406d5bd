// An aluminium plate, 120 mm wide and 30 mm high, under the shoe of
// shoe.geo. A 3 mm polymer liner (30 <= x <= 90, 27 <= y <= 30) lies
// under the shoe: zone "liner"; the rest is zone "alu". Lengths in mm
// (scale = 1e-3). Quadrilaterals, about 0.5 mm along the top face under
// the shoe, 4 mm at the base (after Gmsh's subdivision of every cell).
W = 120; H = 30; a = 30; b = 90; t = 3;
hc = 1.0; hf = 8;
Point(1) = {0, 0, 0, hf};
Point(2) = {W, 0, 0, hf};
Point(3) = {W, H, 0, hf/2};
Point(4) = {b, H, 0, hc};
Point(5) = {a, H, 0, hc};
Point(6) = {0, H, 0, hf/2};
Point(7) = {a, H - t, 0, hc};
Point(8) = {b, H - t, 0, hc};
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
Physical Curve("base") = {1};
Physical Curve("face") = {3, 4, 5};
Physical Surface("alu") = {1};
Physical Surface("liner") = {2};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
