// A square -1 <= x, y <= 1 held by points only (tests/loads/loads.py: uniform pressure on all
// sides, no displacement condition on any face). Physical points: centre (0, 0), inside the
// square (a mesh vertex, embedded), and east (1, 0) on its side; physical curve: sides (all
// four); physical surface: square. Triangles. Counts scale with -clscale.
If (!Exists(h)) h = 0.25; EndIf
Point(1) = {-1, -1, 0, h}; Point(2) = {1, -1, 0, h}; Point(3) = {1, 0, 0, h};
Point(4) = {1, 1, 0, h}; Point(5) = {-1, 1, 0, h}; Point(6) = {0, 0, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 5}; Line(5) = {5, 1};
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};
Point{6} In Surface{1};
Physical Point("centre") = {6};
Physical Point("east") = {3};
Physical Curve("sides") = {1, 2, 3, 4, 5};
Physical Surface("square") = {1};
