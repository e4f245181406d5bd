// A steel shoe, 30 mm wide and 12 mm high, its bottom corners rounded by
// 1 mm fillets, resting on the polymer liner of plate.geo (top face at
// y = 30 mm) between x = 45 and 75 mm. Lengths in mm (scale = 1e-3).
// Quadrilaterals, about 0.4 mm (after Gmsh's subdivision of every cell)
// along the sole, which forms the slave face "sole": 161 slave nodes.
x0 = 45; w = 30; y0 = 30; h = 12; r = 1;
hc = 0.8; ht = 3;
Point(1) = {x0 + r, y0, 0, hc};
Point(2) = {x0 + w - r, y0, 0, hc};
Point(3) = {x0 + w - r, y0 + r, 0, hc};
Point(4) = {x0 + w, y0 + r, 0, hc};
Point(5) = {x0 + w, y0 + h, 0, ht};
Point(6) = {x0, y0 + h, 0, ht};
Point(7) = {x0, y0 + r, 0, hc};
Point(8) = {x0 + r, y0 + r, 0, hc};
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
Line(4) = {5, 6};
Line(5) = {6, 7};
Circle(6) = {7, 8, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Physical Curve("sole") = {6, 1, 2};
Physical Curve("east") = {3};
Physical Curve("crown") = {4};
Physical Curve("west") = {5};
Physical Surface("steel") = {1};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
