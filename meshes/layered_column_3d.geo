// A soil column of three horizontal layers, 3D, structured hexahedra, for the geostatic state
// of layered ground (tests/physics/geostatic.py):
//   deep [0, H1], middle [H1, H1 + H2], shallow [H1 + H2, H] over 0 <= x, y <= W, top at z = H.
// Physical surfaces: bottom, top, xmin, xmax, ymin, ymax (the four sides, all layers);
// physical volumes: deep, middle, shallow. Elements: nz per metre of height, nx along each
// horizontal edge, both divided by -mesh_size_factor. Tetrahedra with -setnumber tetrahedra 1.
W = 0.1; H1 = 0.4; H2 = 0.3; H = 1.0;
If (!Exists(nz)) nz = 20; EndIf   // elements per metre of height at factor 1
If (!Exists(nx)) nx = 2;  EndIf   // elements along each horizontal edge at factor 1
f = Mesh.CharacteristicLengthFactor;
NX = Ceil(nx / f - 1e-9);
N1 = Ceil(nz * H1 / f - 1e-9); N2 = Ceil(nz * H2 / f - 1e-9); N3 = Ceil(nz * (H - H1 - H2) / f - 1e-9);
Point(1) = {0, 0, 0}; Point(2) = {W, 0, 0}; Point(3) = {W, W, 0}; Point(4) = {0, W, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = NX + 1;
Transfinite Surface{1};
If (!Exists(tetrahedra)) tetrahedra = 0; EndIf
If (!tetrahedra)
  Recombine Surface{1};
  a[] = Extrude {0, 0, H1} { Surface{1}; Layers{N1}; Recombine; };
  b[] = Extrude {0, 0, H2} { Surface{a[0]}; Layers{N2}; Recombine; };
  c[] = Extrude {0, 0, H - H1 - H2} { Surface{b[0]}; Layers{N3}; Recombine; };
Else
  a[] = Extrude {0, 0, H1} { Surface{1}; Layers{N1}; };
  b[] = Extrude {0, 0, H2} { Surface{a[0]}; Layers{N2}; };
  c[] = Extrude {0, 0, H - H1 - H2} { Surface{b[0]}; Layers{N3}; };
EndIf
// Extrude returns: [0] the top surface, [1] the volume, [2..5] the sides along lines 1..4
// (y = 0, x = W, y = W, x = 0).
Physical Surface("bottom") = {1};
Physical Surface("top") = {c[0]};
Physical Surface("ymin") = {a[2], b[2], c[2]};
Physical Surface("xmax") = {a[3], b[3], c[3]};
Physical Surface("ymax") = {a[4], b[4], c[4]};
Physical Surface("xmin") = {a[5], b[5], c[5]};
Physical Volume("deep") = {a[1]};
Physical Volume("middle") = {b[1]};
Physical Volume("shallow") = {c[1]};
