# find_package(mujoco) with Debian's libmujoco-dev 2.2.2 made usable: its exported target names
# /usr/include/libqhull_r/ as an include directory without depending on the qhull headers, and
# CMake refuses a missing directory; no qhull header is needed by mujoco.h, so only the
# directories that exist are kept. ARGN: the find mode (REQUIRED or QUIET).
macro(unidyn_find_mujoco)
  find_package(mujoco CONFIG ${ARGN})
  if(mujoco_FOUND)
    get_target_property(_mujoco_includes mujoco::mujoco INTERFACE_INCLUDE_DIRECTORIES)
    set(_mujoco_existing "")
    foreach(_dir IN LISTS _mujoco_includes)
      if(IS_DIRECTORY "${_dir}")
        list(APPEND _mujoco_existing "${_dir}")
      endif()
    endforeach()
    set_target_properties(mujoco::mujoco PROPERTIES INTERFACE_INCLUDE_DIRECTORIES
                                                    "${_mujoco_existing}")
  endif()
endmacro()
