// meshes/block_on_base_2d.geo with the contact line in two named parts, contact_left
// (x < W/2) and contact_right, for interface forces per part.
// Physical curves: bottom, top, base_left, base_right, block_left, block_right, contact.
// Physical surfaces: base, block. Transfinite counts scale with -clscale like the columns.
W = 1.0; H1 = 0.5; H2 = 0.5;
If (!Exists(n)) n = 4; EndIf
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Point(1) = {0, 0, 0};  Point(2) = {W, 0, 0};
Point(3) = {W, H1, 0}; Point(4) = {0, H1, 0};
Point(5) = {W, H1 + H2, 0}; Point(6) = {0, H1 + H2, 0};
Point(7) = {W / 2, H1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 7}; Line(8) = {7, 4}; Line(4) = {4, 1};
Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 8, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {-8, -3, 5, 6, 7}; Plane Surface(2) = {2};
Transfinite Curve{1, 6} = 2 * N + 1;
Transfinite Curve{3, 8} = N + 1;
Transfinite Curve{2, 4, 5, 7} = N + 1;
Transfinite Surface{1} = {1, 2, 3, 4};
Transfinite Surface{2} = {4, 3, 5, 6};
If (!Exists(triangles)) triangles = 0; EndIf
If (!triangles) Recombine Surface{1, 2}; EndIf
Physical Curve("bottom") = {1};
Physical Curve("base_right") = {2};
Physical Curve("base_left") = {4};
Physical Curve("block_right") = {5};
Physical Curve("top") = {6};
Physical Curve("block_left") = {7};
Physical Curve("contact_right") = {3};
Physical Curve("contact_left") = {8};
Physical Surface("base") = {1};
Physical Surface("block") = {2};
