# cmake --install: the headers, the generated headers, the libraries and a
# CMake package, so that another project writes
#
#     find_package(skelconv CONFIG REQUIRED)
#     target_link_libraries(app PRIVATE skelconv::skelconv)
#
# (docs/api.md). Layout under the prefix:
#   include/skelconv/...                  the public headers (and the detail/
#                                         headers they include, listed below)
#   include/skelconv-generated/generated/ the generated kernels (reached as
#                                         "generated/segment_table.hpp", as in
#                                         the source tree)
#   lib/libskelconv_*.a                   the static libraries
#   lib/cmake/skelconv/                   skelconv-config.cmake and the targets
#   lib/python3/dist-packages/skelconv*.so the Python module (python/)
#
# Exported targets (namespace skelconv::):
#   skelconv::runtime  primitives, skeleton files, blends, fields, batches, bounds
#   skelconv::mesh     iso-surface meshing (CGAL Mesh_3; OpenVDB in the module
#                      lib/skelconv/libskelconv_grid_mesher.so, opened on use), PLY/OBJ
#   skelconv::skelconv both: what <skelconv/skelconv.hpp> declares
#   skelconv::reconstruct  skeletons from closed meshes (<skelconv/reconstruct/...>,
#                      docs/reconstruction.md; CGAL's Delaunay, linked in)
#   skelconv::canal    canal surfaces in the Lorentz space of spheres
#                      (<skelconv/canal/...>, docs/canal.md)
#   skelconv::kernels  the header-only generated kernels (templates on the scalar type)
#   skelconv::segment_tables  the double segment table the runtime is built on
#                      (linked by skelconv::runtime; the verifiers use it alone)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(SKELCONV_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/skelconv)
set(SKELCONV_GENERATED_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/skelconv-generated)

target_include_directories(skelconv_kernels INTERFACE
  $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
  $<INSTALL_INTERFACE:${SKELCONV_GENERATED_INCLUDEDIR}>)

set_target_properties(skelconv_all PROPERTIES EXPORT_NAME skelconv)
set_target_properties(skelconv_runtime PROPERTIES EXPORT_NAME runtime)
set_target_properties(skelconv_segment_tables PROPERTIES EXPORT_NAME segment_tables)
set_target_properties(skelconv_mesh PROPERTIES EXPORT_NAME mesh)
set_target_properties(skelconv_kernels PROPERTIES EXPORT_NAME kernels)
set_target_properties(skelconv_reconstruct PROPERTIES EXPORT_NAME reconstruct)
set_target_properties(skelconv_canal PROPERTIES EXPORT_NAME canal)

# The public headers: include/skelconv/ without detail/. detail/ holds the
# internals (numerical helpers, no API); only those that an installed header
# includes are installed, because the public templates and the generated
# kernels are compiled in the user's program and need them. The list is
# checked by scripts/check_include_graph.py (ctest include_graph_is_sound): it
# fails when an installed header reaches a detail header missing here, or
# when a header listed here is reached by none.
set(SKELCONV_INSTALLED_DETAIL_HEADERS
  clip.hpp
  double_word.hpp
  exact_cross.hpp
  exp_pieces.hpp
  far_field_series.hpp
  gauss_moments.hpp
  integer_power.hpp
  plane_height.hpp
  polygon_angle_integrals.hpp
  polygon_far_field.hpp
  scaled_frame.hpp
  scalis_compact_support.hpp
  stable_recurrence.hpp
  support_gap.hpp)
# Every installed header belongs to an installed library. Not installed,
# with its library: view/ (the HTML page of `skelconv view`, the command's
# own).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/skelconv
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp"
        PATTERN detail EXCLUDE
        PATTERN view EXCLUDE)
list(TRANSFORM SKELCONV_INSTALLED_DETAIL_HEADERS
     PREPEND ${PROJECT_SOURCE_DIR}/include/skelconv/detail/
     OUTPUT_VARIABLE skelconv_detail_files)
install(FILES ${skelconv_detail_files}
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/skelconv/detail)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/generated
        DESTINATION ${SKELCONV_GENERATED_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")

# The OBJECT libraries that confine CGAL to their own translation units
# (src/CMakeLists.txt) are linked privately into the static libraries; they
# are exported for their link dependencies (CGAL's GMP), their objects are
# already inside the archives. The OpenVDB module of the grid method is opened at run
# time from <libdir>/skelconv/ (src/mesh/grid_mesher_loader.cpp): installed
# there, not linked.
install(TARGETS skelconv_grid_mesher LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/skelconv)
install(TARGETS skelconv_all skelconv_runtime skelconv_segment_tables skelconv_mesh skelconv_kernels
                skelconv_reconstruct skelconv_canal
                skelconv_planar_polygon skelconv_cgal_mesher skelconv_cgal_reconstruct
        EXPORT skelconv-targets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
        OBJECTS DESTINATION ${CMAKE_INSTALL_LIBDIR}/skelconv-objects
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT skelconv-targets NAMESPACE skelconv:: DESTINATION ${SKELCONV_INSTALL_CMAKEDIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/skelconv-config.cmake.in
  ${PROJECT_BINARY_DIR}/skelconv-config.cmake INSTALL_DESTINATION ${SKELCONV_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/skelconv-config-version.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/skelconv-config.cmake ${PROJECT_BINARY_DIR}/skelconv-config-version.cmake
        DESTINATION ${SKELCONV_INSTALL_CMAKEDIR})
