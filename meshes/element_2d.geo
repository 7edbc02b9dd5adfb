// One quadrilateral, the unit square [0, 1]^2 (y up): the laboratory element of the
// plane-strain and axisymmetric (x = r, a cylindrical sample) element tests
// (tests/plasticity/element.py). Physical lines: left (x = 0, the axis when axisymmetric),
// right, bottom, top; physical surface: soil. Always one cell.
Point(1) = {0, 0, 0, 1};
Point(2) = {1, 0, 0, 1};
Point(3) = {1, 1, 0, 1};
Point(4) = {0, 1, 0, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 2;
Transfinite Surface{1};
Recombine Surface{1};
Physical Line("bottom") = {1};
Physical Line("right") = {2};
Physical Line("top") = {3};
Physical Line("left") = {4};
Physical Surface("soil") = {1};
