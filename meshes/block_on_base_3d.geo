// A block on a base, 3D (z up): base [0, W] x [0, W] x [0, H1], block [0, W] x [0, W] x
// [H1, H1 + H2], the flat contact surface z = H1 between them (physical surface "contact": an
// interface that separates the two bodies completely). Hexahedra unless -setnumber tets 1
// (meshes/block_on_base_3d_tet.geo): each extruded prism is then cut into tetrahedra.
// Physical surfaces: bottom (z = 0), top (z = H1 + H2), base_left/base_right (x = 0 / W),
// base_front/base_back (y = 0 / W), block_left, block_right, block_front, block_back, contact.
// Physical volumes: base, block. Transfinite counts scale with -clscale (-mesh_size_factor).
W = 1.0; H1 = 0.5; H2 = 0.5;
If (!Exists(n)) n = 3; EndIf
If (!Exists(tets)) tets = 0; EndIf
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Point(1) = {0, 0, 0}; Point(2) = {W, 0, 0}; Point(3) = {W, W, 0}; Point(4) = {0, W, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2 * N + 1;
Transfinite Surface{1};
If (!tets)
  Recombine Surface{1};
  base[] = Extrude {0, 0, H1} { Surface{1}; Layers{N}; Recombine; };
  block[] = Extrude {0, 0, H2} { Surface{base[0]}; Layers{N}; Recombine; };
Else
  base[] = Extrude {0, 0, H1} { Surface{1}; Layers{N}; };
  block[] = Extrude {0, 0, H2} { Surface{base[0]}; Layers{N}; };
EndIf
// Extrude returns {top, volume, sides along lines 1 (y = 0), 2 (x = W), 3 (y = W), 4 (x = 0)}.
Physical Surface("bottom") = {1};
Physical Surface("top") = {block[0]};
Physical Surface("contact") = {base[0]};
Physical Surface("base_front") = {base[2]};
Physical Surface("base_right") = {base[3]};
Physical Surface("base_back") = {base[4]};
Physical Surface("base_left") = {base[5]};
Physical Surface("block_front") = {block[2]};
Physical Surface("block_right") = {block[3]};
Physical Surface("block_back") = {block[4]};
Physical Surface("block_left") = {block[5]};
Physical Volume("base") = {base[1]};
Physical Volume("block") = {block[1]};
