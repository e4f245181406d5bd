// A block, 100 mm along the slope of slope.geo and 50 mm high, resting on
// it: its bottom face lies on the slope's surface (angle theta = 20
// degrees) from 150 mm to 250 mm along x. Lengths in mm (scale = 1e-3).
// Structured quadrilaterals (transfinite), finer than the slope's along
// the contact (the slave face).
theta = 20 * Pi / 180;
h  = 50;           // the slope's height at x = 0
x0 = 150;          // where the block's bottom face starts, along x
w  = 100;          // along the slope
b  = 50;           // height, normal to the slope
c = Cos(theta);
s = Sin(theta);
Point(1) = {x0, h + x0 * Tan(theta), 0};
Point(2) = {x0 + w * c, h + x0 * Tan(theta) + w * s, 0};
Point(3) = {x0 + w * c - b * s, h + x0 * Tan(theta) + w * s + b * c, 0};
Point(4) = {x0 - b * s, h + x0 * Tan(theta) + b * c, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 17;
Transfinite Curve{2, 4} = 9;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("bottom") = {1};
Physical Curve("downhill") = {4};
Physical Curve("top") = {3};
Physical Curve("uphill") = {2};
Physical Surface("block") = {1};
