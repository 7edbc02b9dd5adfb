// A block with an inclined face, (0,0) (2,0) (1.5,1) (0,1): the slope from (2,0) to (1.5,1)
// has the outward normal (2, 1)/sqrt(5) (tests/loads/loads.py: a normal pressure there equals
// the traction vector -P n). Physical curves: bottom, slope, top, left, cut (inside); physical
// surface: block.
// Triangles. Counts scale with -clscale.
If (!Exists(h)) h = 0.25; EndIf
Point(1) = {0, 0, 0, h}; Point(2) = {2, 0, 0, h}; Point(3) = {1.5, 1, 0, h}; Point(4) = {0, 1, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Curve("bottom") = {1};
Physical Curve("slope") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
Physical Surface("block") = {1};
// A segment inside the block (for a refused case: a pressure on faces inside the mesh).
Point(5) = {0.5, 0.25, 0, h}; Point(6) = {0.5, 0.75, 0, h};
Line(5) = {5, 6};
Line{5} In Surface{1};
Physical Curve("cut") = {5};
