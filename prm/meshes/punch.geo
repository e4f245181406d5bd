// A steel punch, 40 mm wide and 20 mm high, its bottom corners rounded by
// 2 mm fillets, resting on the foundation of foundation.geo (top face at
// y = 100 mm) between x = 80 and 120 mm. Lengths in mm (scale = 1e-3).
// Quadrilaterals, about 0.5 mm (after Gmsh's subdivision of every cell)
// along the bottom face and the fillets, which form the slave face
// "bottom": 88 Q2 edges, 177 slave nodes.
x0 = 80;  w = 40;  y0 = 100;  h = 20;  r = 2;
h_contact = 1;
h_top     = 4;
Point(1) = {x0 + r, y0, 0, h_contact};
Point(2) = {x0 + w - r, y0, 0, h_contact};
Point(3) = {x0 + w - r, y0 + r, 0, h_contact};   // centre of the right fillet
Point(4) = {x0 + w, y0 + r, 0, h_contact};
Point(5) = {x0 + w, y0 + h, 0, h_top};
Point(6) = {x0, y0 + h, 0, h_top};
Point(7) = {x0, y0 + r, 0, h_contact};
Point(8) = {x0 + r, y0 + r, 0, h_contact};       // centre of the left fillet
Line(1) = {1, 2};
Circle(2) = {2, 3, 4};
Line(3) = {4, 5};
Line(4) = {5, 6};
Line(5) = {6, 7};
Circle(6) = {7, 8, 1};
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};
Physical Curve("bottom") = {6, 1, 2};
Physical Curve("right") = {3};
Physical Curve("top") = {4};
Physical Curve("left") = {5};
Physical Surface("steel") = {1};
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
