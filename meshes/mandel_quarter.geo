// Mandel's problem, quarter model (plane strain), structured quadrilaterals.
// 0 <= x <= a, 0 <= y <= b (a = half width, b = half height of the specimen).
// Physical curves: left (x = 0, symmetry), bottom (y = 0, symmetry),
// right (x = a, drained and traction free), top (y = b, rigid plate); surface: soil.
//
// Refinement: elements per side = ceil(base / Mesh.CharacteristicLengthFactor), so
// poroseam's -mesh_size_factor (gmsh -clscale) refines it although the mesh is transfinite.
// Overrides: gmsh -setnumber n 20, -setnumber a 2, ...
If (!Exists(a)) a = 1.0; EndIf
If (!Exists(b)) b = 1.0; EndIf
If (!Exists(n)) n = 10; EndIf     // elements along each side at factor 1
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Printf("mandel_quarter: %g x %g elements (factor %g)", N, N, f);

Point(1) = {0, 0, 0, a / n};
Point(2) = {a, 0, 0, a / n};
Point(3) = {a, b, 0, a / n};
Point(4) = {0, b, 0, a / n};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = N + 1;
Transfinite Surface{1};
Recombine Surface{1};

Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("soil") = {1};
