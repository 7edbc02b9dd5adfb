// meshes/block_on_base_2d.geo with triangles.
triangles = 1;
Include "block_on_base_2d.geo";
