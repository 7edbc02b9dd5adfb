// meshes/thick_cylinder_plane.geo with triangles (each transfinite quadrangle cut in two):
// the quarter annulus 1 <= r <= 2 m, curved edges on r = a and r = b at -mesh_geometry_order 2.
// Same physical groups: inner, outer, sym_x, sym_y; surface ring.
triangles = 1;
Include "thick_cylinder_plane.geo";
