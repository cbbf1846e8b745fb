# rockfall::bullet: Debian's double-precision (float64) build of Bullet, wrapped once.
#
# Debian's BulletConfig-float64.cmake uses paths relative to the prefix and lists
# BulletInverseDynamics-float64, which the package does not ship, so the libraries are
# located here by name instead of through that file.
#
# An IMPORTED target, so that the exported (static) libraries name it as rockfall::bullet and
# the installed rockfallConfig.cmake defines it by including this same file (cmake/RockfallInstall.cmake).
# There (inside find_package) a missing library sets rockfall_FOUND to FALSE instead of
# stopping the consumer's configure step.
set(_rockfall_bullet_libs BulletDynamics-float64 BulletCollision-float64 LinearMath-float64)
set(_rockfall_bullet_paths "")
set(_rockfall_bullet_missing "")
foreach(lib IN LISTS _rockfall_bullet_libs)
    find_library(ROCKFALL_${lib}_LIBRARY NAMES ${lib})
    if(NOT ROCKFALL_${lib}_LIBRARY)
        list(APPEND _rockfall_bullet_missing ${lib})
    endif()
    list(APPEND _rockfall_bullet_paths ${ROCKFALL_${lib}_LIBRARY})
endforeach()
find_path(ROCKFALL_BULLET_INCLUDE_DIR btBulletDynamicsCommon.h PATH_SUFFIXES bullet)
if(NOT ROCKFALL_BULLET_INCLUDE_DIR)
    list(APPEND _rockfall_bullet_missing btBulletDynamicsCommon.h)
endif()

if(_rockfall_bullet_missing)
    string(JOIN ", " _rockfall_bullet_message ${_rockfall_bullet_missing})
    string(PREPEND _rockfall_bullet_message "Bullet (float64) not found: ")
    string(APPEND _rockfall_bullet_message " (Debian: apt install libbullet-dev)")
    if(NOT CMAKE_FIND_PACKAGE_NAME)
        message(FATAL_ERROR "${_rockfall_bullet_message}")
    endif()
    set(rockfall_FOUND FALSE)
    set(rockfall_NOT_FOUND_MESSAGE "${_rockfall_bullet_message}")
elseif(NOT TARGET rockfall::bullet)
    add_library(rockfall::bullet INTERFACE IMPORTED)
    target_include_directories(rockfall::bullet INTERFACE ${ROCKFALL_BULLET_INCLUDE_DIR})
    target_compile_definitions(rockfall::bullet INTERFACE BT_USE_DOUBLE_PRECISION)
    target_link_libraries(rockfall::bullet INTERFACE ${_rockfall_bullet_paths})
endif()
