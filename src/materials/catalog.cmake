# The scene and simulation sides of the material catalog. Included by src/CMakeLists.txt
# once rkpm_scene and rkpm_sim exist (rkpm_materials, the kernels, comes before both).
#   <model>/params.cpp          -> rkpm_scene, with catalog_tables.cpp
#   <model>/body_material*.cpp  -> rkpm_sim, with make_material.cpp
# It also writes materials/body_materials.hpp into the build tree: one #include of each
# catalogued model's body_material.hpp, in catalog.def order, from which
# rkpm/sim/body.hpp declares the Material variant (an #include cannot come from a macro).
set(material_dir ${CMAKE_CURRENT_LIST_DIR})
file(GLOB material_params CONFIGURE_DEPENDS ${material_dir}/*/params.cpp)
file(GLOB material_bodies CONFIGURE_DEPENDS ${material_dir}/*/body_material*.cpp)
target_sources(rkpm_scene PRIVATE ${material_params} ${material_dir}/catalog_tables.cpp)
target_sources(rkpm_sim PRIVATE ${material_bodies} ${material_dir}/make_material.cpp)

set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${material_dir}/catalog.def)
file(STRINGS ${material_dir}/catalog.def material_entries REGEX "^RKPM_MATERIAL\\(")
set(material_includes "// Generated from src/materials/catalog.def by src/materials/catalog.cmake.\n#pragma once\n")
foreach(entry IN LISTS material_entries)
  string(REGEX REPLACE "^RKPM_MATERIAL\\(([A-Za-z0-9_]+)\\).*$" "\\1" model "${entry}")
  string(APPEND material_includes "#include \"materials/${model}/body_material.hpp\"\n")
endforeach()
file(CONFIGURE OUTPUT ${PROJECT_BINARY_DIR}/generated/materials/body_materials.hpp CONTENT "${material_includes}")
target_include_directories(rkpm_sim PUBLIC $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/generated>)
