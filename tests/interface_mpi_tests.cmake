# Interfaces on several ranks and buried (tip) interfaces; included by tests/CMakeLists.txt.
# Drivers: tests/interface_mpi/interface_mpi_match.py (1 rank vs 2 ranks, by partitioner),
# tests/interface_mpi/buried_crack.py (unknown count of a crack that ends inside the mesh).

# 1 vs 2 ranks with a partition that cuts through the interface (simple: checked to separate
# cohesive cells from a bulk neighbour) and with METIS (checked to separate none): time
# series to 1e-8. Shear scenes options/block_shear_2d/3d (3D also on tetrahedra) and the
# buried cracks.
foreach(case shear_2d shear_3d shear_3d_tet buried_crack_2d buried_crack_3d)
  foreach(partitioner simple metis)
    poroseam_scene_test(interface.mpi_${case}_${partitioner} "interface;mpi"
                        interface_mpi/interface_mpi_match.py --case ${case} --partitioner ${partitioner})
  endforeach()
endforeach()

# A crack ending inside the mesh: the split adds dim x (crack vertices off the tip) unknowns.
foreach(dim 2 3)
  poroseam_scene_test(interface.buried_crack_${dim}d "interface" interface_mpi/buried_crack.py --dim ${dim})
endforeach()
