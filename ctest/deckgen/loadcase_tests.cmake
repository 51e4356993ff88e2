# SPDX-License-Identifier: GPL-3.0-or-later
# Load-case generator tests (deckgen/loadcases): impactor mesh against its analytic shape;
# the posed model variant of the oblique cases up to date.
add_executable(loadcase_impactor_tests ${CMAKE_CURRENT_LIST_DIR}/loadcase_impactor_tests.cpp)
target_link_libraries(loadcase_impactor_tests PRIVATE hbm_loadcases GTest::gtest_main)
gtest_discover_tests(loadcase_impactor_tests PROPERTIES LABELS unit DISCOVERY_TIMEOUT 60)

# The posed model of the oblique thorax cases (decks/hub_posed_arm_l_raised/, the left arm
# raised out of the impactor's path) is regenerated with the command in
# deckgen/loadcases/src/load_case_catalogue.cpp and compared byte for byte, like decks/hbm50.
set(_posed ${CMAKE_CURRENT_BINARY_DIR}/posed_arm_l_raised)
add_test(NAME loadcase_regenerate_posed_arm_l_raised
  COMMAND $<TARGET_FILE:hbm-deckgen> -g ${PROJECT_SOURCE_DIR}/geometry -o ${_posed} -n hbm50_arm_l_raised --no-drop
          --joint shoulder_l=-60)
set_tests_properties(loadcase_regenerate_posed_arm_l_raised PROPERTIES LABELS regression FIXTURES_SETUP posed_arm_l_regen)
add_test(NAME loadcase_compare_posed_arm_l_raised
  COMMAND ${CMAKE_COMMAND} -E compare_files ${_posed}/hbm50_arm_l_raised.inc
          ${PROJECT_SOURCE_DIR}/decks/hub_posed_arm_l_raised/hbm50_arm_l_raised.inc)
set_tests_properties(loadcase_compare_posed_arm_l_raised PROPERTIES LABELS regression FIXTURES_REQUIRED posed_arm_l_regen)

add_executable(loadcase_posed_model_tests ${CMAKE_CURRENT_LIST_DIR}/loadcase_posed_model_tests.cpp)
target_link_libraries(loadcase_posed_model_tests PRIVATE hbm_loadcases GTest::gtest_main)
target_compile_definitions(loadcase_posed_model_tests PRIVATE HBM_SOURCE_DIR="${PROJECT_SOURCE_DIR}")
gtest_discover_tests(loadcase_posed_model_tests PROPERTIES LABELS unit DISCOVERY_TIMEOUT 60)
