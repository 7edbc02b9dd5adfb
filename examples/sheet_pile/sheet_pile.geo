// A steel sheet pile in saturated silt, 2D plane strain, y up, the ground surface at y = 0.
// Soil [-10, 10] x [-10, 0]; the pile a 0.1 m thick plate from the surface down to y = -6 m.
W = 10; D = 10;          // half width and depth of the soil [m]
t = 0.1; L = 6;          // pile thickness and length [m]
hp = 0.15; hf = 1.2;     // element size at the pile and far away [m]
// Corner points of the soil, then of the pile.
Point(1) = {-W, -D, 0, hf};  Point(2) = {W, -D, 0, hf};
Point(3) = {W, 0, 0, hf};    Point(4) = {-W, 0, 0, hf};
Point(5) = {-t/2, 0, 0, hp}; Point(6) = {t/2, 0, 0, hp};
Point(7) = {t/2, -L, 0, hp}; Point(8) = {-t/2, -L, 0, hp};
// The pile's faces: each line is shared by the pile and the soil. Shared lines are what
// poroseam splits into the interface.
Line(1) = {5, 8};   // pile face on the left (dry side)
Line(2) = {8, 7};   // pile tip
Line(3) = {7, 6};   // pile face on the right (river side)
Line(4) = {6, 5};   // pile head
// The soil's outline.
Line(5) = {1, 2}; Line(6) = {2, 3};   // bottom, right side
Line(7) = {3, 6};                     // river bed
Line(8) = {5, 4};                     // ground surface, left of the pile
Line(9) = {4, 1};                     // left side
Curve Loop(1) = {1, 2, 3, 4};          Plane Surface(1) = {1};   // pile
// The pile is thin: a structured mesh, two triangles across, one every 0.15 m down. Counts
// scale with poroseam's -mesh_size_factor (gmsh's Mesh.CharacteristicLengthFactor).
n = Ceil(L / hp / Mesh.CharacteristicLengthFactor);
Transfinite Curve{1, 3} = n + 1;
Transfinite Curve{2, 4} = 3;
Transfinite Surface{1};
Curve Loop(2) = {5, 6, 7, -3, -2, -1, 8, 9}; Plane Surface(2) = {2};  // soil
Physical Surface("soil") = {2};
Physical Surface("pile") = {1};
Physical Curve("bottom") = {5};
Physical Curve("left") = {9};
Physical Curve("right") = {6};
Physical Curve("river") = {7};
Physical Curve("ground") = {8};
Physical Curve("pile_head") = {4};
Physical Curve("wall_dry") = {1};
Physical Curve("wall_river") = {3};
Physical Curve("wall_tip") = {2};
