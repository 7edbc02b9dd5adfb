// Suction caisson in an elastic soil layer, quarter model in 3D (docs/caisson.md; paper
// section 3). x >= 0, y >= 0 (symmetry planes x = 0 and y = 0), z up, soil surface z = 0.
//   soil:    cylinder r <= 24 m, -12 <= z <= 0 (the soil plug inside the skirt is soil)
//   caisson: skirt 3.8 <= r <= 3.9 m, -4 <= z <= 0, and lid r <= 3.9 m, 0 <= z <= 0.4
// All hexahedra (built-in kernel, structured): the plan view (z = -12) is a quarter disk cut
// into an O-grid (a quadrilateral core around the axis, then rings out to r = 3.8, 3.9 and 24
// in two 45-degree sectors), extruded in three layers (-12..-4, -4..0, 0..0.4; the last over
// r <= 3.9 only). Extrusion makes the meshes conformal: bodies that touch share their faces,
// and the only faces shared by soil and caisson are the four interface parts below.
// Refinement: radially towards the skirt from both sides, vertically towards the skirt tip
// (z = -4) and the lid (z = 0). Every count scales with -clscale (-mesh_size_factor):
// 0.5 doubles the divisions in each direction.
//
// Physical volumes:  soil, caisson
// Physical surfaces: interface parts (soil = side 1):
//   outer_skirt (r = 3.9, -4 < z < 0), skirt_tip (z = -4, 3.8 < r < 3.9),
//   inner_skirt (r = 3.8, -4 < z < 0), lid (z = 0, r < 3.8: lid underside on the soil plug)
// boundaries: soil_top (z = 0, r > 3.9: free soil surface), lid_top (z = 0.4),
//   lid_side (r = 3.9, 0 < z < 0.4), sym_x (x = 0, soil and caisson), sym_y (y = 0, soil and
//   caisson), outer (r = 24), bottom (z = -12)
//
// Default (factor 1): 8 divisions per 45 degrees, 6 + 1 + 12 radial (core edge..3.8,
// skirt, 3.9..24), 8 + 14 + 2 vertical: about 10,400 nodes after the interface split
// (about 31,000 displacement unknowns).

R_in = 3.8; R_out = 3.9; R_soil = 24;
Z_bot = -12; Z_tip = -4; Z_top = 0; Z_lid = 0.4;
a = 1.7;  // core: straight edges (a,0)-(c,c)-(0,a) around the axis
c = 1.45;

If (!Exists(nt)) nt = 8; EndIf     // divisions per 45-degree sector (arcs, core edges)
If (!Exists(n1)) n1 = 6; EndIf     // core edge .. r = 3.8
If (!Exists(ns)) ns = 1; EndIf     // through the skirt, 3.8 .. 3.9
If (!Exists(n3)) n3 = 12; EndIf    // 3.9 .. 24
If (!Exists(nz1)) nz1 = 8; EndIf   // -12 .. -4
If (!Exists(nz2)) nz2 = 14; EndIf  // -4 .. 0
If (!Exists(nz3)) nz3 = 2; EndIf   // lid, 0 .. 0.4
f = Mesh.CharacteristicLengthFactor;
NT = Ceil(nt / f - 1e-9); N1 = Ceil(n1 / f - 1e-9); NS = Ceil(ns / f - 1e-9);
N3 = Ceil(n3 / f - 1e-9); NZ1 = Ceil(nz1 / f - 1e-9); NZ2 = Ceil(nz2 / f - 1e-9);
NZ3 = Ceil(nz3 / f - 1e-9);
// geometric ratios per element (the ratio over the whole segment stays the same when the
// counts scale): ring 1 shrinks towards 3.8 (last/first = 1/3), the outer ring grows from
// 3.9 (last/first = 20)
q1 = 3^(-1 / (N1 - 1 + 1e-12)); If (N1 == 1) q1 = 1; EndIf
q3 = 20^(1 / (N3 - 1));

zb = Z_bot;
Point(1) = {0, 0, zb};
Point(2) = {a, 0, zb}; Point(3) = {c, c, zb}; Point(4) = {0, a, zb};
s2 = Sqrt(0.5);
Point(11) = {R_in, 0, zb};    Point(12) = {R_in * s2, R_in * s2, zb};    Point(13) = {0, R_in, zb};
Point(21) = {R_out, 0, zb};   Point(22) = {R_out * s2, R_out * s2, zb};  Point(23) = {0, R_out, zb};
Point(31) = {R_soil, 0, zb};  Point(32) = {R_soil * s2, R_soil * s2, zb}; Point(33) = {0, R_soil, zb};

// core
Line(1) = {1, 2};  // y = 0
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};  // x = 0
// radial lines, all pointing outwards: along y = 0 (10x), the diagonal (10d), x = 0 (10y)
Line(101) = {2, 11};  Line(102) = {3, 12};  Line(103) = {4, 13};
Line(111) = {11, 21}; Line(112) = {12, 22}; Line(113) = {13, 23};
Line(121) = {21, 31}; Line(122) = {22, 32}; Line(123) = {23, 33};
// arcs, counter-clockwise
Circle(201) = {11, 1, 12}; Circle(202) = {12, 1, 13};
Circle(211) = {21, 1, 22}; Circle(212) = {22, 1, 23};
Circle(221) = {31, 1, 32}; Circle(222) = {32, 1, 33};

