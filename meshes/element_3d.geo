// One hexahedron, the unit cube [0, 1]^3 (z up): the laboratory element of the triaxial and
// undrained tests (tests/plasticity/element.py). Physical surfaces named by the plane they lie
// on: x0, x1, y0, y1, bottom (z = 0), top (z = 1); physical volume: soil. Always one cell
// (-mesh_size_factor does not refine it: a homogeneous state needs none).
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
ext[] = Extrude {0, 0, 1} { Surface{1}; Layers{1}; Recombine; };
// ext[0] = top, ext[1] = volume, ext[2..5] = the lateral faces on lines 1..4 (y = 0, x = 1,
// y = 1, x = 0)
Physical Surface("bottom") = {1};
Physical Surface("top") = {ext[0]};
Physical Surface("y0") = {ext[2]};
Physical Surface("x1") = {ext[3]};
Physical Surface("y1") = {ext[4]};
Physical Surface("x0") = {ext[5]};
Physical Volume("soil") = {ext[1]};
