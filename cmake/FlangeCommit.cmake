# SPDX-License-Identifier: MIT
# Writes OUTPUT (flange_commit.h: #define FLANGE_COMMIT "...") with the git commit SOURCE_DIR is
# at: 12 hex digits, "-dirty" appended when tracked files differ from it, "unknown (not built
# from a git checkout)" when SOURCE_DIR is not the top of a git work tree or git is missing. The
# file is rewritten only when its text changes, so a build at the same commit compiles nothing.
# cli/CMakeLists.txt runs it at every build:
#   cmake -DSOURCE_DIR=<source tree> -DOUTPUT=<header> -P cmake/FlangeCommit.cmake
set(commit "unknown (not built from a git checkout)")
find_program(FLANGE_GIT git)
if(FLANGE_GIT)
  execute_process(COMMAND ${FLANGE_GIT} -C ${SOURCE_DIR} rev-parse --show-toplevel
                  RESULT_VARIABLE status OUTPUT_VARIABLE top ERROR_QUIET
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  # A source tree unpacked inside another repository's folder is not that repository's commit.
  if(status EQUAL 0)
    file(REAL_PATH "${top}" top)
    file(REAL_PATH "${SOURCE_DIR}" source)
  endif()
  if(status EQUAL 0 AND top STREQUAL source)
    execute_process(COMMAND ${FLANGE_GIT} -C ${SOURCE_DIR} rev-parse --short=12 HEAD
                    RESULT_VARIABLE status OUTPUT_VARIABLE hash ERROR_QUIET
                    OUTPUT_STRIP_TRAILING_WHITESPACE)
    # --no-optional-locks: never take the index lock a commit running beside the build needs.
    execute_process(COMMAND ${FLANGE_GIT} --no-optional-locks -C ${SOURCE_DIR} status
                            --porcelain --untracked-files=no
                    RESULT_VARIABLE dirty_status OUTPUT_VARIABLE changes ERROR_QUIET)
    if(status EQUAL 0 AND dirty_status EQUAL 0)
      set(commit "${hash}")
      if(NOT changes STREQUAL "")
        string(APPEND commit "-dirty")
      endif()
    endif()
  endif()
endif()
file(CONFIGURE OUTPUT "${OUTPUT}"
     CONTENT "// Written by cmake/FlangeCommit.cmake at build time; do not edit.\n#define FLANGE_COMMIT \"${commit}\"\n"
     @ONLY)
