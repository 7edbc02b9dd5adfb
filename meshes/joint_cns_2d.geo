// A joint sheared under constant normal stiffness, 2D: a base [0, W] x [0, H], a block
// [0, W] x [H, 2H] and a cap [0, W] x [2H, 3H] stacked on two flat lines, y = H (physical
// curve "joint") and y = 2H ("spring"), each separating its bodies completely (interfaces).
// The spring interface, frictionless, gives the block a normal stiffness against the cap that
// carries no shear. Quadrilaterals.
// Physical curves: bottom, top, base_left, base_right, block_left, block_right, cap_left,
// cap_right, joint, spring. Physical surfaces: base, block, cap.
W = 1.0; H = 0.5;
If (!Exists(n)) n = 2; EndIf
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Point(1) = {0, 0, 0};     Point(2) = {W, 0, 0};
Point(3) = {W, H, 0};     Point(4) = {0, H, 0};
Point(5) = {W, 2 * H, 0}; Point(6) = {0, 2 * H, 0};
Point(7) = {W, 3 * H, 0}; Point(8) = {0, 3 * H, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {3, 5}; Line(6) = {5, 6}; Line(7) = {6, 4};
Line(8) = {5, 7}; Line(9) = {7, 8}; Line(10) = {8, 6};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7}; Plane Surface(2) = {2};
Curve Loop(3) = {-6, 8, 9, 10}; Plane Surface(3) = {3};
Transfinite Curve{1, 3, 6, 9} = 2 * N + 1;
Transfinite Curve{2, 4, 5, 7, 8, 10} = N + 1;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};
Physical Curve("bottom") = {1};
Physical Curve("base_right") = {2};
Physical Curve("base_left") = {4};
Physical Curve("block_right") = {5};
Physical Curve("block_left") = {7};
Physical Curve("cap_right") = {8};
Physical Curve("top") = {9};
Physical Curve("cap_left") = {10};
Physical Curve("joint") = {3};
Physical Curve("spring") = {6};
Physical Surface("base") = {1};
Physical Surface("block") = {2};
Physical Surface("cap") = {3};
