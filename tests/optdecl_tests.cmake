# One declaration per option (include/poroseam/options.def, docs/options.md): the docs describe
# every declared option, no reader in src/ names one of poroseam's options by a literal (nor
# an undeclared one), and -help prints each declaration's help and page. Under a second each.
foreach(case docs readers help)
  poroseam_scene_test(optdecl.registry_${case} "input;options" optdecl/registry.py --case ${case})
endforeach()
