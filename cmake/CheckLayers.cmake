# The layers, enforced (docs/ARCHITECTURE.md, "Layers"): what each layer's files may #include
# of sluice's own headers. A file in a layer that includes a sluice header outside its allowed
# list stops the configuration with the file and the include named.
#
#   core     include/sluice/core, src/core         sluice/core
#   physics  include/sluice/physics, src/physics   sluice/core, sluice/physics
#   geometry include/sluice/geometry, src/geometry sluice/core, sluice/geometry
#   motion   include/sluice/motion, src/motion     sluice/core, sluice/motion, sluice/contact
#   contact  include/sluice/contact, src/contact   sluice/core, sluice/contact
#   io       include/sluice/io, src/io             sluice/core, sluice/physics, sluice/geometry,
#                                                  sluice/motion, sluice/io,
#                                                  sluice/version.hpp (generated)
#   tasks    tasks/                                sluice/core, sluice/tasks
#   solver, app: anything.
#
# And the namespace convention: core, physics and io declare their names in `sluice` (internals of
# one file group may sit in `detail`, `case_file` or `h5` below it); the runtime, which knows no
# formula, declares its names in `sluice::tasks`. The layer is the folder, not the namespace, so a
# physics function is called as `sluice::f` from any layer. A named namespace outside the layer's
# list stops the configuration too.
#
# Used two ways:
#  - include()d by CMakeLists.txt: checks the source tree at configure time
#    (sluice_check_layers), and the build re-runs it as a script when a checked file changes;
#  - as a script: cmake -DSLUICE_LAYERS_ROOT=<tree> -P cmake/CheckLayers.cmake checks <tree>
#    (the ctest `layers_check_refuses_bad_includes` runs it on tests/data/layers/).

# The layers: name, folders (relative to the root), allowed include prefixes.
set(SLUICE_LAYERS core physics geometry motion contact io tasks)
set(SLUICE_LAYER_core_DIRS include/sluice/core src/core)
set(SLUICE_LAYER_core_ALLOWED sluice/core/)
set(SLUICE_LAYER_physics_DIRS include/sluice/physics src/physics)
set(SLUICE_LAYER_physics_ALLOWED sluice/core/ sluice/physics/)
set(SLUICE_LAYER_geometry_DIRS include/sluice/geometry src/geometry)
set(SLUICE_LAYER_geometry_ALLOWED sluice/core/ sluice/geometry/)
set(SLUICE_LAYER_motion_DIRS include/sluice/motion src/motion)
set(SLUICE_LAYER_motion_ALLOWED sluice/core/ sluice/motion/ sluice/contact/)
set(SLUICE_LAYER_contact_DIRS include/sluice/contact src/contact)
set(SLUICE_LAYER_contact_ALLOWED sluice/core/ sluice/contact/)
set(SLUICE_LAYER_io_DIRS include/sluice/io src/io)
set(SLUICE_LAYER_io_ALLOWED sluice/core/ sluice/physics/ sluice/geometry/ sluice/motion/ sluice/io/ sluice/version.hpp)
set(SLUICE_LAYER_tasks_DIRS tasks)
set(SLUICE_LAYER_tasks_ALLOWED sluice/core/ sluice/tasks/)

# Named namespaces each layer may declare (a regular expression over the whole name; aliases
# such as `namespace fs = std::filesystem` are not declarations).
set(SLUICE_NS_SHARED "sluice|sluice::(detail|case_file|h5)|detail|case_file|h5")
set(SLUICE_LAYER_core_NAMESPACES "${SLUICE_NS_SHARED}")
set(SLUICE_LAYER_physics_NAMESPACES "${SLUICE_NS_SHARED}")
set(SLUICE_LAYER_geometry_NAMESPACES "${SLUICE_NS_SHARED}")
set(SLUICE_LAYER_motion_NAMESPACES "${SLUICE_NS_SHARED}")
set(SLUICE_LAYER_contact_NAMESPACES "${SLUICE_NS_SHARED}")
set(SLUICE_LAYER_io_NAMESPACES "${SLUICE_NS_SHARED}")
set(SLUICE_LAYER_tasks_NAMESPACES "sluice::tasks(::[a-z_]+)?|detail")

set(SLUICE_LAYER_GLOBS *.hpp *.h *.cpp *.cc *.ipp *.inl)