// Surfaces. The loop order fixes the order of the lateral faces that Extrude returns:
//   core: {y = 0, internal, internal, x = 0}
//   sector A (0..45 deg):  {y = 0, outer arc, diagonal, inner arc}
//   sector B (45..90 deg): {diagonal, outer arc, x = 0, inner arc}
Curve Loop(1) = {1, 2, 3, 4};           Plane Surface(1) = {1};     // core
Curve Loop(11) = {101, 201, -102, -2};  Plane Surface(11) = {11};   // ring 1, A
Curve Loop(12) = {102, 202, -103, -3};  Plane Surface(12) = {12};   // ring 1, B
Curve Loop(21) = {111, 211, -112, -201}; Plane Surface(21) = {21};  // skirt, A
Curve Loop(22) = {112, 212, -113, -202}; Plane Surface(22) = {22};  // skirt, B
Curve Loop(31) = {121, 221, -122, -211}; Plane Surface(31) = {31};  // outer ring, A
Curve Loop(32) = {122, 222, -123, -212}; Plane Surface(32) = {32};  // outer ring, B

Transfinite Curve{1, 2, 3, 4, 201, 202, 211, 212, 221, 222} = NT + 1;
Transfinite Curve{101, 102, 103} = N1 + 1 Using Progression q1;
Transfinite Curve{111, 112, 113} = NS + 1;
Transfinite Curve{121, 122, 123} = N3 + 1 Using Progression q3;
Transfinite Surface{1} = {1, 2, 3, 4};
Transfinite Surface{11, 12, 21, 22, 31, 32};
Recombine Surface{1, 11, 12, 21, 22, 31, 32};

// Vertical layer heights (cumulative, normalised), as lists for Layers{}.
// Layer 1 (-12..-4): geometric, fine at the top (z = -4), last/first = 1/6.
g1 = 6^(1 / (NZ1 - 1)); tot = 0;
For i In {0 : NZ1 - 1}
  w1[i] = g1^(NZ1 - 1 - i); tot += w1[i];
EndFor
acc = 0;
For i In {0 : NZ1 - 1}
  acc += w1[i]; one1[i] = 1; h1[i] = acc / tot;
EndFor
// Layer 2 (-4..0): fine at both ends (the skirt tip and the lid), middle/end = 2.5.
m2 = (NZ2 - 1) / 2; g2 = 2.5^(1 / m2); tot = 0;
For i In {0 : NZ2 - 1}
  d = i; If (NZ2 - 1 - i < d) d = NZ2 - 1 - i; EndIf
  w2[i] = g2^d; tot += w2[i];
EndFor
acc = 0;
For i In {0 : NZ2 - 1}
  acc += w2[i]; one2[i] = 1; h2[i] = acc / tot;
EndFor

// Layer 1: all seven plan surfaces. e1[] holds, per surface (in the order below), 6
// entries: {top, volume, lateral 1..4} (laterals in the loop order above).
e1[] = Extrude {0, 0, Z_tip - Z_bot} {
  Surface{1, 11, 12, 21, 22, 31, 32}; Layers{one1[], h1[]}; Recombine; };
// Layer 2: the tops of layer 1.
e2[] = Extrude {0, 0, Z_top - Z_tip} {
  Surface{e1[0], e1[6], e1[12], e1[18], e1[24], e1[30], e1[36]}; Layers{one2[], h2[]}; Recombine; };
// Layer 3 (lid): the tops of layer 2 over r <= 3.9 (core, ring 1, skirt).
e3[] = Extrude {0, 0, Z_lid - Z_top} {
  Surface{e2[0], e2[6], e2[12], e2[18], e2[24]}; Layers{NZ3}; Recombine; };

// index of surface k (0 core, 1 ring1 A, 2 ring1 B, 3 skirt A, 4 skirt B, 5 outer A,
// 6 outer B) in e1/e2/e3: 6 k; top +0, volume +1, laterals +2..+5
Physical Volume("soil") = {e1[1], e1[7], e1[13], e1[19], e1[25], e1[31], e1[37],
                           e2[1], e2[7], e2[13], e2[31], e2[37]};
Physical Volume("caisson") = {e2[19], e2[25], e3[1], e3[7], e3[13], e3[19], e3[25]};

// interface parts (shared soil-caisson faces)
Physical Surface("outer_skirt") = {e2[18 + 3], e2[24 + 3]};   // skirt A/B, outer arc (r = 3.9)
Physical Surface("inner_skirt") = {e2[18 + 5], e2[24 + 5]};   // skirt A/B, inner arc (r = 3.8)
Physical Surface("skirt_tip") = {e1[18], e1[24]};             // skirt ring at z = -4
Physical Surface("lid") = {e2[0], e2[6], e2[12]};             // core + ring 1 at z = 0
// boundaries
Physical Surface("soil_top") = {e2[30], e2[36]};
Physical Surface("lid_top") = {e3[0], e3[6], e3[12], e3[18], e3[24]};
Physical Surface("lid_side") = {e3[18 + 3], e3[24 + 3]};
Physical Surface("bottom") = {1, 11, 12, 21, 22, 31, 32};
Physical Surface("outer") = {e1[30 + 3], e1[36 + 3], e2[30 + 3], e2[36 + 3]};
// y = 0: core lateral 1, sector A lateral 1 (k = 1, 3, 5), in every layer
Physical Surface("sym_y") = {e1[2], e1[8], e1[20], e1[32], e2[2], e2[8], e2[20], e2[32],
                             e3[2], e3[8], e3[20]};
// x = 0: core lateral 4, sector B lateral 3 (k = 2, 4, 6)
Physical Surface("sym_x") = {e1[5], e1[16], e1[28], e1[40], e2[5], e2[16], e2[28], e2[40],
                             e3[5], e3[16], e3[28]};
