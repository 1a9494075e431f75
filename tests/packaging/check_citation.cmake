# cmake -DSOURCE_DIR=... -DVERSION=... -P check_citation.cmake: CITATION.cff names the project's
# VERSION (CMakeLists.txt, the one source of the version) and the licence of LICENSE, GPL-3.0-or-later.
file(READ ${SOURCE_DIR}/CITATION.cff citation)
foreach(line "cff-version: 1.2.0" "title: stcontact" "version: \"${VERSION}\"" "license: GPL-3.0-or-later")
  string(FIND "${citation}" "\n${line}\n" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "CITATION.cff: no line '${line}' (the version must be CMakeLists.txt's ${VERSION})")
  endif()
endforeach()
file(STRINGS ${SOURCE_DIR}/LICENSE license_head LIMIT_COUNT 2)
if(NOT license_head MATCHES "GNU GENERAL PUBLIC LICENSE;.*Version 3, 29 June 2007")
  message(FATAL_ERROR "LICENSE is not the GNU GPL version 3 text: ${license_head}")
endif()
message(STATUS "CITATION.cff: stcontact ${VERSION}, GPL-3.0-or-later; LICENSE: GPL version 3")
