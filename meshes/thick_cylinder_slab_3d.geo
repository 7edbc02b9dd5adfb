// A slab of the thick-walled cylinder, 3D: the quarter annulus a <= r <= b (x >= 0, y >= 0)
// of meshes/thick_cylinder_plane.geo extruded along z by T, for curved 3D cells
// (-mesh_geometry_order 2): the cells' edges and faces on the cylinders r = a and r = b are
// curved. Hexahedra unless -setnumber tets 1 (meshes/thick_cylinder_slab_3d_tet.geo: each
// extruded prism cut into tetrahedra). Physical surfaces: inner (r = a), outer (r = b),
// sym_x (x = 0), sym_y (y = 0), bottom (z = 0), top (z = T); physical volume: ring.
// n divisions through the wall, 2 n around the quarter, one layer along z; counts scale
// with -clscale.
a = 1.0; b = 2.0; T = 0.25;
If (!Exists(n)) n = 4; EndIf
If (!Exists(tets)) tets = 0; EndIf
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
If (!tets)
  Recombine Surface{1};
  slab[] = Extrude {0, 0, T} { Surface{1}; Layers{1}; Recombine; };
Else
  slab[] = Extrude {0, 0, T} { Surface{1}; Layers{1}; };
EndIf
// Extrude returns {top, volume, sides along curves 1 (y = 0), 2 (r = b), 3 (x = 0), 4 (r = a)}.
Physical Surface("bottom") = {1};
Physical Surface("top") = {slab[0]};
Physical Surface("sym_y") = {slab[2]};
Physical Surface("outer") = {slab[3]};
Physical Surface("sym_x") = {slab[4]};
Physical Surface("inner") = {slab[5]};
Physical Volume("ring") = {slab[1]};
