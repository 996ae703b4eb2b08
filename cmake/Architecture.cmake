# The module graph of docs/architecture.md: which module may use which. One table serves
# two checks (cmake/CheckIncludes.cmake for #include lines, systole_check_links() for the
# libraries), so the rule a reader sees is the rule the build enforces.
#
# "module:allowed,..." - a module may include and link the modules after its colon, and no
# other module of src/. External libraries are confined by SYSTOLE_EXTERNAL below.
set(SYSTOLE_MODULES
  "common:"
  "physics:"
  "scene:common,physics"
  "mesh:common,physics,scene"
  "electro:common,physics,mesh"
  "sim:common,physics,mesh,electro"
  "world:common,physics,scene,mesh,sim,electro"
  "train:common,physics,scene,mesh,sim,electro,world,chart"
  "chart:common"
  "plot:common,chart"
  "render:common,physics,scene,mesh"
  "encode:common"
  "audio:common"
  "overlay:common,physics,scene,chart,plot"
  "clip:common,physics,scene,mesh,sim,electro,world,chart,plot,render,encode,overlay,audio"
  "batch:common,physics,scene,mesh,sim,electro,world,chart,plot,render,encode,overlay,audio,clip"
  "study:common,physics,scene,mesh,sim,electro,world,chart,plot,render,encode,overlay,audio,clip"
  "export:common,physics,scene,mesh,sim,electro,world,chart,plot,render,encode,overlay,audio,clip"
  "cli:common,physics,scene,mesh,sim,electro,world,train,chart,plot,render,encode,overlay,audio,clip,batch,study,export")

# The one place the simulator meets the scene: the translation of a scene into sim's own
# parameter structs. No other file under src/sim/ may include scene/.
set(SYSTOLE_SIM_SCENE_BRIDGE "sim/from_scene.h" "sim/from_scene.cpp")

# The physics value types scene and sim share: each is declared once, in physics/, and
# used elsewhere through a using-declaration (`using physics::Drive;`), never copied.
# tests/architecture/CheckOneHome.cmake (test architecture.one_home) enforces it.
set(SYSTOLE_PHYSICS_HOME "physics")
set(SYSTOLE_PHYSICS_TYPES Waveform Harmonic Drive PathKey InteractionKind Floor)

# "library:module,..." - the modules whose libraries may link an external library, directly
# or through another module. train must never reach OSMesa, libav* or FreeType.
set(SYSTOLE_EXTERNAL
  "PkgConfig::OSMESA:render"
  "PkgConfig::LIBAV:encode"
  "Freetype::Freetype:plot"
  "yaml-cpp:scene"
  "assimp::assimp:mesh"
  "meshoptimizer::meshoptimizer:mesh"
  "tinyxml2::tinyxml2:mesh"
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

# What `target` links: LINK_LIBRARIES, or INTERFACE_LINK_LIBRARIES for a header-only
# (INTERFACE) library such as systole_physics, which has only those.
function(systole_direct_links target out)
  get_target_property(type ${target} TYPE)
  if(type STREQUAL "INTERFACE_LIBRARY")
    get_target_property(links ${target} INTERFACE_LINK_LIBRARIES)
  else()
    get_target_property(links ${target} LINK_LIBRARIES)
  endif()
  if(NOT links)
    set(links "")
  endif()
  set(${out} "${links}" PARENT_SCOPE)
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
    systole_direct_links(${current} links)
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
    systole_direct_links(systole_${module} direct)
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
