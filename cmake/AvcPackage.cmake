# Installation and the Debian package (scripts/package, README "Lab deployment").
# `cmake --install build` puts the same files under CMAKE_INSTALL_PREFIX; the package installs
# them under /usr. Everything avc reads at run time is here: the report's assets are compiled in,
# and `avc spy` finds the message types jar in ../share/avc next to the binary.
include(GNUInstallDirs)
# Installing (and cpack) needs only the installed targets, not the whole tree with the tests.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

install(TARGETS avc RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(AVC_LCMTYPES_JAR)
  install(FILES ${AVC_LCMTYPES_JAR} DESTINATION ${CMAKE_INSTALL_DATADIR}/avc)
endif()
# What a lab runs, and all scripts/setup builds: the installed files above. The tests and the
# fuzz smoke binaries are built by scripts/test (the whole tree), so an installation does not
# compile them (BENCHMARKS.md, build).
add_custom_target(avc_programs)
add_dependencies(avc_programs avc)
if(TARGET avc_lcmtypes_java)
  add_dependencies(avc_programs avc_lcmtypes_java)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/launch/ DESTINATION ${CMAKE_INSTALL_DATADIR}/avc/launch)
install(PROGRAMS ${PROJECT_SOURCE_DIR}/scripts/setup-lab-host
        DESTINATION ${CMAKE_INSTALL_SBINDIR} RENAME avc-setup-lab-host)
# systemd reads units from /usr/lib/systemd/system too; ExecStart names `avc` without a path, so
# the unit runs /usr/local/bin/avc or /usr/bin/avc, whichever install is there.
install(FILES ${PROJECT_SOURCE_DIR}/scripts/avc-up@.service DESTINATION lib/systemd/system)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME avc)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "AVC developers")
# The Maintainer field: who builds the package (a lab sets its own with -DCPACK_PACKAGE_CONTACT).
if(NOT CPACK_PACKAGE_CONTACT)
  set(CPACK_PACKAGE_CONTACT "AVC developers")
endif()
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Automated plant reconstruction cell: UR5, turntable and camera to a 3-D plant model")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The shared libraries the binary links (OpenCV, PCL, Ceres, TBB, LCM, libgphoto2, ...) become
# Depends through dpkg-shlibdeps; the tools avc starts by name are declared by hand.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "liblcm-bin")
# avc spy (lcm-spy with our types) and avc-setup-lab-host's ip.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "liblcm-java, libjchart2d-java, default-jre-headless, iproute2")
include(CPack)
