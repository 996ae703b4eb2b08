# The module graph of docs/architecture.md: which module may use which. One table serves
# two checks (cmake/CheckIncludes.cmake for #include lines, systole_check_links() for the
# libraries), so the rule a reader sees is the rule the build enforces.
#
# "module:allowed,..." - a module may include and link the modules after its colon, and no
# other module of src/. External libraries are confined by SYSTOLE_EXTERNAL below.
set(SYSTOLE_MODULES
  "common:"
  "scene:common"
  "mesh:common,scene"
  "sim:common,mesh"
  "world:common,scene,mesh,sim"
  "train:common,scene,mesh,sim,world,chart"
  "chart:common"
  "plot:common,chart"
  "render:common,scene,mesh"
  "encode:common"
  "audio:common"
  "overlay:common,scene,chart,plot"
  "clip:common,scene,mesh,sim,world,chart,plot,render,encode,overlay,audio"
  "batch:common,scene,mesh,sim,world,chart,plot,render,encode,overlay,audio,clip"
  "study:common,scene,mesh,sim,world,chart,plot,render,encode,overlay,audio,clip"
  "export:common,scene,mesh,sim,world,chart,plot,render,encode,overlay,audio,clip"
  "cli:common,scene,mesh,sim,world,train,chart,plot,render,encode,overlay,audio,clip,batch,study,export")

# The one place the simulator meets the scene: the translation of a scene into sim's own
# parameter structs. No other file under src/sim/ may include scene/.
set(SYSTOLE_SIM_SCENE_BRIDGE "sim/from_scene.h" "sim/from_scene.cpp")

# "library:module,..." - the modules whose libraries may link an external library, directly
# or through another module. train must never reach OSMesa, libav* or FreeType.
set(SYSTOLE_EXTERNAL
  "PkgConfig::OSMESA:render"
  "PkgConfig::LIBAV:encode"
  "Freetype::Freetype:plot"
  "yaml-cpp:scene"
  "assimp::assimp:mesh"
  "meshoptimizer::meshoptimizer:mesh"
  "TinyGLTF::TinyGLTF:export")

# allowed = the modules `module` may use (empty list for common); known = FALSE if not listed.
function(systole_allowed_modules module out_allowed out_known)
  set(${out_known} FALSE PARENT_SCOPE)
  foreach(row IN LISTS SYSTOLE_MODULES)
    string(REPLACE ":" ";" parts "${row}")
    list(GET parts 0 name)
    if(name STREQUAL module)
      list(LENGTH parts n)
      set(allowed "")
      if(n GREATER 1)
        list(GET parts 1 csv)
        string(REPLACE "," ";" allowed "${csv}")
      endif()
      set(${out_allowed} "${allowed}" PARENT_SCOPE)
      set(${out_known} TRUE PARENT_SCOPE)
      return()
    endif()
  endforeach()
endfunction()

# The modules `module` may use, and those they may use, and so on: what its library may reach
# (sim may not include scene outside its bridge, but reaches it through mesh).
function(systole_allowed_closure module out)
  set(closure "")
  systole_allowed_modules(${module} queue known)
  while(queue)
    list(POP_FRONT queue current)
    if(current IN_LIST closure)
      continue()
    endif()
    list(APPEND closure ${current})
    systole_allowed_modules(${current} more known)
    list(APPEND queue ${more})
  endwhile()
  set(${out} "${closure}" PARENT_SCOPE)
endfunction()

# Every systole_<module> library reachable from `target` through its link libraries.
function(systole_link_closure target out)
  set(seen "")
  set(queue ${target})
  while(queue)
    list(POP_FRONT queue current)
    if(NOT TARGET ${current})
      continue()
    endif()
    get_target_property(links ${current} LINK_LIBRARIES)
    if(NOT links)
      continue()
    endif()
    foreach(link IN LISTS links)
      if(link MATCHES "^systole_" AND NOT link IN_LIST seen)
        list(APPEND seen ${link})
        list(APPEND queue ${link})
      endif()
    endforeach()
  endwhile()
  set(${out} "${seen}" PARENT_SCOPE)
endfunction()

# Called after the libraries are defined: fails the configure when a module's library
# reaches a module it may not use, or an external library is linked outside its module.
function(systole_check_links)
  set(violations "")
  foreach(row IN LISTS SYSTOLE_MODULES)
    string(REGEX REPLACE ":.*" "" module "${row}")
    if(NOT TARGET systole_${module})
      continue()
    endif()
    systole_allowed_closure(${module} allowed)
    systole_link_closure(systole_${module} reached)
    foreach(library IN LISTS reached)
      string(REGEX REPLACE "^systole_" "" used "${library}")
      if(NOT used IN_LIST allowed)
        string(APPEND violations "  systole_${module} links ${library}; ${module} may use only: ${allowed}\n")
      endif()
    endforeach()
    get_target_property(direct systole_${module} LINK_LIBRARIES)
    foreach(row2 IN LISTS SYSTOLE_EXTERNAL)
      string(REGEX MATCH "^(.*):([a-z]+)$" _ "${row2}")
      set(external ${CMAKE_MATCH_1})
      set(owner ${CMAKE_MATCH_2})
      if(direct AND external IN_LIST direct AND NOT module STREQUAL owner)
        string(APPEND violations "  systole_${module} links ${external}, which only ${owner} may link\n")
      endif()
    endforeach()
  endforeach()
  if(violations)
    message(FATAL_ERROR "Forbidden library links (docs/architecture.md, cmake/Architecture.cmake):\n${violations}")
  endif()
endfunction()
