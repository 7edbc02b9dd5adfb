# Engineering outputs (docs/outputs.md): stresses and strains per cell against closed forms
# (the geostatic column, Terzaghi consolidated), 2 ranks = 1 rank cell for cell, and meshio
# reading every XDMF file of a 2D, an axisymmetric and a 3D scene with interfaces (compared
# with h5py), units, NaN pressure outside porous regions, both interface faces' displacements.
# Driver tests/outputs/outputs.py (its docstring justifies the tolerances). A few seconds each;
# the meshio case skips (exit 77) when python3-meshio is missing. Included by tests/CMakeLists.txt.
poroseam_scene_test(outputs.stress_geostatic "outputs" outputs/outputs.py --case geostatic)
poroseam_scene_test(outputs.stress_terzaghi "outputs" outputs/outputs.py --case terzaghi)
poroseam_scene_test(outputs.ranks "outputs;mpi" outputs/outputs.py --case ranks)
poroseam_scene_test(outputs.meshio "outputs" outputs/outputs.py --case meshio)
# PETSc's -ts_monitor_solution_vtk writes the displacements and pressures of fields.h5 (2 ranks).
poroseam_scene_test(outputs.petsc_vtk "outputs;mpi" outputs/outputs.py --case petsc_vtk)
set_tests_properties(outputs.meshio outputs.petsc_vtk PROPERTIES SKIP_RETURN_CODE 77)
# The time-series plots: nothing empty for a drained run, the interface flow columns drawn
# (tests/outputs/plots.py; scripts/plot_timeseries).
foreach(case drained interface_flow)
  poroseam_scene_test(outputs.plots_${case} "outputs" outputs/plots.py --case ${case})
endforeach()
# Recovered (continuous) stresses at the nodes against a column under its own weight, orders 1
# and 2, 1 and 2 ranks (tests/outputs/recovered_stress.py). A few seconds.
poroseam_scene_test(outputs.recovered_stress "outputs;order" outputs/recovered_stress.py)
