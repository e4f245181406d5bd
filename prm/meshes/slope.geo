// A slope: a trapezoid whose top face rises at the angle theta (20 degrees)
// over its length, for the block of slope-block.geo. Lengths in mm (scale =
// 1e-3). Structured quadrilaterals (transfinite).
theta = 20 * Pi / 180;
L = 400;   // length
h = 50;    // height at the left end
Point(1) = {0, 0, 0};
Point(2) = {L, 0, 0};
Point(3) = {L, h + L * Tan(theta), 0};
Point(4) = {0, h, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 41;
Transfinite Curve{2, 4} = 6;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("surface") = {3};
Physical Curve("left") = {4};
Physical Surface("ground") = {1};
