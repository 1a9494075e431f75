# One include root, stcontact/<module>/..., in the build tree as in an install (like ceres/...):
#   the core's modules are the folders of src/ (stcontact/mesh/ is src/mesh/), the others the
#   folders of the repository root (stcontact/latin/ is latin/).
# The build tree's root, ${PROJECT_BINARY_DIR}/include, holds one link per module to its folder
# (made at configure time) and the generated stcontact/version.hpp; an install copies the headers,
# without the detail/ folders, to include/stcontact/<module>/.
set(STC_CORE_MODULES core options mesh fem contact scene problem operators spacetime linalg io solver incremental)
set(STC_ROOT_MODULES latin pgd fas strategies studies cli python)
set(STC_INCLUDE_ROOT ${PROJECT_BINARY_DIR}/include)

function(stc_stage_include_root)
  file(MAKE_DIRECTORY ${STC_INCLUDE_ROOT}/stcontact)
  foreach(module IN LISTS STC_CORE_MODULES STC_ROOT_MODULES)
    if(module IN_LIST STC_CORE_MODULES)
      set(folder ${PROJECT_SOURCE_DIR}/src/${module})
    else()
      set(folder ${PROJECT_SOURCE_DIR}/${module})
    endif()
    if(EXISTS ${folder})
      file(CREATE_LINK ${folder} ${STC_INCLUDE_ROOT}/stcontact/${module} SYMBOLIC)
    endif()
  endforeach()
  configure_file(${PROJECT_SOURCE_DIR}/cmake/version.hpp.in ${STC_INCLUDE_ROOT}/stcontact/version.hpp @ONLY)
  install(FILES ${STC_INCLUDE_ROOT}/stcontact/version.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/stcontact)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/build_config.hpp.in ${STC_INCLUDE_ROOT}/stcontact/build_config.hpp)
  install(FILES ${STC_INCLUDE_ROOT}/stcontact/build_config.hpp DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/stcontact)
endfunction()

# stc_add_library(NAME DEPS ... [EXCLUDE subfolder...]): one library per folder (src/ for the core,
# a root folder for the others), sources globbed from it (the folder *is* the component).
# EXCLUDE names subfolders that are not part of it (programs built on top): neither compiled nor
# installed with it.
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
  add_library(${target} ${sources})
  add_library(stcontact::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name} OUTPUT_NAME stcontact_${name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${STC_INCLUDE_ROOT}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_link_libraries(${target} PUBLIC ${ARG_DEPS})
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic
                         $<$<BOOL:${STC_WARNINGS_AS_ERRORS}>:-Werror>)
  stc_precompile_headers(${target})
  # Headers below include/stcontact/<module>/: src/<module>/ for the core, <module>/ for the others.
  file(RELATIVE_PATH folder "${PROJECT_SOURCE_DIR}" "${CMAKE_CURRENT_SOURCE_DIR}")
  string(REGEX REPLACE "^src/?" "" module_path "${folder}")
  install(DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}/"
          DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/stcontact/${module_path}"
          FILES_MATCHING PATTERN "*.hpp" PATTERN "detail" EXCLUDE ${excluded_headers})
  set_property(GLOBAL APPEND PROPERTY STC_EXPORTED_TARGETS ${target})
endfunction()
