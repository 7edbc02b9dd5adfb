// A cube -1 <= x, y, z <= 1 held by points only (tests/loads/loads.py: uniform pressure on all
// faces). Physical points: centre (0, 0, 0), inside the cube (embedded), px (1, 0, 0) and
// py (0, 1, 0), at the centres of two faces (embedded); physical curve: axis, a segment of
// the x axis from (-0.5, 0, 0) to the centre (embedded); physical surface: faces (all six);
// physical volume: cube. Tetrahedra. Counts scale with -clscale.
SetFactory("OpenCASCADE");
If (!Exists(h)) h = 0.5; EndIf
Box(1) = {-1, -1, -1, 2, 2, 2};
Point(100) = {0, 0, 0, h}; Point(101) = {1, 0, 0, h}; Point(102) = {0, 1, 0, h};
Point(103) = {-0.5, 0, 0, h};
Line(200) = {103, 100};
e = 1e-6;
fx() = Surface In BoundingBox{1 - e, -1 - e, -1 - e, 1 + e, 1 + e, 1 + e};
fy() = Surface In BoundingBox{-1 - e, 1 - e, -1 - e, 1 + e, 1 + e, 1 + e};
Point{100} In Volume{1};
Curve{200} In Volume{1};
Transfinite Curve{200} = 5;
Point{101} In Surface{fx(0)};
Point{102} In Surface{fy(0)};
Physical Point("centre") = {100};
Physical Point("px") = {101};
Physical Point("py") = {102};
Physical Curve("axis") = {200};
Physical Surface("faces") = {Abs(Boundary{Volume{1};})};
Physical Volume("cube") = {1};
MeshSize{PointsOf{Volume{1};}} = h;
