# Installation (docs/install.md): `cmake --install build --prefix P` puts the program, its man
# page and bash completion, the static libraries with their public headers and a CMake package
# (find_package(rockfall), targets rockfall::shapes, rockfall::engine, ...) under P. Two
# components: Runtime (the program, its man page, completion and samples) and Development
# (libraries, headers, CMake package). CPack makes one Debian package of each.
include(CMakePackageConfigHelpers)

set(ROCKFALL_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/rockfall CACHE STRING
    "Where the CMake package (rockfallConfig.cmake) is installed, relative to the prefix")

# The libraries, in dependency order; a module without its folder (db, mpm) is left out.
set(ROCKFALL_INSTALLED_MODULES "")
foreach(module shapes engine mpm risk db scenario report)
    if(TARGET rockfall_${module})
        list(APPEND ROCKFALL_INSTALLED_MODULES ${module})
        set_target_properties(rockfall_${module} PROPERTIES EXPORT_NAME ${module})
        # The public headers are C++20: a consumer compiles them at that level.
        target_compile_features(rockfall_${module} INTERFACE cxx_std_20)
        install(TARGETS rockfall_${module} EXPORT rockfallTargets
            ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development
            LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT Development)
        install(DIRECTORY ${PROJECT_SOURCE_DIR}/${module}/include/
            DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT Development)
    endif()
endforeach()
# `cmake --install --strip` (and CPack) strips the executable; the static libraries lose their
# debug information too (about 50 MB each to under 1 MB).
set(_rockfall_archives "")
foreach(module IN LISTS ROCKFALL_INSTALLED_MODULES)
    list(APPEND _rockfall_archives $<TARGET_FILE_NAME:rockfall_${module}>)
endforeach()
install(CODE "
    if(CMAKE_INSTALL_DO_STRIP)
        foreach(archive ${_rockfall_archives})
            execute_process(COMMAND \"${CMAKE_STRIP}\" --strip-debug
                \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/\${archive}\"
                COMMAND_ERROR_IS_FATAL ANY)
        endforeach()
    endif()" COMPONENT Development)
# Linked PRIVATE by every library, so a static library's consumer links it ($<LINK_ONLY:...>):
# it carries only the language standard and warnings, which do not reach the consumer.
set_target_properties(rockfall_options PROPERTIES EXPORT_NAME options)
install(TARGETS rockfall_options EXPORT rockfallTargets COMPONENT Development)
install(EXPORT rockfallTargets NAMESPACE rockfall:: DESTINATION ${ROCKFALL_INSTALL_CMAKEDIR}
    COMPONENT Development)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rockfallConfig.cmake.in
    ${PROJECT_BINARY_DIR}/rockfallConfig.cmake INSTALL_DESTINATION ${ROCKFALL_INSTALL_CMAKEDIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rockfallConfigVersion.cmake
    COMPATIBILITY SameMinorVersion)
# rockfall::bullet is defined by the consumer's find_package(rockfall) from the same file as
# here (the exported engine names it).
install(FILES ${PROJECT_BINARY_DIR}/rockfallConfig.cmake
    ${PROJECT_BINARY_DIR}/rockfallConfigVersion.cmake ${CMAKE_CURRENT_LIST_DIR}/RockfallBullet.cmake
    DESTINATION ${ROCKFALL_INSTALL_CMAKEDIR} COMPONENT Development)

# The program, its man page and bash completion, both written by the program itself from its
# CLI11 definition (the text of --help; app/src/cmd_help_man.cpp).
install(TARGETS rockfall RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT Runtime)
set(ROCKFALL_MAN_PAGE ${PROJECT_BINARY_DIR}/rockfall.1)
set(ROCKFALL_BASH_COMPLETION ${PROJECT_BINARY_DIR}/rockfall.bash)
add_custom_command(OUTPUT ${ROCKFALL_MAN_PAGE}
    COMMAND sh -c "\"$0\" --man-page > \"$1\"" $<TARGET_FILE:rockfall> ${ROCKFALL_MAN_PAGE}
    DEPENDS rockfall VERBATIM COMMENT "Writing the man page rockfall.1")
add_custom_command(OUTPUT ${ROCKFALL_BASH_COMPLETION}
    COMMAND sh -c "\"$0\" --bash-completion > \"$1\"" $<TARGET_FILE:rockfall>
            ${ROCKFALL_BASH_COMPLETION}
    DEPENDS rockfall VERBATIM COMMENT "Writing the bash completion rockfall.bash")
add_custom_target(rockfall_help_files ALL DEPENDS ${ROCKFALL_MAN_PAGE} ${ROCKFALL_BASH_COMPLETION})
install(FILES ${ROCKFALL_MAN_PAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1 COMPONENT Runtime)
install(FILES ${ROCKFALL_BASH_COMPLETION} DESTINATION
    ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME rockfall COMPONENT Runtime)
# The scenarios and meshes the README and docs use, for `rockfall validate --samples`.
install(DIRECTORY ${PROJECT_SOURCE_DIR}/samples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/rockfall/samples
    COMPONENT Runtime)

# Debian packages: `cpack -G DEB` in the build directory gives rockfall_VERSION_ARCH.deb (the
# program) and rockfall-dev_VERSION_ARCH.deb (libraries, headers, CMake package). The program's
# shared-library dependencies come from dpkg-shlibdeps (package dpkg-dev).
set(ROCKFALL_PACKAGE_MAINTAINER "rockfall developers <rockfall@invalid>" CACHE STRING
    "Maintainer field of the Debian packages")
set(CPACK_PACKAGE_NAME rockfall)
set(CPACK_PACKAGE_VENDOR "rockfall developers")
set(CPACK_PACKAGE_CONTACT ${ROCKFALL_PACKAGE_MAINTAINER})
set(CPACK_GENERATOR DEB)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL Runtime Development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME rockfall)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SUGGESTS bash-completion)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME rockfall-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
# What rockfallConfig.cmake finds (find_dependency) and the static libraries link.
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS
    "rockfall (= ${PROJECT_VERSION}), libeigen3-dev, libbullet-dev, libqhull-dev, libassimp-dev, zlib1g-dev, libsqlite3-dev, libtomlplusplus-dev, nlohmann-json3-dev")
include(CPack)
# Each package's description: its first line is the Debian synopsis (so no
# CPACK_PACKAGE_DESCRIPTION_SUMMARY, which CPack would put before both).
cpack_add_component(Runtime DISPLAY_NAME "rockfall program" DESCRIPTION
    "rockfall and soil-flow simulation with Monte Carlo sweeps into SQLite
How far rocks and soil released from a slope travel and how hard they hit a wall: Bullet rigid
bodies, MPM soil flow, Monte Carlo sweeps into SQLite results databases, design formulas,
reports. The rockfall program with its man page, bash completion and sample scenarios.")
cpack_add_component(Development DISPLAY_NAME "rockfall libraries" DESCRIPTION
    "rockfall libraries, headers and CMake package
The static libraries of rockfall (shapes, engine, mpm, risk, db, scenario, report), their
headers and the CMake package: find_package(rockfall) gives rockfall::shapes and the others.")
