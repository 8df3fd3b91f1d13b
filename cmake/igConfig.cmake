# find_package(ig CONFIG): the IG's libraries (ig::ig_terrain, ig::ig_io,
# ig::ig_visual) and the Debian packages they link (docs/architecture.md).
include(CMakeFindDependencyMacro)
find_dependency(Threads)
find_dependency(glm CONFIG)
find_dependency(nlohmann_json 3 CONFIG)
find_dependency(GDAL CONFIG)
find_dependency(glfw3 3.3 CONFIG)
find_dependency(ZLIB)
find_dependency(TinyGLTF CONFIG)  # ig::ig_models
find_dependency(PkgConfig)
# The same imported targets the build used (static libraries carry them).
foreach(_ig_module IN ITEMS "EPOXY epoxy" "EGL egl" "ERFA erfa" "OIIO OpenImageIO")
  separate_arguments(_ig_module)
  list(GET _ig_module 0 _ig_prefix)
  list(GET _ig_module 1 _ig_package)
  if(NOT TARGET PkgConfig::${_ig_prefix})
    pkg_check_modules(${_ig_prefix} REQUIRED IMPORTED_TARGET ${_ig_package})
  endif()
endforeach()
include(${CMAKE_CURRENT_LIST_DIR}/igTargets.cmake)
