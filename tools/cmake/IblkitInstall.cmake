# The installed kit: the iblkit program (its launcher in bin/, the program itself and its built-in
# kernels in libexec/iblkit/),
# the shared library iblkit (the public API of include/iblkit over the static libraries of runtime/),
# the CMake package (iblkit::iblkit, iblkit::cli, iblkit_add_shader), a pkg-config file, the kit's
# HLSL, and `cpack -G DEB`.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(IBLKIT_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/iblkit)
set(IBLKIT_INSTALL_HLSLDIR ${CMAKE_INSTALL_DATADIR}/iblkit/hlsl)

# One shared library a user links. The internal libraries' symbols (and glslang's, SPIRV-Tools',
# SPIRV-Cross's) stay hidden inside it, so a user's own copies never clash with them.
add_library(iblkit_shared SHARED)
target_link_libraries(iblkit_shared PRIVATE iblkit_api)
target_link_options(iblkit_shared PRIVATE -Wl,--exclude-libs,ALL -Wl,--no-undefined)
target_include_directories(iblkit_shared PUBLIC
  $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
target_compile_features(iblkit_shared INTERFACE cxx_std_20)
set_target_properties(iblkit_shared PROPERTIES
  OUTPUT_NAME iblkit EXPORT_NAME iblkit VERSION ${PROJECT_VERSION} SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
add_library(iblkit::iblkit ALIAS iblkit_shared)
set_target_properties(iblkit PROPERTIES EXPORT_NAME cli)

install(TARGETS iblkit iblkit_shared EXPORT iblkitTargets
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The program the launcher `iblkit` starts, where tools/iblkit/launcher.c looks for it.
install(TARGETS iblkit_program RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/iblkit)
# Its built-in kernels, beside it (runtime/kernels/built_in_kernels.hpp).
install(DIRECTORY $<TARGET_FILE_DIR:iblkit_program>/kernels DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/iblkit)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/iblkit DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/hlsl/ DESTINATION ${IBLKIT_INSTALL_HLSLDIR})
install(EXPORT iblkitTargets NAMESPACE iblkit:: DESTINATION ${IBLKIT_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/iblkitConfig.cmake.in
  ${PROJECT_BINARY_DIR}/iblkitConfig.cmake
  INSTALL_DESTINATION ${IBLKIT_INSTALL_CMAKEDIR}
  PATH_VARS IBLKIT_INSTALL_HLSLDIR)
# 0.x: a new minor version may change the API.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/iblkitConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/iblkitConfig.cmake ${PROJECT_BINARY_DIR}/iblkitConfigVersion.cmake
  ${CMAKE_CURRENT_LIST_DIR}/IblkitShaders.cmake DESTINATION ${IBLKIT_INSTALL_CMAKEDIR})

# The .pc file finds its prefix from its own folder, so the tree can be moved after installing.
file(RELATIVE_PATH IBLKIT_PC_PREFIX_FROM_PCDIR /prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig /prefix)
configure_file(${CMAKE_CURRENT_LIST_DIR}/iblkit.pc.in ${PROJECT_BINARY_DIR}/iblkit.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/iblkit.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

set(CPACK_PACKAGE_NAME iblkit)
set(CPACK_PACKAGE_VENDOR iblkit)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "HLSL cross-compilation, a Vulkan compute runner and an image-based-lighting baker")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "iblkit developers <iblkit@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# The shared libraries it links, found by dpkg-shlibdeps; and what it opens at run time: the Vulkan
# loader and lavapipe, the default device. The OpenGL path of `iblkit consistency`, `--validate`
# and the plots of `iblkit bench` and `iblkit shading` want the recommended ones.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libvulkan1, mesa-vulkan-drivers")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libegl-mesa0, libgl1-mesa-dri, vulkan-validationlayers, python3-matplotlib")
include(CPack)
