// Terzaghi consolidation column, 3D, structured hexahedra.
// z vertical: 0 <= x, y <= W, 0 <= z <= H (top at z = H).
// Physical surfaces: top, bottom, sides (the four lateral faces); physical volume: soil.
//
// Refinement: elements along each edge = ceil(base / Mesh.CharacteristicLengthFactor), so
// poroseam's -mesh_size_factor (gmsh -clscale) refines it although the mesh is transfinite.
// Base counts can be overridden with gmsh -setnumber nz 40 (etc.).
W = 0.1;  H = 1.0;
If (!Exists(nz)) nz = 20; EndIf   // elements along the height at factor 1
If (!Exists(nx)) nx = 2;  EndIf   // elements along each horizontal edge at factor 1
f = Mesh.CharacteristicLengthFactor;
NX = Ceil(nx / f - 1e-9); NZ = Ceil(nz / f - 1e-9);
Printf("terzaghi_column_3d: %g x %g x %g elements (factor %g)", NX, NX, NZ, f);

Point(1) = {0, 0, 0, H / nz};
Point(2) = {W, 0, 0, H / nz};
Point(3) = {W, W, 0, H / nz};
Point(4) = {0, W, 0, H / nz};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = NX + 1;
Transfinite Surface{1};
If (!Exists(tetrahedra)) tetrahedra = 0; EndIf
If (!tetrahedra)
  Recombine Surface{1};
  ext[] = Extrude {0, 0, H} { Surface{1}; Layers{NZ}; Recombine; };
Else
  ext[] = Extrude {0, 0, H} { Surface{1}; Layers{NZ}; };
EndIf
// ext[0] = top surface, ext[1] = volume, ext[2..5] = lateral surfaces
Physical Surface("bottom") = {1};
Physical Surface("top") = {ext[0]};
Physical Surface("sides") = {ext[2], ext[3], ext[4], ext[5]};
Physical Volume("soil") = {ext[1]};
