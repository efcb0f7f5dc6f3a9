# `cmake --install build --prefix P`: the programs in P/bin, the libraries in P/lib, the public
# headers in P/include/baize/ with the source tree's layout, the assets in P/share/baize/ and the
# package configuration in P/lib/cmake/Baize/, for find_package(Baize 0.2 CONFIG) (docs/install.md).
include(CMakePackageConfigHelpers)

set(baize_exported baize_physics baize_engine)
set(baize_header_folders physics engine/sim engine/models engine/io engine/play engine/baselines)
if(BAIZE_WITH_BOX2D)
  list(APPEND baize_exported baize_box2d_pool)
endif()
if(BAIZE_WITH_RENDER)
  list(APPEND baize_exported baize_render_core baize_render baize_charts)
  list(APPEND baize_header_folders render)
endif()

set(BAIZE_CONFIG_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Baize)
install(TARGETS ${baize_exported} EXPORT BaizeTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT BaizeTargets NAMESPACE Baize:: DESTINATION ${BAIZE_CONFIG_DIR})

foreach(folder ${baize_header_folders})
  set(excluded)
  if(folder STREQUAL "engine/baselines" AND NOT BAIZE_WITH_BOX2D)
    set(excluded PATTERN "box2d_pool.h" EXCLUDE)
  endif()
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder}/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/baize/${folder}
          FILES_MATCHING PATTERN "*.h" ${excluded})
endforeach()

install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/baize)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/BaizeConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/BaizeConfig.cmake
                              INSTALL_DESTINATION ${BAIZE_CONFIG_DIR}
                              PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/BaizeConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/BaizeConfig.cmake ${PROJECT_BINARY_DIR}/BaizeConfigVersion.cmake
        DESTINATION ${BAIZE_CONFIG_DIR})
