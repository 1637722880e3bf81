# The effect validator's tests (src/engine/effect_validation.cpp). Included from
# tests/engine/CMakeLists.txt.
feel_add_test(feel_effect_validation_test
  SOURCES ${CMAKE_CURRENT_LIST_DIR}/effect_validation_test.cpp
  LIBS feel_engine)
