// Half of a steel roller (a cylinder in plane strain) of radius 50 mm: the
// lower half disk, touching the block below at the origin. Lengths in mm
// (the scene sets scale = 1e-3). Quadrilaterals, graded towards the contact.
R = 50;
h_contact = 0.3;   // element size at the contact [mm], halved by the subdivision
h_far     = 10;    // element size far from it
Point(1) = {0, R, 0};            // centre
Point(2) = {-R, R, 0};
Point(3) = {0, 0, 0};            // lowest point: the first contact
Point(4) = {R, R, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3)   = {4, 2};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Curve("arc") = {1, 2};
Physical Curve("top") = {3};
Physical Surface("steel") = {1};

Field[1] = Distance;
Field[1].PointsList = {3};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = h_contact;
Field[2].SizeMax = h_far;
Field[2].DistMin = 4;
Field[2].DistMax = 40;
Background Field = 2;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.Algorithm = 6;               // frontal-Delaunay (8 crashes gmsh 4.8.4)
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;  // blossom: quadrilaterals only
Mesh.SubdivisionAlgorithm = 1;  // every cell split into quadrilaterals
