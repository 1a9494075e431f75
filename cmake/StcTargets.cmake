# stc_add_library(NAME folder DEPS ...): one library per top-level folder, sources globbed from it
# (the folder *is* the component), includes relative to the repository root ("latin/...").
function(stc_add_library name)
  cmake_parse_arguments(ARG "" "" "DEPS;EXCLUDE" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS "${CMAKE_CURRENT_SOURCE_DIR}/*.cpp")
  # EXCLUDE patterns match the path below the folder, from its "/" ("/cli/"), never the folder's own
  # location (a checkout below a folder named like an excluded one keeps its sources).
  set(kept "")
  foreach(source IN LISTS sources)
    file(RELATIVE_PATH relative "${CMAKE_CURRENT_SOURCE_DIR}" "${source}")
    set(excluded FALSE)
    foreach(pattern IN LISTS ARG_EXCLUDE)
      if("/${relative}" MATCHES "${pattern}")
        set(excluded TRUE)
      endif()
    endforeach()
    if(NOT excluded)
      list(APPEND kept "${source}")
    endif()
  endforeach()
  set(sources ${kept})
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
          FILES_MATCHING PATTERN "*.hpp" PATTERN "cli" EXCLUDE PATTERN "python" EXCLUDE)
  set_property(GLOBAL APPEND PROPERTY STC_EXPORTED_TARGETS ${target})
endfunction()
