// Suction caisson in an elastic soil layer, axisymmetric half-section (docs/caisson.md;
// paper section 3) in the (x = r, y = z) plane, y up, soil surface y = 0.
//   soil:    0 <= r <= 24 m, -12 <= z <= 0 (the soil plug inside the skirt is soil)
//   caisson: skirt 3.8 <= r <= 3.9 m, -4 <= z <= 0, and lid r <= 3.9 m, 0 <= z <= 0.4
// All quadrilaterals (built-in kernel, structured): the three bottom segments (r = 0..3.8,
// 3.8..3.9, 3.9..24) are extruded upwards in three layers (-12..-4, -4..0, 0..0.4; the last
// over r <= 3.9 only), so bodies that touch share their edges, and the only edges shared by
// soil and caisson are the four interface parts below. Refinement: radially towards the skirt
// from both sides, vertically towards the skirt tip (z = -4) and the lid (z = 0). Every count
// scales with -clscale (-mesh_size_factor): 0.5 doubles the divisions in each direction.
// Same names as meshes/caisson_quarter_3d.geo, with the axis instead of the symmetry planes.
//
// Physical surfaces: soil, caisson
// Physical curves: interface parts (soil = side 1):
//   outer_skirt (r = 3.9, -4 < z < 0), skirt_tip (z = -4, 3.8 < r < 3.9),
//   inner_skirt (r = 3.8, -4 < z < 0), lid (z = 0, r < 3.8: lid underside on the soil plug)
// boundaries: axis (r = 0, soil and lid), soil_top (z = 0, r > 3.9), lid_top (z = 0.4),
//   lid_side (r = 3.9, 0 < z < 0.4), outer (r = 24), bottom (z = -12)
//
// Default (factor 1): 16 + 2 + 30 radial, 16 + 28 + 3 vertical divisions: about 2,300 nodes
// after the interface split (about 4,700 displacement unknowns).

R_in = 3.8; R_out = 3.9; R_soil = 24;
Z_bot = -12; Z_tip = -4; Z_top = 0; Z_lid = 0.4;

If (!Exists(nr1)) nr1 = 16; EndIf  // 0 .. 3.8
If (!Exists(nrs)) nrs = 2; EndIf   // through the skirt, 3.8 .. 3.9
If (!Exists(nr3)) nr3 = 30; EndIf  // 3.9 .. 24
If (!Exists(nz1)) nz1 = 16; EndIf  // -12 .. -4
If (!Exists(nz2)) nz2 = 28; EndIf  // -4 .. 0
If (!Exists(nz3)) nz3 = 3; EndIf   // lid, 0 .. 0.4
f = Mesh.CharacteristicLengthFactor;
NR1 = Ceil(nr1 / f - 1e-9); NRS = Ceil(nrs / f - 1e-9); NR3 = Ceil(nr3 / f - 1e-9);
NZ1 = Ceil(nz1 / f - 1e-9); NZ2 = Ceil(nz2 / f - 1e-9); NZ3 = Ceil(nz3 / f - 1e-9);
// geometric ratios per element (the ratio over a whole segment stays the same when the counts
// scale): 0..3.8 shrinks towards the skirt (last/first = 1/4), 3.9..24 grows (last/first = 20)
q1 = 4^(-1 / (NR1 - 1));
q3 = 20^(1 / (NR3 - 1));

Point(1) = {0, Z_bot, 0}; Point(2) = {R_in, Z_bot, 0};
Point(3) = {R_out, Z_bot, 0}; Point(4) = {R_soil, Z_bot, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};
Transfinite Curve{1} = NR1 + 1 Using Progression q1;
Transfinite Curve{2} = NRS + 1;
Transfinite Curve{3} = NR3 + 1 Using Progression q3;

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

// Extrude returns per curve 4 entries: {top, surface, side at the end point (larger r), side
// at the start point (smaller r)}; curve k (0: 0..3.8, 1: skirt, 2: 3.9..24) at 4 k.
e1[] = Extrude {0, Z_tip - Z_bot, 0} { Curve{1, 2, 3}; Layers{one1[], h1[]}; Recombine; };
e2[] = Extrude {0, Z_top - Z_tip, 0} { Curve{e1[0], e1[4], e1[8]}; Layers{one2[], h2[]}; Recombine; };
e3[] = Extrude {0, Z_lid - Z_top, 0} { Curve{e2[0], e2[4]}; Layers{NZ3}; Recombine; };

Physical Surface("soil") = {e1[1], e1[5], e1[9], e2[1], e2[9]};
Physical Surface("caisson") = {e2[5], e3[1], e3[5]};
// interface parts (shared soil-caisson edges)
Physical Curve("outer_skirt") = {e2[6]};   // r = 3.9, -4..0
Physical Curve("skirt_tip") = {e1[4]};     // z = -4, 3.8..3.9
Physical Curve("inner_skirt") = {e2[2]};   // r = 3.8, -4..0
Physical Curve("lid") = {e2[0]};           // z = 0, 0..3.8
// boundaries
Physical Curve("axis") = {e1[3], e2[3], e3[3]};
Physical Curve("outer") = {e1[10], e2[10]};
Physical Curve("bottom") = {1, 2, 3};
Physical Curve("soil_top") = {e2[8]};
Physical Curve("lid_top") = {e3[0], e3[4]};
Physical Curve("lid_side") = {e3[6]};
