# OpenVDB (Debian's libopenvdb-dev) as the imported target OpenVDB::openvdb, for the surface
# meshes of tide::io. Not through OpenVDB's own FindOpenVDB.cmake: that one sets
# BUILD_SHARED_LIBS ON in the caller's scope and wants Boost.Iostreams, which tide does not use.
# Included by src/io and by the installed tideConfig.cmake.
if(NOT TARGET OpenVDB::openvdb)
  find_path(TIDE_OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
  find_library(TIDE_OPENVDB_LIBRARY openvdb REQUIRED)
  find_package(TBB REQUIRED)
  find_package(Boost REQUIRED)  # headers only (openvdb/math/Math.h)
  find_package(Imath REQUIRED)  # its half type, inline in OpenVDB's headers
  add_library(OpenVDB::openvdb UNKNOWN IMPORTED)
  set_target_properties(OpenVDB::openvdb PROPERTIES
    IMPORTED_LOCATION "${TIDE_OPENVDB_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${TIDE_OPENVDB_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "TBB::tbb;Boost::headers;Imath::Imath")
endif()
