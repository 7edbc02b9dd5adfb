// A soil column of three horizontal layers, 2D plane strain, structured quadrilaterals, for the
// geostatic state of layered ground (tests/physics/geostatic.py):
//   deep [0, H1], middle [H1, H1 + H2], shallow [H1 + H2, H] across 0 <= x <= W, top at y = H.
// Physical curves: bottom, top, left, right (all layers); physical surfaces: deep, middle,
// shallow. Elements: ny per metre of height, nx across, both divided by -mesh_size_factor
// (gmsh -clscale; transfinite counts ignore it otherwise). Triangles with -setnumber triangles 1.
W = 0.1; H1 = 0.4; H2 = 0.3; H = 1.0;
If (!Exists(ny)) ny = 20; EndIf   // elements per metre of height at factor 1
If (!Exists(nx)) nx = 2;  EndIf   // elements across the width at factor 1
f = Mesh.CharacteristicLengthFactor;
NX = Ceil(nx / f - 1e-9);
N1 = Ceil(ny * H1 / f - 1e-9); N2 = Ceil(ny * H2 / f - 1e-9); N3 = Ceil(ny * (H - H1 - H2) / f - 1e-9);
Point(1) = {0, 0, 0};       Point(2) = {W, 0, 0};
Point(3) = {W, H1, 0};      Point(4) = {0, H1, 0};
Point(5) = {W, H1 + H2, 0}; Point(6) = {0, H1 + H2, 0};
Point(7) = {W, H, 0};       Point(8) = {0, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Line(8) = {5, 7}; Line(9) = {7, 8}; Line(10) = {8, 6};
Curve Loop(1) = {1, 2, 3, 4};    Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};   Plane Surface(2) = {2};
Curve Loop(3) = {-6, 8, 9, 10};  Plane Surface(3) = {3};
Transfinite Curve{1, 3, 6, 9} = NX + 1;
Transfinite Curve{2, 4} = N1 + 1;
Transfinite Curve{5, 7} = N2 + 1;
Transfinite Curve{8, 10} = N3 + 1;
Transfinite Surface{1, 2, 3};
If (!Exists(triangles)) triangles = 0; EndIf
If (!triangles) Recombine Surface{1, 2, 3}; EndIf
Physical Curve("bottom") = {1};
Physical Curve("top") = {9};
Physical Curve("left") = {4, 7, 10};
Physical Curve("right") = {2, 5, 8};
Physical Surface("deep") = {1};
Physical Surface("middle") = {2};
Physical Surface("shallow") = {3};
