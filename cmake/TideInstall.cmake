# tide::tide, the one target an embedding project links, and the installed CMake package
# TideSPH (headers, static libraries, TideSPHTargets, TideSPHConfig[Version].cmake).
#
# A new library is one entry in TIDE_LIBRARIES: the folder <name>/ builds target tide_<name>
# (alias tide::<name>, EXPORT_NAME <name>) with its public headers in <name>/include/ and,
# if it generates any, in ${PROJECT_BINARY_DIR}/<name>/include/. A new external package that
# its installed target needs (also a PRIVATE one: static libraries carry their link
# dependencies) is one entry in TIDE_PACKAGE_DEPENDENCIES, as find_dependency() arguments.
set(TIDE_LIBRARIES core neighbor solvers io surface render)
set(TIDE_PACKAGE_DEPENDENCIES "Eigen3 3.3 NO_MODULE" "TBB" "nlohmann_json 3.10" "HDF5 COMPONENTS C" "PNG")

include(CMakePackageConfigHelpers)

add_library(tide INTERFACE)
add_library(tide::tide ALIAS tide)
set_target_properties(tide PROPERTIES EXPORT_NAME tide)

set(tide_library_targets "")
foreach(library IN LISTS TIDE_LIBRARIES)
  target_link_libraries(tide INTERFACE tide::${library})
  list(APPEND tide_library_targets tide_${library})
  foreach(header_root IN ITEMS "${PROJECT_SOURCE_DIR}/${library}/include" "${PROJECT_BINARY_DIR}/${library}/include")
    if(IS_DIRECTORY "${header_root}")
      install(DIRECTORY "${header_root}/" DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
              FILES_MATCHING PATTERN "*.hpp")
    endif()
  endforeach()
endforeach()

set(tide_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/TideSPH)

install(TARGETS tide ${tide_library_targets}
  EXPORT TideSPHTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT TideSPHTargets NAMESPACE tide:: DESTINATION ${tide_package_dir})

set(TIDE_FIND_DEPENDENCIES "")
foreach(dependency IN LISTS TIDE_PACKAGE_DEPENDENCIES)
  string(APPEND TIDE_FIND_DEPENDENCIES "find_dependency(${dependency})\n")
endforeach()
configure_package_config_file(cmake/TideSPHConfig.cmake.in
  ${PROJECT_BINARY_DIR}/TideSPHConfig.cmake
  INSTALL_DESTINATION ${tide_package_dir})
# 0.x releases may change the API between minor versions.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/TideSPHConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/TideSPHConfig.cmake ${PROJECT_BINARY_DIR}/TideSPHConfigVersion.cmake
  DESTINATION ${tide_package_dir})
