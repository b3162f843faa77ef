# How each Debian package is found. See notes/dependencies.md in the shared folder for the
# packaging bugs worked around here.
find_package(embree 3.13 CONFIG REQUIRED)            # target: embree
find_package(TBB 2021 CONFIG REQUIRED COMPONENTS tbb) # TBB::tbb
find_package(Imath 3.1 CONFIG REQUIRED)
find_package(OpenEXR 3.1 CONFIG REQUIRED)
find_package(fmt CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)

# OpenImageIO's exported target names /usr/include/opencv4, which exists only with libopencv-dev.
find_package(OpenImageIO 2.4 CONFIG REQUIRED)
foreach(_t OpenImageIO::OpenImageIO OpenImageIO::OpenImageIO_Util)
  get_target_property(_inc ${_t} INTERFACE_INCLUDE_DIRECTORIES)
  if(_inc)
    list(FILTER _inc EXCLUDE REGEX "opencv4")
    set_target_properties(${_t} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_inc}")
  endif()
endforeach()

# OpenColorIO's CMake config is installed where find_package does not look, and computes a wrong
# prefix when pointed at; its pkg-config file is correct.
find_package(PkgConfig REQUIRED)
pkg_check_modules(OCIO REQUIRED IMPORTED_TARGET OpenColorIO>=2.1)
if(NOT TARGET OpenColorIO::OpenColorIO)
  add_library(OpenColorIO::OpenColorIO INTERFACE IMPORTED)
  target_link_libraries(OpenColorIO::OpenColorIO INTERFACE PkgConfig::OCIO)
endif()

# OpenSubdiv's own config is broken on Debian: our Find module (MODULE mode skips the config).
list(APPEND CMAKE_MODULE_PATH ${CMAKE_CURRENT_LIST_DIR})
find_package(OpenSubdiv MODULE REQUIRED)

if(CANDELA_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)
endif()
