// Cylindrical cavity in an axisymmetric (r, z) = (x, y) slice of soil: a <= r <= b,
// 0 <= z <= H, one row of cells (the solution depends on r only; top and bottom take rollers).
// Cell widths grow geometrically from the cavity wall (ratio g) so that the plastic zone near
// the cavity is finely resolved; the outer radius b is far (b = 20 a) and enters the closed
// form exactly. Quadrilaterals. Physical curves: inner (r = a), outer (r = b), bottom, top;
// physical surface: soil. Counts scale with -clscale.
a = 1.0; b = 20.0; H = 0.05;
If (!Exists(n)) n = 60; EndIf   // cells along r at factor 1
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
g = 1.05^(60 / N);   // same grading law on every mesh: finer meshes grow more slowly
Printf("cavity_axisym: %g cells along r, first %g m wide", N, (b - a) * (g - 1) / (g^N - 1));
Point(1) = {a, 0, 0}; Point(2) = {b, 0, 0}; Point(3) = {b, H, 0}; Point(4) = {a, H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {4, 3}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, -3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = N + 1 Using Progression g;
Transfinite Curve{2, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Curve("bottom") = {1};
Physical Curve("outer") = {2};
Physical Curve("top") = {3};
Physical Curve("inner") = {4};
Physical Surface("soil") = {1};
