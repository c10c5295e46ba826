# Read by ctest after Catch's list of the unit tests tagged [long] (tests/CMakeLists.txt): each is
# labelled unit and long.
foreach(test IN LISTS tire_long_tests)
  set_tests_properties("${test}" PROPERTIES LABELS "unit;long")
endforeach()
