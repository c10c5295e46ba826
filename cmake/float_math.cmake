# Every program this project builds links tire::float_math (engine/rigid/CMakeLists.txt): Box2D's
# rotations are then the engine's own bits, the same natively and in the browser. The engine's
# libraries themselves define no C-library function, so a program that embeds them keeps its own
# unless it links tire::float_math too (docs/engine.md).
function(tire_programs_link_float_math dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target ${targets})
    get_target_property(type ${target} TYPE)
    if(type STREQUAL "EXECUTABLE")
      target_link_libraries(${target} PRIVATE tire_float_math)
    endif()
  endforeach()
  get_property(subdirectories DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(subdirectory ${subdirectories})
    tire_programs_link_float_math(${subdirectory})
  endforeach()
endfunction()
