# Writes OUTPUT, a C++ header with poroseam's version and git commit, at every build (the
# poroseam_version target) but touches it only when the text changes, so that a build without
# a new commit recompiles nothing. Outside a git checkout the commit is "unknown".
# usage: cmake -DSOURCE_DIR=... -DOUTPUT=... -DVERSION=... -P version.cmake
set(commit "unknown")
find_package(Git QUIET)
if(GIT_FOUND)
  execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} rev-parse HEAD
                  OUTPUT_VARIABLE head RESULT_VARIABLE failed
                  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(NOT failed AND head)
    set(commit "${head}")
    # Uncommitted changes to tracked files: the commit alone does not say what was built.
    execute_process(COMMAND ${GIT_EXECUTABLE} -C ${SOURCE_DIR} status --porcelain
                            --untracked-files=no
                    OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
    if(changes)
      set(commit "${commit}-dirty")
    endif()
  endif()
endif()
file(WRITE ${OUTPUT}.tmp "#define POROSEAM_VERSION \"${VERSION}\"\n#define POROSEAM_GIT_COMMIT \"${commit}\"\n")
configure_file(${OUTPUT}.tmp ${OUTPUT} COPYONLY)
file(REMOVE ${OUTPUT}.tmp)
