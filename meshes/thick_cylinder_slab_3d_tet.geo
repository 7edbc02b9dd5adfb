// meshes/thick_cylinder_slab_3d.geo with tetrahedra (each extruded prism cut into three tets).
// Same physical groups: inner, outer, sym_x, sym_y, bottom, top; volume ring.
tets = 1;
Include "thick_cylinder_slab_3d.geo";