# Files of one layer under `root`, sorted, into `out` (absolute paths). Further arguments go to
# file(GLOB_RECURSE) before the patterns (CONFIGURE_DEPENDS in project mode).
function(sluice_files_of_layer root layer out)
  set(globs)
  foreach(dir IN LISTS SLUICE_LAYER_${layer}_DIRS)
    foreach(g IN LISTS SLUICE_LAYER_GLOBS)
      list(APPEND globs ${root}/${dir}/${g})
    endforeach()
  endforeach()
  file(GLOB_RECURSE files ${ARGN} ${globs})
  list(SORT files)
  set(${out} ${files} PARENT_SCOPE)
endfunction()

# Files of every layer under `root`, into `out`. Project mode only: the globs are
# CONFIGURE_DEPENDS, so a file added to a layer is seen by the next build.
function(sluice_layer_files root out)
  set(all)
  foreach(layer IN LISTS SLUICE_LAYERS)
    sluice_files_of_layer(${root} ${layer} files CONFIGURE_DEPENDS)
    list(APPEND all ${files})
  endforeach()
  list(SORT all)
  set(${out} ${all} PARENT_SCOPE)
endfunction()

# Checks every layer's files under `root`; FATAL_ERROR listing each offending include.
function(sluice_check_layers root)
  set(errors)
  set(ns_errors)
  set(checked 0)
  foreach(layer IN LISTS SLUICE_LAYERS)
    sluice_files_of_layer(${root} ${layer} files)
    foreach(f IN LISTS files)
      math(EXPR checked "${checked} + 1")
      file(STRINGS ${f} lines ENCODING UTF-8
           REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]sluice/[^\">]*[\">]")
      foreach(line IN LISTS lines)
        string(REGEX MATCH "[<\"](sluice/[^\">]*)[\">]" _ "${line}")
        set(header ${CMAKE_MATCH_1})
        set(ok FALSE)
        foreach(prefix IN LISTS SLUICE_LAYER_${layer}_ALLOWED)
          string(FIND "${header}" "${prefix}" at)
          if(at EQUAL 0)
            set(ok TRUE)
          endif()
        endforeach()
        if(NOT ok)
          file(RELATIVE_PATH rel ${root} ${f})
          string(REPLACE ";" ", " allowed "${SLUICE_LAYER_${layer}_ALLOWED}")
          list(APPEND errors
               "  ${rel} includes ${header}: the ${layer} layer may include only ${allowed}")
        endif()
      endforeach()
      file(STRINGS ${f} decls ENCODING UTF-8
           REGEX "^[ \t]*namespace[ \t]+[A-Za-z_][A-Za-z0-9_:]*[ \t]*{")
      foreach(line IN LISTS decls)
        string(REGEX MATCH "namespace[ \t]+([A-Za-z_][A-Za-z0-9_:]*)" _ "${line}")
        set(ns ${CMAKE_MATCH_1})
        if(NOT ns MATCHES "^(${SLUICE_LAYER_${layer}_NAMESPACES})$")
          file(RELATIVE_PATH rel ${root} ${f})
          set(msg "  ${rel} declares namespace ${ns}: the ${layer} layer declares its names in")
          list(APPEND ns_errors "${msg} ${SLUICE_LAYER_${layer}_NAMESPACES}")
        endif()
      endforeach()
    endforeach()
  endforeach()
  if(errors OR ns_errors)
    list(LENGTH errors n)
    list(LENGTH ns_errors m)
    string(REPLACE ";" "\n" errors "${errors}")
    string(REPLACE ";" "\n" ns_errors "${ns_errors}")
    message(FATAL_ERROR "Layer check (cmake/CheckLayers.cmake): ${n} include(s) against the "
                        "layers and ${m} namespace(s) against the convention "
                        "(docs/ARCHITECTURE.md, \"Layers\"):\n${errors}\n${ns_errors}\n")
  endif()
  if(checked EQUAL 0)
    message(FATAL_ERROR "Layer check: no layer files under ${root}")
  endif()
endfunction()

if(CMAKE_SCRIPT_MODE_FILE STREQUAL CMAKE_CURRENT_LIST_FILE)
  if(NOT SLUICE_LAYERS_ROOT)
    message(FATAL_ERROR "usage: cmake -DSLUICE_LAYERS_ROOT=<source tree> -P ${CMAKE_CURRENT_LIST_FILE}")
  endif()
  sluice_check_layers(${SLUICE_LAYERS_ROOT})
  if(SLUICE_LAYERS_STAMP)
    file(TOUCH ${SLUICE_LAYERS_STAMP})
  endif()
endif()
