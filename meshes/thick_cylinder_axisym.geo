// A thick-walled cylinder in the axisymmetric (r, z) = (x, y) plane: a <= r <= b, 0 <= z <= H.
// Physical curves: inner (r = a), outer (r = b), bottom, top; physical surface: ring.
// Quadrilaterals unless -setnumber triangles 1; counts scale with -clscale.
a = 1.0; b = 2.0; H = 0.5;
If (!Exists(n)) n = 4; EndIf
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Point(1) = {a, 0, 0}; Point(2) = {b, 0, 0}; Point(3) = {b, H, 0}; Point(4) = {a, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 2 * N + 1;
Transfinite Curve{2, 4} = N + 1;
Transfinite Surface{1};
If (!Exists(triangles)) triangles = 0; EndIf
If (!triangles) Recombine Surface{1}; EndIf
Physical Curve("bottom") = {1};
Physical Curve("outer") = {2};
Physical Curve("top") = {3};
Physical Curve("inner") = {4};
Physical Surface("ring") = {1};
