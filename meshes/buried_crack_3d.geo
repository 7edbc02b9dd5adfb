// A buried crack, 3D: the cube [0, L]^3 (one region "rock") with a square crack
// [0.3, 0.7] x [0.3, 0.7] in the plane z = 0.5 L that ends inside the rock on all four edges.
// The crack surface is embedded in the mesh (Surface In Volume: the tetrahedra conform to it)
// and is the physical surface "crack": an interface whose rim (tip edges) is not duplicated
// by the split. Physical surfaces: bottom, top (z = 0 / L), left, right (x = 0 / L), front,
// back (y = 0 / L), crack. Physical volume: rock. Tetrahedra. The crack is a structured grid
// of (2 n + 1)^2 vertices, (2 n - 1)^2 of them inside; sizes scale with -clscale.
L = 1.0;
If (!Exists(n)) n = 2; EndIf
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
h = 0.2;
Point(1) = {0, 0, 0, h}; Point(2) = {L, 0, 0, h}; Point(3) = {L, L, 0, h}; Point(4) = {0, L, 0, h};
Point(5) = {0, 0, L, h}; Point(6) = {L, 0, L, h}; Point(7) = {L, L, L, h}; Point(8) = {0, L, L, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
Curve Loop(1) = {1, 2, 3, 4};    Plane Surface(1) = {1}; // bottom
Curve Loop(2) = {5, 6, 7, 8};    Plane Surface(2) = {2}; // top
Curve Loop(3) = {1, 10, -5, -9}; Plane Surface(3) = {3}; // front (y = 0)
Curve Loop(4) = {2, 11, -6, -10}; Plane Surface(4) = {4}; // right (x = L)
Curve Loop(5) = {3, 12, -7, -11}; Plane Surface(5) = {5}; // back (y = L)
Curve Loop(6) = {4, 9, -8, -12}; Plane Surface(6) = {6}; // left (x = 0)
Surface Loop(1) = {1, 2, 3, 4, 5, 6}; Volume(1) = {1};
// the crack
a = 0.3 * L; b = 0.7 * L; zc = 0.5 * L;
Point(11) = {a, a, zc, h}; Point(12) = {b, a, zc, h}; Point(13) = {b, b, zc, h}; Point(14) = {a, b, zc, h};
Line(21) = {11, 12}; Line(22) = {12, 13}; Line(23) = {13, 14}; Line(24) = {14, 11};
Curve Loop(21) = {21, 22, 23, 24}; Plane Surface(21) = {21};
Transfinite Curve{21, 22, 23, 24} = 2 * N + 1;
Transfinite Surface{21};
Surface{21} In Volume{1};
Physical Surface("bottom") = {1};
Physical Surface("top") = {2};
Physical Surface("front") = {3};
Physical Surface("right") = {4};
Physical Surface("back") = {5};
Physical Surface("left") = {6};
Physical Surface("crack") = {21};
Physical Volume("rock") = {1};
