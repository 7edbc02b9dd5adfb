// meshes/block_on_base_3d.geo with tetrahedra (each extruded prism cut into three tets).
// Same physical groups: bottom, top, base_*/block_* sides, contact; volumes base, block.
tets = 1;
Include "block_on_base_3d.geo";
