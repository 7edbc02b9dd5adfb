// A thick-walled cylinder in plane strain, quarter model: the quarter annulus a <= r <= b in the
// (x, y) plane, x >= 0, y >= 0 (symmetry planes x = 0 and y = 0). The curved boundaries (r = a,
// r = b) make it the check of curved cells (-mesh_geometry_order 2, docs/elements.md).
// Physical curves: inner (r = a), outer (r = b), sym_x (x = 0), sym_y (y = 0); physical
// surface: ring. Quadrilaterals unless -setnumber triangles 1; counts scale with -clscale.
a = 1.0; b = 2.0;
If (!Exists(n)) n = 4; EndIf   // divisions through the wall; 2 n around the quarter
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
If (!Exists(triangles)) triangles = 0; EndIf
If (!triangles) Recombine Surface{1}; EndIf
Physical Curve("sym_y") = {1};
Physical Curve("outer") = {2};
Physical Curve("sym_x") = {3};
Physical Curve("inner") = {4};
Physical Surface("ring") = {1};
