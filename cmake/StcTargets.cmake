# stc_add_library(NAME folder DEPS ...): one library per top-level folder, sources globbed from it
# (the folder *is* the component), includes relative to the repository root ("latin/...").
# EXCLUDE names subfolders that are other targets: neither compiled nor installed with this one.
function(stc_add_library name)
  cmake_parse_arguments(ARG "" "" "DEPS;EXCLUDE" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS RELATIVE "${CMAKE_CURRENT_SOURCE_DIR}"
       "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  set(excluded_headers)
  foreach(subfolder IN LISTS ARG_EXCLUDE)
    list(FILTER sources EXCLUDE REGEX "^${subfolder}/")
    list(APPEND excluded_headers PATTERN "${subfolder}" EXCLUDE)
  endforeach()
  list(TRANSFORM sources PREPEND "${CMAKE_CURRENT_SOURCE_DIR}/")
  set(target stcontact_${name})
  if(sources)
    add_library(${target} ${sources})
    set(scope PUBLIC)
  else()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif()
  add_library(stcontact::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME stcontact_${name})
  target_include_directories(${target} ${scope}
    $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/stcontact>)
  target_compile_features(${target} ${scope} cxx_std_20)
  target_link_libraries(${target} ${scope} ${ARG_DEPS})
  if(sources)
    target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic
                           $<$<BOOL:${STC_WARNINGS_AS_ERRORS}>:-Werror>)
  endif()
  # Headers keep their path below the repository root: include/stcontact/<folder>/...
  file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
  install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/"
          DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/stcontact/${folder}"
          FILES_MATCHING PATTERN "*.hpp" ${excluded_headers})
  set_property(GLOBAL APPEND PROPERTY STC_EXPORTED_TARGETS ${target})
endfunction()
