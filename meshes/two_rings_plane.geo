// Two thick-walled rings in plane strain, quarter model, joined by an interface: a <= r <= c
// (inner_ring) and c <= r <= b (outer_ring), x >= 0, y >= 0. With stiff contact they are
// Lame's one cylinder a <= r <= b; the interface is a quarter circle (curved faces,
// -mesh_geometry_order 2, docs/elements.md). Physical curves: inner (r = a), outer (r = b),
// joint (r = c), sym_x (x = 0), sym_y (y = 0). Quadrilaterals unless -setnumber triangles 1
// (meshes/two_rings_plane_tri.geo); counts scale with -clscale.
a = 1.0; c = 1.5; b = 2.0;
If (!Exists(n)) n = 2; EndIf   // divisions through each ring; 4 n around the quarter
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Point(1) = {0, 0, 0};
Point(2) = {a, 0, 0}; Point(3) = {c, 0, 0}; Point(4) = {b, 0, 0};
Point(5) = {0, a, 0}; Point(6) = {0, c, 0}; Point(7) = {0, b, 0};
Line(1) = {2, 3}; Line(2) = {3, 4}; Line(3) = {7, 6}; Line(4) = {6, 5};
Circle(5) = {2, 1, 5}; Circle(6) = {3, 1, 6}; Circle(7) = {4, 1, 7};
Curve Loop(1) = {1, 6, 4, -5}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 7, 3, -6}; Plane Surface(2) = {2};
Transfinite Curve{1, 2, 3, 4} = N + 1;
Transfinite Curve{5, 6, 7} = 4 * N + 1;
Transfinite Surface{1, 2};
If (!Exists(triangles)) triangles = 0; EndIf
If (!triangles) Recombine Surface{1, 2}; EndIf
Physical Curve("sym_y") = {1, 2};
Physical Curve("sym_x") = {3, 4};
Physical Curve("inner") = {5};
Physical Curve("joint") = {6};
Physical Curve("outer") = {7};
Physical Surface("inner_ring") = {1};
Physical Surface("outer_ring") = {2};
