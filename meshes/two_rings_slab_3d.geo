// A slab of meshes/two_rings_plane.geo, 3D: two rings a <= r <= c (inner_ring) and c <= r <= b
// (outer_ring), x >= 0, y >= 0, extruded along z by T (one layer of hexahedra), joined by an
// interface on the cylinder r = c (curved faces with -mesh_geometry_order 2). Physical
// surfaces: inner (r = a), outer (r = b), joint (r = c), sym_x (x = 0), sym_y (y = 0),
// bottom (z = 0), top (z = T); volumes inner_ring, outer_ring. n divisions through each ring
// (default 1), 4 n around the quarter; counts scale with -clscale. Used by
// tests/verification/curved_output.py (the penalty warning's cell height on curved hexahedra).
a = 1.0; c = 1.5; b = 2.0; T = 0.25;
If (!Exists(n)) n = 1; EndIf
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
Recombine Surface{1, 2};
s1[] = Extrude {0, 0, T} { Surface{1}; Layers{1}; Recombine; };
s2[] = Extrude {0, 0, T} { Surface{2}; Layers{1}; Recombine; };
// Extrude returns {top, volume, sides along the loop's curves}: ring 1 along 1 (y = 0),
// 6 (r = c), 4 (x = 0), 5 (r = a); ring 2 along 2 (y = 0), 7 (r = b), 3 (x = 0), 6 (r = c).
Physical Surface("bottom") = {1, 2};
Physical Surface("top") = {s1[0], s2[0]};
Physical Surface("joint") = {s1[3]};
Physical Surface("inner") = {s1[5]};
Physical Surface("outer") = {s2[3]};
Physical Surface("sym_y") = {s1[2], s2[2]};
Physical Surface("sym_x") = {s1[4], s2[4]};
Physical Volume("inner_ring") = {s1[1]};
Physical Volume("outer_ring") = {s2[1]};
