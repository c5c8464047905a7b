# Every third-party dependency of the project, found in one place. A missing one stops
# configuration with the Debian package that provides it (scripts/setup installs them all).

function(avc_missing_dependency what package)
  message(FATAL_ERROR
    "AVC needs ${what}, which was not found.\n"
    "Install it with:  apt-get install ${package}\n"
    "(scripts/setup installs every dependency of the project.)")
endfunction()

# find_package wrapper: avc_find(<Name> DEBIAN <package> [find_package args...])
macro(avc_find name)
  cmake_parse_arguments(_avc_find "" "DEBIAN" "" ${ARGN})
  find_package(${name} QUIET ${_avc_find_UNPARSED_ARGUMENTS})
  if(NOT ${name}_FOUND)
    avc_missing_dependency(${name} ${_avc_find_DEBIAN})
  endif()
endmacro()

find_package(Threads REQUIRED)
avc_find(OpenSSL DEBIAN libssl-dev)
avc_find(fmt DEBIAN libfmt-dev)
avc_find(CLI11 DEBIAN libcli11-dev)
avc_find(nlohmann_json DEBIAN nlohmann-json3-dev)
avc_find(yaml-cpp DEBIAN libyaml-cpp-dev)
avc_find(tomlplusplus DEBIAN libtomlplusplus-dev)
avc_find(Eigen3 DEBIAN libeigen3-dev NO_MODULE)
avc_find(TBB DEBIAN libtbb-dev)
avc_find(OpenCV DEBIAN libopencv-dev)
avc_find(Ceres DEBIAN libceres-dev)
avc_find(octomap DEBIAN liboctomap-dev)
avc_find(CGAL DEBIAN libcgal-dev)
# Header-only Lanczos eigensolvers on Eigen (sparse spectral clustering baseline).
avc_find(spectra DEBIAN libspectra-dev)
# PCL's config is slow and noisy; only its presence is checked here, components are found by the
# modules that use them.
avc_find(PCL DEBIAN libpcl-dev COMPONENTS common)

find_path(AVC_LIBUSB_INCLUDE_DIR libusb.h PATH_SUFFIXES libusb-1.0)
find_library(AVC_LIBUSB_LIBRARY usb-1.0)
if(NOT AVC_LIBUSB_INCLUDE_DIR OR NOT AVC_LIBUSB_LIBRARY)
  avc_missing_dependency(libusb-1.0 libusb-1.0-0-dev)
endif()
add_library(avc::libusb UNKNOWN IMPORTED)
set_target_properties(avc::libusb PROPERTIES IMPORTED_LOCATION "${AVC_LIBUSB_LIBRARY}"
                      INTERFACE_INCLUDE_DIRECTORIES "${AVC_LIBUSB_INCLUDE_DIR}")

find_path(AVC_GPHOTO2_INCLUDE_DIR gphoto2/gphoto2.h)
find_library(AVC_GPHOTO2_LIBRARY gphoto2)
find_library(AVC_GPHOTO2_PORT_LIBRARY gphoto2_port)
if(NOT AVC_GPHOTO2_INCLUDE_DIR OR NOT AVC_GPHOTO2_LIBRARY OR NOT AVC_GPHOTO2_PORT_LIBRARY)
  avc_missing_dependency(libgphoto2 libgphoto2-dev)
endif()
add_library(avc::gphoto2 INTERFACE IMPORTED)
set_target_properties(avc::gphoto2 PROPERTIES
  INTERFACE_LINK_LIBRARIES "${AVC_GPHOTO2_LIBRARY};${AVC_GPHOTO2_PORT_LIBRARY}"
  INTERFACE_INCLUDE_DIRECTORIES "${AVC_GPHOTO2_INCLUDE_DIR}")

if(AVC_TESTS_ENABLED)
  avc_find(GTest DEBIAN "libgtest-dev libgmock-dev")
endif()
