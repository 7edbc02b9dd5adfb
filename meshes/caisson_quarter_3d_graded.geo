// The 3D quarter caisson (caisson_quarter_3d.geo) with the section (r, z) divided like the
// axisymmetric mesh at mesh factor 1.5 and few divisions round the axis: the uplift is
// axisymmetric, so the error lives in the section (the slip front along the skirt, the skirt
// tip), not round the circle, which curved order-2 cells (-mesh_geometry_order 2) follow.
// For the 3D caisson's price tag at 0.1 % (docs/studies.md, "The 3D quarter caisson at
// 0.1 %"); use with -displacement_order 2 -mesh_geometry_order 2.
nt = 3;    // divisions per 45-degree sector (default mesh: 8; 2 folds the curved cells next to the
           // skirt: a 22.5-degree arc bulges more than the thin ring cells there are thick)
n1 = 11;   // core edge .. r = 3.8 (6)
ns = 2;    // through the skirt (1)
n3 = 20;   // 3.9 .. 24 (12)
nz1 = 11;  // -12 .. -4 (8)
nz2 = 19;  // -4 .. 0 (14)
nz3 = 2;   // lid (2)
Include "caisson_quarter_3d.geo";
