// Terzaghi consolidation column, 2D plane strain, structured TRIANGLES: same geometry, names
// and refinement rule as terzaghi_column_2d.geo (kept self-contained, no Include, so that the
// file can be meshed from any directory); each transfinite quadrangle is split in two.
triangles = 1;
W = 0.1;  H = 1.0;
If (!Exists(ny)) ny = 20; EndIf   // elements along the height at factor 1 (h = H/ny)
If (!Exists(nx)) nx = 2;  EndIf   // elements across the width at factor 1
f = Mesh.CharacteristicLengthFactor;
NX = Ceil(nx / f - 1e-9); NY = Ceil(ny / f - 1e-9);
Printf("terzaghi_column_2d: %g x %g elements (factor %g)", NX, NY, f);

Point(1) = {0, 0, 0, H / ny};
Point(2) = {W, 0, 0, H / ny};
Point(3) = {W, H, 0, H / ny};
Point(4) = {0, H, 0, H / ny};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // top
Line(4) = {4, 1};   // left
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = NX + 1;
Transfinite Curve{2, 4} = NY + 1;
Transfinite Surface{1};
If (!Exists(triangles)) triangles = 0; EndIf
If (!triangles) Recombine Surface{1}; EndIf

Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("soil") = {1};
