# What `cmake --install` and the Debian package (cmake/Package.cmake) put where: the binary
# (shaders are embedded in it; DejaVu Sans comes from Debian's fonts-dejavu-core, which the
# package depends on), its man page and shell completions, the example scenes with the
# meshes they name, the documentation, and Debian's copyright and changelog files.
# docs/install.md says why each is where it is.
include(GNUInstallDirs)

# Directories the install creates: 755 whatever the umask (lintian: non-standard-dir-perm).
set(CMAKE_INSTALL_DEFAULT_DIRECTORY_PERMISSIONS
    OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

set(SYSTOLE_SCENES_INSTALL_DIR ${CMAKE_INSTALL_DATADIR}/systole/scenes)

# The release: packaging/debian/changelog's first entry must be this version; its date is the
# man page's, so the same sources give the same page.
set(changelog ${PROJECT_SOURCE_DIR}/packaging/debian/changelog)
file(STRINGS ${changelog} changelog_head LIMIT_COUNT 1)
if(NOT changelog_head MATCHES "^systole \\(([^)-]+)-([0-9]+)\\)")
  message(FATAL_ERROR "${changelog}: the first line must read 'systole (VERSION-REVISION) ...'; it reads '${changelog_head}'")
endif()
if(NOT CMAKE_MATCH_1 STREQUAL PROJECT_VERSION)
  message(FATAL_ERROR "${changelog}: the first entry is version ${CMAKE_MATCH_1} but the project is ${PROJECT_VERSION}; "
                      "add an entry for ${PROJECT_VERSION}")
endif()
set(SYSTOLE_DEBIAN_REVISION ${CMAKE_MATCH_2})
file(STRINGS ${changelog} changelog_trailers REGEX "^ -- ")
list(GET changelog_trailers 0 changelog_trailer)
if(NOT changelog_trailer MATCHES ", ([0-9]+ [A-Z][a-z][a-z] [0-9][0-9][0-9][0-9]) ")
  message(FATAL_ERROR "${changelog}: no RFC 5322 date in the first entry's trailer '${changelog_trailer}'")
endif()
set(SYSTOLE_RELEASE_DATE ${CMAKE_MATCH_1})

# The man page and completions, written by systole-manual from the CLI11 definitions that
# `systole --help` prints (src/cli/manual/), so the three never disagree.
set(SYSTOLE_MANUAL_DIR ${PROJECT_BINARY_DIR})
set(manual_outputs ${SYSTOLE_MANUAL_DIR}/man/systole.1 ${SYSTOLE_MANUAL_DIR}/man/systole.1.gz
                   ${SYSTOLE_MANUAL_DIR}/completion/systole ${SYSTOLE_MANUAL_DIR}/completion/_systole)
add_custom_command(
  OUTPUT ${manual_outputs}
  COMMAND systole-manual --out ${SYSTOLE_MANUAL_DIR} --date "${SYSTOLE_RELEASE_DATE}"
          --scenes-dir ${CMAKE_INSTALL_FULL_DATADIR}/systole/scenes --docs-dir ${CMAKE_INSTALL_FULL_DOCDIR}
  # -n: no name or time stamp in the header, so the same page gives the same bytes.
  COMMAND gzip -9 -n -f -k ${SYSTOLE_MANUAL_DIR}/man/systole.1
  DEPENDS systole-manual
  COMMENT "Writing the man page and the bash and zsh completions from the command line's definitions"
  VERBATIM)
add_custom_target(systole_manual ALL DEPENDS ${manual_outputs})

# Debian's machine-readable copyright file, from LICENSE (its copyright line and its text).
file(READ ${PROJECT_SOURCE_DIR}/LICENSE license)
if(NOT license MATCHES "Copyright \\(c\\) ([^\n]+)\n")
  message(FATAL_ERROR "${PROJECT_SOURCE_DIR}/LICENSE: no 'Copyright (c) ...' line")
endif()
set(SYSTOLE_COPYRIGHT ${CMAKE_MATCH_1})
string(REGEX REPLACE "^.*Copyright \\(c\\) [^\n]+\n+" "" license_text "${license}")
string(STRIP "${license_text}" license_text)
# A licence's text in the copyright format: every line indented by one space, blank lines as " .".
string(REGEX REPLACE "\n\n" "\n.\n" license_text "${license_text}")
string(REGEX REPLACE "\n" "\n " license_text "${license_text}")
set(SYSTOLE_LICENSE_TEXT " ${license_text}")
configure_file(${PROJECT_SOURCE_DIR}/packaging/debian/copyright.in ${PROJECT_BINARY_DIR}/packaging/copyright @ONLY)

add_custom_command(
  OUTPUT ${PROJECT_BINARY_DIR}/packaging/changelog.Debian.gz
  COMMAND ${CMAKE_COMMAND} -E copy ${changelog} ${PROJECT_BINARY_DIR}/packaging/changelog.Debian
  COMMAND gzip -9 -n -f ${PROJECT_BINARY_DIR}/packaging/changelog.Debian
  DEPENDS ${changelog}
  COMMENT "Compressing the Debian changelog"
  VERBATIM)
add_custom_target(systole_debian_changelog ALL DEPENDS ${PROJECT_BINARY_DIR}/packaging/changelog.Debian.gz)

install(TARGETS systole RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES ${SYSTOLE_MANUAL_DIR}/man/systole.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${SYSTOLE_MANUAL_DIR}/completion/systole DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
install(FILES ${SYSTOLE_MANUAL_DIR}/completion/_systole DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)
# The scenes keep their folder layout, so `mesh: {file: meshes/stomach.obj}` (relative to
# the scene's folder) still resolves.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${SYSTOLE_SCENES_INSTALL_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_BINARY_DIR}/packaging/copyright
              ${PROJECT_BINARY_DIR}/packaging/changelog.Debian.gz
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
