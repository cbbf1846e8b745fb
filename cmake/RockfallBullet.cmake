# rockfall::bullet: Debian's double-precision (float64) build of Bullet, wrapped once.
#
# Debian's BulletConfig-float64.cmake uses paths relative to the prefix and lists
# BulletInverseDynamics-float64, which the package does not ship, so the libraries are
# located here by name instead of through that file.
set(_rockfall_bullet_libs BulletDynamics-float64 BulletCollision-float64 LinearMath-float64)
set(_rockfall_bullet_paths "")
foreach(lib IN LISTS _rockfall_bullet_libs)
    find_library(ROCKFALL_${lib}_LIBRARY NAMES ${lib} REQUIRED)
    list(APPEND _rockfall_bullet_paths ${ROCKFALL_${lib}_LIBRARY})
endforeach()
find_path(ROCKFALL_BULLET_INCLUDE_DIR btBulletDynamicsCommon.h PATH_SUFFIXES bullet REQUIRED)

add_library(rockfall_bullet INTERFACE)
add_library(rockfall::bullet ALIAS rockfall_bullet)
target_include_directories(rockfall_bullet SYSTEM INTERFACE ${ROCKFALL_BULLET_INCLUDE_DIR})
target_compile_definitions(rockfall_bullet INTERFACE BT_USE_DOUBLE_PRECISION)
target_link_libraries(rockfall_bullet INTERFACE ${_rockfall_bullet_paths})
