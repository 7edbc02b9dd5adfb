// Strip footing on a weightless soil, plane strain, half model (x = 0 is the symmetry plane):
// soil 0 <= x <= W, -D <= y <= 0, footing of half-width b on the surface at 0 <= x <= b.
// Structured grid (42 x 24 cells at factor 1): N = 14 columns of equal width b/N under the footing, then columns growing by
// the ratio g to x = W; rows of height b/N at the surface growing by g to y = -D.
// Each grid cell is split into four triangles by its diagonals ("crossed triangles", the
// default, crossed = 1), or is one quadrilateral (crossed = 0). Crossed triangles have no
// volumetric locking in plane strain: in a fully plastic state of a Tresca soil (isochoric
// plastic flow) the four constant-strain triangles of a cell carry only three independent
// volume constraints (Nagtegaal, Parks and Rice 1974), so the collapse load is not
// overestimated; bilinear quadrilaterals with 2x2 Gauss points lock. crossed = 0 with
// triangles = 1: each grid cell split by one diagonal into two triangles (an ordinary mesh, on
// which linear triangles lock; quadratic ones do not, docs/verification.md).
// Physical curves: footing (0 <= x <= b, y = 0), surface (b <= x <= W, y = 0), left (x = 0),
// right (x = W), bottom (y = -D); physical surface: soil. Counts scale with -clscale.
b = 1.0; W = 10.0; D = 6.0;
If (!Exists(n)) n = 14; EndIf    // cells under the footing at factor 1
If (!Exists(g)) g = 1.1; EndIf   // growth ratio of the cells away from the footing
If (!Exists(crossed)) crossed = 1; EndIf
If (!Exists(triangles)) triangles = 0; EndIf  // with crossed = 0: triangles, not quadrilaterals
f = Mesh.CharacteristicLengthFactor;
N = Ceil(n / f - 1e-9);
h = b / N;

// Abscissae: N equal columns under the footing, then M growing ones, scaled to end at W.
xs[] = {};
For i In {0:N}
  xs[] += i * h;
EndFor
M = Ceil(Log(1 + (W - b) * (g - 1) / h) / Log(g) - 1e-9);
s = (W - b) / (h * (g^M - 1) / (g - 1));
For k In {1:M}
  xs[] += b + s * h * (g^k - 1) / (g - 1);
EndFor
NX = N + M;
// Ordinates from the bottom up; depths below the surface grow by g from h at the top.
L = Ceil(Log(1 + D * (g - 1) / h) / Log(g) - 1e-9);
t = D / (h * (g^L - 1) / (g - 1));
ys[] = {};
For j In {0:L}
  k = L - j;
  ys[] += -t * h * (g^k - 1) / (g - 1);
EndFor
NY = L;
Printf("strip_footing_2d: %g x %g cells (%g under the footing), crossed %g", NX, NY, N, crossed);

pt[] = {};
For j In {0:NY}
  For i In {0:NX}
    p = newp; Point(p) = {xs[i], ys[j], 0}; pt[] += p;
  EndFor
EndFor
hl[] = {};   // horizontal lines, index i + j * NX
For j In {0:NY}
  For i In {0:NX - 1}
    l = newl; Line(l) = {pt[i + j * (NX + 1)], pt[i + 1 + j * (NX + 1)]}; hl[] += l;
  EndFor
EndFor
vl[] = {};   // vertical lines, index i + j * (NX + 1)
For j In {0:NY - 1}
  For i In {0:NX}
    l = newl; Line(l) = {pt[i + j * (NX + 1)], pt[i + (j + 1) * (NX + 1)]}; vl[] += l;
  EndFor
EndFor
Transfinite Curve{hl[], vl[]} = 2;

cells[] = {};
For j In {0:NY - 1}
  For i In {0:NX - 1}
    bottom = hl[i + j * NX]; top = hl[i + (j + 1) * NX];
    left = vl[i + j * (NX + 1)]; right = vl[i + 1 + j * (NX + 1)];
    If (crossed)
      c = newp; Point(c) = {0.5 * (xs[i] + xs[i + 1]), 0.5 * (ys[j] + ys[j + 1]), 0};
      d00 = newl; Line(d00) = {pt[i + j * (NX + 1)], c};
      d10 = newl; Line(d10) = {pt[i + 1 + j * (NX + 1)], c};
      d11 = newl; Line(d11) = {pt[i + 1 + (j + 1) * (NX + 1)], c};
      d01 = newl; Line(d01) = {pt[i + (j + 1) * (NX + 1)], c};
      Transfinite Curve{d00, d10, d11, d01} = 2;
      loop = newll; Curve Loop(loop) = {bottom, d10, -d00};
      s1 = news; Plane Surface(s1) = {loop};
      loop = newll; Curve Loop(loop) = {right, d11, -d10};
      s2 = news; Plane Surface(s2) = {loop};
      loop = newll; Curve Loop(loop) = {-top, d01, -d11};
      s3 = news; Plane Surface(s3) = {loop};
      loop = newll; Curve Loop(loop) = {-left, d00, -d01};
      s4 = news; Plane Surface(s4) = {loop};
      Transfinite Surface{s1, s2, s3, s4};
      cells[] += {s1, s2, s3, s4};
    Else
      loop = newll; Curve Loop(loop) = {bottom, right, -top, -left};
      s1 = news; Plane Surface(s1) = {loop};
      Transfinite Surface{s1};
      If (!triangles) Recombine Surface{s1}; EndIf
      cells[] += s1;
    EndIf
  EndFor
EndFor

footing[] = {}; surface[] = {}; left[] = {}; right[] = {}; base[] = {};
For i In {0:NX - 1}
  If (i < N)
    footing[] += hl[i + NY * NX];
  Else
    surface[] += hl[i + NY * NX];
  EndIf
  base[] += hl[i];
EndFor
For j In {0:NY - 1}
  left[] += vl[j * (NX + 1)];
  right[] += vl[NX + j * (NX + 1)];
EndFor
Physical Curve("footing") = footing[];
Physical Curve("surface") = surface[];
Physical Curve("left") = left[];
Physical Curve("right") = right[];
Physical Curve("bottom") = base[];
Physical Surface("soil") = cells[];
