// Sneddon's pressurised crack, half model (plane strain, tests/verification/sneddon.py).
// A straight crack of half-length a on y = 0, its centre on the symmetry plane x = 0: the
// half domain [0, L] x [-L, L] holds the half crack from (0, 0) to (a, 0), embedded in the mesh
// (Curve In Surface: the triangles conform to it) as the physical curve "crack", an interface
// with one end on the symmetry plane (where its water pressure p3 is prescribed) and one
// buried tip (not duplicated by the split). The far boundary, L = 200 a by default, stands in
// for infinity.
// Physical curves: symmetry (x = 0, both halves), far (bottom, right and top), crack.
// Physical surface: rock.
// Sizes: h_c = a / n along the crack, growing by g per metre of distance from it; around the
// tip h_c / tip_ratio, growing by g per metre from the tip (a geometric grading towards the
// singularity); at most L / 5. Gmsh's -clscale (poroseam's -mesh_size_factor) scales every
// size, so a factor 1/2 halves every element (the grading is the same at every factor).
// Overrides: gmsh -setnumber n 16, -setnumber L 20, ...
If (!Exists(a)) a = 1.0; EndIf
If (!Exists(L)) L = 200.0; EndIf
If (!Exists(n)) n = 8; EndIf          // elements along the half crack, away from the tip
If (!Exists(tip_ratio)) tip_ratio = 8; EndIf
If (!Exists(g)) g = 0.3; EndIf
hc = a / n;
ht = hc / tip_ratio;
hmax = L / 5;

Point(1) = {0, -L, 0, hmax};
Point(2) = {L, -L, 0, hmax};
Point(3) = {L, L, 0, hmax};
Point(4) = {0, L, 0, hmax};
Point(5) = {0, 0, 0, hc};   // crack centre, on the symmetry plane
Point(6) = {a, 0, 0, ht};   // crack tip
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 5};   // symmetry, upper half
Line(5) = {5, 1};   // symmetry, lower half
Line(6) = {5, 6};   // crack
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Curve{6} In Surface{1};

// Exact distances (x >= 0): to the crack segment, d_c = sqrt(max(x - a, 0)^2 + y^2); to the tip,
// d_t = sqrt((x - a)^2 + y^2).
Field[1] = MathEval;
Field[1].F = Sprintf("min(%g, min(%g + %g * sqrt(max(x - %g, 0)^2 + y^2), %g + %g * sqrt((x - %g)^2 + y^2)))",
                     hmax, hc, g, a, ht, g, a);
Background Field = 1;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;

Physical Curve("symmetry") = {4, 5};
Physical Curve("far") = {1, 2, 3};
Physical Curve("crack") = {6};
Physical Surface("rock") = {1};
