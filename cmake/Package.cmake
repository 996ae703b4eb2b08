# The Debian package, made by CPack from the install rules (cmake/Install.cmake):
# scripts/package builds it. Run-time dependencies are computed by dpkg-shlibdeps from the
# libraries the binary links, plus the font it opens (fonts-dejavu-core), which no library
# dependency would name. docs/install.md has the figures and lintian's remaining output.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME systole)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "The Systole developers")
set(CPACK_PACKAGE_CONTACT "Systole Developers <dev@systole.invalid>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "self-driven soft-body organ animations from YAML scenes")
# The extended description, one string (a CMake list would lose its semicolons).
set(CPACK_PACKAGE_DESCRIPTION "Systole turns a YAML scene into a teaching video of a living organ. A heart
beats, lungs breathe, a kidney pulses, because each organ is a soft body
whose own springs contract and relax in rhythm, region by region.
It simulates (Eigen), renders off screen (OSMesa) and encodes MP4, MKV,
WebM or GIF (libavcodec), with overlays, captions and cut-away views.
Batches shard across Slurm, Kubernetes and AWS Batch arrays.
Example scenes are in /usr/share/systole/scenes.")
set(CPACK_DEBIAN_PACKAGE_RELEASE ${SYSTOLE_DEBIAN_REVISION})
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # systole_0.1.0-1_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "fonts-dejavu-core")
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
set(CPACK_PACKAGING_INSTALL_PREFIX ${CMAKE_INSTALL_PREFIX})
# Debian ships stripped binaries (lintian: unstripped-binary-or-object).
set(CPACK_STRIP_FILES ON)
# Only what `cmake --install` installs: not the tests' or benchmarks' programs.
set(CPACK_INSTALL_CMAKE_PROJECTS "${PROJECT_BINARY_DIR};${PROJECT_NAME};ALL;/")
include(CPack)
