# `cmake --install`: the rkpm program, the libraries, their headers and an exported
# CMake package, so that another project can `find_package(rkpm)` and link rkpm::rkpm
# (examples/embedding). Layout under the prefix:
#   bin/rkpm
#   lib/librkpm_*.a, lib/cmake/rkpm/{rkpmConfig,rkpmConfigVersion,rkpmTargets}.cmake
#   include/rkpm/...            the public headers (include/ and particles/include/)
#   include/rkpm/internal/...   the material kernels the public headers reach
#                               (rkpm/sim/body.hpp holds every model's body material)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(rkpm_internal_includes ${CMAKE_INSTALL_INCLUDEDIR}/rkpm/internal)
foreach(target rkpm_sim rkpm_scene rkpm_materials)
  target_include_directories(${target} PUBLIC $<INSTALL_INTERFACE:${rkpm_internal_includes}>)
endforeach()
foreach(target rkpm_sim rkpm_scene rkpm_materials rkpm_io rkpm_par rkpm_rk rkpm_particles)
  target_include_directories(${target} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
endforeach()
# One name for everything: rkpm::rkpm.
set_target_properties(rkpm_core PROPERTIES EXPORT_NAME rkpm)

install(TARGETS rkpm RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS rkpm_core rkpm_sim rkpm_scene rkpm_io rkpm_par rkpm_rk rkpm_materials rkpm_particles rkpm_options
        EXPORT rkpmTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/ ${PROJECT_SOURCE_DIR}/particles/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/materials/ DESTINATION ${rkpm_internal_includes}/materials
        FILES_MATCHING PATTERN "*.hpp" PATTERN "*.def")
install(FILES ${PROJECT_BINARY_DIR}/generated/materials/body_materials.hpp
        DESTINATION ${rkpm_internal_includes}/materials)

install(EXPORT rkpmTargets NAMESPACE rkpm:: DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rkpm)
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/rkpmConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/rkpmConfig.cmake
                              INSTALL_DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rkpm)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rkpmConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rkpmConfig.cmake ${PROJECT_BINARY_DIR}/rkpmConfigVersion.cmake
        DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/rkpm)
