// A buried crack, 2D: the square [0, L] x [0, L] (one region "rock") with an inclined straight
// crack from (0.3, 0.4) to (0.7, 0.6) that ends inside the rock at both ends. The crack line is
// embedded in the mesh (Curve In Surface: the triangles conform to it) and is the physical
// curve "crack": an interface with two buried tips, which are not duplicated by the split.
// Physical curves: bottom, right, top, left, crack. Physical surface: rock.
// Triangles unless -setnumber quads 1. The crack has 2 n segments (2 n + 1 vertices, of them
// 2 n - 1 inside); sizes scale with -clscale (-mesh_size_factor).
L = 1.0;
If (!Exists(n)) n = 4; EndIf
If (!Exists(quads)) quads = 0; EndIf
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
h = 0.1;
Point(1) = {0, 0, 0, h}; Point(2) = {L, 0, 0, h}; Point(3) = {L, L, 0, h}; Point(4) = {0, L, 0, h};
Point(5) = {0.3 * L, 0.4 * L, 0, h}; Point(6) = {0.7 * L, 0.6 * L, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve{5} In Surface{1};
Transfinite Curve{5} = 2 * N + 1;
If (quads) Recombine Surface{1}; EndIf
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Curve("crack") = {5};
Physical Surface("rock") = {1};
