// A block on a base, 2D, joined along a circular arc (the curved variant of
// block_on_base_2d.geo, for curved interfaces: -mesh_geometry_order 2). The contact curve
// runs from (0, H1) to (W, H1) on a circle of radius R centred below it (bulging upwards by
// R - sqrt(R^2 - W^2 / 4) = 0.086 m). Physical curves: bottom, top, base_left, base_right,
// block_left, block_right, contact. Physical surfaces: base, block. Quadrilaterals.
W = 1.0; H1 = 0.5; H2 = 0.5; R = 1.5;
If (!Exists(n)) n = 4; EndIf
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Point(1) = {0, 0, 0};  Point(2) = {W, 0, 0};
Point(3) = {W, H1, 0}; Point(4) = {0, H1, 0};
Point(5) = {W, H1 + H2, 0}; Point(6) = {0, H1 + H2, 0};
Point(7) = {W / 2, H1 - Sqrt(R * R - W * W / 4), 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Circle(3) = {3, 7, 4}; Line(4) = {4, 1};
Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};
Transfinite Curve{1, 3, 6} = 2 * N + 1;
Transfinite Curve{2, 4, 5, 7} = N + 1;
Transfinite Surface{1, 2};
Recombine Surface{1, 2};
Physical Curve("bottom") = {1};
Physical Curve("base_right") = {2};
Physical Curve("base_left") = {4};
Physical Curve("block_right") = {5};
Physical Curve("top") = {6};
Physical Curve("block_left") = {7};
Physical Curve("contact") = {3};
Physical Surface("base") = {1};
Physical Surface("block") = {2};
