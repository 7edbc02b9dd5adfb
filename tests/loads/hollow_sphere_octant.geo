// An octant of a hollow sphere a <= r <= b, x, y, z >= 0 (Lame's sphere, tests/loads/loads.py).
// Physical surfaces: inner (r = a), outer (r = b), xsym (x = 0), ysym (y = 0), zsym (z = 0);
// physical curve: rim (r = a, z = 0; for a refused case); physical volume: shell. Tetrahedra on straight-sided faces. Counts scale with -clscale.
SetFactory("OpenCASCADE");
a = 1.0; b = 2.0;
If (!Exists(h)) h = 0.35; EndIf
Sphere(1) = {0, 0, 0, b, 0, Pi / 2, Pi / 2};
Sphere(2) = {0, 0, 0, a, 0, Pi / 2, Pi / 2};
BooleanDifference(3) = {Volume{1}; Delete;}{Volume{2}; Delete;};
e = 1e-6;
sx() = Surface In BoundingBox{-e, -e, -e, e, b + e, b + e};
sy() = Surface In BoundingBox{-e, -e, -e, b + e, e, b + e};
sz() = Surface In BoundingBox{-e, -e, -e, b + e, b + e, e};
si() = Surface In BoundingBox{-e, -e, -e, a + e, a + e, a + e};
all() = Abs(Boundary{Volume{3};});
so() = all();
so() -= {sx(), sy(), sz(), si()};
Physical Surface("xsym") = {sx()};
Physical Surface("ysym") = {sy()};
Physical Surface("zsym") = {sz()};
Physical Surface("inner") = {si()};
Physical Surface("outer") = {so()};
Physical Curve("rim") = Curve In BoundingBox{-e, -e, -e, a + e, a + e, e};
Physical Volume("shell") = {3};
MeshSize{PointsOf{Volume{3};}} = h;
