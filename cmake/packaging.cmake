# Installing and packaging raster with CMake's own install() and CPack: `cmake --install build [--prefix DIR]` puts
# the programs in bin/, the README and docs/ in share/doc/raster/ and the teapot scene (with its mesh) in
# share/raster/examples/; `cpack --config build/CPackConfig.cmake -G DEB` (or TGZ) packs the same tree.
# docs/install.md has the commands.
include(GNUInstallDirs)

install(TARGETS raster RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET raster_view_program)
  # `raster view` runs raster-view from raster's own folder (apps/cmd_view_forward.cpp).
  install(TARGETS raster_view_program RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
# The default scene, its mesh beside it as its relative path expects.
install(FILES corpus/scenes/teapot.yaml DESTINATION ${CMAKE_INSTALL_DATADIR}/raster/examples/scenes)
install(FILES corpus/meshes/teapot.obj DESTINATION ${CMAKE_INSTALL_DATADIR}/raster/examples/meshes)

set(CPACK_PACKAGE_NAME raster)
set(CPACK_PACKAGE_VENDOR "the raster developers")
set(CPACK_PACKAGE_CONTACT "the raster developers <raster@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "CPU triangle rasterizer with an Embree oracle that checks it sample by sample")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB TGZ)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
# The shared libraries' packages (Embree, oneTBB, yaml-cpp, ...) as dpkg-shlibdeps finds them in the binaries.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
include(CPack)
