# The cloud-generator catalog (catalog.def), one folder per generator. Included by
# src/CMakeLists.txt once rkpm_scene and rkpm_sim exist:
#   <generator>/params.cpp, catalog_scene.cpp -> rkpm_scene (table, loading, rescaling)
#   <generator>/cloud.cpp,  catalog_sim.cpp   -> rkpm_sim   (the cloud, its size)
# Sources are collected from the folders: a new generator needs no line in any CMake file.
set(cloud_dir ${CMAKE_CURRENT_LIST_DIR})
file(GLOB cloud_params CONFIGURE_DEPENDS ${cloud_dir}/*/params.cpp)
file(GLOB cloud_makers CONFIGURE_DEPENDS ${cloud_dir}/*/cloud.cpp)
target_sources(rkpm_scene PRIVATE ${cloud_params} ${cloud_dir}/catalog_scene.cpp)
target_sources(rkpm_sim PRIVATE ${cloud_makers} ${cloud_dir}/catalog_sim.cpp)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${cloud_dir}/catalog.def)
