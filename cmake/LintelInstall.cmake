# `cmake --install build --prefix P` installs headers, static libraries and LintelConfig.cmake so
# that a game client can `find_package(Lintel)` and link Lintel::visibility / Lintel::scene / Lintel::gpu_cull / Lintel::render.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS lintel_visibility lintel_scene lintel_gpu_cull lintel_render EXPORT LintelTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/visibility/include/lintel ${PROJECT_SOURCE_DIR}/scene/include/lintel
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/generated/lintel/version.h DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/lintel)
install(TARGETS lintel RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT LintelTargets NAMESPACE Lintel:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Lintel)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/LintelConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/LintelConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Lintel)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/LintelConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/LintelConfig.cmake ${PROJECT_BINARY_DIR}/LintelConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/Lintel)
