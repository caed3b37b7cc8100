# `cmake --install build --prefix P` installs headers, static libraries and LintelConfig.cmake so
# that a game client can `find_package(Lintel [COMPONENTS ...])` and link Lintel::visibility /
# Lintel::scene / Lintel::gpu_cull / Lintel::render. One export set per component, so that
# `find_package(Lintel COMPONENTS visibility)` loads (and needs) nothing but GLM; a core-only build
# (LINTEL_CORE_ONLY) installs that component alone.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(LINTEL_PACKAGE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Lintel)

function(lintel_install_component component target)
  install(TARGETS ${target} EXPORT Lintel_${component}
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
          LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT Lintel_${component} NAMESPACE Lintel:: FILE Lintel_${component}Targets.cmake
          DESTINATION ${LINTEL_PACKAGE_DIR})
endfunction()

lintel_install_component(visibility lintel_visibility)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/visibility/include/lintel
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/generated/lintel/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lintel)

if(NOT LINTEL_CORE_ONLY)
  lintel_install_component(scene lintel_scene)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/scene/include/lintel
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
  lintel_install_component(gpu_cull lintel_gpu_cull)  # gpu_cull/ and render/ install their headers
  lintel_install_component(render lintel_render)
  install(TARGETS lintel RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/LintelConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/LintelConfig.cmake
                              INSTALL_DESTINATION ${LINTEL_PACKAGE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/LintelConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/LintelConfig.cmake ${PROJECT_BINARY_DIR}/LintelConfigVersion.cmake
        DESTINATION ${LINTEL_PACKAGE_DIR})
