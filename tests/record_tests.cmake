# run.yaml, the record of a run (docs/scenes.md, "Run record"): read back and checked against
# what the run printed and wrote, then the scene re-run from the recorded options alone (same
# time series); a run stopped by -ts_max_steps records 'step limit'. Driver
# tests/record/record.py. Included by tests/CMakeLists.txt. A few seconds each.
poroseam_scene_test(record.rerun "record;input" record/record.py --case rerun)
poroseam_scene_test(record.step_limit "record;input" record/record.py --case step_limit)
