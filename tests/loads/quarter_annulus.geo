// A quarter of a thick-walled cylinder in plane strain: a <= r <= b, x >= 0, y >= 0 (the
// normal-pressure tests, tests/loads/loads.py). Physical curves: inner (r = a), outer (r = b),
// xsym (y = 0), ysym (x = 0); physical surface: ring. Triangles (or quadrilaterals with
// -setnumber quads 1) on straight-sided cells: the arcs are polygons. Counts scale with -clscale.
a = 1.0; b = 2.0;
If (!Exists(n)) n = 4; EndIf   // cells across the wall at factor 1
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {b, 0, 0}; Point(4) = {0, b, 0}; Point(5) = {0, a, 0};
Line(1) = {2, 3}; Circle(2) = {3, 1, 4}; Line(3) = {4, 5}; Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = N + 1;
Transfinite Curve{2, 4} = 2 * N + 1;
Transfinite Surface{1};
If (!Exists(quads)) quads = 0; EndIf
If (quads) Recombine Surface{1}; EndIf
Physical Curve("xsym") = {1};
Physical Curve("outer") = {2};
Physical Curve("ysym") = {3};
Physical Curve("inner") = {4};
Physical Surface("ring") = {1};
