// Two horizontal layers crossed by a vertical fault, 2D plane strain, structured quadrilaterals:
// the square [0, 1] x [0, 1] m, layers lower [0, 0.4] and upper [0.4, 1] in y, the fault
// x = 0.5 from the bottom to the top. The fault is two physical curves, one per layer:
// "fault_lower" and "fault_upper", meeting end to end at the layer boundary (0.5, 0.4).
// Regions: with split_sides = 1 (default) one per layer and side of the fault, "lower_west",
// "lower_east", "upper_west", "upper_east"; with split_sides = 0 one per layer, "lower" and
// "upper", each on both sides of the fault.
// Physical curves: bottom, top, left, right, fault_lower, fault_upper.
// An example of an interface in layered ground (docs/interface_parameters.md, "Interfaces in
// layered ground"). Counts scale with -clscale (-mesh_size_factor).
If (!Exists(split_sides)) split_sides = 1; EndIf
If (!Exists(n)) n = 4; EndIf     // cells across each half and up each layer at factor 1
H1 = 0.4;                        // the layer boundary
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
Point(1) = {0, 0, 0};   Point(2) = {0.5, 0, 0};   Point(3) = {1, 0, 0};
Point(4) = {0, H1, 0};  Point(5) = {0.5, H1, 0};  Point(6) = {1, H1, 0};
Point(7) = {0, 1, 0};   Point(8) = {0.5, 1, 0};   Point(9) = {1, 1, 0};
Line(1) = {1, 2};  Line(2) = {2, 3};                 // bottom
Line(3) = {4, 5};  Line(4) = {5, 6};                 // layer boundary
Line(5) = {7, 8};  Line(6) = {8, 9};                 // top
Line(7) = {1, 4};  Line(8) = {4, 7};                 // left
Line(9) = {3, 6};  Line(10) = {6, 9};                // right
Line(11) = {2, 5}; Line(12) = {5, 8};                // the fault, lower and upper part
Curve Loop(1) = {1, 11, -3, -7};  Plane Surface(1) = {1};   // lower west
Curve Loop(2) = {2, 9, -4, -11};  Plane Surface(2) = {2};   // lower east
Curve Loop(3) = {3, 12, -5, -8};  Plane Surface(3) = {3};   // upper west
Curve Loop(4) = {4, 10, -6, -12}; Plane Surface(4) = {4};   // upper east
Transfinite Curve{1:12} = N + 1;
Transfinite Surface{1:4};
Recombine Surface{1:4};
Physical Curve("bottom") = {1, 2};
Physical Curve("top") = {5, 6};
Physical Curve("left") = {7, 8};
Physical Curve("right") = {9, 10};
Physical Curve("fault_lower") = {11};
Physical Curve("fault_upper") = {12};
If (split_sides)
  Physical Surface("lower_west") = {1};
  Physical Surface("lower_east") = {2};
  Physical Surface("upper_west") = {3};
  Physical Surface("upper_east") = {4};
Else
  Physical Surface("lower") = {1, 2};
  Physical Surface("upper") = {3, 4};
EndIf
