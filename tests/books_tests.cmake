# Honest books (issue 23, items 8 and 9): boundary flows and forces add up to the whole (an
# impervious boundary at a drained corner reports 0, the water balance closes, horizontal
# reactions without horizontal load sum to 0), the run lands on -ts_max_time exactly, the final
# state is in fields.h5 after cut-backs, and the same command writes the same files (order
# independent of the ranks and the partition). Driver tests/outputs/books.py (its docstring
# gives every check and tolerance). A few seconds each. Included by tests/CMakeLists.txt.
poroseam_scene_test(outputs.books_water_balance "outputs;faults;conservation;mpi"
                    outputs/books.py --case water_balance)
poroseam_scene_test(outputs.books_reactions "outputs;faults;mpi" outputs/books.py --case reactions)
poroseam_scene_test(outputs.books_final_time "outputs;faults" outputs/books.py --case final_time)
poroseam_scene_test(outputs.books_final_fields "outputs;faults;cutback"
                    outputs/books.py --case final_fields)
poroseam_scene_test(outputs.books_same_files "outputs;faults;mpi" outputs/books.py --case same_files)
