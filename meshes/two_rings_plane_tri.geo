// meshes/two_rings_plane.geo with triangles (each quadrilateral of the transfinite mesh cut in
// two). Same physical groups: inner, outer, joint, sym_x, sym_y; surfaces inner_ring, outer_ring.
triangles = 1;
Include "two_rings_plane.geo";
