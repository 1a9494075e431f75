# Run at every build (cmake -P, target stc_git_commit in cli/CMakeLists.txt): writes OUT with
#   #define STC_GIT_COMMIT "<12-digit commit of SOURCE>[+changes]"   ("unknown" without git)
# "+changes" when tracked files differ from the commit. OUT is rewritten only when the text changes,
# so a report always names the commit the program was built from, and nothing rebuilds for nothing.
execute_process(COMMAND git rev-parse --short=12 HEAD WORKING_DIRECTORY ${SOURCE}
                OUTPUT_VARIABLE commit OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(commit)
  execute_process(COMMAND git status --porcelain --untracked-files=no WORKING_DIRECTORY ${SOURCE}
                  OUTPUT_VARIABLE changes OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
  if(changes)
    string(APPEND commit "+changes")
  endif()
else()
  set(commit unknown)
endif()
set(text "#pragma once\n// Written at build time by cmake/StcGitCommit.cmake.\n#define STC_GIT_COMMIT \"${commit}\"\n")
set(old "")
if(EXISTS ${OUT})
  file(READ ${OUT} old)
endif()
if(NOT old STREQUAL text)
  file(WRITE ${OUT} "${text}")
endif()
