// Two regions, 2D plane strain (y up): a soil layer 0 <= x <= 4 m, 0 <= y <= 2 m (surface at
// y = 2) with an elastic block 0 <= x <= 1 m, 2 <= y <= 2.5 m (a footing) resting on it at the
// left edge (x = 0 is a symmetry plane: the model is half of a 2 m wide footing).
// Unstructured triangles (element size lc, ~0.2 m; refined by -mesh_size_factor = gmsh -clscale).
// Regions (physical surfaces): soil, block.
// Boundaries (physical curves): bottom (y = 0), right (x = 4), surface (soil top not under the
// block, 1 <= x <= 4), left (x = 0, soil and block), block_side (x = 1), block_top (y = 2.5).
// The soil-block contact (y = 2, 0 <= x <= 1) is shared by both regions (conforming mesh).
If (!Exists(lc)) lc = 0.2; EndIf
Point(1) = {0, 0, 0, 2 * lc};
Point(2) = {4, 0, 0, 2 * lc};
Point(3) = {4, 2, 0, lc};
Point(4) = {1, 2, 0, lc / 2};
Point(5) = {0, 2, 0, lc / 2};
Point(6) = {1, 2.5, 0, lc / 2};
Point(7) = {0, 2.5, 0, lc / 2};
Line(1) = {1, 2};   // bottom
Line(2) = {2, 3};   // right
Line(3) = {3, 4};   // surface
Line(4) = {4, 5};   // soil-block contact
Line(5) = {5, 1};   // left, soil
Line(6) = {4, 6};   // block_side
Line(7) = {6, 7};   // block_top
Line(8) = {7, 5};   // left, block
// The block is surface 1, so its cells come first in the mesh file (a probe on the contact
// must still find the soil's pressure).
Curve Loop(1) = {-4, 6, 7, 8};
Plane Surface(1) = {1};
Curve Loop(2) = {1, 2, 3, 4, 5};
Plane Surface(2) = {2};

Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("surface") = {3};
Physical Curve("left") = {5, 8};
Physical Curve("block_side") = {6};
Physical Curve("block_top") = {7};
Physical Surface("block") = {1};
Physical Surface("soil") = {2};
