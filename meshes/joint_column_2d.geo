// A soil column split by a horizontal joint, 2D plane strain, structured quadrilaterals:
// lower layer [0, W] x [0, H1], upper layer [0, W] x [H1, H1 + H2], the joint y = H1 between
// them (physical curve "joint": an interface across the whole column, ending on the sides).
// With H1 = H2 = 0.5 and W = 0.1 it is meshes/terzaghi_column_2d.geo cut at mid height
// (same vertices at factor 1: 2 x 20 cells). Triangles with -setnumber triangles 1.
// Physical curves: bottom, top, left, right (both layers), joint.
// Physical surfaces: lower, upper. Transfinite counts scale with -clscale (-mesh_size_factor).
W = 0.1; H1 = 0.5; H2 = 0.5;
If (!Exists(ny)) ny = 10; EndIf   // elements along the height of each layer at factor 1
If (!Exists(nx)) nx = 2;  EndIf   // elements across the width at factor 1
f = Mesh.CharacteristicLengthFactor;
NX = Ceil(nx / f - 1e-9); NY = Ceil(ny / f - 1e-9);
Point(1) = {0, 0, 0};  Point(2) = {W, 0, 0};
Point(3) = {W, H1, 0}; Point(4) = {0, H1, 0};
Point(5) = {W, H1 + H2, 0}; Point(6) = {0, H1 + H2, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};
Transfinite Curve{1, 3, 6} = NX + 1;
Transfinite Curve{2, 4, 5, 7} = NY + 1;
Transfinite Surface{1, 2};
If (!Exists(triangles)) triangles = 0; EndIf
If (!triangles) Recombine Surface{1, 2}; EndIf
Physical Curve("bottom") = {1};
Physical Curve("top") = {6};
Physical Curve("left") = {4, 7};
Physical Curve("right") = {2, 5};
Physical Curve("joint") = {3};
Physical Surface("lower") = {1};
Physical Surface("upper") = {2};
